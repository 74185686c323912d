// stepdeck-bench's usage text (main.cpp).
#include "BenchUsage.h"
#include "model/ModelInfo.h"
#include <cstdio>

namespace stepdeck::bench {

void printUsage(const ModelInfo* model)
{
    const QByteArray text =
        QStringLiteral(
            "Usage: stepdeck-bench [--json] [--load N] [--panic-only] [--panic-runs N] "
            "[--jog-presses N] [--jog-paced]\n"
            "       stepdeck-bench [--json] --poll-only [--poll-window MS]\n"
            "       stepdeck-bench [--json] --machine-stop-only "
            "[--machine-stop-runs N]\n"
            "       stepdeck-bench --soak N [--model M [--drives D] | --machine] [--seed S] "
            "[--json]\n"
            "       stepdeck-bench --replug N [--model M] [--seed S] [--json]\n"
            "       stepdeck-bench --program [--json]\n"
            "       stepdeck-bench --program-scale [LINES ...] [--json]\n"
            "       stepdeck-bench --contour [--contour-model elab|emis|nanotec] [--json]\n"
            "       stepdeck-bench --window-program [SECONDS] [--json]\n"
            "       stepdeck-bench --preview-frame [FRAMES] [--json]\n"
            "       stepdeck-bench --jog-latency [--jog-presses N] [--jog-paced] "
            "[--json]\n"
            "       stepdeck-bench --gui-idle [SECONDS] [--warmup S] "
            "[--poll-interval MS] [--platform xvfb|offscreen] [--json]\n"
            "Measures the first model with a feed stream (%1) against its "
            "simulator over a "
            "pseudo-terminal with QSerialPort: poll rate, panic latency and "
            "DC2 feed throughput, unpaced and paced at the line rate, and "
            "the machine STOP latency with 1, 2 and 4 controllers, and the jog "
            "latency (below).\n"
            "Figures only; takes 1-2 min.\n"
            "Every model's status poll is also measured on its paced wire against "
            "the limit the characters of its polls allow (E-LAB, Nanotec with 1, "
            "3, 4 and 8 drives on one bus, EMIS), and a Nanotec bus of 8, 32 and "
            "254 drives with one moving: its read interval, the idle drives' round "
            "and the wire's use. --poll-only: only the poll figures; --poll-window "
            "MS: polls counted for MS per model (default 3000; the bus of many "
            "drives 2 x MS + 2000).\n"
            "--load N: the panic latency is measured quiet and again beside N busy "
            "threads at normal priority (default 2). --panic-only: only those two. "
            "--panic-runs N: N runs each instead of 20 and 100.\n"
            "--machine-stop-only: only the machine STOP latency; "
            "--machine-stop-runs N: N runs per machine size instead of 100.\n"
            "--soak N: N random commands with ~1 % injected faults (dropped, "
            "corrupted, delayed replies, noise, peer vanish) against every "
            "simulator (or M); counts crashes, hangs, axes left moving, lost and "
            "duplicated moves; exit 1 unless all are 0. With --machine: one "
            "machine of an E-LAB and a Nanotec simulator driven through "
            "Machine, faults on either link. --drives D (with --model nanotec): a "
            "bus of D drives (1..254) at addresses 1..D instead of 3.\n"
            "--replug N: the peer vanishes N times (mid-poll, -jog, -stream, "
            "-write); time until the host reports it.\n"
            "--program: a program of 1000 short relative moves on the E-LAB and "
            "Nanotec simulators over the paced wire: blocks per second and, at "
            "the device, the gap from an arrival to the next block's first byte "
            "and to its acceptance.\n"
            "--contour: a 50 mm circle and a 2000-segment zigzag as <DC2> streams "
            "on the E-LAB simulator over the paced wire: path error, path-speed "
            "error, vectors/s, underruns; on the circle hold and override latency; "
            "on the EMIS and the Nanotec a circle as chords: gap and arrival skew. "
            "--contour-model: that model's part alone.\n"
            "--window-program: the window (offscreen unless QT_QPA_PLATFORM is "
            "set) runs a 20000-line program of short XY moves on the E-LAB "
            "simulator over the paced wire with the Path tab shown: CPU of the "
            "GUI thread and of the process, % of a core, over SECONDS (15).\n"
            "--preview-frame: the Program page's path view (800x600, offscreen "
            "unless QT_QPA_PLATFORM is set) with a 20000-point path: the time of a "
            "wheel-zoom or drag-pan frame, median and p99 over FRAMES (300) per "
            "view, top and isometric.\n"
            "--jog-latency: the GUI's jog panel (offscreen unless QT_QPA_PLATFORM "
            "is set) against the E-LAB and Nanotec simulators on an unpaced "
            "pseudo-terminal (--jog-paced: at the line rate); N presses on the "
            "pad (default 50) at full +X, each from rest: press -> first jog frame "
            "and release -> end of the jog at the device, median and p99.\n"
            "--gui-idle: CPU and RSS of the stepdeck GUI connected to "
            "stepdeck-sim and polling (default 20 s after 5 s warm-up, 50 ms).\n"
            "See docs/benchmark.md.")
            .arg(model ? model->displayName : QStringLiteral("none built in"))
            .toUtf8() +
        '\n';
    std::fwrite(text.constData(), 1, size_t(text.size()), stdout);
    std::fflush(stdout);
}

} // namespace stepdeck::bench
