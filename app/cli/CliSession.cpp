#include "CliSession.h"
#include "model/ModelOperations.h"
#include "protocols/Registry.h"
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
}

CliSession::~CliSession() = default;

void CliSession::wake()
{
    m_wait.wake();
}

bool CliSession::waitFor(const std::function<bool()>& done, int timeoutMs)
{
    return m_wait.waitFor(done, timeoutMs, m_interrupted);
}

bool CliSession::pause(int ms)
{
    waitFor([] { return false; }, ms);
    return !m_interrupted;
}

ControllerOptions CliSession::baseControllerOptions(const CliOptions& options)
{
    ControllerOptions base;
    base.arrivalTimeoutMs = options.arrivalTimeoutMs;
    // The core's messages name this program's commands (the GUI names its buttons).
    base.actionNames.insert(operation::kResetPositionError,
                            tr("`stepdeck-cli reset-position-error AXIS`"));
    return base;
}

Outcome CliSession::create()
{
    if (m_session.isCreated())
        return Outcome::success();
    ConnectionSpec spec;
    spec.port = m_options.port;
    spec.options = baseControllerOptions(m_options);
    spec.options.axisAddresses = m_options.axisAddresses;
    spec.options.axisNames = m_options.axisNames;
    spec.options.resetLine = m_options.resetLine;
    if (m_options.address)
        spec.options.axisAddresses.insert(Axis::X, *m_options.address);
    QString error;
    const ModelInfo* model = findModel(m_options.model);
    if (!model)
        return Outcome::usage(unknownModelText(m_options.model));
    if (!m_session.create(*model, spec, &error))
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

int CliSession::linkVerdictMs() const
{
    // The poller declares the link lost after its miss limit of unanswered polls, each up to a
    // command timeout apart; then the adapter's safety stop runs (bounded) first.
    return linkVerdictMs(m_session.spec().options);
}

int CliSession::linkVerdictMs(const ControllerOptions& o)
{
    return o.missedPollsForLinkLoss * (o.commandTimeoutMs + o.pollIntervalMs) + 1500;
}

Outcome CliSession::linkLostOutcome() const
{
    QString why = tr("link lost: %1").arg(m_lostReason.isEmpty() ? m_lastError : m_lostReason);
    if (status().motionUnconfirmed)
        why = tr("%1; %2").arg(why, Controller::mayStillBeMovingText());
    return Outcome::failure(ExitLinkDown, why);
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
    if (m_finished.contains(id)) {
        CommandResult result = m_finished.take(id);
        const ErrorKind e = result.error;
        if (m_connected && !m_interrupted &&
            (e == ErrorKind::Timeout || e == ErrorKind::Cancelled || e == ErrorKind::Protocol)) {
            // One fault, one exit code: if the controller stopped answering altogether, the
            // poller is about to declare the link lost -- that is the fault, not this request.
            waitFor([this] { return m_lost; }, linkVerdictMs());
        }
        if (m_lost && !result.ok() && result.error != ErrorKind::LinkDown) {
            const Outcome lost = linkLostOutcome();
            result = CommandResult::failure(id, ErrorKind::LinkDown, lost.message);
        }
        return result;
    }
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

Outcome CliSession::waitUntilIdle(int deadlineMs)
{
    QElapsedTimer clock;
    clock.start();
    for (;;) {
        const Outcome polled = refresh();
        if (!polled.ok())
            return polled;
        QStringList unknown;
        for (auto it = status().axes.cbegin(); it != status().axes.cend(); ++it) {
            if (it.value().motionUnknown)
                unknown << axisName(it.key());
        }
        if (!unknown.isEmpty()) {
            return Outcome::failure(ExitLinkDown,
                                    tr("no status from the drive of axis %1: it may still be "
                                       "moving")
                                        .arg(unknown.join(QStringLiteral(", "))));
        }
        if (status().panic) {
            return Outcome::failure(ExitMotionAborted,
                                    tr("motion aborted: emergency stop is active (positions are "
                                       "unknown until referenced)"));
        }
        if (!status().anyMoving())
            break;
        if (deadlineMs >= 0 && clock.elapsed() > deadlineMs) {
            return Outcome::failure(ExitTimeout,
                                    tr("the motion did not end within %1 ms").arg(deadlineMs));
        }
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

Outcome CliSession::stopMotion()
{
    if (!m_connected)
        return Outcome::success();
    if (m_lost) // the adapter sent its stop when the link went down
        return linkLostOutcome();
    const bool wasInterrupted = std::exchange(m_interrupted, false); // let the waits run
    // A jog ramps down first (the host ramp is the jog's only brake); then the model's stop
    // for whatever else may run (a velocity or reference move brakes on the board).
    m_session.endJog();
    waitFor(
        [this] {
            for (const AxisStatus& a : status().axes) {
                if (a.commandedVelocity != 0.0)
                    return false;
            }
            return true;
        },
        kJogRampDownMs);
    const CommandResult stopped = call([](ControllerSession& s) { return s.stop(); }, 3000);
    m_interrupted = wasInterrupted;
    if (stopped.ok())
        return Outcome::success();
    if (stopped.error == ErrorKind::Unsupported)
        return Outcome::from(stopped);
    return Outcome::failure(
        exitCodeFor(stopped.error),
        stopped.message.contains(Controller::mayStillBeMovingText())
            ? stopped.message
            : tr("%1; %2").arg(stopped.message, Controller::mayStillBeMovingText()));
}

} // namespace stepdeck::cli
