#pragma once
#include "model/Capabilities.h"
#include "model/LineSettings.h"
#include "model/ModelPresentation.h"
#include "model/ParameterSchema.h"
#include "model/SimulatorScenario.h"
#include <functional>
#include <memory>

class QLoggingCategory;

namespace stepdeck {

// Only named here: the descriptor sits on the lowest floor, what it creates above it.
class Controller;
class Simulator;
class Transport;
class TrafficMeter;
struct ControllerOptions;
struct SimulatorOptions;

// What a model's simulator supports of a SimulatorScenario (stepdeck-sim's machine options).
struct ScenarioSupport
{
    ScenarioOptions options; // what apply() understands; stepdeck-sim refuses the rest
    // Applies the supported parts to a fresh simulator that is not attached yet (its replies to
    // any setup commands go nowhere). Called only with options it supports and axes the model
    // has (Capabilities::axes). False, with *error, for a scenario the simulator cannot take
    // (e.g. a drive address it does not simulate).
    std::function<bool(const SimulatorScenario&, Simulator*, QString* error)> apply;
};

// How stepdeck-bench --soak and --replug drive the model's simulator (app/bench/Soak.cpp).
// What the device does is asked through the Simulator's own probes (isMoving, acceptedMoves,
// position, emergencyStop).
struct SoakProfile
{
    QList<int> simulatorAddresses; // bus addresses of the simulated drives (multi-drive models)
    ParameterSet setup;            // written at the start of every session
    QStringList readable;          // parameters `get` reads back (empty: none can be)
    // Model operations (model/ModelOperations.h) an operator runs per axis after a refused
    // move, e.g. Nanotec kResetPositionError after an abrupt stop lost steps (5.14).
    QStringList recovery;
    // Once, before the first session: e.g. switches out of the soak's reach.
    std::function<void(Simulator*)> prepare;
    // The host first sends each axis to where it stands (Simulator::position): the device
    // reports positions only after a command (laser axes).
    bool anchorPositions = false;
};

// What stepdeck-bench's stream figures (panic latency behind a queued stream, feed throughput)
// need from a model with MotionMode::FeedStream. Models without it are not measured.
struct StreamBenchProfile
{
    // Counts, in the bytes the device receives, the stream's single steps and the first panic
    // and stop commands.
    std::function<std::unique_ptr<TrafficMeter>()> createMeter;
    // A step buffer larger than any stream: the device never holds the host back, so the feed
    // figure is what the link delivers.
    std::function<void(Simulator*)> unlimitBuffer;
    // True while the device holds the host back with its flow control (E-LAB: XOFF).
    std::function<bool(Simulator*)> hostPaused;

    bool supported() const { return createMeter && unlimitBuffer && hostPaused; }
};

// A model's own rules for a parameter write (ModelInfo::parameterRules): set is what is
// written, known what the device holds as far as the host knows; returns why the write would be
// refused, or empty.
using ParameterRules = std::function<QString(const ParameterSchema&, const ParameterSet& set,
                                             const ParameterSet& known)>;

// Everything the application knows about one controller model. Adding a model means its
// folder under core/protocols/<model>/ plus one line in core/protocols/Registry.cpp; the
// folder's <Model>Model.cpp fills this and describeModel() adds the factories.
struct ModelInfo
{
    QString id;          // "elab", "nanotec", ...: the only place a model's id is written
    QString displayName; // "E-LAB 3-axis stepper controller" (English; see ui modelDisplayName)
    LineSettings line;
    Capabilities capabilities;
    ParameterSchema schema;
    // Parameters the device wants written before it moves at all (E-LAB: tmInvSetup until the
    // ramp is written); tests and benchmarks write their schema defaults first.
    QStringList setupBeforeMotion;
    std::function<Controller*(Transport*, const ControllerOptions&)> createController;
    std::function<Simulator*(const SimulatorOptions&)> createSimulator;
    // The model's own rules for a parameter write beyond the schema's ranges, pure: the
    // adapter applies them when it writes, and a program's check asks them first (issue 28).
    // set: what is written; known: what the device holds as far as the host knows
    // (MachineStatus::knownParameters). Returns why the write would be refused, or empty.
    // Null: the schema's ranges are the only rule.
    ParameterRules parameterRules;
    ScenarioSupport scenario;
    SoakProfile soak;
    StreamBenchProfile streamBench; // empty unless the model streams (FeedStream)
    // How the UI shows this model's raw words and traffic (optional members; see
    // model/ModelPresentation.h). The UI never interprets bytes itself.
    ModelPresentation presentation;
    // The model's own logging category ("stepdeck.<model>"), declared in its folder.
    const QLoggingCategory& (*logging)() = nullptr;
};

// Adds the factories of a model whose controller takes (Transport*, const ControllerOptions&)
// and whose simulator takes (const SimulatorOptions&): the one place they are written.
// Instantiated in the model's folder, where both types are complete.
template <typename ControllerType, typename SimulatorType> ModelInfo describeModel(ModelInfo info)
{
    info.createController = [](Transport* transport,
                               const ControllerOptions& options) -> Controller* {
        return new ControllerType(transport, options);
    };
    info.createSimulator = [](const SimulatorOptions& options) -> Simulator* {
        return new SimulatorType(options);
    };
    return info;
}

} // namespace stepdeck
