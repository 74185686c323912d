#pragma once
#include "model/MachineStatus.h"
#include <QCoreApplication>
#include <functional>

namespace stepdeck {

// Soft limits (issue 11): per axis a travel range in machine steps that jog and moves must
// not leave. Data, set by whoever knows the machine (the GUI from the operator's settings),
// enforced in the controller thread: the session checks every move before the adapter sees
// it, and the Controller base limits the jog ramp on every tick, so a GUI cannot go around
// them. A limit applies to an axis only while its position is referenced (an unreferenced
// position says nothing about where the machine is). Pure.
struct AxisSoftLimit
{
    bool enabled = true;   // on by default: it applies as soon as a range is set
    bool rangeSet = false; // no range configured: nothing to enforce
    qint64 minimum = 0;
    qint64 maximum = 0;
    bool operator==(const AxisSoftLimit& o) const
    {
        return enabled == o.enabled && rangeSet == o.rangeSet && minimum == o.minimum &&
               maximum == o.maximum;
    }
};

class SoftLimits
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::SoftLimits)
public:
    void set(Axis axis, const AxisSoftLimit& limit) { m_limits.insert(axis, limit); }
    AxisSoftLimit limit(Axis axis) const { return m_limits.value(axis); }
    const QMap<Axis, AxisSoftLimit>& all() const { return m_limits; }
    bool operator==(const SoftLimits& o) const { return m_limits == o.m_limits; }

    // Enforced for this axis now: enabled, a range set, and the position referenced.
    bool isActive(Axis axis, const MachineStatus& status) const;

    // Non-empty: why the move is refused. Targets and positions in machine steps.
    QString checkTargets(const MachineStatus& status, const AxisVector& targets) const;
    QString checkRelative(const MachineStatus& status, const AxisVector& steps) const;
    // A single-step stream: every position it passes through.
    QString checkStream(const MachineStatus& status, const QVector<AxisVector>& steps) const;
    // A velocity move has no end: refused on an axis whose limits are enforced.
    QString checkVelocity(const MachineStatus& status, const AxisVector& stepsPerS) const;

    // How far an axis still travels (steps) after the host sets its jog target to zero at
    // this speed (steps/s): the model's braking distance plus what the latency adds.
    using StopDistance = std::function<double(Axis axis, double speed)>;
    // The braking distance of a ramp decelerating at `deceleration` steps/s^2.
    static StopDistance rampStopDistance(double deceleration);

    // Jog: the target rates limited so that each axis stops before its limit: a rate towards a
    // limit drops to zero once the stop distance at the speed the axis may reach by the next
    // look (`lookaheadS` from now, speeding up at `acceleration`) plus the travel until then
    // reaches it; at or beyond a limit only motion back inside is allowed. *why names the
    // first axis held back (empty if none).
    AxisVelocities limitJog(const MachineStatus& status, const AxisVelocities& targets,
                            const AxisVelocities& current, double acceleration, double lookaheadS,
                            const StopDistance& stopDistance, QString* why) const;

    // A relative move shortened per axis so that it ends at the soft limit at the latest (a
    // jog chunk or jog target must not cross it). An axis at or beyond its limit in the
    // direction of its move gets 0 and *why says so (models that jog by short moves).
    AxisVector clipRelative(const MachineStatus& status, const AxisVector& steps,
                            QString* why) const;
    // Steps axis may still travel in direction (+1/-1) before its limit; -1: no limit applies.
    qint64 room(Axis axis, int direction, const MachineStatus& status) const;
    static QString jogStoppedText(Axis axis, qint64 limit);

private:
    QString beyond(Axis axis, qint64 target) const;
    QMap<Axis, AxisSoftLimit> m_limits;
};

} // namespace stepdeck

Q_DECLARE_METATYPE(stepdeck::SoftLimits)
