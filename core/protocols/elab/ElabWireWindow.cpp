#include "ElabWireWindow.h"
#include <QtMath>

namespace stepdeck::elab {

ElabWireWindow::ElabWireWindow(std::function<qint64()> driverPending)
    : m_driverPending(std::move(driverPending))
{
    m_timer.start();
}

void ElabWireWindow::setClock(std::function<qint64()> nowNs)
{
    m_clock = std::move(nowNs);
    m_wire.clear(); // times of the old clock mean nothing on the new one
}

void ElabWireWindow::wrote(qint64 bytes)
{
    m_wire.write(bytes, now());
}

qint64 ElabWireWindow::onTheWay() const
{
    const qint64 pending = m_driverPending ? m_driverPending() : 0;
    return qMax(pending, m_wire.backlog(now()));
}

qint64 ElabWireWindow::nsUntilOnTheWayAtMost(qint64 bytes) const
{
    // What the driver still holds leaves at the line's rate at best.
    const qint64 pending = m_driverPending ? m_driverPending() : 0;
    const qint64 driverNs =
        pending > bytes ? qCeil(double(pending - bytes) * m_wire.characterUs() * 1000.0) : 0;
    return qMax(driverNs, m_wire.nsUntilBacklog(bytes, now()));
}

} // namespace stepdeck::elab
