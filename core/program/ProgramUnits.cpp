#include "ProgramUnits.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::program::units {

double toAxisUnits(const machine::MachineAxis& axis, double value, bool inches)
{
    return inches && axis.unit == machine::AxisUnit::Millimetre ? value * kMillimetresPerInch
                                                                : value;
}

qint64 feedStepsPerSecond(const machine::MachineAxis& axis, double feedPerMinute, bool inches)
{
    const double unitsPerSecond = toAxisUnits(axis, feedPerMinute, inches) / 60.0;
    const double steps = std::llround(std::abs(unitsPerSecond * axis.stepsPerUnit));
    // A rate above qint64 is out of every parameter's range anyway; keep the number finite.
    return qint64(std::clamp(steps, 1.0, 9.0e15));
}

} // namespace stepdeck::program::units
