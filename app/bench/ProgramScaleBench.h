#pragma once
#include <QStringList>

namespace stepdeck::bench {

// stepdeck-bench --program-scale [LINES ...] [--json] (issue 29; docs/benchmark.md): generated
// programs of LINES lines each (default 100000 1000000 10000000), in the style of a 3D
// finishing pass (G1 X Y Z lines, an arc every 50 lines), written to a temporary file and
// checked against a mill of one E-LAB in one pass from the file, then again over the Program
// that gave (as a run's start does): per size both rates in lines/s and the peak resident
// memory of that run (VmHWM, reset between sizes), or the refusal. Figures only.
// Returns the exit code, or -1 when args do not ask for it.
int programScaleBenchMain(const QStringList& args);

} // namespace stepdeck::bench
