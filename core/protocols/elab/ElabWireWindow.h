#pragma once
#include "transport/WireBudget.h"
#include <QElapsedTimer>
#include <functional>

namespace stepdeck::elab {

// How much of the host's output may still be on its way to the board: the larger of what the
// driver reports (Transport::pendingOutputBytes: Qt's queue and the kernel's TIOCOUTQ) and
// what the line cannot yet have carried at its character rate (WireBudget). The driver alone
// is not enough: a pseudo-terminal reports no queue, and a USB adapter's own FIFO is not part
// of TIOCOUTQ. The wire budget alone is not enough either: a line slower than its nominal
// rate (or a driver holding bytes back) shows up only in what the driver reports.
class ElabWireWindow
{
public:
    // driverPending: bytes the transport reports not yet on the wire.
    explicit ElabWireWindow(std::function<qint64()> driverPending);

    void setCharacterTimeUs(double us) { m_wire.setCharacterUs(us); }
    // The monotonic clock in ns; by default an own QElapsedTimer. Tests use an invented one.
    void setClock(std::function<qint64()> nowNs);

    void wrote(qint64 bytes); // handed to the transport now
    qint64 onTheWay() const;
    // Nanoseconds until at most `bytes` are on their way by both counts (0: already).
    qint64 nsUntilOnTheWayAtMost(qint64 bytes) const;
    void clear() { m_wire.clear(); } // a new link: nothing of ours is on it

private:
    qint64 now() const { return m_clock ? m_clock() : m_timer.nsecsElapsed(); }

    std::function<qint64()> m_driverPending;
    std::function<qint64()> m_clock;
    QElapsedTimer m_timer;
    WireBudget m_wire{11 * 1e6 / 57600}; // 57600 8N2 until told otherwise
};

} // namespace stepdeck::elab
