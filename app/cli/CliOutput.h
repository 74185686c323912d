#pragma once
#include "model/AxisNames.h"
#include "model/Capabilities.h"
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include "model/ParameterSchema.h"
#include <QJsonArray>
#include <QJsonObject>
#include <QString>

namespace stepdeck {
struct ModelInfo;
}

namespace stepdeck::cli {

// One exit code per cause, so scripts can branch without parsing stderr. Documented in --help
// (exitCodeHelp()) and docs/cli.md; keep the three in step.
enum ExitCode : int {
    ExitOk = 0,
    ExitFailure = 1,        // anything not listed below
    ExitUsage = 2,          // unknown command or option, malformed arguments, unknown model
    ExitRefused = 3,        // ErrorKind::Refused: not sent, the manual forbids it now
    ExitNak = 4,            // ErrorKind::Nak: the device said no (decoded status on stderr)
    ExitTimeout = 5,        // ErrorKind::Timeout: no reply in time
    ExitLinkDown = 6,       // ErrorKind::LinkDown: could not connect, or the link was lost
    ExitInvalidValue = 7,   // ErrorKind::InvalidValue: out of range or wrong type; not sent
    ExitUnsupported = 8,    // ErrorKind::Unsupported: the model cannot do this (e.g. read back)
    ExitProtocol = 9,       // ErrorKind::Protocol: malformed reply
    ExitCancelled = 10,     // ErrorKind::Cancelled: dropped by stop/panic/disconnect
    ExitVerifyFailed = 11,  // ErrorKind::VerifyFailed: written, read-back differs
    ExitFile = 12,          // a file could not be read or written, or is not JSON
    ExitMotionAborted = 13, // a move ended on a limit switch or an emergency stop
    ExitInterrupted = 130,  // SIGINT/SIGTERM: motion stopped, then quit
};

int exitCodeFor(ErrorKind kind);
QString exitCodeHelp();

// What a command ends with: an exit code and, when it failed, the one line for stderr.
struct Outcome
{
    int code = ExitOk;
    QString message;

    bool ok() const { return code == ExitOk; }
    static Outcome success() { return {}; }
    static Outcome failure(int code, const QString& message) { return {code, message}; }
    static Outcome usage(const QString& message) { return {ExitUsage, message}; }
    static Outcome from(const CommandResult& result);
};

// stdout, flushed per line so a pipe sees output as it happens.
void printLine(const QString& line);
void printJson(const QJsonObject& object); // one compact JSON object on one line
void printJson(const QJsonArray& array);   // one compact JSON array on one line (scan, records)
// stderr: exactly one line (newlines inside the message are folded).
void printError(const QString& message);

// Human-readable `status`: machine flags, per-axis flags and positions (marked "unknown" or
// "estimated"), temperature (where the model reports one), one row per drive on multi-drive
// links (silent drives named), raw words.
// names: the controller's names of its axes (issue 32: "feeder"; default X, Y, ...).
QString formatStatus(const MachineStatus& status, const ModelInfo& model,
                     const Capabilities& capabilities, const QString& port,
                     const QString& linkState, const AxisNames& names = {});
// "X=100 Y=0 Z=-5" with the same marks, for move/home/feed.
QString formatPositions(const MachineStatus& status);

} // namespace stepdeck::cli
