#include "ProgramUnits.h"
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
    const double unitsPerSecond = toAxisUnits(axis, feedPerMinute, inches) / 60.0;
    const double steps = std::abs(unitsPerSecond * axis.stepsPerUnit);
    // A rate beyond 9e15 (or not finite: a G93 rate of a huge distance) is out of every
    // parameter's range anyway: kept at that bound, before rounding (llround of a value beyond
    // qint64 gives no defined number).
    if (!(steps <= 9.0e15))
        return qint64(9.0e15);
    return std::max<qint64>(1, std::llround(steps));
}

} // namespace stepdeck::program::units
