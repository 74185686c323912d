#pragma once
#include "machine/MachineDescription.h"
#include <optional>

namespace stepdeck::program {

// A program's numbers in a machine axis' terms (docs/programs.md "Units"), shared by the
// check and the runner so both read a block the same way.
namespace units {

constexpr double kMillimetresPerInch = 25.4;

// An axis word's value (G20: inch) in the axis' unit: G20 converts only millimetre axes;
// rotary axes are always degrees and step axes always steps.
double toAxisUnits(const machine::MachineAxis& axis, double value, bool inches);

// Where an axis word sends its axis, in machine coordinates (the axis' unit): an absolute word
// to word + offset (the work offset, G92 and tool length in effect for it, ProgramCoordinates),
// a relative one from `from`, and nowhere known when `from` is not known. The one formula every
// target of a word comes from (issue 49): the check, the run, arcs, cycles, contours.
std::optional<double> wordTarget(const machine::MachineAxis& axis, double word, bool inches,
                                 bool relative, double offset, std::optional<double> from);

// G1's F (program unit per minute) as the axis' rate in whole steps/s, at least 1: what the
// model's feed-rate parameter (Capabilities::feedRateParameter) is written with.
qint64 feedStepsPerSecond(const machine::MachineAxis& axis, double feedPerMinute, bool inches);

} // namespace units
} // namespace stepdeck::program
