#include "BenchHost.h"
#include "BenchDevice.h"
#include "EventWait.h"

namespace stepdeck::bench {

BenchHost::BenchHost(QObject* parent) : QObject(parent)
{
    connect(&m_session, &ControllerSession::requestFinished, this,
            [this](const CommandResult& result) { m_finished.insert(result.id, result); });
    connect(&m_session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected && state != LinkState::Connecting && m_linkLeftNs < 0)
            m_linkLeftNs = nowNs();
    });
    connect(&m_session, &ControllerSession::pollRateChanged, this, [this](double hz) {
        m_pollRateHz = hz;
        ++m_pollRateReports;
    });
}

BenchHost::~BenchHost()
{
    m_session.destroy();
}

bool BenchHost::waitUntil(const std::function<bool()>& done, int timeoutMs)
{
    return bench::waitUntil(done, timeoutMs);
}

void BenchHost::idle(int ms)
{
    waitUntil([] { return false; }, ms);
}

bool BenchHost::connectTo(const ModelInfo& model, const QString& port, const Options& options,
                          QString* error)
{
    m_session.destroy();
    m_finished.clear();
    m_linkLeftNs = -1;
    m_pollRateHz = 0;
    m_pollRateReports = 0;
    ConnectionSpec spec;
    spec.port = port;
    spec.options.pollIntervalMs = options.pollIntervalMs;
    if (!m_axisAddresses.isEmpty())
        spec.options.axisAddresses = m_axisAddresses;
    if (options.arrivalTimeoutMs > 0)
        spec.options.arrivalTimeoutMs = options.arrivalTimeoutMs;
    if (!m_session.create(model, spec, error))
        return false;
    const RequestId id = m_session.open();
    waitUntil([&] { return connected() || (m_finished.contains(id) && !m_finished[id].ok()); },
              options.connectTimeoutMs);
    if (connected()) {
        m_linkLeftNs = -1; // what happened while connecting does not count
        return true;
    }
    *error = m_finished.contains(id) ? m_finished.value(id).message
                                     : QStringLiteral("link did not come up within %1 s")
                                           .arg(options.connectTimeoutMs / 1000);
    return false;
}

void BenchHost::disconnect()
{
    if (m_session.isCreated()) {
        m_session.close();
        waitUntil([&] { return m_session.linkState() != LinkState::Connected; }, 3000);
        m_session.destroy();
    }
}

BenchHost::Outcome BenchHost::call(const std::function<RequestId(ControllerSession&)>& start,
                                   int boundMs)
{
    const RequestId id = start(m_session);
    Outcome out;
    out.finished = waitUntil([&] { return m_finished.contains(id); }, boundMs);
    out.result = out.finished
                     ? m_finished.take(id)
                     : CommandResult::failure(id, ErrorKind::Timeout, QStringLiteral("no result"));
    return out;
}

bool BenchHost::waitIdle(int timeoutMs)
{
    return waitUntil([&] { return !connected() || !m_session.status().anyMoving(); }, timeoutMs);
}

} // namespace stepdeck::bench
