#include "TargetJogger.h"
#include <QtMath>

namespace stepdeck {

TargetJogger::TargetJogger(ControllerSession* session, QObject* parent)
    : QObject(parent), m_session(session)
{
    connect(session, &ControllerSession::requestFinished, this, &TargetJogger::onResult);
    connect(session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected) {
            release();
            m_inFlight = 0;
        }
    });
}

qint64 TargetJogger::chunkSteps(double stepsPerS)
{
    if (!qIsFinite(stepsPerS) || stepsPerS == 0.0)
        return 0;
    const double steps = qBound(-1e9, stepsPerS * kChunkSeconds, 1e9);
    const qint64 rounded = qRound64(steps);
    return rounded != 0 ? rounded : (steps > 0 ? 1 : -1);
}

void TargetJogger::setVelocities(const AxisVelocities& stepsPerS)
{
    m_velocities.clear();
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        if (it.value() != 0.0)
            m_velocities.insert(it.key(), it.value());
    }
    if (m_inFlight == 0)
        sendNext();
}

void TargetJogger::release()
{
    m_velocities.clear();
}

void TargetJogger::sendNext()
{
    AxisVector steps;
    for (auto it = m_velocities.cbegin(); it != m_velocities.cend(); ++it)
        steps.insert(it.key(), chunkSteps(it.value()));
    if (steps.isEmpty())
        return;
    // Never beyond a soft limit; the rates are what the panel shows as commanded.
    m_inFlight = m_session->jogStep(steps, m_velocities);
}

void TargetJogger::onResult(const CommandResult& result)
{
    if (result.id != m_inFlight || m_inFlight == 0)
        return;
    m_inFlight = 0;
    if (!result.ok()) {
        // Refused (position unknown, out of range), timed out or replaced: stop jogging and
        // say why; the operator deflects again once the cause is gone.
        release();
        if (result.error != ErrorKind::Cancelled)
            Q_EMIT refused(result.message);
        return;
    }
    const QStringList endSwitch =
        result.value.toMap().value(QStringLiteral("endSwitch")).toStringList();
    if (!endSwitch.isEmpty()) {
        release();
        Q_EMIT refused(tr("Jog ended: axis %1 reached its end switch")
                           .arg(endSwitch.join(QStringLiteral(", "))));
        return;
    }
    sendNext();
}

} // namespace stepdeck
