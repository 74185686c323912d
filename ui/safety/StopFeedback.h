#pragma once
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include <QElapsedTimer>
#include <QObject>

namespace stepdeck::ui {

class MachineContext;
class StatusMessages;

// What the operator reads after STOP (Esc) (issue 16): first that the stop was sent, then --
// only once a complete status read, asked for after the stop request was answered, showed
// every axis standing still -- that the machine stopped. A status read before the stop (or
// the host's own bookkeeping) never counts: it may predate a move just sent. While the
// controller may still move (MachineStatus::motionUnconfirmed, a silent drive) it keeps
// reading and says nothing more. A link loss or a panic ends the watch without a claim.
class StopFeedback : public QObject
{
    Q_OBJECT
public:
    StopFeedback(MachineContext* context, StatusMessages* messages, QObject* parent = nullptr);

    // Call right after the stop was requested (its id); motionWasRunning: something moved or
    // jogged as far as the host knew when STOP was pressed.
    void stopSent(RequestId stopId, bool motionWasRunning);
    bool isWatching() const { return m_stopId != 0; }

    // Whether anything may be moving as far as the status tells (axes, jog rates, busy).
    static bool motionIn(const MachineStatus& status);
    static constexpr qint64 kWatchMs = 30000; // reads for at most this long after the stop

private:
    void onResult(const CommandResult& result);
    void onStatus(const MachineStatus& status);
    void readStatus();
    void end();

    MachineContext* m_context;
    StatusMessages* m_messages;
    RequestId m_stopId = 0;
    RequestId m_readId = 0;  // the status read asked for after the stop was answered
    bool m_answered = false; // the stop request finished (acknowledged or refused)
    bool m_acknowledged = false;
    bool m_sawMotion = false; // motion known at the stop or reported since
    QElapsedTimer m_since;
};

} // namespace stepdeck::ui
