#pragma once
#include "MachineDescription.h"
#include "model/Capabilities.h"
#include "model/SimulatorScenario.h"

namespace stepdeck {
struct ModelInfo;
}

namespace stepdeck::machine {

// What a simulator of one controller of a machine file must look like for the file's machine
// to work on it (issue 28, docs/machines.md "Simulated machines"): each axis' reference switch
// on the side its reference run searches. Used by the in-process simulators of port "sim"
// (Machine::create) and by `stepdeck-sim --machine`; the model applies what it supports
// (ModelInfo::scenario, ScenarioOption::ReferenceSides).
SimulatorScenario simulatorScenarioOf(const MachineDescription& description,
                                      const QString& controllerId, const Capabilities& caps);
// True when there is something to apply and the model's simulator takes all of it; a model
// whose simulator keeps its own machine (the EMIS picks its reference side) is left as it is.
bool simulatorTakes(const ModelInfo& model, const SimulatorScenario& scenario);

} // namespace stepdeck::machine
