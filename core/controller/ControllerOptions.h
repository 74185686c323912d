#pragma once
#include "model/AxisNames.h"
#include "model/LineSettings.h"

namespace stepdeck {

struct ControllerOptions
{
    // Bus address per axis for multi-drive links (Nanotec: X=1,Y=2,Z=3). Empty: model default.
    QMap<Axis, int> axisAddresses;
    // The names the operator gave the axes ("feeder", "gate"; issue 32): shown and accepted
    // instead of the default names. Empty: every axis by its default name.
    AxisNames axisNames;
    int pollIntervalMs = 50;
    int missedPollsForLinkLoss = 3;
    int commandTimeoutMs = 500;
    // Models that report arrival (Capabilities::reportsArrival): how long a move or home waits
    // for it. Laser motor axes: "If the target-position is not reached within 60 seconds the
    // laser emits a timeout alarm."
    int arrivalTimeoutMs = 60000;
    int jogLeaseMs = 300;                 // a jog rate not renewed within this ramps to zero
    int jogTickMs = 20;                   // JogRamp update period
    double jogAccelerationStepsPerS2 = 0; // 0: the model's default
    // The modem line wired to the board's reset input (E-LAB: RTS by the manual's text, DTR by
    // its pin table); the other line is held de-asserted too.
    LineSettings::ResetLine resetLine = LineSettings::ResetLine::Rts;
    // How this front end lets the operator run a model operation (Controller::modelOperation
    // name -> words), for messages that say what to do next: the CLI names its command, the
    // GUI its button. Without an entry a message says it in neutral words (issue 16: the GUI
    // told operators to run `reset-position-error`, a CLI word).
    QMap<QString, QString> actionNames;
};

} // namespace stepdeck
