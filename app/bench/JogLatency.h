#pragma once
#include "Measurements.h"
#include <QJsonObject>
#include <QStringList>

namespace stepdeck {
struct ModelInfo;
}

namespace stepdeck::bench {

// stepdeck-bench --jog-latency (issue 21, item 4): the GUI's own jog panel (JogPanel with its
// JoystickPad, PadJogSource and JogController, wired to a MachineContext as MainWindow wires
// them) in a QApplication, offscreen unless QT_QPA_PLATFORM says otherwise, against the
// model's simulator on a pseudo-terminal (BenchDevice). Presses on the X/Y pad go through
// QTest; what the device received is timestamped in the device's thread as the bytes arrive.

constexpr int kJogPresses = 50;
constexpr int kJogHoldMs = 100; // press to release: a short tap on the pad
// The models measured, by registry id; a multi-drive model's drive sits on its first soak
// address (Nanotec: 1) and jogs as axis X.
inline const QStringList kJogModels = {QStringLiteral("elab"), QStringLiteral("nanotec")};

struct JogLatencyOptions
{
    int presses = kJogPresses;
    bool paced = false; // both directions at the model's line rate (BenchDevice::Config::paced)
};

struct JogLatencyFigure
{
    QString model;
    // Press -> the first frame after which the device's axis jogs: the frame that starts the
    // jog, its first non-zero jog frame.
    LatencyFigure press;
    // Release -> the frame the model's adapter sends to end the jog: one the simulator calls a
    // stop frame (Simulator::isStopFrame).
    LatencyFigure release;
};

// One model, in a process with a QApplication. Every press starts from rest.
JogLatencyFigure measureJogLatency(const ModelInfo& model, const JogLatencyOptions& options);

// `stepdeck-bench --jog-latency [--jog-presses N] [--jog-paced] [--json]`: creates its own
// QApplication, so it runs before main() creates one. -1 when argv does not ask for it.
int jogLatencyMain(int argc, char** argv);

// The default run's jog figures: this bench as a child process (`--jog-latency --json` plus
// passThrough), so the default run itself keeps its QCoreApplication. Its JSON object, or an
// empty one with *error.
QJsonObject jogLatencyFromChild(const QString& benchPath, const QStringList& passThrough,
                                QString* error);
// The human-readable lines of a --jog-latency JSON object.
QStringList jogLatencyText(const QJsonObject& figures);

} // namespace stepdeck::bench
