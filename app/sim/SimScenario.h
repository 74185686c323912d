#pragma once
#include "model/Axis.h"
#include <QCoreApplication>
#include <QStringList>
#include <optional>

namespace stepdeck {
class Simulator;
}

namespace stepdeck::simapp {

// The texts of stepdeck-sim (English: the program installs no translator).
class SimText
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::simapp::SimText)
};

struct LimitRange
{
    qint64 minimum = 0;
    qint64 maximum = 0;
};

// Machine state a test or a demo wants before the first byte arrives.
struct SimScenario
{
    QString model = QStringLiteral("elab");
    QList<int> drives;
    bool pace = false;
    bool setupComplete = false;
    std::optional<int> temperature;
    QMap<Axis, LimitRange> limits;
    QMap<Axis, qint64> positions;
    // Faults (issue 12), reproducible through the seed.
    double dropProbability = 0;
    double corruptProbability = 0;
    double noiseBytesPerSecond = 0;
    qint64 freezeAfterMs = -1;
    quint32 seed = 1;
    // laser-axis: speed in units/s, end switch positions, faults
    std::optional<double> speed;
    QMap<Axis, qint64> endSwitches;
    bool silent = false;
    bool garbage = false;
    // nanotec: drives without encoder, duration of a calibration run (manual 8.1)
    QList<int> noEncoder;
    std::optional<int> calibrationMs;
    bool help = false;
    bool version = false;
};

bool parseScenario(const QStringList& args, SimScenario* scenario, QString* error);
QString simUsage();

// Applies the model-specific parts (setup, temperature, limits, positions) to a fresh
// simulator that is not attached yet: its replies to the setup commands go nowhere.
// Returns false and says why when the model does not support an option.
bool applyScenario(const SimScenario& scenario, Simulator* simulator, QString* error);
// Switches the scenario's faults on. Call after applyScenario(), so that the setup replies
// neither draw random faults nor start the freeze clock.
void applyFaults(const SimScenario& scenario, Simulator* simulator);

} // namespace stepdeck::simapp
