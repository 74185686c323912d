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
    std::function<void(Simulator*)> halt;               // stops everything at the device
};

// The models a soak covers; adding one is one line in SoakModels.cpp.
const QList<SoakModel>& soakModels();
const SoakModel* findSoakModel(const QString& id);

} // namespace stepdeck::bench
