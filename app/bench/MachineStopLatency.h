#pragma once
#include "Measurements.h"

namespace stepdeck::bench {

constexpr int kMachineStopRepetitions = 100; // p99 of 20 runs was their maximum

// Machine STOP latency (issue 19): a Machine of `controllers` controllers of `model` (each its
// simulator on its own pseudo-terminal, each in a long move), from the call of Machine::stop()
// to the stop bytes arriving at the LAST of them (the machine is stopped only when every
// controller has its stop). Needs the model's TrafficMeter (ModelInfo::streamBench).
LatencyFigure measureMachineStopLatency(const ModelInfo& model, int controllers, int repetitions);

} // namespace stepdeck::bench
