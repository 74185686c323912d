#pragma once
#include "model/AxisNames.h"
#include "model/LineSettings.h"
#include "model/ParameterSchema.h"
#include <QCoreApplication>
#include <QJsonObject>
#include <optional>

namespace stepdeck {
struct ModelInfo;
}

namespace stepdeck::machine {

// What a machine axis counts in. Rotary axes are degrees, linear ones millimetres; "steps"
// keeps the controller's own counts (a single controller without a machine file).
enum class AxisUnit { Millimetre, Degree, Step };

QString unitKey(AxisUnit unit); // "mm", "deg", "steps": the file's words
std::optional<AxisUnit> unitFromKey(const QString& key);

// What a program's feed above the highest a move can run at, or its S above the spindle's
// maxRpm, does (issue 50; file: "limits"). Clamp: it runs at that highest, and the check says
// so in a note, as LinuxCNC limits a move to the axes' maximum velocities and GRBL to its
// $110..$112 and $30. Refuse: the check refuses it, as StepDeck did before issue 50.
enum class LimitPolicy { Clamp, Refuse };

QString limitPolicyKey(LimitPolicy policy); // "clamp", "refuse": the file's words
std::optional<LimitPolicy> limitPolicyFromKey(const QString& key);

// One controller of a machine (docs/machines.md, "controllers").
struct MachineController
{
    QString id;      // short name, unique in the machine ("table", "rotary")
    QString modelId; // a registry id ("elab", "nanotec", ...)
    QString port;    // device path, tcp://HOST:PORT, or "sim" for the in-process simulator
    // Multi-drive models: controller axis -> bus address (the CLI's --axes). Empty: the
    // model's default addresses.
    QMap<Axis, int> busAddresses;
    std::optional<LineSettings::ResetLine> resetLine; // models with a reset line only
    // The controller's setup (issue 28, item 1): a parameter file as `export` writes it,
    // written to the device on every connect (MachineSetup). setupFile is the path as the
    // machine file gives it (relative to the machine file's folder); empty: none. setup holds
    // its values once MachineFile::load / parse read and validated it.
    QString setupFile;
    ParameterSet setup;
    // The names given to its bus axes (version 2 files: [{"name": "feeder", "address": 5}]).
    AxisNames axisNames;

    bool isSimulated() const { return port == QLatin1String("sim"); }
};

// One named axis of a machine and the controller axis that drives it.
struct MachineAxis
{
    QString name;       // X Y Z A B C U V W, unique in the machine
    QString controller; // MachineController::id
    Axis axis = Axis::X;
    AxisUnit unit = AxisUnit::Step;
    double stepsPerUnit = 1; // > 0, finite
    bool invert = false;     // a positive machine move is a negative controller move
    std::optional<double> softMinimum, softMaximum; // in unit; both or neither
    std::optional<double> maxJogSpeed;              // unit/s
    std::optional<double> jogAcceleration;          // unit/s^2, > 0 (issue 28 item 6)
    int referenceDirection = 0; // -1 or +1; 0: the file leaves it to the model's default
    int referenceOrder = 0;     // lower orders are referenced first

