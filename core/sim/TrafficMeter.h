#pragma once
#include <QByteArray>
#include <atomic>

namespace stepdeck {

// What a benchmark counts in the bytes a simulated device receives from the host: the single
// steps of a stream and the arrival of the first panic and stop commands (stepdeck-bench's
// feed, panic and machine STOP figures). The bytes are the model's, so each model with a stream
// supplies its own (ModelInfo::streamBench). scan() runs in the device's thread; the figures may be
// read from any thread.
class TrafficMeter
{
public:
    virtual ~TrafficMeter() = default;

    // Bytes as they reach the device, at steady-clock time nowNs.
    virtual void scan(const QByteArray& bytes, qint64 nowNs) = 0;

    void reset()
    {
        m_stepBytes = 0;
        m_firstStepNs = -1;
        m_lastStepNs = -1;
        m_panicNs = -1;
        m_stopNs = -1;
    }
    qint64 stepBytes() const { return m_stepBytes.load(); }
    qint64 firstStepNs() const { return m_firstStepNs.load(); } // -1 until the first step
    qint64 lastStepNs() const { return m_lastStepNs.load(); }
    qint64 panicSeenNs() const { return m_panicNs.load(); } // -1 until seen
    qint64 stopSeenNs() const { return m_stopNs.load(); }   // -1 until seen

protected:
    void noteStep(qint64 nowNs)
    {
        if (m_firstStepNs.load() < 0)
            m_firstStepNs = nowNs;
        m_lastStepNs = nowNs;
        ++m_stepBytes;
    }
    void notePanic(qint64 nowNs)
    {
        if (m_panicNs.load() < 0)
            m_panicNs = nowNs;
    }
    void noteStop(qint64 nowNs)
    {
        if (m_stopNs.load() < 0)
            m_stopNs = nowNs;
    }

private:
    std::atomic<qint64> m_stepBytes{0};
    std::atomic<qint64> m_firstStepNs{-1};
    std::atomic<qint64> m_lastStepNs{-1};
    std::atomic<qint64> m_panicNs{-1};
    std::atomic<qint64> m_stopNs{-1};
};

} // namespace stepdeck
