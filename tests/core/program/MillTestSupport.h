#pragma once
// A mill of one E-LAB with X, Y, Z in millimetres at 100 steps/mm, no soft limits: the machine
// of the path tests (tst_arcpath, tst_drillcycle), which plan from positions they give.
#include "machine/MachineDescription.h"

namespace stepdeck::program::pathtest {

inline machine::MachineDescription mill()
{
    machine::MachineDescription d;
    machine::MachineController c;
    c.id = QStringLiteral("table");
    c.modelId = QStringLiteral("elab");
    d.controllers << c;
    const auto axis = [](const char* name, Axis on) {
        machine::MachineAxis a;
        a.name = QLatin1String(name);
        a.controller = QStringLiteral("table");
        a.axis = on;
        a.unit = machine::AxisUnit::Millimetre;
        a.stepsPerUnit = 100;
        return a;
    };
    d.axes << axis("X", Axis::X) << axis("Y", Axis::Y) << axis("Z", Axis::Z);
    return d;
}

} // namespace stepdeck::program::pathtest
