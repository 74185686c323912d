#include "StopFeedback.h"
#include "machine/MachineContext.h"
#include "messages/StatusMessages.h"

namespace stepdeck::ui {

namespace {
// The Safety owner's message is the panic's (cleared by every status without a panic).
constexpr StatusMessages::Owner kOwner = StatusMessages::Owner::General;
} // namespace

StopFeedback::StopFeedback(MachineContext* context, StatusMessages* messages, QObject* parent)
    : QObject(parent), m_context(context), m_messages(messages)
{
    ControllerSession* session = context->session();
    connect(session, &ControllerSession::requestFinished, this, &StopFeedback::onResult);
    connect(session, &ControllerSession::statusChanged, this, &StopFeedback::onStatus);
    connect(session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected)
            end(); // the link's own message says what is known
    });
    connect(context, &MachineContext::panicTriggered, this, &StopFeedback::end);
}

bool StopFeedback::motionIn(const MachineStatus& status)
{
    if (status.busy || status.motionUnconfirmed)
        return true;
    for (const AxisStatus& a : status.axes) {
        if (a.moving || a.jogging || a.motionUnknown || a.commandedVelocity != 0.0)
            return true;
    }
    return false;
}

void StopFeedback::stopSent(RequestId stopId, bool motionWasRunning)
{
    // Sent, not confirmed: what the device reports decides what is said next.
    m_messages->show(kOwner,
                     motionWasRunning
                         ? tr("Stop sent: waiting for the controller to report standstill\u2026")
                         : tr("Stop sent"),
                     StatusMessages::Severity::Info, motionWasRunning ? 15000 : 3000);
    m_stopId = stopId;
    m_readId = 0;
    m_since.start();
    m_answered = m_acknowledged = false;
    m_sawMotion = motionWasRunning;
}

void StopFeedback::onResult(const CommandResult& result)
{
    if (m_stopId == 0 || result.id == 0)
        return;
    if (result.id == m_stopId) {
        m_answered = true;
        m_acknowledged = result.ok();
        readStatus();
        return;
    }
    if (result.id != m_readId)
        return;
    m_readId = 0;
    const MachineStatus status = result.value.canConvert<MachineStatus>()
                                     ? result.value.value<MachineStatus>()
                                     : m_context->status();
    if (!result.ok() || motionIn(status)) {
        m_sawMotion = m_sawMotion || motionIn(status);
        return; // read again with the next status round (onStatus)
    }
    if (m_sawMotion)
        m_messages->show(kOwner,
                         m_acknowledged
                             ? tr("Stopped: the controller reports every axis at standstill.")
                             : tr("Every axis is at standstill, as the controller reports."),
                         StatusMessages::Severity::Info, 10000);
    end();
}

void StopFeedback::onStatus(const MachineStatus& status)
{
    if (m_stopId == 0)
        return;
    if (m_since.elapsed() > kWatchMs) {
        end(); // still moving by then: the banner and the status panel say what is known
        return;
    }
    m_sawMotion = m_sawMotion || motionIn(status);
    // Still moving at the last read: read again, at the pace of the controller's own status.
    if (m_answered && m_readId == 0)
        readStatus();
}

void StopFeedback::readStatus()
{
    m_readId = m_context->session()->refreshStatus();
}

void StopFeedback::end()
{
    m_stopId = m_readId = 0;
    m_answered = m_acknowledged = m_sawMotion = false;
}

} // namespace stepdeck::ui
