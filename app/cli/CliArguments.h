#pragma once
#include "CliOutput.h"
#include "model/Axis.h"
#include "model/LineSettings.h"
#include <QStringList>
#include <optional>

namespace stepdeck::cli {

// The command line split into global options (accepted before or after the command) and the
// command with its own arguments and options (--abs, --no-wait, --for MS stay in `args`).
struct CliOptions
{
    QString model = QStringLiteral("elab");
    QString port = QStringLiteral("sim");
    std::optional<int> address;    // --address N: X=N for a single-drive model
    QMap<Axis, int> axisAddresses; // --axes X=1,Y=2,Z=3
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
    QStringList args;
};

// argv without the program name. Returns false with a one-line reason on a usage error.
bool parseArguments(const QStringList& argv, CliOptions* options, QString* error);

QString usageText();

// --- helpers for the commands' own arguments ---

// Removes a flag ("--abs") from args; true if it was there.
bool takeFlag(QStringList* args, const QString& flag);
// Removes "--for MS" / "--for=MS"; std::nullopt when absent. *error is set when malformed.
std::optional<QString> takeOption(QStringList* args, const QString& option, QString* error);
// Any leftover "--something" is a usage error.
QString unknownOption(const QStringList& args);

// "X=N Y=N" -> per-axis integers (decimal, NumberParsing.h). Axes must belong to `axes`, none
// twice, at least one. A failure's message starts with `command`; a malformed or non-finite
// number ("abc", "0x40", "nan", "inf") is a usage error (exit 2), a decimal number beyond
// what the type holds an invalid value (exit 7).
Outcome parseAxisIntegers(const QString& command, const QStringList& args, const QList<Axis>& axes,
                          AxisVector* out);
// The same for decimal rates ("X=-1500.5", "Y=1e3").
Outcome parseAxisDoubles(const QString& command, const QStringList& args, const QList<Axis>& axes,
                         AxisVelocities* out);
// "X=1,Y=2,Z=3" (the --axes map).
bool parseAxisMap(const QString& text, QMap<Axis, int>* out, QString* error);

} // namespace stepdeck::cli
