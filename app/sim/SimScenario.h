#pragma once
#include "model/Axis.h"
#include <QStringList>
#include <optional>

namespace stepdeck {
class Simulator;
}

namespace stepdeck::simapp {

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
    bool help = false;
    bool version = false;
};

bool parseScenario(const QStringList& args, SimScenario* scenario, QString* error);
QString simUsage();

// Applies the model-specific parts (setup, temperature, limits, positions) to a fresh
// simulator that is not attached yet: its replies to the setup commands go nowhere.
// Returns false and says why when the model does not support an option.
bool applyScenario(const SimScenario& scenario, Simulator* simulator, QString* error);

} // namespace stepdeck::simapp
