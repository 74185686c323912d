#pragma once
#include "model/ModelInfo.h"

namespace stepdeck::elab {

// E-LAB line: 57600 baud, 8 data bits, 2 stop bits, no parity (manual: RS232-C). No hardware
// flow control (RTS is the board's reset) and no software flow control (0x13 is a command).
LineSettings lineSettings();
Capabilities capabilities();
ParameterSchema parameterSchema();
ModelInfo modelInfo();
// The simulator beyond the protocol: stepdeck-sim's machine options, the fault soak and the
// DC2 stream meter of the benchmarks (ElabSimProfile.cpp).
ScenarioSupport scenarioSupport();
SoakProfile soakProfile();
StreamBenchProfile streamBenchProfile();
// Status bit names and console notation for the UI (model/ModelPresentation.h).
ModelPresentation presentation();

} // namespace stepdeck::elab
