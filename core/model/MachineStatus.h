#pragma once
#include "Axis.h"
#include "ParameterSchema.h"
#include <QJsonObject>
#include <QMetaType>
#include <QVariantMap>
#include <optional>

namespace stepdeck {

// The switch an axis last reported stopping at, on models that report events rather than
// switch levels (laser motor axes: end switch = Limit, home switch = Reference).
enum class SwitchEvent : quint8 { None, Limit, Reference };

// Normalised per-axis status. Every model maps its own status words onto this.
struct AxisStatus
{
    bool moving = false;            // positioning, feed, reference or velocity move running
    bool jogging = false;           // in jog mode with a non-zero rate
    bool limitSwitch = false;       // a limit switch of this axis is active
    bool referenceSwitch = false;   // the reference switch of this axis is active
    bool referenced = false;        // referenced since the last panic, reset or reconnect
    bool positionKnown = false;     // false until referenced (or set by the operator)
    bool positionEstimated = false; // integrated from jog/velocity rates, not confirmed
    qint64 position = 0;            // steps, host-side bookkeeping unless the model reads it back
    double commandedVelocity = 0;   // steps/s the host currently commands (jog ramp output)
    // No fresh status for this axis (its drive stopped answering): moving/jogging are the last
    // known values and the axis may be moving. Never shown as idle.
    bool motionUnknown = false;
    SwitchEvent lastSwitch = SwitchEvent::None;
};

// One drive on the link (E-LAB: the board; Nanotec: one bus address per axis).
struct DriveStatus
{
    int address = 0;
    QList<Axis> axes;
    bool responding = true;
    QString firmware;
    QString detail; // model-specific plain-words state ("ready", "position error", ...)
};

struct MachineStatus
{
    bool driveOn = false;
    bool spindleOn = false;
    bool busy = false;
    bool overTemperature = false;
    bool setupIncomplete = false;
    bool panic = false;     // emergency stop active (button or host panic not yet cleared)
    bool commFault = false; // link lost or replies missing
    // The host stopped tracking a motion without the device confirming standstill (link lost,
    // stop not acknowledged, a model without a stop command): the machine may still be moving.
    // Cleared only by a status read from the device that shows every axis standing still.
    bool motionUnconfirmed = false;
    // Digital I/O of the controller (Capabilities::digitalInputs / digitalOutputs), input 1
    // first. Inputs as last read; outputs as the host last switched them in this session
    // (nullopt: unknown, e.g. after connecting), and the controller's own firmware string.
    std::optional<QList<bool>> inputs;
    QList<std::optional<bool>> outputs;
    QString deviceFirmware;
    std::optional<bool> startButton;
    std::optional<bool> doorOpen; // door switch, where the model reports one (laser status 3/4)
    std::optional<double> temperatureCelsius;
    QMap<Axis, AxisStatus> axes;
    QList<DriveStatus> drives;
    // The parameter values the host knows the device holds: written and acknowledged in this
    // session, or read back; emptied when the device lost them (E-LAB power cycle or reset).
    // A program's check judges the model's parameter rules against these (ProgramRules), as
    // the adapter does when the run writes (issue 28).
    ParameterSet knownParameters;
    QVariantMap raw; // the model's raw words, e.g. {"machineState":128,"axeState":5}
    quint64 resyncCount = 0;
    quint64 commFaultCount = 0;

    bool anyLimitSwitch() const;
    bool anyMoving() const;
    // The JSON contract of `stepdeck-cli status --json` (see issue #2, section 5).
    QJsonObject toJson(const QString& modelId) const;
};

} // namespace stepdeck

Q_DECLARE_METATYPE(stepdeck::MachineStatus)
