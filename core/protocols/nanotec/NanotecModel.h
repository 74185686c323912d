#pragma once
#include "model/ModelInfo.h"

namespace stepdeck::nanotec {

// RS485 line of the SMCI33 / SMCI47-S (manual 1.1): 19200 baud, 8 data bits, 1 stop bit,
// no parity.
LineSettings lineSettings();
// The default machine when no axis map is given: X=1, Y=2, Z=3.
QMap<Axis, int> defaultAxisAddresses();
Capabilities capabilities(const QList<Axis>& axes);
ModelInfo modelInfo();
// The simulator beyond the protocol: stepdeck-sim's machine options and the fault soak
// (NanotecSimProfile.cpp).
ScenarioSupport scenarioSupport();
SoakProfile soakProfile();
// Status bit names (5.21) and console notation for the UI (model/ModelPresentation.h).
ModelPresentation presentation();

} // namespace stepdeck::nanotec
