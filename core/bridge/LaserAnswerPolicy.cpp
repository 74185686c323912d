#include "LaserAnswerPolicy.h"
#include <cmath>

namespace stepdeck::bridge {

using namespace stepdeck::laser;

std::optional<int> LaserAnswerPolicy::position(const AxisStatus& axis, QString* why) const
{
    if (axis.moving || axis.jogging || axis.motionUnknown) {
        *why = tr("it may still be moving");
        return std::nullopt;
    }
    if (!axis.positionKnown || axis.positionEstimated) {
        *why = tr("its position is unknown");
        return std::nullopt;
    }
    // "The range of the actual-position is thus [0000...9999]" (five digits on the wire, see
    // LaserCodec): a position outside is not told, neither clamped nor wrapped.
    const double units = std::round(double(axis.position) / m_scale);
    if (!(units >= 0 && units <= double(kMaxPosition))) {
        *why = tr("its position (%1 steps, %2 laser units) is outside the laser's range 0..%3")
                   .arg(axis.position)
                   .arg(units, 0, 'f', 0)
                   .arg(kMaxPosition);
        return std::nullopt;
    }
    return int(units);
}

LaserAnswer LaserAnswerPolicy::withPosition(Axis laserAxis, const AxisStatus& status, Status code,
                                            const QString& event) const
{
    QString why;
    if (const std::optional<int> at = position(status, &why))
        return {StatusFrame{laserAxis, *at, code}, {}};
    return {std::nullopt, tr("%1, but %2").arg(event, why)};
}

LaserAnswer LaserAnswerPolicy::referenced(Axis laserAxis, Axis axis, const AxisStatus& status) const
{
    // "The home position is also the '0' position of the axis": the controller's position
    // after its reference run, normally 0.
    return withPosition(laserAxis, status, Status::HomeSwitch,
                        tr("axis %1 is referenced").arg(axisName(axis)));
}

LaserAnswer LaserAnswerPolicy::referenceFailed(Axis laserAxis, Axis axis,
                                               const AxisStatus& status) const
{
    if (status.limitSwitch) {
        return withPosition(
            laserAxis, status, Status::EndSwitch,
            tr("axis %1 stopped at a limit switch before it was referenced").arg(axisName(axis)));
    }
    return {std::nullopt, tr("axis %1 stopped before it was referenced").arg(axisName(axis))};
}

LaserAnswer LaserAnswerPolicy::moveEnded(Axis laserAxis, Axis axis, const AxisStatus& status,
                                         qint64 targetSteps) const
{
    const QString name = axisName(axis);
    if (status.limitSwitch) {
        return withPosition(laserAxis, status, Status::EndSwitch,
                            tr("axis %1 stopped at a limit switch").arg(name));
    }
    QString why;
    const bool known = position(status, &why).has_value();
    if (known && status.position == targetSteps)
        return withPosition(laserAxis, status, Status::TargetReached, {});
    if (!known) { // a reference switch input alone does not tell where the axis stands
        return {std::nullopt, tr("axis %1 did not confirm reaching its target %2 steps: %3")
                                  .arg(name)
                                  .arg(targetSteps)
                                  .arg(why)};
    }
    if (status.referenceSwitch)
        return {StatusFrame{laserAxis, *position(status, &why), Status::HomeSwitch}, {}};
    return {std::nullopt,
            tr("axis %1 stopped at %2 steps, short of its target %3 (stopped by the operator?)")
                .arg(name)
                .arg(status.position)
                .arg(targetSteps)};
}

LaserAnswer LaserAnswerPolicy::refusedAtLimit(Axis laserAxis, Axis axis,
                                              const AxisStatus& status) const
{
    return withPosition(laserAxis, status, Status::EndSwitch,
                        tr("axis %1 stands at an active limit switch").arg(axisName(axis)));
}

LaserAnswer LaserAnswerPolicy::door(Axis laserAxis, Axis axis, const AxisStatus& status,
                                    bool open) const
{
    return withPosition(laserAxis, status, open ? Status::DoorOpened : Status::DoorClosed,
                        open ? tr("the door opened (axis %1)").arg(axisName(axis))
                             : tr("the door closed (axis %1)").arg(axisName(axis)));
}

} // namespace stepdeck::bridge
