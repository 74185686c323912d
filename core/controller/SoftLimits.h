#pragma once
#include "model/MachineStatus.h"
#include <QCoreApplication>

namespace stepdeck {

// Soft limits (issue 11): per axis a travel range in machine steps that jog and moves must
// not leave. Data, set by whoever knows the machine (the GUI from the operator's settings),
// enforced in the controller thread: the session checks every move before the adapter sees
// it, and the Controller base limits the jog ramp on every tick, so a GUI cannot go around
// them. A limit applies to an axis only while its position is referenced (an unreferenced
// position says nothing about where the machine is). Pure.
struct AxisSoftLimit
{
    bool enabled = true;  // on by default: it applies as soon as a range is set
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

    // Jog: the target rates limited so that each axis, decelerating at `deceleration`, stops
    // before its limit: a rate towards a limit drops to zero once the braking distance at the
    // current rate (plus `lookaheadS` of travel) reaches it; at or beyond a limit only motion
    // back inside is allowed. *why names the first axis held back (empty if none).
    AxisVelocities limitJog(const MachineStatus& status, const AxisVelocities& targets,
                            const AxisVelocities& current, double deceleration,
                            double lookaheadS, QString* why) const;

private:
    QString beyond(Axis axis, qint64 target) const;
    QMap<Axis, AxisSoftLimit> m_limits;
};

} // namespace stepdeck

Q_DECLARE_METATYPE(stepdeck::SoftLimits)
