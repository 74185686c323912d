#pragma once
#include <QStringList>

namespace stepdeck::bench {

// stepdeck-bench --gui-idle [SECONDS]: the idle cost of the GUI (issue 10). Starts
// stepdeck-sim (a simulated E-LAB board on a pseudo-terminal) and the built `stepdeck` GUI
// connected to it (--model/--port/--poll-interval), on Xvfb when installed (a real X server,
// so painting costs what it costs on a desktop), else on the offscreen platform; waits a
// warm-up, then samples /proc/<pid>/stat (utime+stime) and /proc/<pid>/status (VmRSS) of
// the GUI for SECONDS and prints CPU % of one core and RSS. The simulator's read bytes
// (/proc/<pid>/io) prove the link is polling. Returns -1 when args do not ask for it.
int guiIdleMain(const QString& appDir, const QStringList& args);

} // namespace stepdeck::bench
