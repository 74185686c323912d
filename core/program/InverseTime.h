#pragma once
#include "ArcPath.h"
#include "ProgramBlock.h"
#include "machine/MachineDescription.h"

namespace stepdeck::program {

// G93, LinuxCNC's inverse time feed (docs/programs.md "Inverse time"): a G1 takes 1/F minutes.
// The axes of a block move each at its own rate (no interpolation, "How F maps onto each
// model"), so in G93 each axis gets the rate that makes it arrive in that time: its distance
// times F, in its unit per minute. All the block's axes then arrive together, which G94 does not
// give. The distance depends on where the block starts: resolved at the current point, by the
// check's walk and by the run from the same positions. Pure.
namespace InverseTime {

// The distance each axis of `block` moves, in its unit (above 0 only), from the current point
// `start` (machine coordinates, by axis index) to the block's target plus its work offsets. An
// absolute word on an axis whose start is unknown gives none (the check refuses the move); a
// relative one from there, its word. wholeSteps: between the whole steps of both ends, as the
// device runs them (Machine::move rounds each target to the step, a relative move counts the
// difference of the whole steps; CoordinatedFeed).
QMap<QString, double> distances(const ProgramBlock& block, const machine::MachineDescription& d,
                                const AxisPositions& start,
                                const QMap<QString, double>& workOffsets, bool wholeSteps = false);
// `block` with axisRates set: each axis it moves (distance above 0) and that axis' rate in its
// unit per minute. start: the current point (machine coordinates, the axes' units, by axis
// index); workOffsets: the block's offsets per axis name (ProgramCoordinates::offsets). An
// absolute word on an axis whose start is unknown gets no rate (the check refuses the move).
ProgramBlock resolve(const ProgramBlock& block, const machine::MachineDescription& d,
                     const AxisPositions& start, const QMap<QString, double>& workOffsets);
// A G2/G3 in G93 along `path` (planned from the current point): its chords run as a G1's at one
// rate over its moving axes (docs/programs.md "Arcs"), so every moving axis gets the path speed
// that covers the curve in 1/F minutes: its length times F, in the axes' unit per minute.
ProgramBlock resolveArc(const ProgramBlock& block, const ArcPath& path);

} // namespace InverseTime
} // namespace stepdeck::program
