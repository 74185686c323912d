#include "ProgramUnits.h"
#include "motion/executors/MoveRates.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::program::units {

double toAxisUnits(const machine::MachineAxis& axis, double value, bool inches)
{
    return inches && axis.unit == machine::AxisUnit::Millimetre ? value * kMillimetresPerInch
                                                                : value;
}

std::optional<double> wordTarget(const machine::MachineAxis& axis, double word, bool inches,
                                 bool relative, double offset, std::optional<double> from)
{
    const double value = toAxisUnits(axis, word, inches);
    if (!relative)
        return value + offset;
    if (from)
        return *from + value;
    return std::nullopt;
}

qint64 feedStepsPerSecond(const machine::MachineAxis& axis, double feedPerMinute, bool inches)
{
    // The one rounding of a speed to steps/s (the move executor's, motion::MoveRates).
    return motion::MoveRates::stepsPerSecond(axis, toAxisUnits(axis, feedPerMinute, inches) / 60.0);
}

} // namespace stepdeck::program::units
