#include "JogRamp.h"
#include <QtMath>
#include <algorithm>

namespace stepdeck {

JogRamp::JogRamp(double accelerationStepsPerS2, double maxSpeedStepsPerS)
    : m_acceleration(accelerationStepsPerS2 > 0 ? accelerationStepsPerS2 : 2000),
      m_maxSpeed(qAbs(maxSpeedStepsPerS))
{}

void JogRamp::setAcceleration(double stepsPerS2)
{
    // A non-positive acceleration would freeze (or invert) the ramp: keep the old value.
    if (stepsPerS2 > 0)
        m_acceleration = stepsPerS2;
}

void JogRamp::setMaxSpeed(double stepsPerS)
{
    m_maxSpeed = qAbs(stepsPerS);
    // Existing targets obey the new ceiling; the rates follow them through the ramp.
    for (double& t : m_targets)
        t = qBound(-m_maxSpeed, t, m_maxSpeed);
}

void JogRamp::setTarget(Axis axis, double stepsPerS)
{
    if (!qIsFinite(stepsPerS))
        stepsPerS = 0.0;
    m_targets.insert(axis, qBound(-m_maxSpeed, stepsPerS, m_maxSpeed));
}

void JogRamp::setTargets(const AxisVelocities& targets)
{
    for (auto it = targets.cbegin(); it != targets.cend(); ++it)
        setTarget(it.key(), it.value());
}

void JogRamp::releaseAll()
{
    for (double& t : m_targets)
        t = 0.0;
}

void JogRamp::reset()
{
    // Keep the axes known (callers see explicit zeros), drop every rate at once.
    for (double& t : m_targets)
        t = 0.0;
    for (double& c : m_current)
        c = 0.0;
}

void JogRamp::stopAxis(Axis axis)
{
    if (m_targets.contains(axis))
        m_targets[axis] = 0.0;
    if (m_current.contains(axis))
        m_current[axis] = 0.0;
}

AxisVelocities JogRamp::advance(double dtSeconds)
{
    if (!(dtSeconds > 0))
        return m_current;
    const double maxStep = m_acceleration * dtSeconds;
    QList<Axis> axes = m_targets.keys();
    for (Axis a : m_current.keys()) {
        if (!axes.contains(a))
            axes.append(a);
    }
    for (Axis a : axes) {
        const double target = m_targets.value(a, 0.0);
        const double cur = m_current.value(a, 0.0);
        double next;
        if (cur != 0.0 && target != 0.0 && (cur > 0) != (target > 0)) {
            // Reversal: ramp down to zero and hold there for this tick. The next tick starts
            // from standstill, so the motor never sees a sign flip within one step.
            next = cur > 0 ? qMax(0.0, cur - maxStep) : qMin(0.0, cur + maxStep);
        } else if (qAbs(target - cur) <= maxStep) {
            next = target;
        } else {
            next = cur + (target > cur ? maxStep : -maxStep);
        }
        m_current.insert(a, next);
    }
    return m_current;
}

AxisVelocities JogRamp::heldRates(double tickSeconds, const AxisVelocities& sent,
                                  double sinceSentSeconds) const
{
    AxisVelocities held = m_current;
    const double step = m_acceleration * qMax(0.0, tickSeconds);
    const double followable = m_acceleration * qMax(0.0, sinceSentSeconds);
    for (auto it = held.begin(); it != held.end(); ++it) {
        const double cur = it.value();
        const double target = m_targets.value(it.key(), 0.0);
        const bool reversing = cur != 0.0 && target != 0.0 && (cur > 0) != (target > 0);
        const double floor = reversing ? 0.0 : target; // where this braking ends
        if (cur == 0.0 || qAbs(floor) >= qAbs(cur))
            continue; // standing, holding or speeding up: the current rate
        const double last = sent.value(it.key(), cur);
        // Never beyond the ramp's current rate (a rate stopped at once stays stopped).
        it.value() = cur > 0 ? qMin(cur, std::max({floor, cur - step, last - followable}))
                             : qMax(cur, std::min({floor, cur + step, last + followable}));
    }
    return held;
}

double JogRamp::stopDistance(double speed, double acceleration, double tickSeconds)
{
    const double v = qAbs(speed);
    const double ramp = acceleration > 0 ? v * v / (2 * acceleration) : 0.0;
    return qMax(ramp, v * qMax(0.0, tickSeconds));
}

bool JogRamp::isIdle() const
{
    for (double c : m_current) {
        if (c != 0.0)
            return false;
    }
    for (double t : m_targets) {
        if (t != 0.0)
            return false;
    }
    return true;
}

} // namespace stepdeck
