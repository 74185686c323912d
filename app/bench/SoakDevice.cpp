#include "SoakDevice.h"
#include "BenchDevice.h"
#include "protocols/Registry.h"
#include "sim/PtyEndpoint.h"
#include <QRandomGenerator>
#include <QTimer>

namespace stepdeck::bench {

class SoakDevice::Worker : public QObject
{
public:
    Simulator* simulator = nullptr;
    PtyEndpoint* endpoint = nullptr;
    QRandomGenerator noise;
};

SoakDevice::SoakDevice(const SoakModel& model, quint32 seed) : m_model(model), m_seed(seed)
{
    m_thread.setObjectName(QStringLiteral("soak-device"));
}

SoakDevice::~SoakDevice()
{
    if (m_worker) {
        Worker* w = m_worker;
        QMetaObject::invokeMethod(
            w,
            [w] {
                delete w->simulator; // before the endpoint it talks to
                delete w;
            },
            Qt::BlockingQueuedConnection);
    }
    m_thread.quit();
    m_thread.wait();
}

bool SoakDevice::start(QString* error)
{
    const ModelInfo* info = findModel(m_model.id);
    if (!info || !info->createSimulator) {
        *error = QStringLiteral("model %1 has no simulator in this build").arg(m_model.id);
        return false;
    }
    m_thread.start();
    m_worker = new Worker;
    m_worker->moveToThread(&m_thread);
    Worker* w = m_worker;
    bool ok = false;
    QMetaObject::invokeMethod(
        w,
        [&] {
            SimulatorOptions options = m_model.simulator;
            options.line = info->line;
            options.seed = m_seed;
            w->simulator = info->createSimulator(options);
            w->simulator->setParent(w);
            w->noise.seed(m_seed ^ 0x5eed);
            if (m_model.prepare)
                m_model.prepare(w->simulator);
            ok = openEndpoint(error);
        },
        Qt::BlockingQueuedConnection);
    return ok;
}

bool SoakDevice::openEndpoint(QString* error)
{
    Worker* w = m_worker;
    w->endpoint = new PtyEndpoint(w);
    if (!w->endpoint->create(error)) {
        delete w->endpoint;
        w->endpoint = nullptr;
        return false;
    }
    w->endpoint->open(findModel(m_model.id)->line);
    w->simulator->attach(w->endpoint);
    m_slavePath = w->endpoint->slavePath();
    m_present = true;
    return true;
}

void SoakDevice::withSimulator(const std::function<void(Simulator*)>& fn)
{
    Worker* w = m_worker;
    QMetaObject::invokeMethod(
        w, [w, &fn] { fn(w->simulator); }, Qt::BlockingQueuedConnection);
}

qint64 SoakDevice::vanish()
{
    Worker* w = m_worker;
    QMetaObject::invokeMethod(
        w,
        [this, w] {
            if (!w->endpoint)
                return;
            m_vanishNs = nowNs();
            w->endpoint->vanish();
            delete w->endpoint; // its connections to the simulator go with it
            w->endpoint = nullptr;
            m_present = false;
        },
        Qt::BlockingQueuedConnection);
    return m_vanishNs.load();
}

void SoakDevice::vanishLater(int afterMs)
{
    Worker* w = m_worker;
    QMetaObject::invokeMethod(w, [this, w, afterMs] {
        QTimer::singleShot(afterMs, w, [this, w] {
            if (!w->endpoint)
                return;
            m_vanishNs = nowNs();
            w->endpoint->vanish();
            w->endpoint->deleteLater();
            w->endpoint = nullptr;
            m_present = false;
        });
    });
}

bool SoakDevice::reappear(QString* error)
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

void SoakDevice::noiseBurst(int bytes)
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

QList<Axis> SoakDevice::movingAxes()
{
    QList<Axis> out;
    withSimulator([&](Simulator* s) { out = m_model.movingAxes(s); });
    return out;
}

QList<DeviceMove> SoakDevice::moves()
{
    QList<DeviceMove> out;
    withSimulator([&](Simulator* s) { out = m_model.moves(s); });
    return out;
}

void SoakDevice::halt()
{
    withSimulator([&](Simulator* s) {
        const bool silent = s->faults().silent;
        s->faults().silent = true; // nobody is listening; keep the line clean for the next host
        m_model.halt(s);
        s->faults().silent = silent;
    });
}

} // namespace stepdeck::bench
