#pragma once

namespace stepdeck::bench {

// stepdeck-bench --window-program [SECONDS] [--json] (issue 28, item 7; docs/benchmark.md):
// the window's CPU while a program runs. The whole GUI (MainWindow, in this process, on the
// offscreen platform unless QT_QPA_PLATFORM says otherwise) runs a program of
// kWindowProgramLines short relative XY moves on an E-LAB machine of one controller, its
// simulator on a pseudo-terminal behind the paced wire, with the Program page raised and its
// Path tab shown (the path has the preview's full 20 000 points). Over SECONDS (default 15)
// after Run it measures the GUI thread's CPU time (getrusage RUSAGE_THREAD) and the whole
// process' (controller and device threads included) against the wall clock, and the blocks
// run. Prints the figures, or JSON. Returns the exit code, or -1 when args do not ask for it.
// Needs its own QApplication: called before main() creates the QCoreApplication.
int windowProgramBenchMain(int argc, char** argv);

constexpr int kWindowProgramLines = 20000;

} // namespace stepdeck::bench
