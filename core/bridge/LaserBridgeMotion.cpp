// The controller side of the bridge: reference and move requests through the session,
// standstill confirmed by a status read, retargeting by stop where the controller allows it.
#include "LaserBridgeMotion.h"
#include "Logging.h"

namespace stepdeck::bridge {

using namespace stepdeck::laser;

LaserBridgeMotion::LaserBridgeMotion(ControllerSession* session, const LaserBridgeConfig& config,
                                     const Capabilities& caps, const LaserAnswerPolicy& answers,
                                     QMap<Axis, Slot>& axisSlots, Hooks hooks)
    : m_session(session), m_config(config), m_caps(caps), m_answers(answers), m_slots(axisSlots),
      m_hooks(std::move(hooks))
{}

bool LaserBridgeMotion::referencedNow(const Slot& slot) const
{
    // Referenced by the bridge since it started, and not lost since (panic, reconnect, a stop
    // without ramp): the controller's own flag says the latter.
    const AxisStatus axis = m_session->status().axes.value(slot.axis);
    return slot.referenced && axis.referenced && axis.positionKnown;
}

bool LaserBridgeMotion::controllerIdle() const
{
    for (const AxisStatus& a : m_session->status().axes) {
        if (a.moving || a.jogging)
            return false;
    }
    return true;
}

void LaserBridgeMotion::dispatch(Slot& slot)
{
    slot.waitingForIdle = false;
    if (!slot.wanted || m_hooks.shuttingDown())
        return;
    if (!m_session || m_session->linkState() != LinkState::Connected)
        return m_hooks.drop(slot, tr("the controller is not connected"));
    if (m_session->status().axes.value(slot.axis).jogging)
        return m_hooks.drop(slot, tr("the operator is jogging axis %1").arg(axisName(slot.axis)));
    if (slot.wanted->command == Command::Home || !referencedNow(slot))
        startReference(slot);
    else
        startMove(slot);
    m_hooks.publish(slot);
}

void LaserBridgeMotion::startReference(Slot& slot)
{
    const int direction = m_config.referenceRequest(slot.axis, m_caps);
    if (slot.wanted->command == Command::Move) {
        log(LaserBridgeLogEntry::Kind::Note, tr("axis %1 not referenced since the bridge started: "
                                                "referencing it first")
                                                 .arg(axisName(slot.axis)));
    }
    slot.referenced = false;
    slot.job = Job{Job::Kind::Reference, 0, 0, false, *slot.wanted, 0};
    slot.job.id = m_session->reference({{slot.axis, direction}});
}

void LaserBridgeMotion::startMove(Slot& slot)
{
    // Range-checked as double first: target x scale can leave the integer range.
    const double steps = double(slot.wanted->position) * m_config.scale;
    if (!(qAbs(steps) < 9e15))
        return m_hooks.drop(slot, tr("target x scale is out of range"));
    slot.job = Job{Job::Kind::Move, 0, 0, false, *slot.wanted, qRound64(steps)};
    slot.job.id = m_session->moveAbsolute({{slot.axis, slot.job.steps}});
}

bool LaserBridgeMotion::canStopToRetarget() const
{
    // A stop that loses the position (no ramp: Nanotec 'S') would force a new reference run
    // for every retarget; such controllers finish the move first.
    return m_caps.stopCommand && m_caps.rampedStop;
}

void LaserBridgeMotion::retarget(Slot& slot)
{
    if (!slot.job.accepted || slot.job.confirmId != 0)
        return; // the request or its confirmation is under way; conclude() sees the new target
    if (canStopToRetarget()) {
        log(LaserBridgeLogEntry::Kind::Note,
            tr("new target for axis %1 while it moves: stopping first").arg(axisName(slot.axis)));
        requestStop();
    } else {
        log(LaserBridgeLogEntry::Kind::Note,
            tr("new target for axis %1 while it moves: the controller "
               "cannot retarget without a ramped stop, so it arrives "
               "first")
                .arg(axisName(slot.axis)));
    }
}

void LaserBridgeMotion::requestStop()
{
    if (m_stop != StopStage::None || !m_session)
        return;
    bool anyJob = false;
    for (const Slot& slot : std::as_const(m_slots))
        anyJob = anyJob || slot.job.kind != Job::Kind::None;
    if (!anyJob)
        return;
    if (!m_caps.stopCommand) {
        log(LaserBridgeLogEntry::Kind::Error,
            tr("the controller has no stop command: the axes go on to their targets"));
        return;
    }
    m_stop = StopStage::Requested;
    m_stopId = m_session->stop();
    for (const Slot& slot : std::as_const(m_slots))
        m_hooks.publish(slot);
}

void LaserBridgeMotion::stopForShutdown()
{
    m_stopId = m_session->stop();
    m_stop = StopStage::Requested;
}

LaserBridgeMotion::Slot* LaserBridgeMotion::slotForRequest(RequestId id)
{
    for (Slot& slot : m_slots) {
        if (slot.job.kind != Job::Kind::None && (slot.job.id == id || slot.job.confirmId == id))
            return &slot;
    }
    return nullptr;
}

void LaserBridgeMotion::onResult(const CommandResult& result)
{
    if (result.id == m_stopId || (m_stopConfirmId != 0 && result.id == m_stopConfirmId))
        return onStopResult(result);
    Slot* slot = slotForRequest(result.id);
    if (!slot)
        return; // not the bridge's (the operator's pages share the session)
    if (result.id == slot->job.confirmId) {
        slot->job.confirmId = 0;
        if (!result.ok()) {
            slot->job = Job{};
            return m_hooks.drop(
                *slot, tr("the controller's status could not be read: %1").arg(result.message));
        }
        return conclude(*slot);
    }
    if (!result.ok())
        return onRefused(*slot, result);
    slot->job.accepted = true;
    const bool superseded = slot->wanted && !(*slot->wanted == slot->job.frame);
    if (superseded && canStopToRetarget())
        requestStop();
    else if (m_stop == StopStage::None)
        checkStandstill(*slot);
}

void LaserBridgeMotion::onRefused(Slot& slot, const CommandResult& result)
{
    const Job job = std::exchange(slot.job, Job{});
    m_hooks.publish(slot);
    if (m_stop != StopStage::None || m_hooks.shuttingDown())
        return; // the stop under way dropped it; redispatchAll() sends the newest target
    if (slot.wanted && !(*slot.wanted == job.frame))
        return dispatch(slot); // superseded meanwhile
    const AxisStatus axis = m_session->status().axes.value(slot.axis);
    if (result.error == ErrorKind::Refused && axis.limitSwitch) {
        log(LaserBridgeLogEntry::Kind::Note,
            tr("controller refused at an active limit switch: %1").arg(result.message));
        return m_hooks.reply(slot, m_answers.refusedAtLimit(slot.laserAxis, slot.axis, axis));
    }
    if (result.error == ErrorKind::Refused && !controllerIdle()) {
        slot.waitingForIdle = true;
        log(LaserBridgeLogEntry::Kind::Note, tr("axis %1 waits until the controller is idle (%2)")
                                                 .arg(axisName(slot.axis), result.message));
        return m_hooks.publish(slot);
    }
    m_hooks.drop(slot, tr("the controller did not take it: %1").arg(result.message));
}

void LaserBridgeMotion::onLinkState(LinkState state, bool serving)
{
    if (state != LinkState::Connected && serving)
        dropTargetsOfLostLink();
}

void LaserBridgeMotion::dropTargetsOfLostLink()
{
    // Nothing can be reached or confirmed any more: the controller may still be moving and
    // its positions are unknown. Every open target is dropped at once, with the reason.
    const QString why = m_session && m_session->linkState() == LinkState::Lost
                            ? tr("the controller's link was lost")
                            : tr("the controller is not connected");
    for (Slot& slot : m_slots) {
        if (!slot.wanted && slot.job.kind == Job::Kind::None)
            continue;
        slot.job = Job{};
        m_hooks.drop(slot, why);
    }
}

void LaserBridgeMotion::onStatus()
{
    if (m_stop != StopStage::None)
        return advanceStop();
    for (Slot& slot : m_slots) {
        if (slot.job.kind != Job::Kind::None && slot.job.accepted && slot.job.confirmId == 0)
            checkStandstill(slot);
    }
    if (!controllerIdle() || m_hooks.doorOpen())
        return;
    for (Slot& slot : m_slots) {
        if (slot.waitingForIdle && slot.job.kind == Job::Kind::None)
            dispatch(slot);
    }
}

void LaserBridgeMotion::checkStandstill(Slot& slot)
{
    const AxisStatus axis = m_session->status().axes.value(slot.axis);
    if (axis.jogging) {
        slot.job = Job{};
        return m_hooks.drop(slot, tr("the operator took over axis %1").arg(axisName(slot.axis)));
    }
    if (axis.moving)
        return;
    // Standing: one more complete status read, so a position the adapter corrects after a
    // stop (E-LAB RequestRelPosition) is in before the bridge answers.
    slot.job.confirmId = m_session->refreshStatus();
}

void LaserBridgeMotion::conclude(Slot& slot)
{
    const AxisStatus axis = m_session->status().axes.value(slot.axis);
    if (axis.moving) { // moving again (the operator, or a late status): wait once more
        if (m_stop == StopStage::None)
            checkStandstill(slot);
        return;
    }
    const Job job = std::exchange(slot.job, Job{});
    if (job.kind == Job::Kind::Reference) {
        if (!(axis.referenced && axis.positionKnown))
            return m_hooks.reply(slot, m_answers.referenceFailed(slot.laserAxis, slot.axis, axis));
        slot.referenced = true;
        if (slot.wanted && slot.wanted->command == Command::Home)
            return m_hooks.reply(slot, m_answers.referenced(slot.laserAxis, slot.axis, axis));
        return dispatch(slot); // home before the first move: now the move
    }
    if (slot.wanted && !(*slot.wanted == job.frame))
        return dispatch(slot); // a newer target arrived while it moved
    m_hooks.reply(slot, m_answers.moveEnded(slot.laserAxis, slot.axis, axis, job.steps));
}

void LaserBridgeMotion::onStopResult(const CommandResult& result)
{
    if (result.id == m_stopId) {
        m_stopId = 0;
        if (!result.ok()) {
            log(LaserBridgeLogEntry::Kind::Error, tr("stop failed: %1").arg(result.message));
            if (m_hooks.shuttingDown())
                return m_hooks.finishShutdown();
            // Back to waiting for arrival: the jobs still run.
            m_stop = StopStage::None;
            m_hooks.stopEnded();
            return;
        }
        if (m_hooks.shuttingDown())
            return m_hooks.finishShutdown();
        m_stop = StopStage::Settling;
        return advanceStop();
    }
    m_stopConfirmId = 0;
    if (!result.ok())
        log(LaserBridgeLogEntry::Kind::Error, tr("status after the stop: %1").arg(result.message));
    m_stop = StopStage::None;
    m_hooks.stopEnded();
    redispatchAll();
}

void LaserBridgeMotion::advanceStop()
{
    if (m_stop != StopStage::Settling || !controllerIdle())
        return;
    m_stop = StopStage::Confirming;
    m_stopConfirmId = m_session->refreshStatus();
}

void LaserBridgeMotion::redispatchAll()
{
    for (Slot& slot : m_slots) {
        slot.job = Job{};
        slot.waitingForIdle = slot.wanted.has_value();
        if (m_hooks.doorOpen() || !slot.wanted) {
            m_hooks.publish(slot);
            continue;
        }
        dispatch(slot);
    }
}

} // namespace stepdeck::bridge
