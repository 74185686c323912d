#pragma once
#include <QtGlobal>

namespace stepdeck {

// A serial line in one direction, as time: every byte occupies the line for one character
// time (start, data, parity and stop bits at the baud rate), the bytes go out back to back,
// and an idle line earns no credit -- bytes written after a pause start when they are written.
// backlog() is therefore the least that can still be on the way of what the host wrote,
// whatever the driver reports: a pseudo-terminal reports no output queue at all, and a USB
// adapter's own FIFO is not part of the kernel's (TIOCOUTQ).
//
// Pure: times are nanoseconds of the caller's monotonic clock (QElapsedTimer::nsecsElapsed),
// passed in, so tests drive it with an invented clock.
class WireBudget
{
public:
    explicit WireBudget(double characterUs) { setCharacterUs(characterUs); }
    void setCharacterUs(double us);
    double characterUs() const { return m_characterNs / 1000.0; }

    // `bytes` enter the line at nowNs, behind whatever it still has to carry. Returns when
    // the first of them starts on the line.
    qint64 write(qint64 bytes, qint64 nowNs);
    // Bytes written that the line cannot all have carried by nowNs (a byte partly sent counts).
    qint64 backlog(qint64 nowNs) const;
    // Nanoseconds from nowNs until at most `bytes` are left (0 when that is so already).
    qint64 nsUntilBacklog(qint64 bytes, qint64 nowNs) const;
    // When the last byte written will have left the line.
    qint64 lineFreeNs() const { return qint64(m_lineFreeNs); }
    void clear() { m_lineFreeNs = 0; } // nothing written is on the line any more

private:
    double m_characterNs = 1000;
    double m_lineFreeNs = 0; // when the last byte written will have left (ns, caller's clock)
};

} // namespace stepdeck
