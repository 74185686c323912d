#pragma once
#include "model/ModelInfo.h"
#include "sim/Simulator.h"
#include <QThread>
#include <atomic>
#include <functional>
#include <memory>

namespace stepdeck {
class PtyEndpoint;
class TrafficMeter;
} // namespace stepdeck

namespace stepdeck::bench {

class WireCounter;

// Monotonic nanoseconds, comparable across threads (steady clock).
qint64 nowNs();

// The device side of every stepdeck-bench run: the model's simulator on a pseudo-terminal in
// its own thread, so the adapter under test (in the ControllerSession's thread) competes with
// it only for CPU. What the device does is asked through the Simulator's probes.
//
// The peer can vanish (the pty master closes, as when a USB adapter is pulled: the host's
// QSerialPort sees EIO) and reappear on a new terminal with the same simulated machine behind
// it, its axes still where they were (soak and replug runs).
//
// Paced: both directions run through a WirePacer (the simulator's replies to the host and the
// host's bytes to the simulator), so they behave like the real wire at the model's line rate.
// Metered: every byte the host sends is scanned where the simulator receives it by the model's
// TrafficMeter (ModelInfo::streamBench): stream steps counted, the first panic timestamped.
class BenchDevice
{
public:
    struct Config
    {
        quint32 seed = 1;     // the simulator's fault generator and the noise bursts
        QList<int> addresses; // SimulatorOptions::addresses (multi-drive models)
        bool paced = false;
        bool metered = false; // needs ModelInfo::streamBench
        // Paced only: counts the characters each direction carries (PollWire.h); the host's
        // bytes then reach the simulator one at a time. Must outlive the device.
        WireCounter* wireCounter = nullptr;
        // The device thread asks for real-time scheduling (SCHED_FIFO), standing in for a board
        // that does not share the host's CPU: a latency measured under a CPU load then shows
        // the host's delay, not the simulator's. Needs CAP_SYS_NICE or RLIMIT_RTPRIO (root);
        // realtime() says whether it was granted.
        bool realtime = false;
        // Once, in the device thread, before the terminal opens.
        std::function<void(Simulator*)> prepare;
        // In the device thread, after each chunk of host bytes was handed to the simulator, with
        // the steady-clock time the chunk arrived (paced: when its last bit would have): what
        // the device decoded from it is then in Simulator::receivedFrames() and its probes.
        std::function<void(Simulator*, qint64 arrivedNs)> received;
    };

    // A soak or replug run's device: the simulator as the model's soak profile wants it.
    static Config soakConfig(const ModelInfo& model, quint32 seed);

    BenchDevice(const ModelInfo& model, Config config);
    ~BenchDevice();
    BenchDevice(const BenchDevice&) = delete;
    BenchDevice& operator=(const BenchDevice&) = delete;

    bool start(QString* error);
    QString slavePath() const { return m_slavePath; }
    bool present() const { return m_present; }
    bool realtime() const { return m_realtime; }
    // Runs fn on the simulator in the device thread and waits for it.
    void withSimulator(const std::function<void(Simulator*)>& fn);
    // The model's meter, or nullptr unless Config::metered.
    TrafficMeter* meter() const { return m_meter.get(); }

    // Closes the terminal now (in the device thread); returns the steady-clock time of it.
    qint64 vanish();
    // The same, `afterMs` from now, without waiting: the vanish lands wherever the host is.
    void vanishLater(int afterMs);
    qint64 lastVanishNs() const { return m_vanishNs.load(); }
    // A new terminal for the same simulator; slavePath() changes.
    bool reappear(QString* error);
    // Random bytes on the line towards the host, as from a noisy cable.
    void noiseBurst(int bytes);

    QList<Axis> movingAxes();     // of the model's axes, those moving at the device
    QList<SimulatedMove> moves(); // accepted so far, in order
    void halt();                  // stops every axis at the device without answering anybody

private:
    class Worker;
    bool openEndpoint(QString* error); // device thread
    void closeEndpoint(bool later);    // device thread

    const ModelInfo& m_model;
    Config m_config;
    std::unique_ptr<TrafficMeter> m_meter;
    QThread m_thread;
    Worker* m_worker = nullptr;
    QString m_slavePath;
    std::atomic<bool> m_present{false};
    bool m_realtime = false;
    std::atomic<qint64> m_vanishNs{-1};
};

} // namespace stepdeck::bench
