#pragma once
#include <QJsonArray>

namespace stepdeck::bench {

// Part of stepdeck-bench --contour (issue 30, docs/benchmark.md): a circle of radius 10 mm at
// F1200 run by ProgramRunner as chords on the controllers that coordinate (CoordinatedFeed):
// an EMIS SMC-IC4 (X, Y in one vector move with IP1) and a Nanotec bus of three drives (X, Y
// moving, Z idle), each simulator on a pseudo-terminal behind the paced wire (115200 8N1, 19200
// 8N1), X and Y at 100 steps/mm. From the simulators' own records (when each move was accepted or
// started, when each axis arrived): the gap between chords (an arrival of chord k's last axis to
// the device's acceptance of chord k+1: median, p99) and the arrival skew between the axes of one
// chord (median, largest). Prints the figures (json: appends one object per model to out).
void runChordBench(bool json, QJsonArray* out, const QString& only = {});
// --contour-model emis|nanotec: that model's chords alone, printed; the exit code.
int runChordBench(bool json, const QString& only);

} // namespace stepdeck::bench
