#pragma once
#include <QStringList>

namespace stepdeck::bench {

// stepdeck-bench --contour (issue 30, docs/benchmark.md): programs of continuous feed moves run
// by ProgramRunner (a circle, a spiral of 600 G1 chords, a zigzag) on an E-LAB table (X, Y at
// 100 steps/mm, start speed 2000 steps/s: the stream ticks at 1999/s) whose simulator sits on a
// pseudo-terminal behind the paced wire (57600 8N2).
// Each runs as one <DC2> stream; the board's executed vectors give, per program: the largest
// path error in steps against the ideal path worked out here, the path-speed error (the ticks
// the board executed against length / F at the tick rate), the vectors/s the wire carried
// against its 2 618, and the board's underruns. On the circle also the hold latency (holdFeed
// -> the board's last step) and the override latency (100 % -> 50 %: until the board's angular
// rate fell below 75 % of what it was). Figures only. Returns the exit code, or -1 when args do
// not ask for it. Then the EMIS and Nanotec chords (ChordBench.h).
int contourBenchMain(const QStringList& args);

} // namespace stepdeck::bench
