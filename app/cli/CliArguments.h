#pragma once
#include "CliOutput.h"
#include "model/AxisNames.h"
#include "model/LineSettings.h"
#include <QList>
#include <QMap>
#include <QStringList>
#include <optional>

namespace stepdeck::cli {

// An option of one command (`move --abs`, `jog --for MS`). valueName is null for a flag.
struct CommandOption
{
    const char* name;
    const char* valueName = nullptr;
};

// What the parser knows of a command: its name and its own options. Everything else after
// the command name is the command's positional arguments.
struct CommandSyntax
{
    const char* name;
    QList<CommandOption> options;
};

// The command line: global options (accepted before or after the command), the command, its
// positional arguments and the options of its own it was given.
struct CliOptions
{
    QString model; // parseArguments() starts from the first registered model (E-LAB)
    QString port = QStringLiteral("sim");
    bool modelOrPortGiven = false; // --model or --port on the command line
    QString machineFile;           // --machine FILE: the machine path (CliMachineRun.cpp)
    QString controller;            // --controller ID: per-controller commands on a machine
    std::optional<int> address;    // --address N: X=N for a single-drive model
    QMap<Axis, int> axisAddresses; // --axes X=1,Y=2,Z=3 or feeder=5,gate=6
    AxisNames axisNames;           // the names --axes gave (issue 32)
    bool json = false;
    bool setupDefaults = false;
    bool verbose = false;
    bool help = false;
    bool version = false;
    int connectTimeoutMs = 3000;
    // --reset-line rts|dtr: the modem line wired to the board's reset input (E-LAB).
    LineSettings::ResetLine resetLine = LineSettings::ResetLine::Rts;
    int arrivalTimeoutMs = 60000; // --arrival-timeout: models that report arrival (laser-axis)
    QString command;
    QStringList args;                      // the command's positional arguments
    QMap<QString, QString> commandOptions; // its own options: name -> value (empty for a flag)

    bool flag(const char* name) const { return commandOptions.contains(QLatin1String(name)); }
    std::optional<QString> value(const char* name) const;
};

// arguments as QCoreApplication::arguments() gives them (program name first), parsed with
// QCommandLineParser: first the global options up to the command name, then the rest with
// the global options plus the command's own (where a name is both, as `move --timeout MS`,
// the command's wins after the command). Returns false with a one-line reason on a usage
// error: unknown command or option, a missing or malformed option value.
bool parseArguments(const QStringList& arguments, const QList<CommandSyntax>& commands,
                    CliOptions* options, QString* error);

QString usageText();
// "unknown command 'stauts' (did you mean status?)": the nearest command name, when one is
// close (NearestName.h); else a pointer to --help.
QString unknownCommandText(const QString& name, const QList<CommandSyntax>& commands);

// --- the commands' AXIS=VALUE arguments (CliAxisArguments.cpp) ---

// "X=N Y=N" -> per-axis integers (decimal, NumberParsing.h). Axes must belong to `axes`, none
// twice, at least one. A failure's message starts with `command`; a malformed or non-finite
// number ("abc", "0x40", "nan", "inf") is a usage error (exit 2), a decimal number beyond
// what the type holds an invalid value (exit 7). An axis goes by its name in `names`
// ("feeder=100") or its default name.
Outcome parseAxisIntegers(const QString& command, const QStringList& args, const QList<Axis>& axes,
                          AxisVector* out, const AxisNames& names = {});
// The same for decimal rates ("X=-1500.5", "Y=1e3").
Outcome parseAxisDoubles(const QString& command, const QStringList& args, const QList<Axis>& axes,
                         AxisVelocities* out, const AxisNames& names = {});
// "X=1,Y=2,Z=3" or "feeder=5,gate=6" (the --axes list; assignBusAxes says which axis each name
// is). Only the syntax and the names are checked here; which addresses a bus allows is the
// model's (Capabilities::minBusAddress..maxBusAddress), checked when the controller is created.
bool parseAxisMap(const QString& text, QMap<Axis, int>* addresses, AxisNames* names,
                  QString* error);

} // namespace stepdeck::cli
