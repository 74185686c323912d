#include "InverseTime.h"
#include "ProgramUnits.h"
#include <cmath>

namespace stepdeck::program::InverseTime {

QMap<QString, double> distances(const ProgramBlock& block, const machine::MachineDescription& d,
                                const AxisPositions& start,
                                const QMap<QString, double>& workOffsets, bool wholeSteps)
{
    QMap<QString, double> out;
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        qsizetype index = 0;
        while (index < d.axes.size() && d.axes.at(index).name != it.key())
            ++index;
        if (index == d.axes.size())
            continue;
        const machine::MachineAxis& axis = d.axes.at(index);
        const double value = units::toAxisUnits(axis, it.value(), block.inches);
        const std::optional<double> from = start.at(size_t(index));
        const double to = *units::wordTarget(axis, it.value(), block.inches, block.relative,
                                             workOffsets.value(axis.name, 0.0), from.value_or(0.0));
        double distance = 0;
        if (from && (wholeSteps || !block.relative))
            distance = wholeSteps ? double(std::abs(axis.toSteps(to) - axis.toSteps(*from))) /
                                        axis.stepsPerUnit
                                  : std::abs(to - *from);
        else if (block.relative)
            distance = std::abs(value);
        if (distance > 0)
            out.insert(axis.name, distance);
    }
    return out;
}

ProgramBlock resolve(const ProgramBlock& block, const machine::MachineDescription& d,
                     const AxisPositions& start, const QMap<QString, double>& workOffsets)
{
    ProgramBlock out = block;
    out.axisRates.clear();
    if (!block.inverseTime || !block.feed)
        return out;
    const QMap<QString, double> moved = distances(block, d, start, workOffsets);
    for (auto it = moved.cbegin(); it != moved.cend(); ++it)
        out.axisRates.insert(it.key(), it.value() * *block.feed);
    return out;
}

ProgramBlock resolveArc(const ProgramBlock& block, const ArcPath& path)
{
    ProgramBlock out = block;
    out.axisRates.clear();
    if (!block.inverseTime || !block.feed || !(path.length() > 0))
        return out;
    for (const QString& name : ArcPath::movingAxes(block))
        out.axisRates.insert(name, path.length() * *block.feed);
    return out;
}

} // namespace stepdeck::program::InverseTime
