#include "CoordinatedFeed.h"
#include "InverseTime.h"
#include "ProgramUnits.h"
#include <cmath>

namespace stepdeck::program::CoordinatedFeed {

int unitRank(machine::AxisUnit unit)
{
    return unit == machine::AxisUnit::Millimetre ? 0 : unit == machine::AxisUnit::Step ? 1 : 2;
}

namespace {
std::optional<machine::AxisUnit> lengthUnit(const machine::MachineDescription& d,
                                            const QMap<QString, double>& moved)
{
    std::optional<machine::AxisUnit> best;
    for (auto it = moved.cbegin(); it != moved.cend(); ++it)
        if (const machine::MachineAxis* a = d.axis(it.key());
            a && (!best || unitRank(a->unit) < unitRank(*best)))
            best = a->unit;
    return best;
}
} // namespace

bool applies(const ProgramBlock& block, const machine::MachineDescription& d,
             const Controllers& coordinated, bool single)
{
    if (coordinated.isEmpty() || block.kind != BlockKind::Feed || block.inverseTime ||
        !block.feed || block.axes.size() < (single ? 1 : 2))
        return false;
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it)
        if (const machine::MachineAxis* a = d.axis(it.key());
            a && coordinated.contains(a->controller))
            return true;
    return false;
}

ProgramBlock resolve(const ProgramBlock& block, const machine::MachineDescription& d,
                     const Controllers& coordinated, const AxisPositions& start,
                     const QMap<QString, double>& workOffsets, double override)
{
    ProgramBlock out = block;
    out.axisRates.clear();
    const bool overridden = override != 1.0;
    if (!applies(block, d, coordinated, overridden))
        return out;
    // The whole steps the device runs, so that the axes arrive together.
    const QMap<QString, double> moved = InverseTime::distances(block, d, start, workOffsets, true);
    const std::optional<machine::AxisUnit> unit = lengthUnit(d, moved);
    if (moved.size() < (overridden ? 1 : 2) || !unit)
        return out;
    double squares = 0;
    const machine::MachineAxis* reference = nullptr;
    for (auto it = moved.cbegin(); it != moved.cend(); ++it) {
        const machine::MachineAxis* a = d.axis(it.key());
        if (a->unit == *unit) {
            squares += it.value() * it.value();
            reference = a;
        }
    }
    const double length = std::sqrt(squares);
    if (!(length > 0))
        return out;
    // F in the length's unit per minute (G20: inch/min on a mm axis), then the block's time.
    const double minutes = length / units::toAxisUnits(*reference, *block.feed, block.inches);
    for (auto it = moved.cbegin(); it != moved.cend(); ++it)
        if (coordinated.contains(d.axis(it.key())->controller))
            out.axisRates.insert(it.key(), it.value() / minutes * override);
    return out;
}

ProgramBlock resolveChord(const ProgramBlock& arc, const ArcPath& path, qint64 k,
                          const machine::MachineDescription& d, const Controllers& coordinated,
                          double override)
{
    // The chord's ends are machine positions in the axes' units: a block in those units
    // (inches off, F converted as the length's unit takes it) from the chord's start.
    ProgramBlock chord;
    chord.kind = BlockKind::Feed;
    chord.line = arc.line;
    if (arc.inverseTime || !arc.feed)
        return chord;
    AxisPositions start(size_t(d.axes.size()));
    for (const auto& [axis, value] : path.pointAt(k - 1))
        start[size_t(axis)] = value;
    bool millimetres = false;
    for (const auto& [axis, value] : path.pointAt(k)) {
        chord.axes.insert(d.axes.at(axis).name, value);
        millimetres = millimetres || d.axes.at(axis).unit == machine::AxisUnit::Millimetre;
    }
    chord.feed = arc.inches && millimetres ? *arc.feed * units::kMillimetresPerInch : *arc.feed;
    return resolve(chord, d, coordinated, start, {}, override);
}

} // namespace stepdeck::program::CoordinatedFeed
