#include "BenchSession.h"
#include "EventWait.h"

namespace stepdeck::bench {

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
    return bench::waitUntil(done, timeoutMs);
}

bool BenchSession::connectTo(const ModelInfo& model, const QString& port, int pollIntervalMs,
                             QString* error)
{
    ConnectionSpec spec;
    spec.port = port;
    spec.options.pollIntervalMs = pollIntervalMs;
    if (!m_session.create(model, spec, error))
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
