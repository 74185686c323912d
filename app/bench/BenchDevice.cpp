#include "BenchDevice.h"
#include "WirePacer.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include "sim/PtyEndpoint.h"
#include <chrono>

namespace stepdeck::bench {

qint64 nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Lives in the device thread; owns the endpoint, the simulator and, paced, the two wires.
class BenchDevice::Worker : public QObject
{
public:
    PtyEndpoint* endpoint = nullptr;
    Simulator* simulator = nullptr;
};

BenchDevice::BenchDevice(const ModelInfo& model, const Config& config)
    : m_model(model), m_config(config)
{
    m_thread.setObjectName(QStringLiteral("bench-device"));
}

BenchDevice::~BenchDevice()
{
    if (m_worker) {
        Worker* worker = m_worker;
        QMetaObject::invokeMethod(
            worker,
            [worker] {
                delete worker->simulator; // before the endpoint and pacers it talks to
                delete worker;
            },
            Qt::BlockingQueuedConnection);
    }
    m_thread.quit();
    m_thread.wait();
}

bool BenchDevice::start(QString* error)
{
    m_thread.start();
    m_worker = new Worker;
    m_worker->moveToThread(&m_thread);
    Worker* w = m_worker;
    bool ok = false;
    QMetaObject::invokeMethod(
        w,
        [&] {
            // Paced, both directions run through a WirePacer here rather than the
            // simulator's own output pacing, so requests and replies share one wire model.
            SimulatorOptions options;
            options.line = m_model.line;
            w->simulator = m_model.createSimulator(options);
            w->simulator->setParent(w);
            if (m_config.unlimitedStreamBuffer) {
                if (auto* elabSim = qobject_cast<elab::ElabSimulator*>(w->simulator))
                    elabSim->setStreamBuffer(1 << 24, (1 << 24) - 64, 1 << 23);
            }
            w->endpoint = new PtyEndpoint(w);
            if (!w->endpoint->create(error))
                return;
            w->endpoint->open(m_model.line);
            const auto toHost = [w](const QByteArray& bytes) { w->endpoint->write(bytes); };
            const auto toDevice = [this, w](const QByteArray& bytes) {
                scan(bytes);
                w->simulator->receive(bytes);
            };
            if (!m_config.paced) {
                QObject::connect(w->simulator, &Simulator::transmit, w, toHost);
                QObject::connect(w->endpoint, &Transport::dataReceived, w, toDevice);
            } else {
                const double characterUs = m_model.line.characterTimeUs();
                auto* out = new WirePacer(characterUs, toHost, w);
                auto* in = new WirePacer(characterUs, toDevice, w);
                QObject::connect(w->simulator, &Simulator::transmit, out, &WirePacer::push);
                QObject::connect(w->endpoint, &Transport::dataReceived, in, &WirePacer::push);
            }
            m_slavePath = w->endpoint->slavePath();
            ok = true;
        },
        Qt::BlockingQueuedConnection);
    return ok;
}

void BenchDevice::withSimulator(const std::function<void(Simulator*)>& fn)
{
    Worker* w = m_worker;
    QMetaObject::invokeMethod(
        w, [w, &fn] { fn(w->simulator); }, Qt::BlockingQueuedConnection);
}

void BenchDevice::resetCounters()
{
    m_stepBytes = 0;
    m_firstStepNs = -1;
    m_lastStepNs = -1;
    m_panicNs = -1;
}

void BenchDevice::scan(const QByteArray& bytes)
{
    // E-LAB framing (manual, SetFeedStepXYZ): <DC2> is followed by one raw step byte, which
    // may take any value with bits 7 and 3 clear -- including 0x07, so track the pairs.
    const qint64 now = nowNs();
    for (const char byte : bytes) {
        if (m_afterDc2) {
            m_afterDc2 = false;
            if (m_firstStepNs.load() < 0)
                m_firstStepNs = now;
            m_lastStepNs = now;
            ++m_stepBytes;
        } else if (byte == elab::ctrl::DC2) {
            m_afterDc2 = true;
        } else if (byte == elab::ctrl::BEL && m_panicNs.load() < 0) {
            m_panicNs = now;
        }
    }
}

} // namespace stepdeck::bench
