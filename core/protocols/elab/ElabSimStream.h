#pragma once
#include <QtGlobal>
#include <deque>
#include <vector>

namespace stepdeck::elab {

// The controller's XYZ single-step buffer of the <DC2> stream (manual: SetFeedStepXYZ):
// filled by the host, drained at the feed rate from the first <DC2> on, throttled with
// <XOFF>/<XON> at a high and a low water mark. Pure bookkeeping: the simulator executes the
// steps it hands out and sends the flow-control bytes it asks for.
class ElabSimStream
{
public:
    enum class Flow { None, SendXOff, SendXOn };

    // capacity >= 1; lowWater < highWater <= capacity (clamped).
    void configure(int capacity, int highWater, int lowWater);
    int capacity() const { return m_capacity; }
    int highWater() const { return m_highWater; }
    int lowWater() const { return m_lowWater; }

    // Buffers one step byte; false (and counted as an overflow) when the buffer is full.
    bool push(quint8 stepByte);
    // How many buffered steps are due after `seconds` at `rate` steps/s. Time spent with an
    // empty buffer earns no credit beyond the next step (an underrun does not make the
    // following steps run faster).
    int due(double seconds, double rate);
    quint8 pop();
    int size() const { return int(m_buffer.size()); }
    bool isEmpty() const { return m_buffer.empty(); }
    // Which flow-control byte the host must get now, if any (updates the paused state).
    Flow flow();
    bool hostPaused() const { return m_hostPaused; }
    // A <DC2> pair arrived (buffered, rejected or overflowing alike). Between an XOFF and the
    // next XON such pairs are the host's reaction time and whatever it had on the way: a host
    // paced by the wire sends at most one chunk after the XOFF (docs/architecture.md).
    void noteArrival();
    int pairsAfterLastXOff() const { return m_afterXOff; }
    int mostPairsAfterXOff() const { return m_mostAfterXOff; }

    // ---- stream state ----
    void start(); // first <DC2>: execution starts at once
    bool running() const { return m_running; }
    void endOfFeed() { m_endPending = true; } // <CR>: finish when drained
    bool endPending() const { return m_endPending; }
    void finish(); // drained after EndOfFeed
    void halt();   // ForceStopMove / limit: stop, keep the buffer
    bool halted() const { return m_halted; }
    void flush(); // ForceFlushBuffer: empty, halt cleared

    // ---- counters for tests ----
    qint64 overflows() const { return m_overflows; }
    qint64 rejected() const { return m_rejected; }
    void countRejected() { ++m_rejected; }
    qint64 executed() const { return m_executed; }
    // Times the board had a tick due while the stream ran with its buffer empty and no
    // EndOfFeed yet: the host fell behind (an underrun; the path stops there for a while).
    qint64 underruns() const { return m_underruns; }
    // The step bytes executed since the counters were cleared, in order (at most
    // kMaxRecord; tests rebuild the path the axes took from them).
    static constexpr size_t kMaxRecord = 4000000;
    const std::vector<quint8>& executedRecord() const { return m_record; }
    void clearCounters();
    void reset(); // power-on (keeps the configured capacity and marks)

private:
    std::deque<quint8> m_buffer;
    int m_capacity = 256;
    int m_highWater = 192;
    int m_lowWater = 64;
    bool m_hostPaused = false;
    bool m_running = false;
    bool m_endPending = false;
    bool m_halted = false;
    int m_afterXOff = 0;     // pairs that arrived since the last XOFF (while paused)
    int m_mostAfterXOff = 0; // the most of them after any one XOFF
    double m_credit = 0;
    qint64 m_overflows = 0;
    qint64 m_rejected = 0;
    qint64 m_executed = 0;
    qint64 m_underruns = 0;
    bool m_starving = false; // in an underrun now (counted once)
    std::vector<quint8> m_record;
};

} // namespace stepdeck::elab
