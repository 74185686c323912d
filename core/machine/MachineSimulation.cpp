#include "MachineSimulation.h"
#include "MachineReferenceRun.h"
#include "model/ModelInfo.h"

namespace stepdeck::machine {

SimulatorScenario simulatorScenarioOf(const MachineDescription& description,
                                      const QString& controllerId, const Capabilities& caps)
{
    SimulatorScenario scenario;
    if (!caps.referenceDirection)
        return scenario; // the device picks the direction (EMIS 9.9): its switch is its own
    for (const MachineAxis& a : description.axes)
        if (a.controller == controllerId)
            scenario.referenceSides.insert(a.axis, referenceSearchDirection(a, caps));
    return scenario;
}

bool simulatorTakes(const ModelInfo& model, const SimulatorScenario& scenario)
{
    const ScenarioOptions used = scenario.used();
    return used && !(used & ~model.scenario.options) && model.scenario.apply;
}

} // namespace stepdeck::machine
