#pragma once
#include "SimScenario.h"

namespace stepdeck::simapp {

// `stepdeck-sim --machine FILE` (issue 19): one simulator per controller of the machine file,
// each on its own pseudo-terminal, and a copy of the file whose ports point at them. The copy
// is the first line on stdout (compact JSON, the same contract as the single simulator's
// path line) and, with --out, an indented file a user hands to `stepdeck-cli --machine` or
// the GUI. Serves until SIGINT/SIGTERM. Returns the process exit code.
int runMachine(const SimScenario& scenario);

} // namespace stepdeck::simapp
