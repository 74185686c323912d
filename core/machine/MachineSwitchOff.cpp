// Spindle and coolant off after a stop, a panic or a program's end (issue 47, docs/machines.md
// "Spindle and coolant").
#include "MachineSwitchOff.h"
#include "Machine.h"

namespace stepdeck::machine {

namespace {
bool standing(const ControllerSession& s)
{
    return !s.status().anyMoving() && !s.status().motionUnconfirmed;
}
} // namespace

MachineSwitchOff::MachineSwitchOff(Machine& machine) : m_machine(machine)
{
    m_deadline.setSingleShot(true);
    QObject::connect(&m_deadline, &QTimer::timeout, &m_machine, [this] {
        QStringList ids;
        for (const Part& p : std::as_const(m_parts))
            ids << m_machine.controllerIdOf(p.session);
        fail(tr("controller \"%1\" did not confirm spindle and coolant off within %2 s: switch "
                "them off at the machine")
                 .arg(ids.join(QStringLiteral("\", \"")))
                 .arg(kWaitMs / 1000));
    });
}

void MachineSwitchOff::start()
{
    m_parts.clear();
    for (const auto& s : m_machine.m_sessions) {
        const Capabilities caps = s->capabilities();
        if ((!caps.spindle && !caps.coolant) || s->linkState() != LinkState::Connected)
            continue; // a link that is down takes nothing; its own error line says so
        Part part;
        part.session = s.get();
        part.spindle = caps.spindle;
        part.coolant = caps.coolant;
        m_parts << part;
    }
    if (m_parts.isEmpty()) {
        m_deadline.stop();
        return;
    }
    m_deadline.start(kWaitMs);
    // The stop went out ahead of these (urgent); a status from before it may still show the
    // axes at rest, which the controller's own check before the write corrects (a refusal is
    // tried again).
    for (Part& p : m_parts)
        send(p);
}

void MachineSwitchOff::send(Part& part)
{
    if (!standing(*part.session))
        return; // once a status shows the axes standing
    if (part.spindle && part.spindleRequest == 0)
        part.spindleRequest = part.session->setSpindle(0);
    if (part.coolant && part.coolantRequest == 0)
        part.coolantRequest = part.session->setCoolant(false);
}

void MachineSwitchOff::onStatus(ControllerSession* session)
{
    for (Part& p : m_parts)
        if (p.session == session)
            send(p);
}

void MachineSwitchOff::onResult(ControllerSession* session, const CommandResult& result)
{
    for (Part& p : m_parts) {
        if (p.session != session || result.id == 0 ||
            (result.id != p.spindleRequest && result.id != p.coolantRequest))
            continue;
        const bool spindle = result.id == p.spindleRequest;
        (spindle ? p.spindleRequest : p.coolantRequest) = 0;
        if (result.ok()) {
            (spindle ? p.spindle : p.coolant) = false;
        } else if (result.error != ErrorKind::Refused && result.error != ErrorKind::Cancelled) {
            // Refused: the board still braked (tried again at the next status); cancelled: a
            // later stop dropped it. Anything else (NAK, no answer) is a failure.
            fail(tr("controller \"%1\" did not switch the %2 off (%3): switch it off at the "
                    "machine")
                     .arg(m_machine.controllerIdOf(session),
                          spindle ? tr("spindle") : tr("coolant"), result.message));
            return;
        }
        finishIfDone();
        return;
    }
}

void MachineSwitchOff::onLinkLost(ControllerSession* session)
{
    for (const Part& p : std::as_const(m_parts))
        if (p.session == session) {
            fail(tr("controller \"%1\" lost its link before it switched spindle and coolant "
                    "off: switch them off at the machine")
                     .arg(m_machine.controllerIdOf(session)));
            return;
        }
}

void MachineSwitchOff::cancel()
{
    m_parts.clear();
    m_deadline.stop();
}

void MachineSwitchOff::finishIfDone()
{
    for (const Part& p : std::as_const(m_parts))
        if (p.spindle || p.coolant)
            return;
    m_parts.clear();
    m_deadline.stop();
    Q_EMIT m_machine.spindleAndCoolantOff(true, tr("spindle and coolant switched off"));
}

void MachineSwitchOff::fail(const QString& message)
{
    m_parts.clear();
    m_deadline.stop();
    Q_EMIT m_machine.spindleAndCoolantOff(false, message);
}

} // namespace stepdeck::machine
