#pragma once
#include <QString>
#include <QThread>
#include <atomic>
#include <functional>

namespace stepdeck {
struct ModelInfo;
class Simulator;
class PtyEndpoint;
} // namespace stepdeck

namespace stepdeck::bench {

// Monotonic nanoseconds, comparable across threads (steady clock).
qint64 nowNs();

// The device side of a benchmark: a simulator on a pseudo-terminal in its own thread, so the
// adapter under test (in the ControllerSession's thread) competes with it only for CPU.
// Every byte the host sends is scanned where the simulator receives it: DC2 step bytes are
// counted and the first panic byte outside a DC2 frame is timestamped.
//
// Paced: both directions run through a WirePacer (the simulator's replies to the host and the
// host's bytes to the simulator), so they behave like the real 57600 8N2 wire.
class BenchDevice
{
public:
    struct Config
    {
        bool paced = false;
        // A step buffer larger than any stream: the simulator never sends XOFF, so the feed
        // figure is what the link delivers, not the simulated feed rate.
        bool unlimitedStreamBuffer = false;
    };

    BenchDevice(const ModelInfo& model, const Config& config);
    ~BenchDevice();
    BenchDevice(const BenchDevice&) = delete;
    BenchDevice& operator=(const BenchDevice&) = delete;

    bool start(QString* error);
    QString slavePath() const { return m_slavePath; }
    // Runs fn on the simulator in the device thread and waits for it.
    void withSimulator(const std::function<void(Simulator*)>& fn);

    void resetCounters();
    qint64 stepBytes() const { return m_stepBytes.load(); }
    qint64 firstStepNs() const { return m_firstStepNs.load(); }
    qint64 lastStepNs() const { return m_lastStepNs.load(); }
    qint64 panicSeenNs() const { return m_panicNs.load(); } // -1 until seen

private:
    class Worker;
    void scan(const QByteArray& bytes); // device thread

    const ModelInfo& m_model;
    Config m_config;
    QThread m_thread;
    Worker* m_worker = nullptr;
    QString m_slavePath;
    bool m_afterDc2 = false; // device thread only
    std::atomic<qint64> m_stepBytes{0};
    std::atomic<qint64> m_firstStepNs{-1};
    std::atomic<qint64> m_lastStepNs{-1};
    std::atomic<qint64> m_panicNs{-1};
};

} // namespace stepdeck::bench
