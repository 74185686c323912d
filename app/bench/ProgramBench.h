#pragma once
#include <QStringList>

namespace stepdeck::bench {

// stepdeck-bench --program (issue 20, docs/benchmark.md): a program of kProgramBlocks short
// relative moves run by ProgramRunner on a machine of one controller, E-LAB and Nanotec, each
// simulator on a pseudo-terminal behind the paced wire. Prints blocks per second and the gap
// between blocks at the device (an axis' arrival to the acceptance of the next move), median
// and p99. Returns the exit code, or -1 when args do not ask for it.
int programBenchMain(const QStringList& args);

constexpr int kProgramBlocks = 1000;

} // namespace stepdeck::bench
