#pragma once
#include "LaserCodec.h" // lineSettings()
#include "model/ModelInfo.h"

namespace stepdeck::laser {

// No parameters, no stop, no jog stream, no status query: the protocol has two commands
// (home, move to position) and the axes report by themselves.
Capabilities capabilities();
// Console notation: the frames as ASCII; a missing final CR is added.
ModelPresentation presentation();
ModelInfo modelInfo();
// The simulator beyond the protocol: stepdeck-sim's machine options and the fault soak
// (LaserSimProfile.cpp).
ScenarioSupport scenarioSupport();
SoakProfile soakProfile();

} // namespace stepdeck::laser
