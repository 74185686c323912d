#pragma once
#include "CliArguments.h"
#include "CliMachineSession.h"
#include "CliOutput.h"

namespace stepdeck::cli {

// The whole of one invocation with --model/--port (main.cpp): its own session, signals and
// exit code.
int runSingleController(const CliOptions& options);

// The machine commands (move, jog, home, stop, panic, status) run on a machine also without a
// file: runOneControllerMachine() makes --model/--port a machine of that one controller
// (issue 19: one code path), its axes under their controller names in steps. Only
// `home --simultaneous` and `home --closed-loop`, a controller's own reference operations,
// run on the controller's session.
bool runsOnTheMachine(const CliOptions& options);
int runOneControllerMachine(const CliOptions& options);

// The whole of one invocation with --machine FILE (CliMachineRun.cpp): loads and validates the
// file (exit 12 unreadable, 7 invalid), runs move/jog/home/stop/panic/status/machine on the
// machine and every other command on the controller --controller names (exit 2 without it
// when the machine has several). SIGINT/SIGTERM/SIGHUP stop every controller, then exit 130.
int runWithMachine(const CliOptions& options);

// The machine commands (CliMachineMotion.cpp, CliMachineStatus.cpp).
Outcome machineMove(CliMachineSession& m, const CliOptions& o);
Outcome machineJog(CliMachineSession& m, const CliOptions& o);
Outcome machineHome(CliMachineSession& m, const CliOptions& o);
Outcome machineStop(CliMachineSession& m, const CliOptions& o);
Outcome machinePanic(CliMachineSession& m, const CliOptions& o);
Outcome machineStatus(CliMachineSession& m, const CliOptions& o);
// Every axis' position in its unit, how it is known (one line, or JSON with --json; a machine
// of one controller prints the controller's status object, as `status --json`).
Outcome printMachinePositions(CliMachineSession& m, bool json);
QString machinePositionsLine(CliMachineSession& m); // "X=2.500 A=25.000 (unknown)"

// The resolved controllers and axes (CliMachineCommands.cpp; `machine check`, `machine`).
void printMachineTable(const machine::MachineDescription& m);

} // namespace stepdeck::cli
