// Targets out, status frames in: the motion part of the laser-axis adapter.
#include "LaserAxisMotion.h"
#include "LaserLogging.h"
#include "Logging.h"

namespace stepdeck::laser {

LaserAxisMotion::LaserAxisMotion(LaserAxisHost& host, const QList<Axis>& axes, QObject* owner)
    : m_host(host)
{
    for (Axis axis : axes)
        m_tracks.insert(axis, Track{});
    m_clock.start();
    m_deadline.setParent(owner);
    m_deadline.setSingleShot(true);
    QObject::connect(&m_deadline, &QTimer::timeout, owner, [this] { onDeadline(); });
}

bool LaserAxisMotion::mayBeRunning() const
{
    for (const Track& t : std::as_const(m_tracks)) {
        if (t.awaiting || t.unconfirmed)
            return true;
    }
    return false;
}

QStringList LaserAxisMotion::stopTracking()
{
    QStringList heading;
    for (auto it = m_tracks.begin(); it != m_tracks.end(); ++it) {
        if (!it->awaiting)
            continue;
        it->awaiting = false;
        it->unconfirmed = true;
        m_host.statusToChange().axes[it.key()].moving = false;
        heading << axisName(it.key());
    }
    return heading;
}

void LaserAxisMotion::failPending(ErrorKind kind, const QString& message)
{
    for (const Pending& p : std::exchange(m_pending, {}))
        m_host.fail(p.id, kind, message);
}

QString LaserAxisMotion::checkTargets(const AxisVector& targets) const
{
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        if (!m_tracks.contains(it.key()))
            return tr("this machine has no axis %1").arg(axisName(it.key()));
        if (!isValidPosition(it.value())) {
            return tr("target %1 for axis %2 is out of range (allowed: 0..%3)")
                .arg(it.value())
                .arg(axisName(it.key()))
                .arg(kMaxPosition);
        }
    }
    return {};
}

void LaserAxisMotion::moveAbsolute(RequestId id, const AxisVector& targets)
{
    if (const QString bad = checkTargets(targets); !bad.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, bad);
    if (!m_host.requireLink(id))
        return;
    if (targets.isEmpty())
        return m_host.succeed(id);
    QMap<Axis, int> out;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it)
        out.insert(it.key(), int(it.value()));
    sendTargets(id, Command::Move, out);
}

void LaserAxisMotion::moveRelative(RequestId id, const AxisVector& steps)
{
    AxisVector targets;
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        if (!m_tracks.contains(it.key())) {
            return m_host.fail(id, ErrorKind::InvalidValue,
                               tr("this machine has no axis %1").arg(axisName(it.key())));
        }
        // From the target the axis is heading for, else from where it last said it is.
        const Track& track = m_tracks[it.key()];
        const AxisStatus& axis = m_host.controller().status().axes.value(it.key());
        if (!track.awaiting && !axis.positionKnown) {
            return m_host.fail(id, ErrorKind::Refused,
                               tr("relative move refused: the position of axis %1 is unknown (no "
                                  "status frame from it in this session); home it or move it to "
                                  "an absolute target first")
                                   .arg(axisName(it.key())));
        }
        const qint64 from = track.awaiting && track.command == Command::Move ? track.target
                            : track.awaiting                                 ? 0
                                                                             : axis.position;
        targets.insert(it.key(), from + it.value());
    }
    moveAbsolute(id, targets);
}

void LaserAxisMotion::reference(RequestId id, const QMap<Axis, int>& directions)
{
    // The axis homes toward its home switch whatever the direction; 0 leaves an axis out, as
    // on the other models.
    QMap<Axis, int> homes;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it) {
        if (!m_tracks.contains(it.key())) {
            return m_host.fail(id, ErrorKind::InvalidValue,
                               tr("this machine has no axis %1").arg(axisName(it.key())));
        }
        if (it.value() != 0)
            homes.insert(it.key(), 0);
    }
    if (homes.isEmpty()) {
        return m_host.fail(id, ErrorKind::InvalidValue,
                           tr("no axis to home: every direction is 0"));
    }
    if (!m_host.requireLink(id))
        return;
    sendTargets(id, Command::Home, homes);
}

