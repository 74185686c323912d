#include "FeedLimit.h"
#include "ProgramUnits.h"
#include "motion/ContourSteps.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::program::FeedLimit {

namespace {

// How far below the tick's highest feed a limited contour move runs: ContourSteps refuses a
// move that needs more than its tick, and the highest feed is a quotient in floating point.
constexpr double kBelowHighest = 1.0 - 1e-9;

// The rate as programmed: F on the axis, or its resolved rate (G93, a coordinated share).
qint64 programmedRate(const machine::MachineAxis& axis, const ProgramBlock& block)
{
    const auto resolved = block.axisRates.find(axis.name);
    if (resolved == block.axisRates.end())
        return block.inverseTime ? 0 : units::feedStepsPerSecond(axis, *block.feed, block.inches);
    return units::feedStepsPerSecond(axis, resolved.value(), false);
}

// The one factor that keeps every resolved rate of the block on `controller` within its
// ceiling, so that the axes still arrive together.
double togetherFactor(const machine::MachineDescription& d, const QString& controller,
                      const Capabilities& caps, const ParameterSpec* rateSpec,
                      const ParameterSet& known, const ProgramBlock& block)
{
    double factor = 1.0;
    for (auto it = block.axisRates.cbegin(); it != block.axisRates.cend(); ++it) {
        const machine::MachineAxis* a = d.axis(it.key());
        if (!a || a->controller != controller)
            continue;
        const qint64 rate = programmedRate(*a, block);
        const Ceiling c = highestRate(caps, rateSpec, known, a->axis);
        if (c.rate > 0 && rate > c.rate)
            factor = std::min(factor, double(c.rate) / double(rate));
    }
    return factor;
}

} // namespace

Ceiling highestRate(const Capabilities& caps, const ParameterSpec* rateSpec,
                    const ParameterSet& known, Axis axis)
{
    Ceiling c;
    if (rateSpec && rateSpec->maximum > 0)
        c.rate = rateSpec->maximum;
    if (!caps.feedRateUsesFeedMode || !caps.contourTickBelow)
        return c;
    // Feed mode has no ramp (E-LAB, SetFeedSpeed: "unterhalb der Startgeschwindigkeit"): the
    // same bound a contour's tick keeps (motion::StreamExecutor::tickRate). Not known: the model's rules
    // refuse the write and say what to set up.
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

AxisRate axisRate(const machine::MachineDescription& d, const machine::MachineAxis& axis,
                  const Capabilities& caps, const ParameterSpec* rateSpec,
                  const ParameterSet& known, const ProgramBlock& block)
{
    AxisRate out;
    if (!block.feed)
        return out;
    out.programmed = programmedRate(axis, block);
    out.runs = out.programmed;
    if (out.programmed == 0)
        return out; // G93 on an axis that does not move: no rate
    const bool resolved = block.axisRates.contains(axis.name);
    if (d.limits == machine::LimitPolicy::Clamp) {
        out.ceiling = highestRate(caps, rateSpec, known, axis.axis);
        out.limited = out.ceiling.rate > 0 && out.programmed > out.ceiling.rate;
        if (resolved) {
            out.feedFactor = togetherFactor(d, axis.controller, caps, rateSpec, known, block);
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
    if (resolved && !block.inverseTime && rateSpec && rateSpec->minimum <= rateSpec->maximum)
        out.runs = std::clamp(out.runs, rateSpec->minimum, rateSpec->maximum);
    return out;
}

double contourFeed(const ContourMoves::Stream& stream, const motion::CanonicalMove& move,
                   machine::LimitPolicy limits)
{
    if (limits != machine::LimitPolicy::Clamp || stream.tickRate <= 0 || move.feed <= 0 ||
        move.length() <= 0)
        return move.feed;
    if (motion::ContourSteps::neededTickRate(move, stream.scale) <= stream.tickRate)
        return move.feed;
    return std::min(move.feed,
                    motion::ContourSteps::highestFeed(move, stream.scale, stream.tickRate) *
                        kBelowHighest);
}

} // namespace stepdeck::program::FeedLimit
