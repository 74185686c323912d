// Machine::jog: one jog input for the axes of several controllers (issue 19).
#include "Machine.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::machine {

bool Machine::jog(const QMap<QString, double>& unitsPerSecond, QString* refusal)
{
    auto refuse = [refusal](const QString& why) {
        if (refusal)
            *refusal = why;
        return false;
    };
    // A run holds the machine (a program, an MDI line) or a reference run goes: no jog, unless
    // a run lent it (held between blocks). Else the jog holds the motion itself while it moves.
    if (const QString why = motionRefusal(&m_jogToken); !why.isEmpty())
        return refuse(why);
    QMap<ControllerSession*, AxisVelocities> rates;
    for (auto& s : m_sessions)
        rates.insert(s.get(), {});
    for (auto it = unitsPerSecond.cbegin(); it != unitsPerSecond.cend(); ++it) {
        const MachineAxis* axis = m_description.axis(it.key());
        if (!axis)
            return refuse(tr("the machine has no axis %1").arg(it.key()));
        ControllerSession* s = session(axis->controller);
        if (s->linkState() != LinkState::Connected)
            return refuse(
                tr("%1: controller \"%2\" is not connected").arg(axis->name, axis->controller));
        if (!std::isfinite(it.value()))
            return refuse(tr("%1: the jog rate is not a finite number").arg(axis->name));
        double rate = it.value();
        if (axis->maxJogSpeed)
            rate = qBound(-*axis->maxJogSpeed, rate, *axis->maxJogSpeed);
        rates[s].insert(axis->axis, axis->toStepRate(rate));
    }
    if (m_owner.isFree() && std::any_of(rates.cbegin(), rates.cend(), [](const AxisVelocities& v) {
            return std::any_of(v.cbegin(), v.cend(), [](double rate) { return rate != 0; });
        }))
        claimMotion(&m_jogToken, tr("the axes are being jogged"));
    // The controllers jogged by this input hear from it each time (those without a named axis
    // now with zero rates: they ramp down); controllers it never jogged are left alone.
    for (auto it = rates.cbegin(); it != rates.cend(); ++it) {
        ControllerSession* s = it.key();
        const bool moves = std::any_of(it.value().cbegin(), it.value().cend(),
                                       [](double rate) { return rate != 0; });
        if (moves)
            m_jogSessions.insert(s);
        if (!m_jogSessions.contains(s) || s->linkState() != LinkState::Connected)
            continue;
        if (s->capabilities().jogByTargets)
            jogByTargets(s, it.value());
        else
            s->setJogVelocity(it.value());
    }
    return true;
}

void Machine::endJog()
{
    releaseTargetJogs();
    for (ControllerSession* s : std::as_const(m_jogSessions)) {
        if (!s->capabilities().jogByTargets)
            s->endJog();
    }
    m_jogSessions.clear();
    releaseMotion(&m_jogToken);
}

// A controller without a jog command: short targets while the input is renewed (the lease
// that a jog command's controller keeps itself is kept here).
void Machine::jogByTargets(ControllerSession* session, const AxisVelocities& stepsPerS)
{
    TargetJog& jog = m_targetJogs[session];
    if (!jog.jogger) {
        jog.jogger = std::make_unique<TargetJogger>(session);
        connect(jog.jogger.get(), &TargetJogger::refused, this,
                [this, session](const QString& why) {
                    Q_EMIT jogRefused(controllerIdOf(session), why);
                });
        jog.lease = std::make_unique<QTimer>();
        jog.lease->setSingleShot(true);
        TargetJogger* jogger = jog.jogger.get();
        connect(jog.lease.get(), &QTimer::timeout, jogger, &TargetJogger::release);
    }
    jog.lease->start(qMax(1, session->spec().options.jogLeaseMs));
    jog.jogger->setVelocities(stepsPerS);
}

void Machine::releaseTargetJogs()
{
    for (auto& [session, jog] : m_targetJogs) {
        jog.lease->stop();
        jog.jogger->release();
    }
}

} // namespace stepdeck::machine
