#include "LaserSimAxis.h"
#include <QtMath>

namespace stepdeck::laser {

void LaserSimAxis::powerOn(qint64 physical)
{
    m_physical = double(qMax<qint64>(0, physical));
    m_offset = m_physical;
    m_homed = false;
    m_halted = false;
    m_phase = Phase::Idle;
    m_thenMove = false;
}

qint64 LaserSimAxis::position() const
{
    return qRound64(m_physical - m_offset);
}

void LaserSimAxis::home()
{
    // "Move to home. The axis moves to its home position which is usually defined by an
    // endswitch" -- always run into the switch, also when the axis was home before.
    m_phase = Phase::Homing;
    m_thenMove = false;
}

void LaserSimAxis::stop()
{
    m_phase = Phase::Idle;
    m_thenMove = false;
}

void LaserSimAxis::moveTo(int target)
{
    // "If the axis has not yet been in its home position since power-up the axis should first
    // move to its home position ... and then proceed to the target-position." A target that
    // arrives while homing replaces the home command ("discard the previous target-position and
    // proceed directly to the last commanded"): homing goes on only where it is still needed.
    m_target = target;
    if (!m_homed) {
        m_phase = Phase::Homing;
        m_thenMove = true;
    } else {
        m_phase = Phase::Moving;
        m_thenMove = false;
    }
}

void LaserSimAxis::setHalted(bool halt)
{
    m_halted = halt;
}

LaserSimAxis::Event LaserSimAxis::advance(double seconds)
{
    if (!isMoving() || seconds <= 0)
        return Event::None;
    const double distance = m_config.speed * seconds;
    if (m_phase == Phase::Homing)
        return advanceHoming(distance);
    return advanceMoving(distance);
}

LaserSimAxis::Event LaserSimAxis::advanceHoming(double distance)
{
    m_physical = qMax(0.0, m_physical - distance);
    if (m_physical > 0.0)
        return Event::None;
    m_homed = true;
    m_offset = 0;
    if (m_thenMove) {
        // On the way to a target: no status here, the laser waits for the target.
        m_phase = Phase::Moving;
        m_thenMove = false;
        return m_target == 0 ? advanceMoving(0) : Event::None;
    }
    m_phase = Phase::Idle;
    return Event::HomeReached;
}

LaserSimAxis::Event LaserSimAxis::advanceMoving(double distance)
{
    const double target = double(m_target) + m_offset;
    const double endSwitch = double(m_config.endSwitch);
    if (target > m_physical) {
        const double next = qMin(target, m_physical + distance);
        if (next >= endSwitch) {
            // "the endswitch of the axis has been reached": the motor stops there.
            m_physical = endSwitch;
            m_phase = Phase::Idle;
            return Event::EndSwitch;
        }
        m_physical = next;
    } else {
        m_physical = qMax(target, m_physical - distance);
    }
    if (m_physical != target)
        return Event::None;
    m_phase = Phase::Idle;
    return Event::TargetReached;
}

} // namespace stepdeck::laser
