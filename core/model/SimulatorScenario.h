#pragma once
#include "model/Axis.h"
#include <QFlags>
#include <QMap>
#include <optional>

namespace stepdeck {

// What a simulated machine looks like before the first byte arrives (stepdeck-sim's
// --setup-complete, --temperature, --limit, ...). Pure data: each model's descriptor says which
// parts its simulator supports (ModelInfo::scenario) and applies them.
enum class ScenarioOption {
    SetupComplete = 0x01,   // the board's setup already written
    Temperature = 0x02,     // board temperature
    Limits = 0x04,          // limit switches at positions
    Positions = 0x08,       // where the carriages stand at power-on
    Speed = 0x10,           // axis speed in position units per second
    EndSwitches = 0x20,     // an end switch per axis
    Silent = 0x40,          // the device never reports by itself
    Garbage = 0x80,         // a malformed line before every report
    NoEncoder = 0x100,      // drives without encoder (closed loop, Nanotec manual 8.1)
    CalibrationMs = 0x200,  // how long a closed-loop calibration run takes
    Inputs = 0x400,         // digital inputs the operator's machine sets (a part sensor)
    ReferenceSides = 0x800, // on which side of the power-on position a reference switch sits
};
Q_DECLARE_FLAGS(ScenarioOptions, ScenarioOption)
Q_DECLARE_OPERATORS_FOR_FLAGS(ScenarioOptions)

struct SwitchRange
{
    qint64 minimum = 0;
    qint64 maximum = 0;
};

struct SimulatorScenario
{
    bool setupComplete = false;
    std::optional<int> temperature;
    QMap<Axis, SwitchRange> limits;
    QMap<Axis, qint64> positions;
    std::optional<double> speed;
    QMap<Axis, qint64> endSwitches;
    bool silent = false;
    bool garbage = false;
    QList<int> drivesWithoutEncoder; // bus addresses
    std::optional<int> calibrationMs;
    QMap<int, bool> inputs; // input number (the controller's, from 1) -> level
    // Axis -> -1 or +1: its reference switch lies in that direction from where the carriage
    // stands at power-on, so a reference run in that direction finds it (a machine file's
    // reference.direction; the distance is the simulator's own, docs/machines.md).
    QMap<Axis, int> referenceSides;

    // The options this scenario asks for.
    ScenarioOptions used() const
    {
        ScenarioOptions out;
        out.setFlag(ScenarioOption::SetupComplete, setupComplete);
        out.setFlag(ScenarioOption::Temperature, temperature.has_value());
        out.setFlag(ScenarioOption::Limits, !limits.isEmpty());
        out.setFlag(ScenarioOption::Positions, !positions.isEmpty());
        out.setFlag(ScenarioOption::Speed, speed.has_value());
        out.setFlag(ScenarioOption::EndSwitches, !endSwitches.isEmpty());
        out.setFlag(ScenarioOption::Silent, silent);
        out.setFlag(ScenarioOption::Garbage, garbage);
        out.setFlag(ScenarioOption::NoEncoder, !drivesWithoutEncoder.isEmpty());
        out.setFlag(ScenarioOption::CalibrationMs, calibrationMs.has_value());
        out.setFlag(ScenarioOption::Inputs, !inputs.isEmpty());
        out.setFlag(ScenarioOption::ReferenceSides, !referenceSides.isEmpty());
        return out;
    }
    // Every axis the scenario names.
    QList<Axis> axes() const
    {
        QList<Axis> out = limits.keys();
        for (const QMap<Axis, qint64>* map : {&positions, &endSwitches}) {
            for (Axis a : map->keys()) {
                if (!out.contains(a))
                    out << a;
            }
        }
        for (Axis a : referenceSides.keys()) {
            if (!out.contains(a))
                out << a;
        }
        return out;
    }
};

} // namespace stepdeck
