#pragma once
#include "Axis.h"
#include "LineSettings.h"

namespace stepdeck {

enum class MotionMode {
    Jog,          // continuous, host-ramped or drive-ramped rate per axis
    RelativeMove, // positioning by signed step counts
    AbsoluteMove, // positioning to a target (host-tracked where the model has no absolute move)
    Feed,         // constant-rate linear feed
    FeedStream,   // single-step stream (E-LAB DC2)
    Reference,    // reference (homing) run with a direction per axis
    Velocity,     // velocity move until stopped
};

// What a model can do. Drives UI enabling, CLI checks and core refusals.
struct Capabilities
{
    QList<Axis> axes;
    QList<MotionMode> motionModes;
    bool spindle = false;
    // The spindle can turn both ways (M4, issue 29). No model can today: the E-LAB board only
    // switches relay RS1 on and off (manual, SetSpindleRPM: "kann keine Spindel Drehzahl
    // direkt einstellen, sondern diese nur über das Relais RS1 ein oder ausschalten"), and
    // the other models have no spindle.
    bool spindleReverse = false;
    bool coolant = false;
    bool drivePower = false;
    bool temperature = false;
    bool startButton = false;
    bool positionReadback = false; // the device reports absolute positions
    bool rampedStop = false;
    // false: the protocol documents no stop command at all (EMIS SMC-IC4, laser motor axes).
    // stop and panic are then refused Unsupported with Controller::noStopCommandText(), the GUI
    // says so permanently next to STOP/PANIC, and jog is built so that every chunk ends by itself.
    bool stopCommand = true;
    bool panic = true;
    bool resetLine = false;  // hardware reset via a modem line (E-LAB: RTS)
    bool multiDrive = false; // several addressed drives on one link (Nanotec)
    // multiDrive: the addresses a drive on the bus may have (Nanotec 1.1: 1..254).
    int minBusAddress = 0;
    int maxBusAddress = 0;
    bool records = false; // stored records and error memory as model operations (Nanotec)
    // The closed-loop commissioning workflow as model operations (model/ClosedLoop.h): motor
    // data check, calibration run, closed-loop reference run, enable (Nanotec manual 8.1).
    bool closedLoop = false;
    bool hostRampedJog = false; // the host must ramp jog rates itself (E-LAB manual, jog mode)
    // Digital inputs and outputs of the controller itself (EMIS SMC-IC4: 8 inputs, 7 outputs).
    // Their levels come in MachineStatus::inputs / outputs; an output is switched with
    // Controller::modelOperation(operation::kSetOutput, {output: 1..N, on: bool}).
    int digitalInputs = 0;
    int digitalOutputs = 0;
    // A power-on parameter set kept by the device (EMIS "##" system parameters): the CLI's
    // `store` / `get`, model operations kStoreParameters, kReadStoredParameters,
    // kClearStoredParameters (model/ModelOperations.h; arguments in the model's controller
    // header).
    bool storedParameters = false;
    // Programs stored per input that the device runs by itself (EMIS 9.17): model operations
    // kWriteInputProgram, kEraseInputProgram.
    bool inputPrograms = false;
    // false: the device chooses the direction of its reference runs (EMIS 9.9); a reference
    // request then takes 1 (reference this axis) or 0 (leave it out) per axis.
    bool referenceDirection = true;
    double maxJogSpeed = 1000;            // steps/s, the ceiling a jog source may request
    double defaultJogAcceleration = 2000; // steps/s^2 for the host-side JogRamp

    // false: the device has no status request and only reports by itself (laser motor axes);
    // refreshStatus() then returns what it last reported.
    bool statusQuery = true;
    // Move and home requests finish only when the device reports that the axes arrived, or
    // with Timeout after ControllerOptions::arrivalTimeoutMs (laser motor axes).
    bool reportsArrival = false;
    // A started move shows as moving in the status published before its request finishes and
    // stays so until a status read of the device after the start shows it at rest (Nanotec:
    // HostDrive::motionPending). Machine then needs no status read of its own after the
    // acceptance to tell an arrival from a status taken before the start (issue 30: on the
    // Nanotec's bus that read cost a sweep of every drive between two chords).
    bool statusHoldsStartedMove = false;
    // No jog stream: jog inputs become short targets, the next one sent only after the
    // previous one arrived, never a target far ahead (laser motor axes).
    bool jogByTargets = false;
    // A relative move is sent as an absolute target from where the axis said it is: refused
    // while its position is unknown (laser motor axes: a move carries only a target, and the
    // position is known from the first status frame, after a home or an absolute move).
    bool relativeNeedsPosition = false;
    bool doorSwitch = false; // the device reports a door switch (MachineStatus::doorOpen)
    // How a program's G1 F (docs/programs.md, issue 20) reaches the device: the per-axis
    // parameter in steps/s (its schema range is the rate's range) that is written before the
    // move. Null: the model takes no rate (laser motor axes), and G1 is a check error.
    const char* feedRateParameter = nullptr;
    // The G1 move runs as MotionMode::Feed (E-LAB: a feed move at its feed speed) rather than
    // as a positioning move.
    bool feedRateUsesFeedMode = false;
    // The parameter is also the speed of positioning moves (Nanotec o, EMIS #E1): a program
    // reads it before its first G1 and writes it back before a G0 and at its end.
    bool feedRateSetsRapid = false;
    // The feed-rate parameter is written for every axis of the controller at once (E-LAB
    // SetFeedSpeed <FS> carries X, Y and Z in one frame): a G1 writes a rate for each.
    bool feedRateWholeSet = false;
    // A G1 over several axes moves the tool along the line at F (issue 30, LinuxCNC's
    // meaning): each axis gets the share of F its distance has of the path
    // (program/CoordinatedFeed), so all arrive together. False: each axis at F (E-LAB blocks of
    // their own; its contours coordinate by their stream).
    bool coordinatedFeed = false;
    // A global boolean parameter that makes the axes of one move arrive together (EMIS IP1,
    // 9.12): a program writes it on before its first coordinated G1 and puts the value the
    // adapter knew back at its end.
    const char* interpolationParameter = nullptr;
    // About how long after a move request the axes start (the set-up exchanges on the wire):
    // a feed move across controllers starts this far apart at worst, and the check's estimate
    // of its path error follows from it (issue 30). Nanotec: ten exchanges of about 6 ms
    // (mode, distance, direction, read back) before 'A'.
    double moveSetupSeconds = 0.005;
    // Contours as one step stream (issue 30, Controller::feedContour): a program's chain of
    // feed moves becomes step vectors, one per tick, the tick rate written as
    // feedRateParameter on every axis of the controller. contourTickBelow: the per-axis
    // parameter the tick rate must stay below (E-LAB: feed mode has no ramp, so the feed speed
    // is below the start speed); contourMaxTickRate: the ticks per second the wire carries
    // beside the polls.
    bool contourStream = false;
    const char* contourTickBelow = nullptr;
    double contourMaxTickRate = 0;
    // The parameter whose schema range is M3's S (E-LAB "spindle-rpm"); null: S is not
    // range-checked beyond the program's own 0..1000000.
    const char* spindleSpeedParameter = nullptr;
    // What the protocol's positions count: English data, shown through
    // QCoreApplication::translate("Units", positionUnit). Step counters count "steps"; the
    // laser motor-axis protocol's positions are plain numbers 0..99999 whose unit the axis
    // defines (its manual names none), so they are "units", never steps.
    const char* positionUnit = QT_TRANSLATE_NOOP("Units", "steps");

    bool has(MotionMode mode) const { return motionModes.contains(mode); }
};

} // namespace stepdeck
