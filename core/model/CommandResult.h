#pragma once
#include <QMetaType>
#include <QString>
#include <QVariant>

namespace stepdeck {

using RequestId = quint64;

// Why a request did not succeed; the CLI maps these to exit codes, the UI to messages.
enum class ErrorKind {
    None,
    Refused,      // not sent: the manual forbids it now (limit switch, not idle, setup incomplete)
    Nak,          // the device said no; message carries the decoded status
    Timeout,      // no reply in time
    LinkDown,     // not connected or link lost
    InvalidValue, // out of range or wrong type; not sent
    Unsupported,  // the model cannot do this
    Protocol,     // malformed reply
    Cancelled,    // dropped by stop/panic/disconnect before it was sent
    VerifyFailed, // written, but the read-back differs
};

struct CommandResult
{
    RequestId id = 0;
    ErrorKind error = ErrorKind::None;
    QString message; // one line naming the cause, for stderr/status bar
    QVariant value;  // e.g. a ParameterSet for reads

    bool ok() const { return error == ErrorKind::None; }
    static CommandResult success(RequestId id, QVariant value = {})
    {
        return CommandResult{id, ErrorKind::None, {}, std::move(value)};
    }
    static CommandResult failure(RequestId id, ErrorKind kind, QString message)
    {
        return CommandResult{id, kind, std::move(message), {}};
    }
};

} // namespace stepdeck

Q_DECLARE_METATYPE(stepdeck::CommandResult)
