#include "BenchSession.h"
#include "protocols/Registry.h"
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

namespace stepdeck::bench {

namespace {
constexpr int kWakeMs = 2; // how often a wait re-checks its condition
}

BenchSession::BenchSession(QObject* parent) : QObject(parent)
{
    connect(&m_session, &ControllerSession::requestFinished, this,
            [this](const CommandResult& result) { m_finished.insert(result.id, result); });
    connect(&m_session, &ControllerSession::pollRateChanged, this, [this](double hz) {
        m_pollRateHz = hz;
        ++m_pollRateReports;
    });
}

bool BenchSession::waitUntil(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() >= timeoutMs)
            return false;
        QEventLoop loop;
        QTimer::singleShot(kWakeMs, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

bool BenchSession::connectTo(const QString& modelId, const QString& port, int pollIntervalMs,
                             QString* error)
{
    ConnectionSpec spec;
    spec.modelId = modelId;
    spec.port = port;
    spec.options.pollIntervalMs = pollIntervalMs;
    const ModelInfo* model = findModel(modelId);
    if (!model) {
        *error = unknownModelText(modelId);
        return false;
    }
    if (!m_session.create(*model, spec, error))
        return false;
    const RequestId id = m_session.open();
    const bool connected = waitUntil(
        [&] {
            return m_session.linkState() == LinkState::Connected ||
                   (m_finished.contains(id) && !m_finished.value(id).ok());
        },
        3000);
    if (connected && m_session.linkState() == LinkState::Connected)
        return true;
    *error = m_finished.contains(id) ? m_finished.value(id).message
                                     : QStringLiteral("link did not come up within 3 s");
    return false;
}

CommandResult BenchSession::call(const std::function<RequestId(ControllerSession&)>& start,
                                 int timeoutMs)
{
    const RequestId id = start(m_session);
    if (!waitUntil([&] { return m_finished.contains(id); }, timeoutMs))
        return CommandResult::failure(id, ErrorKind::Timeout, QStringLiteral("no result"));
    return m_finished.take(id);
}

} // namespace stepdeck::bench
