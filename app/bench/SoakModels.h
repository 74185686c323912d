#pragma once
#include "model/Axis.h"
#include "model/ParameterSchema.h"
#include "sim/Simulator.h"
#include <functional>

namespace stepdeck::bench {

// One move the simulated device accepted, on one axis.
struct DeviceMove
{
    Axis axis;
    qint64 steps;
};

// What the soak and replug runs need to know about a model beyond the Registry: how to set up
// its simulator, what the device is doing right now, and which moves it accepted. Every probe
// runs in the device thread on the model's own Simulator subclass.
struct SoakModel
{
    QString id;
    SimulatorOptions simulator;
    ParameterSet setup;   // written at the start of every session
    QStringList readable; // parameters `get` reads back (empty: none can be)
    // Model operations an operator runs per axis after a refused move, e.g. Nanotec
    // "reset-position-error" after an abrupt stop lost steps (5.14).
    QStringList recovery;
    std::function<void(Simulator*)> prepare;            // once, before the first session
    std::function<QList<Axis>(Simulator*)> movingAxes;  // axes in motion at the device
    std::function<QList<DeviceMove>(Simulator*)> moves; // accepted so far, in order
    // Stops everything at the device. For models whose protocol has no stop command
    // (Capabilities::stopCommand false: EMIS, laser axes) this is the machine's emergency stop,
    // i.e. what an operator would press; the soak uses it only where the figures say so.
    std::function<void(Simulator*)> halt;
    bool stopCommand = true; // Capabilities::stopCommand, known also while disconnected
    // Absolute targets the host sends at the start of every session, or empty: the laser
    // axes report their position only in a status frame after a command, so the host first
    // sends each axis to where it stands (a zero-length move the device journal leaves out).
    std::function<AxisVector(Simulator*)> anchor;
};

// The models a soak covers; adding one is one line in SoakModels.cpp.
const QList<SoakModel>& soakModels();
const SoakModel* findSoakModel(const QString& id);

} // namespace stepdeck::bench
