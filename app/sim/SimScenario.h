#pragma once
#include "model/ModelInfo.h"
#include <QCoreApplication>
#include <QStringList>

namespace stepdeck {
class Simulator;
}

namespace stepdeck::simapp {

// The texts of stepdeck-sim (English: the program installs no translator).
class SimText
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::simapp::SimText)
};

// What stepdeck-sim was asked for: the model, the simulator's options, the machine before the
// first byte (applied by the model's own ModelInfo::scenario) and the faults.
struct SimScenario
{
    QString model; // empty: the first registered model
    QList<int> drives;
    bool pace = false;
    SimulatorScenario machine;
    // Faults (issue 12), reproducible through the seed.
    double dropProbability = 0;
    double corruptProbability = 0;
    double noiseBytesPerSecond = 0;
    qint64 freezeAfterMs = -1;
    quint32 seed = 1;
    QString machineFile; // --machine: a simulator per controller of this file
    QString machineOut;  // --out: where to write the copy whose ports point at them
    bool help = false;
    bool version = false;
};

bool parseScenario(const QStringList& args, SimScenario* scenario, QString* error);
QString simUsage();

// Applies the machine options to a fresh simulator of `model` that is not attached yet: its
// replies to any setup commands go nowhere. Returns false and says why when the model does
// not support an option or has no such axis.
bool applyScenario(const SimScenario& scenario, const ModelInfo& model, Simulator* simulator,
                   QString* error);
// Switches the scenario's faults on. Call after applyScenario(), so that the setup replies
// neither draw random faults nor start the freeze clock.
void applyFaults(const SimScenario& scenario, Simulator* simulator);

} // namespace stepdeck::simapp
