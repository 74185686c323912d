#include "DemoMachine.h"
#include "machine/MachineControl.h"
#include "program/ProgramFiles.h"
#include "program/ProgramPage.h"
#include "window/MainWindow.h"
#include <QDir>
#include <QFile>
#include <QStandardPaths>

namespace stepdeck::ui {

namespace {

// The table: its reference switches are the simulator's (negative ends), each run ends at 0.
const char kMachine[] = R"json({
  "format": "stepdeck-machine",
  "version": 2,
  "name": "Demo plotter (simulated)",
  "controllers": [
    { "id": "table", "model": "elab", "port": "sim", "setup": "demo-table.setup.json" }
  ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 200,
      "softLimits": [0, 150], "maxJogSpeed": 20, "reference": { "direction": -1, "order": 1 } },
    { "name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 200,
      "softLimits": [0, 100], "maxJogSpeed": 20, "reference": { "direction": -1, "order": 1 } },
    { "name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 400,
      "softLimits": [0, 40], "maxJogSpeed": 10, "reference": { "direction": -1, "order": 0 } }
  ]
}
)json";

// The E-LAB's ramps; the start speed sets the contour stream's tick rate (feed mode runs
// below it): 999 ticks/s, F up to about 300 mm/min on X and Y.
const char kSetup[] = R"json({
    "format": "stepdeck-parameters",
    "model": "elab",
    "parameters": {
        "acceleration": { "X": 1000, "Y": 1000, "Z": 1000 },
        "feed-speed": { "X": 500, "Y": 500, "Z": 500 },
        "max-speed": { "X": 5000, "Y": 5000, "Z": 5000 },
        "start-speed": { "X": 1000, "Y": 1000, "Z": 1000 }
    },
    "version": 1
}
)json";

// In the style of a plotter's CAM post: absolute, mm, contours in G64 (one step stream each).
const char kProgram[] = R"ngc((StepDeck demo: a rounded frame and a circle, plotted)
(First: Machine > Reference all, Ctrl+H. Then Run.)
G21 G90 G17 G64
G0 Z5                 (pen up)
G0 X20 Y20
G1 Z0 F120            (pen down)
G1 X100 F240
G3 X110 Y30 I0 J10
G1 Y70
G3 X100 Y80 I-10 J0
G1 X20
G3 X10 Y70 I0 J-10
G1 Y30
G3 X20 Y20 I10 J0
G0 Z5
G0 X80 Y50
G1 Z0 F120
G2 X80 Y50 I-20 J0 F240 (a full circle, 20 mm radius)
G0 Z5
G0 X0 Y0
M2
)ngc";

} // namespace

QString DemoMachine::directory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/demo");
}

QString DemoMachine::machinePath()
{
    return directory() + QStringLiteral("/demo.machine.json");
}

QString DemoMachine::programPath()
{
    return directory() + QStringLiteral("/demo.ngc");
}

bool DemoMachine::writeIfMissing(const QString& path, const QByteArray& content, QString* error)
{
    if (QFile::exists(path))
        return true; // the newcomer's own changes stay
    QFile file(path);
    if (file.open(QIODevice::WriteOnly) && file.write(content) == content.size() && file.flush())
        return true;
    if (error)
        *error = tr("Cannot write the demo file %1: %2").arg(path, file.errorString());
    return false;
}

bool DemoMachine::open(MainWindow* window, QString* error)
{
    if (!QDir().mkpath(directory())) {
        if (error)
            *error = tr("Cannot create the demo folder %1").arg(directory());
        return false;
    }
    if (!writeIfMissing(machinePath(), kMachine, error) ||
        !writeIfMissing(directory() + QStringLiteral("/demo-table.setup.json"), kSetup, error) ||
        !writeIfMissing(programPath(), kProgram, error))
        return false;
    if (!window->openMachine(machinePath())) {
        if (error)
            *error = window->lastError();
        return false;
    }
    window->machineControl()->connect();
    if (!window->programPage()->files()->load(programPath())) {
        if (error)
            *error = tr("Cannot open the demo program %1").arg(programPath());
        return false;
    }
    return true;
}

} // namespace stepdeck::ui
