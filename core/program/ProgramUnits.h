#pragma once
#include "machine/MachineDescription.h"

namespace stepdeck::program {

// A program's numbers in a machine axis' terms (docs/programs.md "Units"), shared by the
// check and the runner so both read a block the same way.
namespace units {

constexpr double kMillimetresPerInch = 25.4;

// An axis word's value (G20: inch) in the axis' unit: G20 converts only millimetre axes;
// rotary axes are always degrees and step axes always steps.
double toAxisUnits(const machine::MachineAxis& axis, double value, bool inches);

// G1's F (program unit per minute) as the axis' rate in whole steps/s, at least 1: what the
// model's feed-rate parameter (Capabilities::feedRateParameter) is written with.
qint64 feedStepsPerSecond(const machine::MachineAxis& axis, double feedPerMinute, bool inches);

} // namespace units
} // namespace stepdeck::program
