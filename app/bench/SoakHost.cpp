#include "SoakHost.h"
#include "BenchDevice.h"
#include "EventWait.h"

namespace stepdeck::bench {

SoakHost::SoakHost(QObject* parent) : QObject(parent)
{
    connect(&m_session, &ControllerSession::requestFinished, this,
            [this](const CommandResult& result) { m_finished.insert(result.id, result); });
    connect(&m_session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected && state != LinkState::Connecting && m_linkLeftNs < 0)
            m_linkLeftNs = nowNs();
    });
}

SoakHost::~SoakHost()
{
    m_session.destroy();
}

bool SoakHost::waitUntil(const std::function<bool()>& done, int timeoutMs)
{
    return bench::waitUntil(done, timeoutMs);
}

void SoakHost::idle(int ms)
{
    waitUntil([] { return false; }, ms);
}

bool SoakHost::connectTo(const ModelInfo& model, const QString& port, QString* error)
{
    m_session.destroy();
    m_finished.clear();
    m_linkLeftNs = -1;
    ConnectionSpec spec;
    spec.port = port;
    spec.options.pollIntervalMs = 20;
    // Models that learn of an arrival only from the device (laser status frames) wait this
    // long for it (--arrival-timeout in the CLI, 60 s by default). Every target of the soak
    // arrives within a fraction of a second, so a lost arrival frame is reported as a timeout
    // after 3 s instead of outlasting kRequestBoundMs and counting as a hang.
    spec.options.arrivalTimeoutMs = 3000;
    if (!m_session.create(model, spec, error))
        return false;
    const RequestId id = m_session.open();
    waitUntil([&] { return connected() || m_finished.contains(id); }, 5000);
    if (connected()) {
        m_linkLeftNs = -1; // what happened while connecting does not count
        return true;
    }
    *error = m_finished.contains(id) ? m_finished.value(id).message
                                     : QStringLiteral("link did not come up within 5 s");
    return false;
}

void SoakHost::disconnect()
{
    if (m_session.isCreated()) {
        m_session.close();
        waitUntil([&] { return m_session.linkState() != LinkState::Connected; }, 3000);
        m_session.destroy();
    }
}

SoakHost::Outcome SoakHost::call(const std::function<RequestId(ControllerSession&)>& start,
                                 int boundMs)
{
    const RequestId id = start(m_session);
    Outcome out;
    out.finished = waitUntil([&] { return m_finished.contains(id); }, boundMs);
    if (out.finished)
        out.result = m_finished.take(id);
    return out;
}

bool SoakHost::waitIdle(int timeoutMs)
{
    return waitUntil([&] { return !connected() || !m_session.status().anyMoving(); }, timeoutMs);
}

} // namespace stepdeck::bench
