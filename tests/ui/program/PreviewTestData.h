// Machines and previews for the preview's tests (issue 29): written by hand, no check run.
#pragma once
#include "machine/MachineDescription.h"
#include "program/ProgramCheck.h"
#include <initializer_list>
#include <optional>

namespace stepdeck::previewtest {

struct AxisSpec
{
    QString name;
    std::optional<std::pair<double, double>> limits = std::nullopt; // soft limits, machine
};

inline machine::MachineDescription machineWith(std::initializer_list<AxisSpec> axes)
{
    machine::MachineDescription d;
    d.name = QStringLiteral("test");
    for (const AxisSpec& spec : axes) {
        machine::MachineAxis axis;
        axis.name = spec.name;
        axis.controller = QStringLiteral("c1");
        axis.unit = machine::AxisUnit::Millimetre;
        if (spec.limits) {
            axis.softMinimum = spec.limits->first;
            axis.softMaximum = spec.limits->second;
        }
        d.axes << axis;
    }
    return d;
}

// A machine of X, Y, Z (soft limits when asked).
inline machine::MachineDescription machineXyz(bool limits)
{
    if (!limits)
        return machineWith({{QStringLiteral("X")}, {QStringLiteral("Y")}, {QStringLiteral("Z")}});
    return machineWith({{QStringLiteral("X"), std::make_pair(0.0, 100.0)},
                        {QStringLiteral("Y"), std::make_pair(0.0, 50.0)},
                        {QStringLiteral("Z"), std::make_pair(-20.0, 0.0)}});
}

struct Step
{
    double x, y, z;
    bool rapid = false;
    int line = 0;
};

inline program::ProgramPreview previewOf(std::initializer_list<Step> steps)
{
    program::ProgramPreview preview;
    int line = 1;
    for (const Step& s : steps) {
        program::PreviewPoint p;
        p.line = s.line ? s.line : line;
        p.position = {
            {QStringLiteral("X"), s.x}, {QStringLiteral("Y"), s.y}, {QStringLiteral("Z"), s.z}};
        p.rapid = s.rapid;
        preview.path << p;
        ++line;
    }
    preview.lines = line - 1;
    return preview;
}

} // namespace stepdeck::previewtest
