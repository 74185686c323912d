#pragma once
#include "SoakModels.h"
#include <QThread>
#include <functional>

namespace stepdeck {
class PtyEndpoint;
}

namespace stepdeck::bench {

// The device side of soak and replug runs: the model's simulator on a pseudo-terminal in its
// own thread. The peer can vanish (the pty master closes, as when a USB adapter is pulled:
// the host's QSerialPort sees EIO) and reappear on a new terminal with the same simulated
// machine behind it, its axes still where they were.
class SoakDevice
{
public:
    explicit SoakDevice(const SoakModel& model, quint32 seed);
    ~SoakDevice();
    SoakDevice(const SoakDevice&) = delete;
    SoakDevice& operator=(const SoakDevice&) = delete;

    bool start(QString* error);
    QString slavePath() const { return m_slavePath; }
    bool present() const { return m_present; }

    // Runs fn on the simulator in the device thread and waits for it.
    void withSimulator(const std::function<void(Simulator*)>& fn);
    // Closes the terminal now (in the device thread); returns the steady-clock time of it.
    qint64 vanish();
    // The same, `afterMs` from now, without waiting: the vanish lands wherever the host is.
    void vanishLater(int afterMs);
    qint64 lastVanishNs() const { return m_vanishNs.load(); }
    // A new terminal for the same simulator; slavePath() changes.
    bool reappear(QString* error);
    // Random bytes on the line towards the host, as from a noisy cable.
    void noiseBurst(int bytes);

    QList<Axis> movingAxes();
    QList<DeviceMove> moves();
    void halt(); // stops every axis at the device without answering anybody

private:
    class Worker;
    bool openEndpoint(QString* error); // device thread

    const SoakModel& m_model;
    quint32 m_seed;
    QThread m_thread;
    Worker* m_worker = nullptr;
    QString m_slavePath;
    std::atomic<bool> m_present{false};
    std::atomic<qint64> m_vanishNs{-1};
};

} // namespace stepdeck::bench
