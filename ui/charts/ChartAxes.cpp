#include "ChartAxes.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QtMath>

namespace stepdeck::ui {

double ChartAxis::position(double steps) const
{
    if (!inMachine || !qIsFinite(steps)) // NaN: no sample of this axis
        return steps;
    return inMachine->toUnits(qRound64(steps));
}

double ChartAxis::velocity(double stepsPerSecond) const
{
    if (!inMachine)
        return stepsPerSecond;
    const double rate = stepsPerSecond / inMachine->stepsPerUnit;
    return inMachine->invert ? -rate : rate;
}

QString ChartAxis::csvUnit() const
{
    return inMachine ? machine::unitKey(inMachine->unit) : QStringLiteral("steps");
}

QList<ChartAxis> chartAxes(const MachineContext& context)
{
    const machine::Machine* m = context.machine();
    QList<ChartAxis> out;
    for (Axis a : context.axes()) {
        ChartAxis line;
        line.axis = a;
        line.name = context.controllerAxisName(a);
        line.unit = context.machineUnitName();
        if (m) {
            for (const machine::MachineAxis& axis : m->description().axes) {
                if (axis.controller != context.selectedController() || axis.axis != a)
                    continue;
                line.name = axis.name;
                if (axis.unit != machine::AxisUnit::Step) {
                    line.unit = context.axisUnitName(axis); // as the read-out names it
                    line.inMachine = axis;
                }
                break;
            }
        }
        out << line;
    }
    return out;
}

QStringList chartUnits(const QList<ChartAxis>& axes)
{
    QStringList units;
    for (const ChartAxis& a : axes) {
        if (!units.contains(a.unit))
            units << a.unit;
    }
    return units;
}

} // namespace stepdeck::ui
