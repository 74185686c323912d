#pragma once
#include "CliOutput.h"
#include "CliSession.h"
#include "protocols/Registry.h"

namespace stepdeck::cli {

// What every command handler gets: the parsed options, the model (nullptr only for the
// commands that need none), and the session, connected on demand by connect().
struct CliContext
{
    const CliOptions& options;
    const ModelInfo* model = nullptr;
    CliSession& session;
    bool setupWritten = false;

    // Opens the link (once) and, with --setup-defaults, writes the schema defaults.
    Outcome connect();
    bool json() const { return options.json; }
    // The controller's capabilities and axes. runCommand() creates the stack (no I/O) before
    // a command that needs a model runs, so these follow the axis map (--address, --axes).
    Capabilities capabilities() const { return session.capabilities(); }
    QList<Axis> axes() const { return session.capabilities().axes; }
};

// Every command with its own options, for parseArguments().
QList<CommandSyntax> commandSyntax();

// Runs options.command; the caller prints the outcome's message and exits with its code.
Outcome runCommand(CliContext& context);

// Every writable parameter at its schema default, per-axis ones for each of `axes`.
ParameterSet schemaDefaults(const ModelInfo& model, const QList<Axis>& axes);
// What --setup-defaults writes: the schema's defaults without the parameters that carry a
// warning (Nanotec motor-address: the drive moves to the default address; closed-loop motor
// data: over-speed), which are never written behind the user's back.
ParameterSet unattendedDefaults(const ModelInfo& model, const QList<Axis>& axes);
// Writes the set. With verify, every value is read back afterwards (issue 4: drives may echo
// a value and ignore it) -- but only when every parameter in the set is readable; a model
// that cannot read back (E-LAB) just writes.
Outcome writeParameters(CliContext& context, const ParameterSet& set, bool verify = true);
// True when every parameter of set can be read back, so a write can be verified.
bool canVerify(const ModelInfo& model, const ParameterSet& set);

// Handlers, grouped by file. Each takes the command's positional arguments; its own options
// (commandSyntax()) are in context.options.
Outcome cmdPorts(CliContext& c, QStringList args);
Outcome cmdModels(CliContext& c, QStringList args);
Outcome cmdMachine(CliContext& c, QStringList args); // CliMachineCommands.cpp
Outcome cmdParams(CliContext& c, QStringList args);
Outcome cmdScan(CliContext& c, QStringList args);
Outcome cmdRecords(CliContext& c, QStringList args);
Outcome cmdResetPositionError(CliContext& c, QStringList args);

Outcome cmdSet(CliContext& c, QStringList args);
Outcome cmdGet(CliContext& c, QStringList args);
Outcome cmdExport(CliContext& c, QStringList args);
Outcome cmdImport(CliContext& c, QStringList args);

Outcome cmdHome(CliContext& c, QStringList args);
Outcome cmdVelocity(CliContext& c, QStringList args);
Outcome cmdFeed(CliContext& c, QStringList args);
Outcome cmdReset(CliContext& c, QStringList args);
Outcome cmdSpindle(CliContext& c, QStringList args);
Outcome cmdCoolant(CliContext& c, QStringList args);
Outcome cmdPower(CliContext& c, QStringList args);

// Stored system parameters, outputs and input programs (CliEmisCommands.cpp).
Outcome cmdStore(CliContext& c, QStringList args);
Outcome cmdGetStored(CliContext& c, QStringList args); // `get` on models with stored values
Outcome cmdOutput(CliContext& c, QStringList args);
Outcome cmdProgram(CliContext& c, QStringList args);
Outcome cmdLaserBridge(CliContext& c, QStringList args); // CliBridgeCommand.cpp

// The closed-loop workflow of encoder drives (CliClosedLoopCommands.cpp, model/ClosedLoop.h).
Outcome cmdClosedLoop(CliContext& c, QStringList args); // check, on, off, reset-error
Outcome cmdCalibrate(CliContext& c, QStringList args);
Outcome homeClosedLoop(CliContext& c, const QStringList& args); // `home --closed-loop`

} // namespace stepdeck::cli
