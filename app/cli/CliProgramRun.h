#pragma once
#include "CliMachineSession.h"
#include "CliOutput.h"

namespace stepdeck::cli {

// `stepdeck-cli [--machine FILE | --model M --port P] run PROGRAM [--dry-run] [--from-line N]
// [--skip-pauses] [--optional-stops on|off]` (issue 20; docs/cli.md "run"): reads and parses the
// program before anything is opened (every FILE:LINE:COL error on stderr, exit 7, nothing
// sent), refuses M0 (and M1 with optional stops on, the default) without a terminal on stdin
// (exit 2, unless --skip-pauses or, for M1, --optional-stops off) and, with tool lengths by
// touch-off, an M6 of another tool than the one before it (exit 2 in any case: the CLI cannot
// set a work Z; issue 50 item 4), checks it against the connected
// machine (exit 7 on a check error, no motion sent), then runs it through program::ProgramRunner:
// exit 0 finished, 3/4/5/6 after a refusal, NAK, timeout or lost link (the machine stopped),
// 130 after SIGINT/SIGTERM/SIGHUP. --dry-run prints the check's preview and sends no motion.
Outcome machineRunProgram(CliMachineSession& m, const CliOptions& o);

} // namespace stepdeck::cli
