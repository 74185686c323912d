#pragma once
#include "ArcPath.h"
#include "ProgramBlock.h"
#include "machine/MachineDescription.h"
#include <QSet>

namespace stepdeck::program {

// A G94 G1 over several axes, as LinuxCNC moves it: the tool along the line at F (issue 30).
// The length is measured over the linear axes that move (mm; on a machine counted in steps, the
// step axes); a move of rotary axes alone is measured in degrees. A controller that takes a rate
// per axis and starts its axes together (Capabilities::coordinatedFeed: the EMIS with IP1, a
// Nanotec bus) gets for each moving axis the share of F that its distance has of that length,
// so that every axis takes the block's time length / F and all arrive together. Distances are
// those of the whole steps the device runs (each end rounded to the step, as Machine::move
// does), so a short chord's shares are its steps', not its ideal ones'. Axes of other
// controllers keep F (docs/programs.md "How F maps onto each model"). The rates go into
// ProgramBlock::axisRates as G93's do (InverseTime); the check and the run resolve a block from
// the same current point. Pure.
namespace CoordinatedFeed {

// Which unit a path length is measured in (LinuxCNC: X, Y, Z when they move, else A, B, C):
// the lower, the first; mm, then steps (a machine without units), then degrees.
int unitRank(machine::AxisUnit unit);

// The controllers of `d` whose capabilities say coordinatedFeed.
using Controllers = QSet<QString>;

// True when `block` may resolve to rates per axis: a G94 G1 with F over more than one axis (or
// one, with `single`: a feed override applies), one of them on a coordinating controller.
// Cheap: the check asks it of every block.
bool applies(const ProgramBlock& block, const machine::MachineDescription& d,
             const Controllers& coordinated, bool single = false);
// `block` with axisRates for the moving axes of coordinating controllers (none where fewer
// than two axes move, or where the length is 0). start and workOffsets as in InverseTime.
// override: the run's feed override (ProgramRunner::setFeedOverride) times every share; other
// than 1 a move of one axis gets its rate too.
ProgramBlock resolve(const ProgramBlock& block, const machine::MachineDescription& d,
                     const Controllers& coordinated, const AxisPositions& start,
                     const QMap<QString, double>& workOffsets, double override = 1.0);

// Chord k (1..chords) of the G2/G3 `arc` along `path`, as the G1 it runs as, resolved: each
// moving axis' share of the arc's F along that chord (LinuxCNC keeps the path speed on the
// curve). A G93 arc is not resolved here (InverseTime::resolveArc).
ProgramBlock resolveChord(const ProgramBlock& arc, const ArcPath& path, qint64 k,
                          const machine::MachineDescription& d, const Controllers& coordinated,
                          double override = 1.0);

} // namespace CoordinatedFeed
} // namespace stepdeck::program
