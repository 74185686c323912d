// Motion on a Nanotec bus, mapped onto the motor modes of the manual: positioning (!1, p1/p2,
// 6.6), reference runs (p3/p4 with d) and velocity moves in speed mode (!2, p1).
#include "NanotecMotion.h"
#include "NanotecController.h"
#include <limits>

namespace stepdeck::nanotec {

NanotecMotion::NanotecMotion(NanotecController& controller)
    : m_ctl(controller), m_link(controller.m_exchange)
{}

QString NanotecMotion::unknownAxes(const QList<Axis>& axes) const
{
    for (Axis a : axes) {
        if (!m_ctl.m_drives.contains(a))
            return tr("this machine has no axis %1").arg(m_ctl.nameOf(a));
    }
    return {};
}

QString NanotecMotion::motionRefusal(Axis axis, bool needsPosition, bool referenceRun) const
{
    if (!m_ctl.m_drives.contains(axis))
        return tr("this machine has no axis %1").arg(m_ctl.nameOf(axis));
    if (m_ctl.m_panic)
        return tr("emergency stop is active; reset it first");
    const HostDrive& d = m_ctl.m_drives[axis];
    if (!d.responding)
        return tr("%1 is not answering").arg(m_ctl.driveName(axis));
    if (d.jog != JogPhase::Idle)
        return tr("axis %1 runs in speed mode (jog or velocity move); stop it first")
            .arg(m_ctl.nameOf(axis));
    const DriveState s = decodeStatus(d.status.value_or(0x01));
    if (d.motionPending || !s.ready)
        return tr("axis %1 is still moving (the drive is not ready)").arg(m_ctl.nameOf(axis));
    if (s.positionError && !referenceRun) {
        const QString how =
            m_ctl.options().actionNames.value(QStringLiteral("reset-position-error"));
        return how.isEmpty() ? tr("%1 reports a position error; reset the position error first")
                                   .arg(m_ctl.driveName(axis))
                             : tr("%1 reports a position error; reset it first with %2")
                                   .arg(m_ctl.driveName(axis), how);
    }
    if (needsPosition && !m_ctl.status().axes.value(axis).positionKnown)
        return tr("absolute move refused: position of axis %1 is unknown, reference it first")
            .arg(m_ctl.nameOf(axis));
    return {};
}

void NanotecMotion::moveRelative(RequestId id, const AxisVector& steps)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(steps.keys()); !bad.isEmpty())
        return m_ctl.finishError(id, ErrorKind::InvalidValue, bad);
    QMap<Axis, QList<QByteArray>> setup;
    QMap<Axis, QMap<QByteArray, qint64>> verify;
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        if (it.value() == 0 && m_ctl.m_drives.contains(it.key()))
            continue;
        if (qAbs(it.value()) > std::numeric_limits<qint32>::max())
            return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                     tr("move of axis %1: %2 steps exceed the 32-bit range (6.7)")
                                         .arg(m_ctl.nameOf(it.key()))
                                         .arg(it.value()));
        const QString why = motionRefusal(it.key(), false);
        if (!why.isEmpty())
            return m_ctl.finishError(id, ErrorKind::Refused, why);
        // 6.6 p=1: 's' is the positive distance, 'd' the direction (1 counts up).
        setup[it.key()] = {"!1", "p1", commandWithValue("s", qAbs(it.value())),
                           commandWithValue("d", it.value() > 0)};
        verify[it.key()] = {{"!", 1},
                            {"p", 1},
                            {"s", qAbs(it.value())},
                            {"d", it.value() > 0},
                            {"o", m_ctl.m_drives[it.key()].maxFrequency}};
    }
    if (setup.isEmpty())
        return m_ctl.finishOk(id);
    startPositioning(id, setup, false, verify);
}

