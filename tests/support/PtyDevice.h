#pragma once
// A simulated controller on a pseudo-terminal in a thread of its own (tst_machine,
// tst_machinewindow): a device is a world of its own, so a session's close
// (which waits for the device to acknowledge its stop) never waits for a blocked test thread.
// Probes run in the device's thread; every assertion that matters is made here, at the device.
#include "protocols/Registry.h"
#include "sim/PtyEndpoint.h"
#include "sim/Simulator.h"
#include <QThread>
#include <algorithm>

namespace stepdeck::test {

class PtyDevice
{
public:
    // addresses: the drives of a bus model (Nanotec); the others take {1}.
    explicit PtyDevice(const QString& modelId, const QList<int>& addresses = {1})
    {
        m_thread.start();
        m_home.moveToThread(&m_thread);
        const ModelInfo* info = findModel(modelId);
        probe([&] {
            m_end = new PtyEndpoint;
            QString error;
            if (!m_end->create(&error))
                qFatal("pty: %s", qPrintable(error));
            SimulatorOptions options;
            options.line = info->line;
            options.addresses = addresses;
            m_sim = info->createSimulator(options);
            m_sim->attach(m_end);
            m_path = m_end->slavePath();
            return true;
        });
    }
    ~PtyDevice()
    {
        probe([this] {
            delete m_sim;
            delete m_end;
            return true;
        });
        m_thread.quit();
        m_thread.wait();
    }
    PtyDevice(const PtyDevice&) = delete;
    PtyDevice& operator=(const PtyDevice&) = delete;

    QString path() const { return m_path; }
    Simulator* sim() const { return m_sim; } // only inside probe()
    template <typename F> auto probe(F f) -> decltype(f())
    {
        decltype(f()) result{};
        QMetaObject::invokeMethod(
            &m_home, [&] { result = f(); }, Qt::BlockingQueuedConnection);
        return result;
    }
    bool receivedStop()
    {
        return probe([this] {
            const QList<QByteArray> frames = m_sim->receivedFrames();
            return std::any_of(frames.cbegin(), frames.cend(),
                               [this](const QByteArray& f) { return m_sim->isStopFrame(f); });
        });
    }
    void vanish() // the USB adapter pulled
    {
        probe([this] {
            m_end->vanish();
            return true;
        });
    }
    QList<QByteArray> frames()
    {
        return probe([this] { return m_sim->receivedFrames(); });
    }
    qsizetype acceptedMoveCount() const { return m_sim->acceptedMoves().size(); } // in probe()
    int receivedCount()
    {
        return probe([this] { return int(m_sim->receivedFrames().size()); });
    }
    bool moving(Axis axis = Axis::X)
    {
        return probe([&] { return m_sim->isMoving(axis); });
    }
    bool still()
    {
        return probe([this] { return m_sim->standingStill(); });
    }
    qint64 position(Axis axis = Axis::X)
    {
        return probe([&] { return m_sim->position(axis); });
    }

private:
    QThread m_thread;
    QObject m_home; // lives in m_thread
    PtyEndpoint* m_end = nullptr;
    Simulator* m_sim = nullptr;
    QString m_path;
};

} // namespace stepdeck::test
