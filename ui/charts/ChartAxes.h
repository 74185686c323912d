#pragma once
#include "machine/MachineDescription.h"
#include "model/Axis.h"
#include <QList>
#include <QString>
#include <QStringList>
#include <optional>

namespace stepdeck::ui {

class MachineContext;

// One line of the Position and Commanded velocity charts: a controller axis of the selected
// controller, plotted in its machine unit when the open machine gives it one (mm, deg:
// MachineAxis::toUnits, as the Position read-out shows it), otherwise in what the controller
// counts (steps; laser axes: units). The samples stay in steps; only the plot converts.
struct ChartAxis
{
    Axis axis = Axis::X;
    QString name;                                  // the machine axis' name, else the controller's
    QString unit;                                  // translated: "mm", "deg", "steps"
    std::optional<machine::MachineAxis> inMachine; // set when it is plotted in a machine unit

    double position(double steps) const;
    double velocity(double stepsPerSecond) const;
    // The unit as a CSV header spells it, untranslated: "mm", "deg" (the machine file's
    // words), else "steps".
    QString csvUnit() const;
};

// The selected controller's axes as the charts plot them.
QList<ChartAxis> chartAxes(const MachineContext& context);
// The units the value axis plots, each once, in the axes' order ("mm", or "mm", "deg").
QStringList chartUnits(const QList<ChartAxis>& axes);

} // namespace stepdeck::ui
