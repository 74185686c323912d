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
};

// Runs options.command; the caller prints the outcome's message and exits with its code.
Outcome runCommand(CliContext& context);

// Every writable parameter at its schema default, per-axis ones for each axis of the model.
ParameterSet schemaDefaults(const ModelInfo& model);
// Writes the set; verifies by read-back where the model can read any of it.
Outcome writeParameters(CliContext& context, const ParameterSet& set);

// Handlers, grouped by file. Each takes the command's own arguments.
Outcome cmdPorts(CliContext& c, QStringList args);
Outcome cmdModels(CliContext& c, QStringList args);
Outcome cmdParams(CliContext& c, QStringList args);
Outcome cmdStatus(CliContext& c, QStringList args);

Outcome cmdSet(CliContext& c, QStringList args);
Outcome cmdGet(CliContext& c, QStringList args);
Outcome cmdExport(CliContext& c, QStringList args);
Outcome cmdImport(CliContext& c, QStringList args);

Outcome cmdMove(CliContext& c, QStringList args);
Outcome cmdJog(CliContext& c, QStringList args);
Outcome cmdHome(CliContext& c, QStringList args);
Outcome cmdVelocity(CliContext& c, QStringList args);
Outcome cmdFeed(CliContext& c, QStringList args);
Outcome cmdStop(CliContext& c, QStringList args);
Outcome cmdPanic(CliContext& c, QStringList args);
Outcome cmdReset(CliContext& c, QStringList args);
Outcome cmdSpindle(CliContext& c, QStringList args);
Outcome cmdCoolant(CliContext& c, QStringList args);
Outcome cmdPower(CliContext& c, QStringList args);

} // namespace stepdeck::cli
