#pragma once
#include "controller/ControllerSession.h"
#include <QHash>
#include <functional>

namespace stepdeck::bench {

// The host side of soak and replug runs: StepDeck's own stack (ControllerSession -> adapter
// -> SerialTransport -> QSerialPort), recreated for every session because a reappeared peer
// has a new terminal. Waits run the event loop; nothing here sleeps.
class SoakHost : public QObject
{
public:
    static constexpr int kRequestBoundMs = 10000; // no result within this: a hang

    explicit SoakHost(QObject* parent = nullptr);
    ~SoakHost() override;

    // Creates the stack on port and waits until Connected; false with *error otherwise.
    bool connectTo(const ModelInfo& model, const QString& port, QString* error);
    // Orderly end: close (the adapter stops what it tracks), then destroy the stack.
    void disconnect();
    bool connected() const { return m_session.linkState() == LinkState::Connected; }
    // The steady-clock time the link left Connected (nowNs()), -1 while it has not.
    qint64 linkLeftNs() const { return m_linkLeftNs; }

    struct Outcome
    {
        bool finished = false; // false: no result within the bound (a hang)
        CommandResult result;
    };
    Outcome call(const std::function<RequestId(ControllerSession&)>& start,
                 int boundMs = kRequestBoundMs);
    bool waitUntil(const std::function<bool()>& done, int timeoutMs);
    void idle(int ms);
    // Polls until the status shows no axis moving (or the link is gone); false on timeout.
    bool waitIdle(int timeoutMs);
    ControllerSession& session() { return m_session; }

private:
    ControllerSession m_session;
    QHash<RequestId, CommandResult> m_finished;
    qint64 m_linkLeftNs = -1;
};

} // namespace stepdeck::bench
