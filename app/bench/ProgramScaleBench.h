#pragma once
#include <QStringList>

namespace stepdeck::bench {

// stepdeck-bench --program-scale [LINES ...] [--json] (issue 29; docs/benchmark.md): generated
// programs of LINES lines each (default 100000 1000000 10000000), in the style of a 3D
// finishing pass (G1 X Y Z lines, an arc every 50 lines), written to a temporary file and read
// back in 64 KiB chunks through ProgramParser, then ProgramCheck against a mill of one E-LAB:
// per size the parse and check rates in lines/s and the peak resident memory of that run
// (VmHWM, reset between sizes), or the refusal the parser or check gave. Figures only.
// Returns the exit code, or -1 when args do not ask for it.
int programScaleBenchMain(const QStringList& args);

} // namespace stepdeck::bench
