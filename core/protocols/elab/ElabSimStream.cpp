#include "ElabSimStream.h"

namespace stepdeck::elab {

void ElabSimStream::configure(int capacity, int highWater, int lowWater)
{
    m_capacity = qMax(1, capacity);
    m_highWater = qBound(1, highWater, m_capacity);
    m_lowWater = qBound(0, lowWater, m_highWater - 1);
}

bool ElabSimStream::push(quint8 stepByte)
{
    if (size() >= m_capacity) {
        ++m_overflows; // a host that honours XOFF never gets here
        return false;
    }
    m_buffer.push_back(stepByte);
    return true;
}

int ElabSimStream::due(double seconds, double rate)
{
    if (!m_running || m_halted || rate <= 0)
        return 0;
    m_credit += seconds * rate;
    const bool starving = m_buffer.empty() && !m_endPending && m_credit >= 1.0;
    if (starving && !m_starving)
        ++m_underruns;
    m_starving = starving;
    const int count = int(qMin<double>(m_credit, double(size())));
    if (m_buffer.empty() || count == size())
        m_credit = qMin(m_credit, double(count) + 1.0);
    return count;
}

quint8 ElabSimStream::pop()
{
    const quint8 byte = m_buffer.front();
    m_buffer.pop_front();
    m_credit = qMax(0.0, m_credit - 1.0);
    ++m_executed;
    if (m_record.size() < kMaxRecord)
        m_record.push_back(byte);
    return byte;
}

ElabSimStream::Flow ElabSimStream::flow()
{
    if (!m_hostPaused && size() >= m_highWater) {
        m_hostPaused = true;
        m_afterXOff = 0;
        return Flow::SendXOff;
    }
    if (m_hostPaused && size() <= m_lowWater) {
        m_hostPaused = false;
        return Flow::SendXOn;
    }
    return Flow::None;
}

void ElabSimStream::noteArrival()
{
    if (!m_hostPaused)
        return;
    ++m_afterXOff;
    m_mostAfterXOff = qMax(m_mostAfterXOff, m_afterXOff);
}

void ElabSimStream::start()
{
    m_running = true;
    m_endPending = false;
    // "dass der Controller sofort mit dem ersten <DC2> mit der Fahrt anfängt": the first step
    // is due at once.
    m_credit = 1.0;
}

void ElabSimStream::finish()
{
    m_running = false;
    m_endPending = false;
    m_credit = 0;
}

void ElabSimStream::halt()
{
    m_running = false;
    m_endPending = false;
    m_halted = true;
    m_credit = 0;
}

void ElabSimStream::flush()
{
    m_buffer.clear();
    m_running = false;
    m_endPending = false;
    m_halted = false;
    m_credit = 0;
}

void ElabSimStream::clearCounters()
{
    m_overflows = 0;
    m_rejected = 0;
    m_executed = 0;
    m_underruns = 0;
    m_starving = false;
    m_record.clear();
    m_afterXOff = 0;
    m_mostAfterXOff = 0;
}

void ElabSimStream::reset()
{
    flush();
    m_hostPaused = false;
    clearCounters();
}

} // namespace stepdeck::elab
