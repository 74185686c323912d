#include "SoftLimits.h"
#include <cmath>

namespace stepdeck {

bool SoftLimits::isActive(Axis axis, const MachineStatus& status) const
{
    const AxisSoftLimit l = m_limits.value(axis);
    const AxisStatus a = status.axes.value(axis);
    return l.enabled && l.rangeSet && a.referenced && a.positionKnown;
}

QString SoftLimits::beyond(Axis axis, qint64 target) const
{
    const AxisSoftLimit l = m_limits.value(axis);
    if (target > l.maximum)
        return tr("refused: axis %1 would reach %2, beyond its soft limit %3")
            .arg(axisName(axis))
            .arg(target)
            .arg(l.maximum);
    if (target < l.minimum)
        return tr("refused: axis %1 would reach %2, beyond its soft limit %3")
            .arg(axisName(axis))
            .arg(target)
            .arg(l.minimum);
    return {};
}

QString SoftLimits::checkTargets(const MachineStatus& status, const AxisVector& targets) const
{
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        if (!isActive(it.key(), status))
            continue;
        const QString why = beyond(it.key(), it.value());
        if (!why.isEmpty())
            return why;
    }
    return {};
}

QString SoftLimits::checkRelative(const MachineStatus& status, const AxisVector& steps) const
{
    AxisVector targets;
    for (auto it = steps.cbegin(); it != steps.cend(); ++it)
        targets.insert(it.key(), status.axes.value(it.key()).position + it.value());
    return checkTargets(status, targets);
}

QString SoftLimits::checkStream(const MachineStatus& status, const QVector<AxisVector>& steps) const
{
    AxisVector position;
    for (auto it = status.axes.cbegin(); it != status.axes.cend(); ++it)
        position.insert(it.key(), it.value().position);
    for (const AxisVector& step : steps) {
        for (auto it = step.cbegin(); it != step.cend(); ++it) {
            qint64& p = position[it.key()];
            p += it.value();
            if (isActive(it.key(), status)) {
                const QString why = beyond(it.key(), p);
                if (!why.isEmpty())
                    return why;
            }
        }
    }
    return {};
}

QString SoftLimits::checkVelocity(const MachineStatus& status, const AxisVector& stepsPerS) const
{
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        if (it.value() != 0 && isActive(it.key(), status))
            return tr("refused: a velocity move has no end, and axis %1 has soft limits; jog "
                      "or move to a position instead")
                .arg(axisName(it.key()));
    }
    return {};
}

SoftLimits::StopDistance SoftLimits::rampStopDistance(double deceleration)
{
    return [deceleration](Axis, double speed) {
        return deceleration > 0 ? speed * speed / (2 * deceleration) : 0.0;
    };
}

QString SoftLimits::jogStoppedText(Axis axis, qint64 limit)
{
    return tr("jog stopped: axis %1 at its soft limit %2").arg(axisName(axis)).arg(limit);
}

AxisVelocities SoftLimits::limitJog(const MachineStatus& status, const AxisVelocities& targets,
                                    const AxisVelocities& current, double acceleration,
                                    double lookaheadS, const StopDistance& stopDistance,
                                    QString* why) const
{
    AxisVelocities out = targets;
    if (why)
        why->clear();
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        const Axis axis = it.key();
        const double target = it.value();
        if (target == 0.0 || !isActive(axis, status))
            continue;
        const AxisSoftLimit l = m_limits.value(axis);
        const double p = double(status.axes.value(axis).position);
        const double v = current.value(axis, 0.0);
        // Where the axis comes to rest if it is held back at the next look: it may still
        // speed up until then (same direction only), then stops within stopDistance.
        const double lookahead = qMax(0.0, lookaheadS);
        double speed = (v > 0) == (target > 0) ? std::fabs(v) : 0.0;
        speed = qMax(speed, qMin(std::fabs(target), speed + acceleration * lookahead));
        const double stopping = stopDistance ? stopDistance(axis, speed) : 0.0;
        const double reach = stopping + speed * lookahead + 1.0;
        const bool towardsMax = target > 0;
        const bool blocked =
            towardsMax ? p + reach >= double(l.maximum) : p - reach <= double(l.minimum);
        if (!blocked)
            continue;
        out.insert(axis, 0.0);
        if (why && why->isEmpty())
            *why = jogStoppedText(axis, towardsMax ? l.maximum : l.minimum);
    }
    return out;
}

qint64 SoftLimits::room(Axis axis, int direction, const MachineStatus& status) const
{
    if (!isActive(axis, status))
        return -1;
    const AxisSoftLimit l = m_limits.value(axis);
    const qint64 p = status.axes.value(axis).position;
    return qMax<qint64>(0, direction > 0 ? l.maximum - p : p - l.minimum);
}

AxisVector SoftLimits::clipRelative(const MachineStatus& status, const AxisVector& steps,
                                    QString* why) const
{
    AxisVector out;
    if (why)
        why->clear();
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        const qint64 s = it.value();
        const qint64 left = s == 0 ? -1 : room(it.key(), s > 0 ? 1 : -1, status);
        if (left < 0 || qAbs(s) <= left) {
            out.insert(it.key(), s);
            continue;
        }
        out.insert(it.key(), s > 0 ? left : -left);
        if (left == 0 && why && why->isEmpty()) {
            const AxisSoftLimit l = m_limits.value(it.key());
            *why = jogStoppedText(it.key(), s > 0 ? l.maximum : l.minimum);
        }
    }
    return out;
}

} // namespace stepdeck
