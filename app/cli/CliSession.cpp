#include "CliSession.h"
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <climits>

namespace stepdeck::cli {

CliSession::CliSession(const CliOptions& options, QObject* parent)
    : QObject(parent), m_options(options)
{
    connect(&m_session, &ControllerSession::requestFinished, this,
            [this](const CommandResult& result) {
                m_finished.insert(result.id, result);
                wake();
            });
    connect(&m_session, &ControllerSession::linkStateChanged, this,
            [this](LinkState state, const QString& reason) {
                if (state == LinkState::Lost || (state == LinkState::Disconnected && m_connected)) {
                    m_lost = true;
                    m_lostReason = reason;
                }
                wake();
            });
    connect(&m_session, &ControllerSession::statusChanged, this, [this] { wake(); });
    connect(&m_session, &ControllerSession::errorOccurred, this, [this](const QString& message) {
        m_lastError = message;
        wake();
    });
    connect(&m_session, &ControllerSession::jogRefused, this, [this](const QString& reason) {
        m_jogRefusal = reason;
        wake();
    });
}

CliSession::~CliSession() = default;

void CliSession::wake()
{
    if (m_loop)
        m_loop->quit();
}

bool CliSession::waitFor(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (m_interrupted)
            return false;
        const qint64 left = timeoutMs < 0 ? -1 : timeoutMs - clock.elapsed();
        if (timeoutMs >= 0 && left <= 0)
            return false;
        QEventLoop loop;
        QTimer deadline;
        deadline.setSingleShot(true);
        connect(&deadline, &QTimer::timeout, &loop, &QEventLoop::quit);
        if (left > 0)
            deadline.start(int(qMin<qint64>(left, INT_MAX)));
        m_loop = &loop;
        loop.exec();
        m_loop = nullptr;
    }
    return true;
}

bool CliSession::pause(int ms)
{
    waitFor([] { return false; }, ms);
    return !m_interrupted;
}

Outcome CliSession::create()
{
    if (m_session.isCreated())
        return Outcome::success();
    ConnectionSpec spec;
    spec.modelId = m_options.model;
    spec.port = m_options.port;
    spec.options.axisAddresses = m_options.axisAddresses;
    spec.options.arrivalTimeoutMs = m_options.arrivalTimeoutMs;
    if (m_options.address)
        spec.options.axisAddresses.insert(Axis::X, *m_options.address);
    QString error;
    if (!m_session.create(spec, &error))
        return Outcome::usage(error);
    return Outcome::success();
}

Outcome CliSession::connectLink()
{
    if (m_connected)
        return Outcome::success();
    if (const Outcome created = create(); !created.ok())
        return created;

    const RequestId id = m_session.open();
    const auto settled = [&] {
        if (m_lost || m_session.linkState() == LinkState::Lost)
            return true;
        if (!m_finished.contains(id))
            return false;
        return !m_finished.value(id).ok() || m_session.linkState() == LinkState::Connected;
    };
    waitFor(settled, m_options.connectTimeoutMs);
    if (m_interrupted)
        return Outcome::failure(ExitInterrupted, tr("interrupted"));
    const CommandResult result = m_finished.take(id);
    if (result.id == id && !result.ok()) {
        return Outcome::failure(exitCodeFor(result.error),
                                result.message.contains(m_options.port)
                                    ? result.message
                                    : tr("%1: %2").arg(m_options.port, result.message));
    }
    if (m_session.linkState() != LinkState::Connected) {
        const QString why = !m_lostReason.isEmpty() ? m_lostReason : m_lastError;
        return Outcome::failure(
            ExitLinkDown,
            why.isEmpty()
                ? tr("%1: no answer from the controller within %2 ms (powered, cabled, right "
                     "model?)")
                      .arg(m_options.port)
                      .arg(m_options.connectTimeoutMs)
                : tr("%1: link did not come up: %2").arg(m_options.port, why));
    }
    m_connected = true;
    return Outcome::success();
}

CommandResult CliSession::call(const std::function<RequestId(ControllerSession&)>& start,
                               int timeoutMs)
{
    const RequestId id = start(m_session);
    waitFor([&] { return m_finished.contains(id) || m_lost; }, timeoutMs);
    if (!m_finished.contains(id) && m_lost && !m_interrupted) {
        // The adapter finishes what was pending when the link drops; give it a moment so its
        // more precise message wins.
        waitFor([&] { return m_finished.contains(id); }, 250);
    }
    if (m_finished.contains(id))
        return m_finished.take(id);
    if (m_interrupted)
        return CommandResult::failure(id, ErrorKind::Cancelled, tr("interrupted"));
    if (m_lost) {
        return CommandResult::failure(
            id, ErrorKind::LinkDown,
            tr("link lost: %1").arg(m_lostReason.isEmpty() ? m_lastError : m_lostReason));
    }
    return CommandResult::failure(id, ErrorKind::Timeout,
                                  tr("no result from the controller within %1 ms").arg(timeoutMs));
}

Outcome CliSession::refresh()
{
    return run([](ControllerSession& s) { return s.refreshStatus(); });
}

Outcome CliSession::waitUntilIdle()
{
    for (;;) {
        const Outcome polled = refresh();
        if (!polled.ok())
            return polled;
        if (status().panic) {
            return Outcome::failure(ExitMotionAborted,
                                    tr("motion aborted: emergency stop is active (positions are "
                                       "unknown until referenced)"));
        }
        if (!status().anyMoving())
            break;
        if (!pause(kIdlePollMs))
            return Outcome::failure(ExitInterrupted, tr("interrupted"));
    }
    QStringList limits;
    for (auto it = status().axes.cbegin(); it != status().axes.cend(); ++it) {
        if (it.value().limitSwitch)
            limits << axisName(it.key());
    }
    if (!limits.isEmpty()) {
        return Outcome::failure(ExitMotionAborted,
                                tr("motion ended on an active limit switch (axis %1); only jog "
                                   "moves are allowed until it is cleared")
                                    .arg(limits.join(QStringLiteral(", "))));
    }
    return Outcome::success();
}

void CliSession::interrupt()
{
    m_interrupted = true;
    wake();
}

void CliSession::stopMotion()
{
    if (!m_connected)
        return;
    m_interrupted = false; // let the stop's own wait run
    m_session.endJog();
    call([](ControllerSession& s) { return s.stop(); }, 1000);
    m_interrupted = true;
}

} // namespace stepdeck::cli