void LaserAxisMotion::replaceTargetOf(Axis axis)
{
    // "the axis should discard the previous target-position and proceed directly to the last
    // commanded target-position": whoever waited for the old one learns it was replaced.
    for (int i = m_pending.size() - 1; i >= 0; --i) {
        if (!m_pending.at(i).waiting.contains(axis))
            continue;
        const RequestId id = m_pending.takeAt(i).id;
        m_host.fail(id, ErrorKind::Cancelled,
                    tr("replaced by a newer target for axis %1").arg(axisName(axis)));
    }
}

void LaserAxisMotion::sendTargets(RequestId id, Command command, const QMap<Axis, int>& targets)
{
    QByteArray frames;
    Pending pending{id, command, {}, {}};
    const qint64 deadline =
        m_clock.elapsed() + qMax(1, m_host.controller().options().arrivalTimeoutMs);
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        const CommandFrame frame{command, it.key(), it.value()};
        frames += encodeCommand(frame);
        // Tracked, not unconfirmed: the host waits for this axis' report (issue 16: "Motion
        // unconfirmed" lit red during every normal jog). An axis the host had lost track of
        // stays unconfirmed until a status frame from it comes.
        trackTarget(frame, deadline, m_tracks.value(it.key()).unconfirmed);
        pending.waiting << it.key();
    }
    if (!m_host.sendFrames(frames)) {
        m_host.fail(id, ErrorKind::LinkDown, tr("not connected"));
        return m_host.abort(ErrorKind::LinkDown, tr("not connected"));
    }
    m_pending << pending;
    armDeadline();
    updateMachineFlags();
    m_host.publish();
}

void LaserAxisMotion::trackTarget(const CommandFrame& frame, qint64 deadlineMs, bool unconfirmed)
{
    replaceTargetOf(frame.axis);
    m_tracks[frame.axis] = Track{true, unconfirmed, frame.command, frame.position, deadlineMs};
    AxisStatus& axis = m_host.statusToChange().axes[frame.axis];
    axis.moving = true; // commanded; its status frame ends it
    axis.limitSwitch = axis.referenceSwitch = false;
}

void LaserAxisMotion::trackRawCommands(const QByteArray& bytes)
{
    // A frame typed in the traffic console moves the axis like any target: it replaces the
    // axis' target (a request waiting for the old one is cancelled, as the axis discards it)
    // and stays unconfirmed until the axis reports. Malformed frames are ignored by the axes
    // (the simulator does the same), so they are not tracked.
    const qint64 deadline =
        m_clock.elapsed() + qMax(1, m_host.controller().options().arrivalTimeoutMs);
    bool any = false;
    for (const DecodedCommand& d : m_rawDecoder.feed(bytes)) {
        if (!d.ok() || !m_tracks.contains(d.frame->axis))
            continue;
        qCInfo(lcLaser) << "raw command tracked:" << commandText(*d.frame);
        trackTarget(*d.frame, deadline, true);
        any = true;
    }
    if (!any)
        return;
    armDeadline();
    updateMachineFlags();
    m_host.publish();
}

void LaserAxisMotion::onStatusFrame(const StatusFrame& frame)
{
    if (!m_tracks.contains(frame.axis))
        return;
    const Track& track = m_tracks[frame.axis];
    AxisStatus& axis = m_host.statusToChange().axes[frame.axis];
    axis.position = frame.position;
    axis.positionKnown = true;
    axis.positionEstimated = false;
    bool settles = false;
    switch (frame.status) {
    case Status::TargetReached:
        axis.limitSwitch = axis.referenceSwitch = false;
        if (track.awaiting && track.command == Command::Home)
            axis.referenced = true; // '0' after a home command: the axis is home
        settles = true;
        break;
    case Status::EndSwitch:
        axis.limitSwitch = true;
        axis.lastSwitch = SwitchEvent::Limit;
        settles = true;
        break;
    case Status::HomeSwitch:
        // "The home position is also the '0' position of the axis."
        axis.referenceSwitch = true;
        axis.lastSwitch = SwitchEvent::Reference;
        axis.referenced = true;
        // On the way to a target the axis homes first and goes on: not the end of a move.
        settles = !(track.awaiting && track.command == Command::Move);
        break;
    case Status::DoorOpened:
    case Status::DoorClosed:
        // The door stops the motor but not its attempt to reach the target: keep waiting.
        m_host.statusToChange().doorOpen = frame.status == Status::DoorOpened;
        break;
    }
    if (settles)
        return settle(frame.axis, frame.status == Status::EndSwitch);
    updateMachineFlags();
    m_host.publish();
}

