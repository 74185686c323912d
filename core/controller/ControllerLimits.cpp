// Soft limits (issue 11) at the one door every motion request passes: ControllerSession
// calls these in the controller thread, with the controller's own status, before the adapter
// sees the request. A request refused here sends nothing.
#include "Controller.h"

namespace stepdeck {

void Controller::guardedMoveRelative(RequestId id, const AxisVector& steps)
{
    if (!refuse(id, m_softLimits.checkRelative(m_status, steps)))
        moveRelative(id, steps);
}

void Controller::guardedMoveAbsolute(RequestId id, const AxisVector& targets)
{
    if (!refuse(id, m_softLimits.checkTargets(m_status, targets)))
        moveAbsolute(id, targets);
}

void Controller::guardedFeed(RequestId id, const AxisVector& steps)
{
    if (!refuse(id, m_softLimits.checkRelative(m_status, steps)))
        feed(id, steps);
}

void Controller::guardedFeedStream(RequestId id, const QVector<AxisVector>& steps)
{
    if (!refuse(id, m_softLimits.checkStream(m_status, steps)))
        feedStream(id, steps);
}

void Controller::guardedVelocityMove(RequestId id, const AxisVector& stepsPerS)
{
    if (!refuse(id, m_softLimits.checkVelocity(m_status, stepsPerS)))
        velocityMove(id, stepsPerS);
}

void Controller::jogStep(RequestId id, const AxisVector& steps, const AxisVelocities& stepsPerS)
{
    // Models that jog by short targets: the target ends at the limit at the latest; no ramp
    // to wait for (each target is a move of its own that ends there by itself).
    QString why;
    AxisVector clipped = m_softLimits.clipRelative(m_status, steps, &why);
    for (auto it = clipped.begin(); it != clipped.end();)
        it = it.value() == 0 ? clipped.erase(it) : std::next(it);
    if (clipped.isEmpty() && refuse(id, why)) {
        endStepJog();
        return;
    }
    // The rate the host commands now, as a jog stream's would be (issue 16: the jog panel
    // showed +0 while the laser axes moved); the adapter publishes it with the target.
    m_stepJogLease.stop();
    m_jogStepId = id;
    for (auto it = m_status.axes.begin(); it != m_status.axes.end(); ++it) {
        const double rate = clipped.contains(it.key()) ? stepsPerS.value(it.key(), 0.0) : 0.0;
        it->commandedVelocity = rate;
        if (rate != 0.0 && !m_stepJogAxes.contains(it.key()))
            m_stepJogAxes << it.key();
    }
    moveRelative(id, clipped);
}

bool Controller::refuse(RequestId id, const QString& refusal)
{
    if (refusal.isEmpty())
        return false;
    finishError(id, ErrorKind::Refused, refusal);
    return true;
}

} // namespace stepdeck
