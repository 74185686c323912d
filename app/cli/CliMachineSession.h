#pragma once
#include "CliArguments.h"
#include "CliEventWait.h"
#include "CliOutput.h"
#include "machine/Machine.h"
#include <QHash>
#include <QObject>
#include <functional>

namespace stepdeck::cli {

// Synchronous face of a core Machine for `stepdeck-cli --machine FILE` (issue 19): connects
// every controller, waits for moves, reference runs and requests with local event loops, and
// remembers which controller failed, so a command can exit 6 naming it. The Machine owns the
// sessions; its destruction stops every controller (ControllerSession::destroy).
class CliMachineSession : public QObject
{
    Q_OBJECT
public:
    static constexpr int kStopWaitMs = 3000;

    CliMachineSession(const CliOptions& options, const machine::MachineDescription& description,
                      QObject* parent = nullptr);

    machine::Machine& machine() { return m_machine; }
    const machine::MachineDescription& description() const { return m_description; }

    // Creates the sessions (no I/O), opens every link and waits until all are Connected (at
    // most options.connectTimeoutMs), then reads every status once; with --setup-defaults
    // writes each model's schema defaults first. Failure names the controller (exit 6).
    Outcome connectAll();
    // `home X=1`: reference directions from the command line instead of the file (before
    // connectAll(), which creates the machine from the description).
    void setReferenceDirections(const QMap<QString, int>& directions);
    bool isConnected() const { return m_connected; }

    // Waits until done() or timeout (ms < 0: no deadline); false on timeout or interrupt.
    bool waitFor(const std::function<bool()>& done, int timeoutMs);
    bool pause(int ms);
    // Waits for one request of one controller; the result (a failure on timeout).
    CommandResult waitResult(const QString& controllerId, RequestId id, int timeoutMs);
    // Waits for every request of `ids` (controller id -> request) and names the first failure.
    Outcome waitAll(const QMap<QString, RequestId>& ids, int timeoutMs);

    // A controller's link was lost (or its part of a motion failed) since the connection:
    // its id, and exit 6 with the machine's message naming it.
    bool linkLost() const { return !m_lostController.isEmpty(); }
    Outcome linkLostOutcome() const;
    // The exit code for a failed move or reference run with `message`.
    Outcome motionFailure(const QString& message) const;

    // A controller refused a jog rate after it was sent (its own rules: a limit switch, a
    // drive that stopped answering); empty while none did.
    const QString& jogRefusal() const { return m_jogRefusal; }
    // What the controllers reported by themselves since the connection (errorOccurred: a
    // motion the host did not command and stopped, a resynchronisation), each once, in order.
    const QStringList& notes() const { return m_notes; }

    void interrupt();
    // A signal from the SignalPipe: while a program's handler is set (CliFeedHold: SIGTSTP,
    // SIGCONT, SIGUSR1, SIGUSR2) it takes the signals it knows (true); every other one
    // interrupts.
    void signal(int signalNumber);
    void setProgramSignals(std::function<bool(int)> handler)
    {
        m_programSignals = std::move(handler);
    }
    bool interrupted() const { return m_interrupted; }
    // SIGINT/SIGTERM/SIGHUP and failures: every jog ramps down and every controller gets its
    // stop at once; success when every controller acknowledged it.
    Outcome stopAll();

    // Makes a waitFor() check its condition again now (for conditions the machine's signals
    // do not announce, such as a program runner's state).
    void wake();

private:
    void watchSessions();
    Outcome openAll();
    CommandResult verdict(const QString& controllerId, const CommandResult& r);
    QString faultText(const machine::MachineController& c, const QString& message) const;
    Outcome awaitMachineSetup();
    Outcome writeSetupDefaults();

    CliOptions m_options;
    machine::MachineDescription m_description;
    machine::Machine m_machine;
    QHash<QString, QHash<RequestId, CommandResult>> m_finished; // per controller id
    CliEventWait m_wait;
    bool m_connected = false;
    bool m_interrupted = false;
    std::function<bool(int)> m_programSignals;
    QString m_lostController;
    QString m_lostMessage;
    QHash<QString, QString> m_lostReasons;
    QString m_jogRefusal; // the first jog refusal, prefixed with its controller on a machine
    QStringList m_notes;
    ErrorKind m_lastFailure = ErrorKind::None;
};

} // namespace stepdeck::cli
