#include "MoveRates.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::motion::MoveRates {

namespace {

const AxisSpeed* speedOf(const RatedMove& move, int axisIndex)
{
    for (const AxisSpeed& s : move.speeds)
        if (s.axis == axisIndex)
            return &s;
    return nullptr;
}

qint64 programmedRate(const machine::MachineAxis& axis, const AxisSpeed* speed)
{
    return speed ? stepsPerSecond(axis, speed->perSecond) : 0;
}

// The one factor that keeps every rate of the move on `controller` that goes together within
// its ceiling, so that the axes still arrive together.
double togetherFactor(const machine::MachineDescription& d, const QString& controller,
                      const Capabilities& caps, const ParameterSpec* rateSpec,
                      const ParameterSet& known, const RatedMove& move)
{
    double factor = 1.0;
    for (const AxisSpeed& s : move.speeds) {
        if (!s.together || s.axis < 0 || s.axis >= d.axes.size())
            continue;
        const machine::MachineAxis& a = d.axes.at(s.axis);
        if (a.controller != controller)
            continue;
        const qint64 rate = programmedRate(a, &s);
        const Ceiling c = highestRate(caps, rateSpec, known, a.axis);
        if (c.rate > 0 && rate > c.rate)
            factor = std::min(factor, double(c.rate) / double(rate));
    }
    return factor;
}

} // namespace

qint64 stepsPerSecond(const machine::MachineAxis& axis, double unitsPerSecond)
{
    const double steps = std::abs(unitsPerSecond * axis.stepsPerUnit);
    // A rate beyond 9e15 (or not finite: a G93 rate of a huge distance) is out of every
    // parameter's range anyway: kept at that bound, before rounding (llround of a value beyond
    // qint64 gives no defined number).
    if (!(steps <= 9.0e15))
        return qint64(9.0e15);
    return std::max<qint64>(1, std::llround(steps));
}

Ceiling highestRate(const Capabilities& caps, const ParameterSpec* rateSpec,
                    const ParameterSet& known, Axis axis)
{
    Ceiling c;
    if (rateSpec && rateSpec->maximum > 0)
        c.rate = rateSpec->maximum;
    if (!caps.feedRateUsesFeedMode || !caps.contourTickBelow)
        return c;
    // Feed mode has no ramp (E-LAB, SetFeedSpeed: "unterhalb der Startgeschwindigkeit"): the
    // same bound a contour's tick keeps (StreamExecutor::tickRate). Not known: the model's
    // rules refuse the write and say what to set up.
    const QVariant held =
        known.value(QString::fromLatin1(caps.contourTickBelow)).perAxis.value(axis);
    bool ok = false;
    const qint64 below = held.toLongLong(&ok) - 1;
    if (ok && below >= 1 && (c.rate == 0 || below < c.rate)) {
        c.rate = below;
        c.belowParameter = true;
    }
    return c;
}

AxisRate axisRate(const machine::MachineDescription& d, int axisIndex, const Capabilities& caps,
                  const ParameterSpec* rateSpec, const ParameterSet& known, const RatedMove& move)
{
    AxisRate out;
    const AxisSpeed* speed = speedOf(move, axisIndex);
    if (!speed || axisIndex < 0 || axisIndex >= d.axes.size())
        return out;
    const machine::MachineAxis& axis = d.axes.at(axisIndex);
    out.programmed = programmedRate(axis, speed);
    out.runs = out.programmed;
    if (d.limits == machine::LimitPolicy::Clamp) {
        out.ceiling = highestRate(caps, rateSpec, known, axis.axis);
        out.limited = out.ceiling.rate > 0 && out.programmed > out.ceiling.rate;
        if (speed->together) {
            out.feedFactor = togetherFactor(d, axis.controller, caps, rateSpec, known, move);
            if (out.feedFactor < 1.0) {
                out.runs =
                    std::max<qint64>(1, std::llround(double(out.programmed) * out.feedFactor));
                if (out.ceiling.rate > 0)
                    out.runs = std::min(out.runs, out.ceiling.rate);
            }
        } else if (out.limited) {
            out.runs = out.ceiling.rate;
            out.feedFactor = double(out.runs) / double(out.programmed);
        }
    }
    // A share (G94) within the parameter's range: below its minimum it runs at it; above its
    // maximum only under a feed override (the check judged F at 100 %), clamped there as
    // LinuxCNC clamps at the axes' limits.
    if (speed->together && !move.inverseTime && rateSpec && rateSpec->minimum <= rateSpec->maximum)
        out.runs = std::clamp(out.runs, rateSpec->minimum, rateSpec->maximum);
    return out;
}

ParameterSet feedRateWrite(const machine::MachineDescription& d, const QString& controller,
                           const Capabilities& caps, const RatedMove& move,
                           const ParameterSet& known, const ParameterSpec* rateSpec)
{
    if (!caps.feedRateParameter || !move.feed || move.speeds.empty())
        return {};
    const QString name = QString::fromLatin1(caps.feedRateParameter);
    ParameterValue rate;
    qint64 slowest = 0;
    for (const AxisSpeed& s : move.speeds) {
        if (s.axis < 0 || s.axis >= d.axes.size() || d.axes.at(s.axis).controller != controller)
            continue;
        const qint64 r = axisRate(d, s.axis, caps, rateSpec, known, move).runs;
        if (r == 0)
            continue;
        rate.perAxis.insert(d.axes.at(s.axis).axis, r);
        slowest = slowest == 0 ? r : std::min(slowest, r);
    }
    if (rate.perAxis.isEmpty())
        return {};
    if (caps.feedRateWholeSet) {
        const ParameterValue held = known.value(name);
        for (Axis axis : caps.axes) {
            if (rate.perAxis.contains(axis))
                continue;
            rate.perAxis.insert(axis, held.perAxis.contains(axis) ? held.perAxis.value(axis)
                                                                  : QVariant(slowest));
        }
    }
    return {{name, rate}};
}

} // namespace stepdeck::motion::MoveRates