void NanotecMotion::moveAbsolute(RequestId id, const AxisVector& targets)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(targets.keys()); !bad.isEmpty())
        return m_ctl.finishError(id, ErrorKind::InvalidValue, bad);
    QMap<Axis, QList<QByteArray>> setup;
    QMap<Axis, QMap<QByteArray, qint64>> verify;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        if (qAbs(it.value()) > std::numeric_limits<qint32>::max())
            return m_ctl.finishError(
                id, ErrorKind::InvalidValue,
                tr("target of axis %1 exceeds the 32-bit range (6.7)").arg(m_ctl.nameOf(it.key())));
        const QString why = motionRefusal(it.key(), true);
        if (!why.isEmpty())
            return m_ctl.finishError(id, ErrorKind::Refused, why);
        // 6.6 p=2: 's' is the target relative to the reference position; 'd' is ignored.
        // Issue 30: in a chain of chords the drive stays in positioning mode; what a read-back
        // showed and nothing can have changed since (NanotecHeldSettings) is neither written
        // nor read back again. The target always is.
        const Axis axis = it.key();
        const qint64 o = m_ctl.m_drives[axis].maxFrequency;
        const bool modeHeld =
            m_link.holds(axis, '!', 1) && m_link.holds(axis, 'p', 2) && m_link.holds(axis, 'N', 0);
        setup[axis] = {commandWithValue("s", it.value())};
        verify[axis] = {{"s", it.value()}};
        if (!modeHeld) {
            setup[axis] = QList<QByteArray>{"!1", "p2"} + setup[axis];
            verify[axis].insert("!", 1);
            verify[axis].insert("p", 2);
        }
        if (!m_link.holds(axis, 'o', o))
            verify[axis].insert("o", o);
    }
    if (setup.isEmpty())
        return m_ctl.finishOk(id);
    startPositioning(id, setup, false, verify, {'N'});
}

void NanotecMotion::referenceWithType(RequestId id, const QMap<Axis, int>& directions,
                                      bool internal)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(directions.keys()); !bad.isEmpty())
        return m_ctl.finishError(id, ErrorKind::InvalidValue, bad);
    QMap<Axis, QList<QByteArray>> setup;
    QMap<Axis, QMap<QByteArray, qint64>> verify;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it) {
        if (it.value() == 0 && m_ctl.m_drives.contains(it.key()))
            continue;
        const QString why = motionRefusal(it.key(), false, true);
        if (!why.isEmpty())
            return m_ctl.finishError(id, ErrorKind::Refused, why);
        // 6.6: p=4 runs at the upper speed into the external switch, p=3 at the lower speed
        // to the encoder index; free travel afterwards as 'l' says (5.6).
        setup[it.key()] = {"!1", internal ? "p3" : "p4", commandWithValue("d", it.value() > 0)};
        // A position error (after a stop without ramp, 6.2) would refuse the run that finds
        // the position anew: it is reset first (5.14), as the operator would have to.
        if (decodeStatus(m_ctl.m_drives[it.key()].status.value_or(0)).positionError)
            setup[it.key()].prepend("D");
        verify[it.key()] = {{"!", 1},
                            {"p", internal ? 3 : 4},
                            {"d", it.value() > 0},
                            {"o", m_ctl.m_drives[it.key()].maxFrequency}};
    }
    if (setup.isEmpty())
        return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                 tr("no axis to reference: every direction is 0"));
    startPositioning(id, setup, true, verify);
}

void NanotecMotion::startPositioning(RequestId id, const QMap<Axis, QList<QByteArray>>& setup,
                                     bool referenceRun,
                                     const QMap<Axis, QMap<QByteArray, qint64>>& verify,
                                     const QList<char>& learn)
{
    // Set every drive up first and read back what 'A' runs with (a drive left in speed mode by
    // a jog, or a value it ignored, would start the wrong run), then start them one right
    // after the other.
    QList<Step> steps;
    for (auto it = setup.cbegin(); it != setup.cend(); ++it) {
        for (const QByteArray& body : it.value())
            steps << m_link.setting(it.key(), body);
    }
    for (auto it = verify.cbegin(); it != verify.cend(); ++it) {
        for (auto v = it.value().cbegin(); v != it.value().cend(); ++v)
            steps << m_link.expectValue(it.key(), v.key(), v.value());
        for (char key : learn) {
            if (!m_link.holds(it.key(), key, 0))
                steps << m_link.learnValue(it.key(), key);
        }
    }
    auto started = std::make_shared<QList<Axis>>();
    for (Axis axis : setup.keys()) {
        steps << [this, axis, started, referenceRun](const Done& done) {
            m_link.startRun(axis)([this, axis, started, referenceRun, done](const Failure& f) {
                if (f.ok()) {
                    *started << axis;
                    HostDrive& d = m_ctl.m_drives[axis];
                    d.motionPending = true;
                    d.referencing = referenceRun;
                    if (referenceRun) {
                        AxisStatus& a = m_ctl.mutableStatus().axes[axis];
                        a.referenced = a.positionKnown = false;
                    }
                }
                done(f);
            });
        };
    }
    runSteps(steps, [this, id, started](const Failure& f) {
        if (!f.ok() && f.kind != ErrorKind::Cancelled) {
            // Never leave some axes of a multi-axis move running alone.
            for (Axis axis : *started)
                tolerant(m_link.exchange(axis, "S", {}, NanotecBus::Priority::Urgent, 2))(
                    [](const Failure&) {});
        }
        m_ctl.m_sweep.updateStatus();
        m_ctl.m_sweep.paceForMotion();
        m_ctl.publishStatus();
        m_ctl.finishWith(id, f);
    });
}

