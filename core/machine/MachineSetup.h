#pragma once
#include "MachineDescription.h"
#include "model/CommandResult.h"
#include <QHash>
#include <QObject>
#include <optional>

namespace stepdeck {
class ControllerSession;
}

namespace stepdeck::machine {

class Machine;

// Writes each controller's setup from the machine file (MachineController::setup, issue 28
// item 1) whenever its link comes up: every connect and every reconnect, so that a machine
// comes up with its drives set as the file says, as LinuxCNC keeps drive settings in its INI
// file. A write-only board (E-LAB) then knows its values from the start (the session's
// knownParameters), and the program check judges by them. Readable parameters are read back
// (verify); a write that fails is reported, never claimed.
class MachineSetup : public QObject
{
    Q_OBJECT
public:
    explicit MachineSetup(Machine* machine);

    // A setup write is under way on some controller (the CLI waits for it before a command).
    bool pending() const { return !m_writes.isEmpty(); }
    // Controller id -> the request writing its setup now.
    QHash<QString, RequestId> pendingWrites() const { return m_writes; }
    // The result of the controller's last setup write since its link came up (none: no write
    // finished yet, or the controller has no setup).
    std::optional<CommandResult> lastResult(const QString& controllerId) const
    {
        const auto it = m_results.constFind(controllerId);
        return it == m_results.cend() ? std::nullopt : std::optional<CommandResult>(*it);
    }

Q_SIGNALS:
    // One controller's setup was written (ok) or not; message says which file, how many
    // values, or why it failed.
    void written(const QString& controllerId, bool ok, const QString& message);

private:
    void write(const MachineController& controller, ControllerSession* session);
    void onResult(const MachineController& controller, const CommandResult& result);

    QHash<QString, RequestId> m_writes;      // controller id -> its setup write in flight
    QHash<QString, CommandResult> m_results; // controller id -> its last write's result
};

} // namespace stepdeck::machine
