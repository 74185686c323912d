// `stepdeck-cli --machine FILE COMMAND`: the machine commands through the core Machine, the
// per-controller commands on the controller --controller names (issue 19; docs/cli.md).
#include "CliMachineRun.h"
#include "../common/SignalPipe.h"
#include "CliProgramRun.h"
#include "CliText.h"
#include "machine/MachineFile.h"
#include "protocols/Registry.h"
#include <QFileInfo>

namespace stepdeck::cli {

namespace {
using MachineCommand = Outcome (*)(CliMachineSession&, const CliOptions&);

struct MachineCommandEntry
{
    const char* name;
    MachineCommand run;
};

const MachineCommandEntry kMachineCommands[] = {
    {"move", machineMove},      {"jog", machineJog},     {"home", machineHome},
    {"stop", machineStop},      {"panic", machinePanic}, {"status", machineStatus},
    {"run", machineRunProgram},
};

// The commands that need no controller at all run as without a machine.
bool needsNoController(const CliOptions& o)
{
    const QString& c = o.command;
    return c == QLatin1String("ports") || c == QLatin1String("models") ||
           (c == QLatin1String("machine") && !o.args.isEmpty());
}

MachineCommand machineCommand(const QString& name)
{
    for (const MachineCommandEntry& entry : kMachineCommands) {
        if (name == QLatin1String(entry.name))
            return entry.run;
    }
    return nullptr;
}

// Exit 12 unreadable, 7 invalid: as `machine check`.
Outcome loadMachine(const QString& path, machine::MachineDescription* out)
{
    if (!QFileInfo(path).isReadable())
        return Outcome::failure(ExitFile, CliText::tr("cannot read %1").arg(path));
    machine::MachineFileError error;
    const std::optional<machine::MachineDescription> m = machine::MachineFile::load(path, &error);
    if (!m)
        return Outcome::failure(
            ExitInvalidValue, CliText::tr("%1: %2").arg(QFileInfo(path).fileName(), error.text()));
    *out = *m;
    return Outcome::success();
}

// The options of the one controller a per-controller command talks to.
Outcome controllerOptions(const CliOptions& o, const machine::MachineDescription& d,
                          CliOptions* out)
{
    QStringList ids;
    for (const machine::MachineController& c : d.controllers)
        ids << c.id;
    QString id = o.controller;
    if (id.isEmpty() && d.controllers.size() == 1)
        id = d.controllers.constFirst().id;
    if (id.isEmpty())
        return Outcome::usage(CliText::tr("%1 talks to one controller: give --controller ID (this "
                                          "machine has %2)")
                                  .arg(o.command, ids.join(QStringLiteral(", "))));
    const machine::MachineController* c = d.controller(id);
    if (!c)
        return Outcome::usage(CliText::tr("--controller: the machine has no controller \"%1\" "
                                          "(it has %2)")
                                  .arg(id, ids.join(QStringLiteral(", "))));
    *out = o;
    out->machineFile.clear();
    out->controller.clear();
    out->model = c->modelId;
    out->port = c->port;
    out->axisAddresses = c->busAddresses;
    out->axisNames = c->axisNames;
    if (c->resetLine)
        out->resetLine = *c->resetLine;
    return Outcome::success();
}

int finish(const Outcome& outcome)
{
    if (!outcome.ok())
        printError(outcome.message);
    return outcome.code;
}

int runMachineCommand(const CliOptions& options, const machine::MachineDescription& d,
                      MachineCommand run)
{
    CliMachineSession session(options, d);
    const app::SignalPipe signalPipe([&session](int number) { session.signal(number); });
    Outcome outcome = run(session, options);
    if (session.interrupted()) {
        // Every controller stops at once; the line says whether all of them confirmed it.
        const bool connected = session.isConnected();
        const Outcome stopped = session.stopAll();
        const QString text =
            !connected     ? CliText::tr("interrupted")
            : stopped.ok() ? CliText::tr("interrupted: every controller acknowledged the stop")
                           : CliText::tr("interrupted: %1").arg(stopped.message);
        outcome = Outcome::failure(ExitInterrupted, text);
    }
    return finish(outcome);
}
// --model/--port without a file: a machine of that one controller, its axes under their
// controller names in steps (MachineDescription::singleController).
Outcome singleControllerMachine(const CliOptions& o, machine::MachineDescription* out)
{
    const ModelInfo* model = findModel(o.model);
    if (!model)
        return Outcome::usage(unknownModelText(o.model));
    QMap<Axis, int> addresses = o.axisAddresses;
    if (o.address)
        addresses.insert(Axis::X, *o.address);
    // Every drive of a bus by its name for move, jog, home and status (issue 32); a program
    // (run) addresses axes by letter, so only the first nine.
    const auto drives = o.command == QLatin1String("run")
                            ? machine::MachineDescription::DriveAxes::Letters
                            : machine::MachineDescription::DriveAxes::All;
    *out = machine::MachineDescription::singleController(*model, o.port, addresses, o.axisNames,
                                                         drives);
    if (model->capabilities.resetLine)
        out->controllers.first().resetLine = o.resetLine;
    return Outcome::success();
}
} // namespace

bool runsOnTheMachine(const CliOptions& o)
{
    // The controller's own reference operations stay with the controller (as --controller ID
    // on a machine file): EMIS' simultaneous run, a closed-loop drive's reference.
    if (o.command == QLatin1String("home") && (o.flag("simultaneous") || o.flag("closed-loop")))
        return false;
    return machineCommand(o.command) != nullptr;
}

int runOneControllerMachine(const CliOptions& options)
{
    machine::MachineDescription d;
    if (const Outcome built = singleControllerMachine(options, &d); !built.ok())
        return finish(built);
    return runMachineCommand(options, d, machineCommand(options.command));
}

int runWithMachine(const CliOptions& options)
{
    if (needsNoController(options))
        return runSingleController(options);
    machine::MachineDescription d;
    if (const Outcome loaded = loadMachine(options.machineFile, &d); !loaded.ok())
        return finish(loaded);
    if (options.command == QLatin1String("machine")) {
        if (options.json)
            printJson(d.toJson());
        else
            printMachineTable(d);
        return ExitOk;
    }
    // `status --controller ID`: that controller's own status (raw words, drive rows).
    const bool controllerStatus =
        options.command == QLatin1String("status") && !options.controller.isEmpty();
    if (const MachineCommand run = machineCommand(options.command);
        run && !controllerStatus && runsOnTheMachine(options)) {
        if (!options.controller.isEmpty())
            return finish(Outcome::usage(
                CliText::tr("%1 takes the machine's axes by name; --controller is for the "
                            "per-controller commands")
                    .arg(options.command)));
        return runMachineCommand(options, d, run);
    }
    CliOptions single;
    if (const Outcome resolved = controllerOptions(options, d, &single); !resolved.ok())
        return finish(resolved);
    return runSingleController(single);
}

} // namespace stepdeck::cli
