#pragma once
#include "CliArguments.h"
#include "CliEventWait.h"
#include "CliOutput.h"
#include "controller/ControllerSession.h"
#include <QHash>
#include <QObject>
#include <functional>
#include <utility>

namespace stepdeck::cli {

// Synchronous face of a ControllerSession for a one-shot command line tool: every call posts a
// request to the controller thread and runs a local event loop until that request id's
// requestFinished arrives (or the link drops, a deadline passes, or the user interrupts).
class CliSession : public QObject
{
    Q_OBJECT
public:
    static constexpr int kRequestTimeoutMs = 30000; // safety net; adapters time out sooner
    static constexpr int kIdlePollMs = 50;
    static constexpr int kJogRampDownMs = 5000; // bound for a jog's host ramp to reach zero

    explicit CliSession(const CliOptions& options, QObject* parent = nullptr);
    ~CliSession() override;

    // What every controller of this invocation starts from (CliSession and, for each
    // controller of a machine, CliMachineSession): --arrival-timeout, the CLI's action names.
    static ControllerOptions baseControllerOptions(const CliOptions& options);

    // Creates the stack (unknown model: usage error) without touching the port; once.
    Outcome create();
    // create(), then opens the link and waits until it is Connected, at most
    // options.connectTimeoutMs.
    Outcome connectLink();
    bool isConnected() const { return m_connected; }

    // Posts one request and waits for its result.
    CommandResult call(const std::function<RequestId(ControllerSession&)>& start,
                       int timeoutMs = kRequestTimeoutMs);
    Outcome run(const std::function<RequestId(ControllerSession&)>& start,
                int timeoutMs = kRequestTimeoutMs)
    {
        return Outcome::from(call(start, timeoutMs));
    }
    // One complete status read; status() is current afterwards.
    Outcome refresh();
    // Polls until no axis moves (deadlineMs < 0: no deadline; past it: ExitTimeout). A move
    // that ends on a limit switch or an emergency stop is reported as ExitMotionAborted; an
    // axis whose drive stopped answering as ExitLinkDown.
    Outcome waitUntilIdle(int deadlineMs = -1);
    // The link went down (lost or closed) after it was up. The adapter has sent its stop.
    bool linkLost() const { return m_lost; }
    // ExitLinkDown with the reason, and whether the controller may still be moving.
    Outcome linkLostOutcome() const;
    // Runs the event loop for ms (jog lease renewal, poll spacing); false when interrupted.
    bool pause(int ms);
    // Waits until done() or timeout (ms < 0: no deadline); false on timeout or interrupt.
    bool waitFor(const std::function<bool()>& done, int timeoutMs);

    ControllerSession& session() { return m_session; }
    // The controller's own capabilities (after create()): on bus models the axes follow the
    // axis map (--address 2: only X), unlike ModelInfo::capabilities.
    Capabilities capabilities() const { return m_session.capabilities(); }
    const MachineStatus& status() const { return m_session.status(); }

    // SIGINT/SIGTERM/SIGHUP: ends every wait; stopMotion() then ramps jogs down and stops.
    void interrupt();
    bool interrupted() const { return m_interrupted; }
    // For commands that end normally on a signal (velocity): clears and returns the flag.
    bool takeInterrupt() { return std::exchange(m_interrupted, false); }
    // Ramps every jog down, then sends the model's stop and waits for its answer. Success only
    // when the controller acknowledged the stop; the failure says that it may still move.
    Outcome stopMotion();
    // How long a failed request waits for the link verdict: a controller that stopped
    // answering is a lost link (exit 6) whatever the request was, not a timeout by chance.
    int linkVerdictMs() const;
    static int linkVerdictMs(const ControllerOptions& options);

private:
    void wake();

    CliOptions m_options;
    ControllerSession m_session;
    QHash<RequestId, CommandResult> m_finished;
    CliEventWait m_wait;
    bool m_connected = false;
    bool m_lost = false;
    QString m_lostReason;
    QString m_lastError;
    bool m_interrupted = false;
};

} // namespace stepdeck::cli