    // A target in units becomes the nearest whole step the device can hold.
    qint64 toSteps(double units) const;
    // The device's step count in units: the position shown is always one the device holds.
    double toUnits(qint64 steps) const;
    // A rate in unit/s as steps/s (sign kept, inversion applied).
    double toStepRate(double unitsPerSecond) const;
    bool hasSoftLimits() const { return softMinimum.has_value() && softMaximum.has_value(); }
    // The fastest this axis jogs in unit/s: its maxJogSpeed, or else the controller's jog
    // ceiling (Capabilities::maxJogSpeed, steps/s) in the axis' unit.
    double topJogSpeed(double controllerCeilingStepsPerS) const;
    // The deceleration its jog ramp follows, unit/s^2: the file's jogAcceleration, or else
    // topJogSpeed^2 / (2 x 1 unit), which stops a release from the top speed within one unit
    // (1 mm, 1 deg). An axis counted in steps has no default (one step would be no ramp at
    // all): none, the model's own jog ramp (Capabilities::defaultJogAcceleration).
    std::optional<double> effectiveJogAcceleration(double controllerCeilingStepsPerS) const;
};

// The machine's spindle (docs/machines.md, "spindle"; issue 29). maxRpm: the speed the
// controller's full spindle-speed range stands for, as GRBL's $30 does: a program's S in rpm
// is mapped linearly onto that range (motion::SwitchExecutor::spindleValue), and an S above it
// runs at maxRpm with a note (a check error with "limits": "refuse", issue 50). Without it, S
// is sent as written, in the controller's own units.
//
// laser (issue 50 item 5; file: "laser": true): the spindle output drives a laser. M4 (GRBL's
// dynamic power) then runs as M3 with the power S maps to, since no controller of StepDeck's has
// dynamic power (the check notes it), and the check speaks of S as the beam's power.
struct MachineSpindle
{
    std::optional<double> maxRpm; // > 0, finite
    bool laser = false;
};

// Where a tool's length comes from (issue 50 item 4; file: "toolLength", docs/programs.md
// "Tools"). Table: the machine's tool table, G43 H adding the tool's length (LinuxCNC's way).
// TouchOff: most hobby shops keep no table and touch off Z after each tool change: M6 holds
// until the operator set the work Z for the new tool, and G43 adds nothing.
enum class ToolLength { Table, TouchOff };

QString toolLengthKey(ToolLength mode); // "table", "touchOff": the file's words
std::optional<ToolLength> toolLengthFromKey(const QString& key);

// A machine: a name, its controllers and its named axes (docs/machines.md). Built by
// MachineFile from a "stepdeck-machine" file, or by singleController() for --model/--port,
// so the rest of StepDeck has one code path for both.
struct MachineDescription
{
    QString name;
    QList<MachineController> controllers;
    QList<MachineAxis> axes;
    MachineSpindle spindle;
    // Feed moves whose axes sit on several controllers (issue 30): the controllers start
    // together but share no clock, so the path between a move's ends is approximate (the check
    // says so with an estimate). False (file: "crossControllerFeed": false): the check refuses
    // them.
    bool crossControllerFeed = true;
    // Feeds and spindle speeds above what the machine can run (issue 50, program::FeedLimit):
    // run at its highest with a note (file: no "limits", or "clamp"), or refused ("refuse").
    LimitPolicy limits = LimitPolicy::Clamp;
    // LinuxCNC's SUBROUTINE_PATH (issue 33; file: "subroutineFolder"): where "O<name> call"
    // finds <name>.ngc when the program does not define it. As written (relative: to the
    // machine file), and resolved when the file is read. Empty: none.
    QString subroutineFolder;
    QString subroutineFolderPath;
    // How tools get their length (issue 50 item 4; file: "toolLength", "table" by default and
    // then left out, so older versions still read the file).
    ToolLength toolLength = ToolLength::Table;
    // singleController(..., DriveAxes::All): axes past the ninth go by their drive names
    // (validation accepts them; no file has them, so toJson leaves this out).
    bool driveNamedAxes = false;

    const MachineController* controller(const QString& id) const;
    const MachineAxis* axis(const QString& name) const;
    // The axis a person means by `name` (CLI move, jog, home; issue 32): its machine name, as
    // given or in any case, else the name its controller gives it ("feeder"), when exactly one
    // axis has that name. nullptr: none, or several.
    const MachineAxis* findAxis(const QString& name) const;
    // The name its controller gives the controller axis of `a` ("feeder"; issue 32).
    QString controllerAxisName(const MachineAxis& a) const;
    int
    axisIndex(const QString& axisNameInMachine) const; // its place in `axes`, -1 when there is none
    // The axes in referencing order: groups of equal order, lowest first, file order inside.
    QList<QList<const MachineAxis*>> referenceGroups() const;
    // The jog ramp of controller `id` in steps/s^2 (ControllerOptions::jogAccelerationStepsPerS2;
    // 0: the model's default, when none of its axes has an effectiveJogAcceleration).
    double jogRampAcceleration(const QString& controllerId,
                               double controllerCeilingStepsPerS) const;

    // A machine of one controller: unit steps, 1 step per unit, no limits. `addresses` and
    // `names` as for MachineController. An axis whose default name is a machine axis' letter
    // (X, Y, Z, U) keeps it; the others take the free letters of X Y Z A B C U V W in axis
    // order (a program addresses axes by letter). A bus of more than nine drives has nine
    // machine axes; the drive pages reach every drive. With DriveAxes::All (the CLI's move,
    // jog, home and status without a machine file) every further drive is a machine axis too,
    // under its controller name (axis10, "feeder"): nothing in a program can address it.
    enum class DriveAxes { Letters, All };
    static MachineDescription singleController(const ModelInfo& model, const QString& port,
                                               const QMap<Axis, int>& addresses = {},
                                               const AxisNames& names = {},
                                               DriveAxes drives = DriveAxes::Letters);
    // The letters a machine axis may have: X Y Z A B C U V W.
    static const QStringList& axisLetters();
    // The file form (MachineFile::parse reads it back to an equal description).
    QJsonObject toJson() const;
};

bool operator==(const MachineController& a, const MachineController& b);
bool operator==(const MachineAxis& a, const MachineAxis& b);
bool operator==(const MachineSpindle& a, const MachineSpindle& b);
bool operator==(const MachineDescription& a, const MachineDescription& b);

} // namespace stepdeck::machine