void LaserAxisMotion::settle(Axis axis, bool endSwitch)
{
    Track& track = m_tracks[axis];
    const bool wasAwaiting = track.awaiting;
    track.awaiting = false;
    track.unconfirmed = false;
    m_host.statusToChange().axes[axis].moving = false;
    // The status first, then the results: whoever waits for a result reads a current status.
    updateMachineFlags();
    m_host.publish();
    armDeadline();
    if (endSwitch && wasAwaiting) {
        Q_EMIT m_host.controller().errorOccurred(
            tr("axis %1 stopped at its end switch at %2 before reaching %3")
                .arg(axisName(axis))
                .arg(m_host.controller().status().axes.value(axis).position)
                .arg(track.target));
    }
    for (int i = m_pending.size() - 1; i >= 0; --i) {
        Pending& p = m_pending[i];
        if (!p.waiting.removeOne(axis))
            continue;
        if (endSwitch)
            p.endSwitch << axisName(axis);
        if (!p.waiting.isEmpty())
            continue;
        const Pending done = m_pending.takeAt(i);
        QVariantMap value;
        if (!done.endSwitch.isEmpty())
            value.insert(QStringLiteral("endSwitch"), done.endSwitch);
        m_host.succeed(done.id, value.isEmpty() ? QVariant() : QVariant(value));
    }
}

void LaserAxisMotion::armDeadline()
{
    qint64 earliest = -1;
    for (const Track& t : std::as_const(m_tracks)) {
        if (t.awaiting && (earliest < 0 || t.deadlineMs < earliest))
            earliest = t.deadlineMs;
    }
    if (earliest < 0) {
        m_deadline.stop();
        return;
    }
    m_deadline.start(
        int(qBound<qint64>(0, earliest - m_clock.elapsed(), qint64(24) * 3600 * 1000)));
}

void LaserAxisMotion::onDeadline()
{
    const qint64 now = m_clock.elapsed();
    QList<QPair<Axis, QString>> expired;
    for (auto it = m_tracks.begin(); it != m_tracks.end(); ++it) {
        if (!it->awaiting || it->deadlineMs > now)
            continue;
        it->awaiting = false;
        it->unconfirmed = true; // no longer tracked, and it may be moving yet
        AxisStatus& axis = m_host.statusToChange().axes[it.key()];
        axis.moving = false;
        // The axis is somewhere between where it was and the target: a relative move from the
        // last reported position would go to the wrong place (found by the fault soak). The
        // next status frame makes it known again.
        axis.positionKnown = false;
        expired.append(
            {it.key(), tr("axis %1 did not report reaching its target %2 within %3 s; "
                          "it may still be moving")
                           .arg(axisName(it.key()))
                           .arg(it->command == Command::Home ? 0 : it->target)
                           .arg(m_host.controller().options().arrivalTimeoutMs / 1000.0)});
    }
    armDeadline();
    updateMachineFlags();
    m_host.publish();
    for (const auto& [axis, why] : expired) {
        qCWarning(lcLaser) << why;
        for (int i = m_pending.size() - 1; i >= 0; --i) {
            if (m_pending.at(i).waiting.contains(axis))
                m_host.fail(m_pending.takeAt(i).id, ErrorKind::Timeout, why);
        }
        Q_EMIT m_host.controller().errorOccurred(why);
    }
}

void LaserAxisMotion::updateMachineFlags()
{
    MachineStatus& s = m_host.statusToChange();
    bool busy = false;
    bool unconfirmed = false;
    for (const Track& t : std::as_const(m_tracks)) {
        busy = busy || t.awaiting;
        unconfirmed = unconfirmed || t.unconfirmed;
    }
    s.busy = busy;
    // An axis the host stopped tracking (arrival overdue, link closed or lost while a target
    // was out) may still move: motion unconfirmed (docs/architecture.md) until a status frame
    // from every such axis came. A target being tracked is motion, shown as busy/moving.
    if (unconfirmed)
        s.motionUnconfirmed = true;
    else
        m_host.confirmStandstill();
}

} // namespace stepdeck::laser
