#pragma once
#include "controller/ControllerSession.h"
#include <QHash>
#include <functional>

namespace stepdeck::bench {

// The host side: stepdeck's own stack (ControllerSession -> adapter -> SerialTransport ->
// QSerialPort) on the pseudo-terminal's slave, with blocking helpers for the benchmark.
class BenchSession : public QObject
{
public:
    explicit BenchSession(QObject* parent = nullptr);

    // Opens port with the model's adapter and waits for LinkState::Connected.
    bool connectTo(const ModelInfo& model, const QString& port, int pollIntervalMs, QString* error);
    CommandResult call(const std::function<RequestId(ControllerSession&)>& start, int timeoutMs);
    // Runs the event loop until done() or timeoutMs; false on timeout (EventWait.h).
    bool waitUntil(const std::function<bool()>& done, int timeoutMs);
    void idle(int ms)
    {
        waitUntil([] { return false; }, ms);
    }

    ControllerSession& session() { return m_session; }
    double lastPollRateHz() const { return m_pollRateHz; }
    int pollRateReports() const { return m_pollRateReports; }
    bool hasResult(RequestId id) const { return m_finished.contains(id); }

private:
    ControllerSession m_session;
    QHash<RequestId, CommandResult> m_finished;
    double m_pollRateHz = 0;
    int m_pollRateReports = 0;
};

} // namespace stepdeck::bench
