#pragma once

namespace stepdeck::bench {

// stepdeck-bench --preview-frame [FRAMES] [--json] (issue 29; docs/benchmark.md): the time of
// one frame of the Program page's path view (ProgramPathView, 800x600, offscreen unless
// QT_QPA_PLATFORM says otherwise) while the operator zooms with the wheel and pans with a drag,
// for a preview of the full kMaxPathPoints points (arcs' chords at several depths, rapids
// between), in the top and the isometric view: each frame is the input event handled and the
// widget painted into an image; median and p99 (nearest rank) over FRAMES frames (default
// 300) per view, and the frame while only the tool marker moves. Figures only.
// Returns the exit code, or -1 when args do not ask for it. Needs its own QApplication:
// called before main() creates the QCoreApplication.
int previewFrameBenchMain(int argc, char** argv);

} // namespace stepdeck::bench
