#pragma once
#include "controller/ControllerSession.h"
#include <QHash>
#include <functional>

namespace stepdeck::bench {

// The host side of every bench run (measurements, soak, replug): StepDeck's own stack
// (ControllerSession -> adapter -> SerialTransport -> QSerialPort) on the pseudo-terminal's
// slave of a BenchDevice. connectTo() recreates the stack, because a reappeared peer has a new
// terminal. Waits run the event loop (EventWait.h); nothing here sleeps.
class BenchHost : public QObject
{
public:
    static constexpr int kRequestBoundMs = 10000; // no result within this: a hang

    // How the stack is set up for a run.
    struct Options
    {
        int pollIntervalMs = 20;
        // Models that learn of an arrival only from the device (laser status frames) wait
        // this long for it (--arrival-timeout in the CLI, 60 s by default); <= 0 keeps the
        // model's default.
        int arrivalTimeoutMs = 0;
        int connectTimeoutMs = 5000; // the link must be Connected within this
    };
    // Soak and replug runs: every target of the soak arrives within a fraction of a second,
    // so a lost arrival frame is reported as a timeout after 3 s instead of outlasting
    // kRequestBoundMs and counting as a hang.
    static Options soakOptions() { return {20, 3000, 5000}; }

    explicit BenchHost(QObject* parent = nullptr);
    ~BenchHost() override;

    // Creates the stack on port and waits until Connected; false with *error otherwise.
    bool connectTo(const ModelInfo& model, const QString& port, const Options& options,
                   QString* error);
    // Multi-drive models: the drive polled for each axis (ControllerOptions::axisAddresses)
    // from the next connectTo() on; empty (the default) keeps the model's own.
    void setAxisAddresses(const QMap<Axis, int>& addresses) { m_axisAddresses = addresses; }
    // Orderly end: close (the adapter stops what it tracks), then destroy the stack.
    void disconnect();
    bool connected() const { return m_session.linkState() == LinkState::Connected; }
    // The steady-clock time the link left Connected (nowNs()), -1 while it has not.
    qint64 linkLeftNs() const { return m_linkLeftNs; }

    struct Outcome
    {
        bool finished = false; // false: no result within the bound (a hang)
        // The request's result; without one, a Timeout failure "no result".
        CommandResult result;
    };
    Outcome call(const std::function<RequestId(ControllerSession&)>& start,
                 int boundMs = kRequestBoundMs);
    // Runs the event loop until done() or timeoutMs; false on timeout.
    bool waitUntil(const std::function<bool()>& done, int timeoutMs);
    void idle(int ms);
    // Polls until the status shows no axis moving (or the link is gone); false on timeout.
    bool waitIdle(int timeoutMs);

    ControllerSession& session() { return m_session; }
    // The poller's last reported rate and how many reports came since connectTo().
    double lastPollRateHz() const { return m_pollRateHz; }
    int pollRateReports() const { return m_pollRateReports; }

private:
    ControllerSession m_session;
    QHash<RequestId, CommandResult> m_finished;
    QMap<Axis, int> m_axisAddresses;
    qint64 m_linkLeftNs = -1;
    double m_pollRateHz = 0;
    int m_pollRateReports = 0;
};

} // namespace stepdeck::bench
