#include "BenchDevice.h"
#include "PollWire.h"
#include "WirePacer.h"
#include "sim/PtyEndpoint.h"
#include "sim/TrafficMeter.h"
#include <QRandomGenerator>
#include <QTimer>
#include <chrono>
#include <pthread.h>
#include <sched.h>

namespace stepdeck::bench {

qint64 nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

namespace {
// The calling thread to the lowest SCHED_FIFO priority: above every normal thread, below the
// kernel's own real-time work. False where the process may not (no CAP_SYS_NICE, RLIMIT_RTPRIO
// 0); the thread then stays as it was.
bool makeCallingThreadRealtime()
{
    sched_param param{};
    param.sched_priority = sched_get_priority_min(SCHED_FIFO);
    return pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
}
} // namespace

// Lives in the device thread; owns the endpoint, the simulator and, paced, the two wires.
class BenchDevice::Worker : public QObject
{
public:
    void toHost(const QByteArray& bytes)
    {
        if (endpoint)
            endpoint->write(bytes);
    }
    void toDevice(const QByteArray& bytes)
    {
        const qint64 arrivedNs = nowNs();
        if (meter)
            meter->scan(bytes, arrivedNs);
        if (!wire) {
            simulator->receive(bytes);
        } else {
            // One character at a time: the simulator answers a request as soon as it has read
            // it, so a character behind it that crosses the reply is seen as such.
            for (qsizetype i = 0; i < bytes.size(); ++i) {
                wire->requestCharArrived();
                simulator->receive(bytes.mid(i, 1));
            }
        }
        if (received)
            received(simulator, arrivedNs);
    }

