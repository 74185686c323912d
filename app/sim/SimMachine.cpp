#include "SimMachine.h"
#include "../common/SignalPipe.h"
#include "machine/MachineFile.h"
#include "machine/MachineSimulation.h"
#include "protocols/Registry.h"
#include "sim/PtyEndpoint.h"
#include "sim/Simulator.h"
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonDocument>
#include <cstdio>
#include <memory>
#include <vector>

namespace stepdeck::simapp {

namespace {
void printLine(FILE* stream, const QByteArray& bytes)
{
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stream);
    std::fputc('\n', stream);
    std::fflush(stream);
}

// One controller of the machine: its simulator on its own pseudo-terminal.
struct SimulatedController
{
    std::unique_ptr<PtyEndpoint> endpoint;
    std::unique_ptr<Simulator> simulator;

    ~SimulatedController() { simulator.reset(); } // before the endpoint it is attached to
};

// With --machine the file names the models and bus addresses; only the options that make
// sense for every controller at once apply (to each of them).
QString refusedWithMachine(const SimScenario& s)
{
    if (!s.model.isEmpty())
        return QStringLiteral("--model");
    if (!s.drives.isEmpty())
        return QStringLiteral("--drives");
    if (s.machine.used() & ~ScenarioOptions(ScenarioOption::SetupComplete))
        return SimText::tr("the model's machine options (--limit, --position, \u2026)");
    return {};
}

bool startController(const SimScenario& scenario, const machine::MachineDescription& description,
                     const machine::MachineController& controller, quint32 seed,
                     SimulatedController* out, QString* error)
{
    const ModelInfo* model = findModel(controller.modelId);
    if (!model->createSimulator) {
        *error = SimText::tr("controller %1: model %2 has no simulator")
                     .arg(controller.id, controller.modelId);
        return false;
    }
    SimulatorOptions options;
    options.addresses = controller.busAddresses.values();
    options.paceOutput = scenario.pace;
    options.line = model->line;
    options.seed = seed;
    out->simulator.reset(model->createSimulator(options));
    // The machine of the file (reference switches where its runs search), as the built-in
    // simulators of port "sim" get it (machine::simulatorScenarioOf).
    SimScenario setup;
    setup.machine = machine::simulatorScenarioOf(description, controller.id, model->capabilities);
    if (machine::simulatorTakes(*model, setup.machine) &&
        !applyScenario(setup, *model, out->simulator.get(), error))
        return false;
    if (scenario.machine.setupComplete &&
        model->scenario.options.testFlag(ScenarioOption::SetupComplete)) {
        SimScenario complete;
        complete.machine.setupComplete = true;
        if (!applyScenario(complete, *model, out->simulator.get(), error))
            return false;
    }
    applyFaults(scenario, out->simulator.get());
    out->endpoint = std::make_unique<PtyEndpoint>();
    if (!out->endpoint->create(error))
        return false;
    QObject::connect(
        out->endpoint.get(), &Transport::failed, [id = controller.id](const QString& why) {
            printLine(stderr, SimText::tr("stepdeck-sim: controller %1: %2").arg(id, why).toUtf8());
            QCoreApplication::exit(1);
        });
    out->endpoint->open(model->line);
    out->simulator->attach(out->endpoint.get());
    return true;
}

int fail(const QString& message, int code)
{
    printLine(stderr, QStringLiteral("stepdeck-sim: %1").arg(message).toUtf8());
    return code;
}
} // namespace

int runMachine(const SimScenario& scenario)
{
    const QString refused = refusedWithMachine(scenario);
    if (!refused.isEmpty())
        return fail(SimText::tr("%1 cannot be combined with --machine (the file names the "
                                "models and bus addresses)")
                        .arg(refused),
                    2);
    // The CLI's exit codes for machine files: 12 unreadable, 7 invalid.
    if (!QFileInfo(scenario.machineFile).isReadable())
        return fail(SimText::tr("cannot read %1").arg(scenario.machineFile), 12);
    machine::MachineFileError invalid;
    std::optional<machine::MachineDescription> description =
        machine::MachineFile::load(scenario.machineFile, &invalid);
    if (!description)
        return fail(QStringLiteral("%1: %2").arg(QFileInfo(scenario.machineFile).fileName(),
                                                 invalid.text()),
                    7);

    std::vector<std::unique_ptr<SimulatedController>> controllers;
    for (int i = 0; i < description->controllers.size(); ++i) {
        machine::MachineController& controller = description->controllers[i];
        auto simulated = std::make_unique<SimulatedController>();
        QString error;
        if (!startController(scenario, *description, controller, scenario.seed + quint32(i),
                             simulated.get(), &error))
            return fail(error, 1);
        controller.port = simulated->endpoint->slavePath();
        controllers.push_back(std::move(simulated));
    }

    // The copy lives elsewhere: its setup files by their absolute paths.
    machine::MachineFile::anchorSetupFiles(&*description, scenario.machineFile);
    const QJsonDocument copy(description->toJson());
    QString error;
    if (!scenario.machineOut.isEmpty() &&
        !machine::MachineFile::save(*description, scenario.machineOut, &error))
        return fail(error, 1);
    printLine(stdout, copy.toJson(QJsonDocument::Compact)); // first line: the contract
    for (const machine::MachineController& c : description->controllers)
        printLine(stderr,
                  SimText::tr("stepdeck-sim: %1 (%2) on %3").arg(c.id, c.modelId, c.port).toUtf8());
    printLine(stderr, SimText::tr("stepdeck-sim: machine '%1' ready; SIGINT/SIGTERM to quit")
                          .arg(description->name)
                          .toUtf8());

    const stepdeck::app::SignalPipe signalPipe([](int) { QCoreApplication::quit(); });
    return QCoreApplication::exec();
}

} // namespace stepdeck::simapp