QString NanotecMotion::belowStartFrequency(Axis axis, double stepsPerS) const
{
    // 6.6 speed mode runs between the start frequency 'u' and 'o'; a lower speed cannot be
    // run, and raising it silently would move faster than the operator asked.
    if (!m_ctl.m_drives.contains(axis))
        return {};
    const qint64 u = m_ctl.m_drives[axis].minFrequency;
    if (stepsPerS == 0 || qAbs(stepsPerS) >= double(u))
        return {};
    return tr("axis %1: %2 steps/s is below the drive's start frequency u=%3 steps/s; refused")
        .arg(m_ctl.nameOf(axis))
        .arg(qAbs(stepsPerS))
        .arg(u);
}

void NanotecMotion::velocityMove(RequestId id, const AxisVector& stepsPerS)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(stepsPerS.keys()); !bad.isEmpty())
        return m_ctl.finishError(id, ErrorKind::InvalidValue, bad);
    QList<Step> steps;
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        if (qAbs(it.value()) > kMaxFrequency)
            return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                     tr("velocity of axis %1: %2 steps/s is outside 0..25000 (6.9)")
                                         .arg(m_ctl.nameOf(it.key()))
                                         .arg(it.value()));
        if (it.value() == 0 && m_ctl.m_drives.contains(it.key()))
            continue;
        const QString why = motionRefusal(it.key(), false);
        if (!why.isEmpty())
            return m_ctl.finishError(id, ErrorKind::Refused, why);
        if (const QString slow = belowStartFrequency(it.key(), double(it.value())); !slow.isEmpty())
            return m_ctl.finishError(id, ErrorKind::Refused, slow);
        const Axis axis = it.key();
        const qint64 v = it.value();
        HostDrive& d = m_ctl.m_drives[axis];
        const qint64 hz = qBound<qint64>(d.minFrequency, qAbs(v), kMaxFrequency);
        d.savedMaxFrequency = d.maxFrequency;
        steps << m_link.setting(axis, "!2") << m_link.setting(axis, "p1")
              << m_link.setting(axis, commandWithValue("o", hz))
              << m_link.exchange(axis, commandWithValue("d", v > 0));
        steps << [this, axis, hz, v](const Done& done) {
            m_link.startRun(axis)([this, axis, hz, v, done](const Failure& f) {
                if (f.ok()) {
                    HostDrive& dd = m_ctl.m_drives[axis];
                    dd.jog = JogPhase::Running;
                    dd.velocityMove = true;
                    dd.jogApplied = dd.jogDesired = v < 0 ? -double(hz) : double(hz);
                }
                done(f);
            });
        };
    }
    runSteps(steps, [this, id](const Failure& f) {
        if (!f.ok() && f.kind != ErrorKind::Cancelled) {
            for (HostDrive& d : m_ctl.m_drives) {
                if (!d.velocityMove)
                    continue;
                d.velocityMove = false;
                d.jog = JogPhase::Idle;
                tolerant(m_link.exchange(d.axis, "S", {}, NanotecBus::Priority::Urgent, 2))(
                    [](const Failure&) {});
            }
        }
        m_ctl.m_sweep.updateStatus();
        m_ctl.m_sweep.paceForMotion();
        m_ctl.publishStatus();
        m_ctl.finishWith(id, f);
    });
}

} // namespace stepdeck::nanotec
