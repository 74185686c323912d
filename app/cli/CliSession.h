#pragma once
#include "CliArguments.h"
#include "CliOutput.h"
#include "controller/ControllerSession.h"
#include <QHash>
#include <QObject>
#include <functional>
#include <utility>

class QEventLoop;

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

    explicit CliSession(const CliOptions& options, QObject* parent = nullptr);
    ~CliSession() override;

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
    // Polls until no axis moves. A move that ends on a limit switch or an emergency stop is
    // reported as ExitMotionAborted.
    Outcome waitUntilIdle();
    // Runs the event loop for ms (jog lease renewal, poll spacing); false when interrupted.
    bool pause(int ms);
    // Waits until done() or timeout (ms < 0: no deadline); false on timeout or interrupt.
    bool waitFor(const std::function<bool()>& done, int timeoutMs);

    ControllerSession& session() { return m_session; }
    // The controller's own capabilities (after create()): on bus models the axes follow the
    // axis map (--address 2: only X), unlike ModelInfo::capabilities.
    Capabilities capabilities() const { return m_session.capabilities(); }
    const MachineStatus& status() const { return m_session.status(); }
    QString linkStateText() const { return linkStateName(m_session.linkState()); }
    QString jogRefusal() const { return m_jogRefusal; }

    // SIGINT/SIGTERM: ends every wait; stopMotion() then ends jogs and sends a ramped stop.
    void interrupt();
    bool interrupted() const { return m_interrupted; }
    // For commands that end normally on a signal (velocity): clears and returns the flag.
    bool takeInterrupt() { return std::exchange(m_interrupted, false); }
    void stopMotion();

private:
    void wake();

    CliOptions m_options;
    ControllerSession m_session;
    QHash<RequestId, CommandResult> m_finished;
    QEventLoop* m_loop = nullptr;
    bool m_connected = false;
    bool m_lost = false;
    QString m_lostReason;
    QString m_lastError;
    QString m_jogRefusal;
    bool m_interrupted = false;
};

} // namespace stepdeck::cli
