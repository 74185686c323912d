#include "EmisSimAxis.h"
#include <QtMath>

namespace stepdeck::emis {

namespace {
double acceleration(const EmisSimAxis::Profile& p)
{
    const double rise = qMax(0.0, p.workSpeed - p.startSpeed);
    return p.rampMs > 0 && rise > 0 ? rise / (p.rampMs / 1000.0) : 0.0;
}
} // namespace

void EmisSimAxis::setPhysical(qint64 steps)
{
    m_position = double(steps);
    m_phase = Phase::Idle;
}

void EmisSimAxis::beginLeg(double target, const Profile& profile)
{
    m_profile = profile;
    m_profile.workSpeed = qMax(1.0, profile.workSpeed);
    m_profile.startSpeed = qBound(1.0, profile.startSpeed, m_profile.workSpeed);
    m_target = target;
    m_direction = target >= m_position ? 1 : -1;
    m_speed = m_profile.startSpeed;
}

void EmisSimAxis::startMove(qint64 physicalTarget, const Profile& profile)
{
    beginLeg(double(physicalTarget), profile);
    m_phase = Phase::Moving;
}

void EmisSimAxis::startReference(const Profile& profile, qint64 offset)
{
    // The search runs at the reference speed without a ramp (the board gives no ramp for it).
    Profile search = profile;
    search.startSpeed = profile.workSpeed;
    beginLeg(m_position - 1e12, search);
    m_offset = offset;
    m_phase = Phase::Searching;
}

bool EmisSimAxis::advance(double dt, const std::function<bool(qint64)>& switchActive)
{
    if (m_phase == Phase::Idle)
        return false;
    if (m_phase == Phase::Searching) {
        // Step by step, as the board samples its switch at every step, so the search stops
        // on the first step where the switch is active; then leave it by the offset (9.10).
        const qint64 steps = qMax<qint64>(1, qRound64(m_profile.workSpeed * dt));
        qint64 at = physical();
        bool found = switchActive(at);
        for (qint64 i = 0; i < steps && !found; ++i)
            found = switchActive(--at);
        m_position = double(at);
        if (!found)
            return false;
        beginLeg(double(at + m_offset), m_profile);
        m_phase = m_offset == 0 ? Phase::Idle : Phase::Leaving;
        return m_offset == 0;
    }
    const double a = acceleration(m_profile);
    const double remaining = qAbs(m_target - m_position);
    const double start = m_profile.startSpeed;
    const double braking = a > 0 ? (m_speed * m_speed - start * start) / (2 * a) : 0.0;
    if (m_phase == Phase::Moving && a > 0 && remaining <= braking)
        m_speed = qMax(start, m_speed - a * dt);
    else if (a > 0)
        m_speed = qMin(m_profile.workSpeed, m_speed + a * dt);
    else
        m_speed = m_profile.workSpeed;
    const double step = m_speed * dt;
    if (step >= remaining) {
        m_position = m_target;
        m_phase = Phase::Idle;
        return true;
    }
    m_position += m_direction * step;
    return false;
}

} // namespace stepdeck::emis