    Simulator* simulator = nullptr;
    PtyEndpoint* endpoint = nullptr;
    WirePacer* fromHost = nullptr; // paced only
    TrafficMeter* meter = nullptr;
    WireCounter* wire = nullptr; // paced only
    std::function<void(Simulator*, qint64)> received;
    QRandomGenerator noise;
};

BenchDevice::Config BenchDevice::soakConfig(const ModelInfo& model, quint32 seed)
{
    Config config;
    config.seed = seed;
    config.addresses = model.soak.simulatorAddresses;
    config.prepare = model.soak.prepare;
    return config;
}

BenchDevice::BenchDevice(const ModelInfo& model, Config config)
    : m_model(model), m_config(std::move(config))
{
    m_thread.setObjectName(QStringLiteral("bench-device"));
}

BenchDevice::~BenchDevice()
{
    if (m_worker) {
        Worker* w = m_worker;
        QMetaObject::invokeMethod(
            w,
            [w] {
                delete w->simulator; // before the endpoint and pacers it talks to
                delete w;
            },
            Qt::BlockingQueuedConnection);
    }
    m_thread.quit();
    m_thread.wait();
}

bool BenchDevice::start(QString* error)
{
    if (!m_model.createSimulator) {
        *error = QStringLiteral("model %1 has no simulator in this build").arg(m_model.id);
        return false;
    }
    if (m_config.metered) {
        if (!m_model.streamBench.supported()) {
            *error = QStringLiteral("model %1 has no stream to measure").arg(m_model.id);
            return false;
        }
        m_meter = m_model.streamBench.createMeter();
    }
    m_thread.start();
    m_worker = new Worker;
    m_worker->moveToThread(&m_thread);
    Worker* w = m_worker;
    w->meter = m_meter.get();
    w->wire = m_config.paced ? m_config.wireCounter : nullptr;
    w->received = m_config.received;
    bool ok = false;
    QMetaObject::invokeMethod(
        w,
        [&] {
            if (m_config.realtime)
                m_realtime = makeCallingThreadRealtime();
            SimulatorOptions options;
            options.addresses = m_config.addresses;
            options.line = m_model.line;
            options.seed = m_config.seed;
            w->simulator = m_model.createSimulator(options);
            w->simulator->setParent(w);
            w->noise.seed(m_config.seed ^ 0x5eed);
            if (m_config.prepare)
                m_config.prepare(w->simulator);
            const auto toHost = [w](const QByteArray& bytes) { w->toHost(bytes); };
            if (m_config.paced) {
                // Both directions through a WirePacer here rather than the simulator's own
                // output pacing, so requests and replies share one wire model.
                const double characterUs = m_model.line.characterTimeUs();
                auto* out = new WirePacer(
                    characterUs,
                    [w](const QByteArray& bytes) {
                        if (w->wire)
                            w->wire->replyDelivered(bytes.size());
                        w->toHost(bytes);
                    },
                    w, WirePacer::Delivery::WholeWrites);
                w->fromHost = new WirePacer(
                    characterUs, [w](const QByteArray& bytes) { w->toDevice(bytes); }, w);
                QObject::connect(w->simulator, &Simulator::transmit, out,
                                 [w, out](const QByteArray& bytes) {
                                     if (w->wire)
                                         w->wire->replyQueued(bytes.size());
                                     out->push(bytes);
                                 });
            } else {
                QObject::connect(w->simulator, &Simulator::transmit, w, toHost);
            }
            ok = openEndpoint(error);
        },
        Qt::BlockingQueuedConnection);
    return ok;
}

bool BenchDevice::openEndpoint(QString* error)
{
    Worker* w = m_worker;
    w->endpoint = new PtyEndpoint(w);
    if (!w->endpoint->create(error)) {
        delete w->endpoint;
        w->endpoint = nullptr;
        return false;
    }
    w->endpoint->open(m_model.line);
    if (w->fromHost) {
        QObject::connect(w->endpoint, &Transport::dataReceived, w->fromHost, &WirePacer::push);
    } else {
        QObject::connect(w->endpoint, &Transport::dataReceived, w,
                         [w](const QByteArray& bytes) { w->toDevice(bytes); });
    }
    m_slavePath = w->endpoint->slavePath();
    m_present = true;
    return true;
}

void BenchDevice::closeEndpoint(bool later)
{
    Worker* w = m_worker;
    if (!w->endpoint)
        return;
    m_vanishNs = nowNs();
    w->endpoint->vanish();
    if (later)
        w->endpoint->deleteLater();
    else
        delete w->endpoint; // its connections to the simulator go with it
    w->endpoint = nullptr;
    m_present = false;
}

void BenchDevice::withSimulator(const std::function<void(Simulator*)>& fn)
{
    Worker* w = m_worker;
    QMetaObject::invokeMethod(
        w, [w, &fn] { fn(w->simulator); }, Qt::BlockingQueuedConnection);
}

qint64 BenchDevice::vanish()
{
    QMetaObject::invokeMethod(
        m_worker, [this] { closeEndpoint(false); }, Qt::BlockingQueuedConnection);
    return m_vanishNs.load();
}

void BenchDevice::vanishLater(int afterMs)
{
    Worker* w = m_worker;
    QMetaObject::invokeMethod(
        w, [this, w, afterMs] { QTimer::singleShot(afterMs, w, [this] { closeEndpoint(true); }); });
}

bool BenchDevice::reappear(QString* error)
{
    bool ok = false;
    Worker* w = m_worker;
    QMetaObject::invokeMethod(
        w,
        [&] {
            if (w->endpoint) { // still there: a vanishLater() that has not fired yet
                w->endpoint->vanish();
                delete w->endpoint;
                w->endpoint = nullptr;
            }
            ok = openEndpoint(error);
        },
        Qt::BlockingQueuedConnection);
    return ok;
}

void BenchDevice::noiseBurst(int bytes)
{
    Worker* w = m_worker;
    QMetaObject::invokeMethod(w, [w, bytes] {
        if (!w->endpoint)
            return;
        QByteArray noise(bytes, Qt::Uninitialized);
        for (char& c : noise)
            c = char(w->noise.bounded(256));
        w->endpoint->write(noise);
    });
}

QList<Axis> BenchDevice::movingAxes()
{
    QList<Axis> out;
    withSimulator([&](Simulator* s) {
        for (Axis a : m_model.capabilities.axes) {
            if (s->isMoving(a))
                out << a;
        }
    });
    return out;
}

QList<SimulatedMove> BenchDevice::moves()
{
    QList<SimulatedMove> out;
    withSimulator([&](Simulator* s) { out = s->acceptedMoves(); });
    return out;
}

void BenchDevice::halt()
{
    withSimulator([](Simulator* s) {
        const bool silent = s->faults().silent;
        s->faults().silent = true; // nobody is listening; keep the line clean for the next host
        s->emergencyStop();
        s->faults().silent = silent;
    });
}

} // namespace stepdeck::bench
