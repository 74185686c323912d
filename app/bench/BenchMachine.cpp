#include "BenchMachine.h"
#include "EventWait.h"

namespace stepdeck::bench {

bool openTable(machine::Machine& m, const QString& name, const QString& modelId,
               const QString& port, const QList<Axis>& axes, double stepsPerMm, QString* error)
{
    machine::MachineDescription d;
    d.name = name;
    d.controllers = {{"table", modelId, port, {}, {}, {}, {}, {}}};
    for (Axis a : axes) {
        machine::MachineAxis axis;
        axis.name = axisName(a);
        axis.controller = QStringLiteral("table");
        axis.axis = a;
        axis.unit = machine::AxisUnit::Millimetre;
        axis.stepsPerUnit = stepsPerMm;
        d.axes << axis;
    }
    if (!m.create(d, error))
        return false;
    m.open();
    if (!waitUntil([&] { return m.state() == machine::MachineState::Idle; }, 5000)) {
        *error = QStringLiteral("the controller did not connect");
        return false;
    }
    return true;
}

} // namespace stepdeck::bench
