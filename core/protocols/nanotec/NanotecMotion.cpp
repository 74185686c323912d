// Motion on a Nanotec bus, mapped onto the motor modes of the manual: positioning (!1, p1/p2,
// 6.6), reference runs (p3/p4 with d), speed mode (!2, p1) for jog and velocity moves, 'S' to
// stop (6.2) and '#*S' for panic.
#include "Logging.h"
#include "NanotecController.h"
#include "transport/Transport.h"
#include <QTimer>
#include <QtMath>

namespace stepdeck::nanotec {

namespace {
constexpr qint64 kMaxFrequency = 25000; // 'o' range (6.9)

QByteArray num(const char* cmd, qint64 v)
{
    return QByteArray(cmd) + QByteArray::number(v);
}
} // namespace

QString NanotecController::unknownAxes(const QList<Axis>& axes) const
{
    for (Axis a : axes) {
        if (!m_drives.contains(a))
            return tr("this machine has no axis %1").arg(axisName(a));
    }
    return {};
}

QString NanotecController::motionRefusal(Axis axis, bool needsPosition) const
{
    if (!m_drives.contains(axis))
        return tr("this machine has no axis %1").arg(axisName(axis));
    if (m_panic)
        return tr("emergency stop is active; reset it first");
    const Drive& d = m_drives[axis];
    if (!d.responding)
        return tr("%1 is not answering").arg(driveName(axis));
    if (d.jog != Jog::Idle)
        return tr("axis %1 runs in speed mode (jog or velocity move); stop it first")
            .arg(axisName(axis));
    const DriveState s = decodeStatus(d.status.value_or(0x01));
    if (d.motionPending || !s.ready)
        return tr("axis %1 is still moving (the drive is not ready)").arg(axisName(axis));
    if (s.positionError) {
        const QString how = options().actionNames.value(QStringLiteral("reset-position-error"));
        return how.isEmpty() ? tr("%1 reports a position error; reset the position error first")
                                   .arg(driveName(axis))
                             : tr("%1 reports a position error; reset it first with %2")
                                   .arg(driveName(axis), how);
    }
    if (needsPosition && !status().axes.value(axis).positionKnown)
        return tr("absolute move refused: position of axis %1 is unknown, reference it first")
            .arg(axisName(axis));
    return {};
}

void NanotecController::moveRelative(RequestId id, const AxisVector& steps)
{
    if (linkState() != LinkState::Connected)
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(steps.keys()); !bad.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, bad);
    QMap<Axis, QList<QByteArray>> setup;
    QMap<Axis, QMap<QByteArray, qint64>> verify;
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        if (it.value() == 0 && m_drives.contains(it.key()))
            continue;
        if (qAbs(it.value()) > std::numeric_limits<qint32>::max())
            return finishError(id, ErrorKind::InvalidValue,
                               tr("move of axis %1: %2 steps exceed the 32-bit range (6.7)")
                                   .arg(axisName(it.key()))
                                   .arg(it.value()));
        const QString why = motionRefusal(it.key(), false);
        if (!why.isEmpty())
            return finishError(id, ErrorKind::Refused, why);
        // 6.6 p=1: 's' is the positive distance, 'd' the direction (1 counts up).
        setup[it.key()] = {"!1", "p1", num("s", qAbs(it.value())), num("d", it.value() > 0)};
        verify[it.key()] = {{"!", 1},
                            {"p", 1},
                            {"s", qAbs(it.value())},
                            {"d", it.value() > 0},
                            {"o", m_drives[it.key()].maxFrequency}};
    }
    if (setup.isEmpty())
        return finishOk(id);
    startPositioning(id, setup, false, verify);
}

void NanotecController::moveAbsolute(RequestId id, const AxisVector& targets)
{
    if (linkState() != LinkState::Connected)
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(targets.keys()); !bad.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, bad);
    QMap<Axis, QList<QByteArray>> setup;
    QMap<Axis, QMap<QByteArray, qint64>> verify;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        if (qAbs(it.value()) > std::numeric_limits<qint32>::max())
            return finishError(
                id, ErrorKind::InvalidValue,
                tr("target of axis %1 exceeds the 32-bit range (6.7)").arg(axisName(it.key())));
        const QString why = motionRefusal(it.key(), true);
        if (!why.isEmpty())
            return finishError(id, ErrorKind::Refused, why);
        // 6.6 p=2: 's' is the target relative to the reference position; 'd' is ignored.
        setup[it.key()] = {"!1", "p2", num("s", it.value())};
        verify[it.key()] = {
            {"!", 1}, {"p", 2}, {"s", it.value()}, {"o", m_drives[it.key()].maxFrequency}};
    }
    if (setup.isEmpty())
        return finishOk(id);
    startPositioning(id, setup, false, verify);
}

void NanotecController::reference(RequestId id, const QMap<Axis, int>& directions)
{
    referenceWithType(id, directions, false);
}

void NanotecController::referenceWithType(RequestId id, const QMap<Axis, int>& directions,
                                          bool internal)
{
    if (linkState() != LinkState::Connected)
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(directions.keys()); !bad.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, bad);
    QMap<Axis, QList<QByteArray>> setup;
    QMap<Axis, QMap<QByteArray, qint64>> verify;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it) {
        if (it.value() == 0 && m_drives.contains(it.key()))
            continue;
        const QString why = motionRefusal(it.key(), false);
        if (!why.isEmpty())
            return finishError(id, ErrorKind::Refused, why);
        // 6.6: p=4 runs at the upper speed into the external switch, p=3 at the lower speed
        // to the encoder index; free travel afterwards as 'l' says (5.6).
        setup[it.key()] = {"!1", internal ? "p3" : "p4", num("d", it.value() > 0)};
        verify[it.key()] = {{"!", 1},
                            {"p", internal ? 3 : 4},
                            {"d", it.value() > 0},
                            {"o", m_drives[it.key()].maxFrequency}};
    }
    if (setup.isEmpty())
        return finishError(id, ErrorKind::InvalidValue,
                           tr("no axis to reference: every direction is 0"));
    startPositioning(id, setup, true, verify);
}

void NanotecController::startPositioning(RequestId id, const QMap<Axis, QList<QByteArray>>& setup,
                                         bool referenceRun,
                                         const QMap<Axis, QMap<QByteArray, qint64>>& verify)
{
    // Set every drive up first and read back what 'A' runs with (a drive left in speed mode by
    // a jog, or a value it ignored, would start the wrong run), then start them one right
    // after the other.
    QList<Step> steps;
    for (auto it = setup.cbegin(); it != setup.cend(); ++it) {
        for (const QByteArray& body : it.value())
            steps << setting(it.key(), body);
    }
    for (auto it = verify.cbegin(); it != verify.cend(); ++it) {
        for (auto v = it.value().cbegin(); v != it.value().cend(); ++v)
            steps << expectValue(it.key(), v.key(), v.value());
    }
    auto started = std::make_shared<QList<Axis>>();
    for (Axis axis : setup.keys()) {
        steps << [this, axis, started, referenceRun](const Done& done) {
            startRun(axis)([this, axis, started, referenceRun, done](const Failure& f) {
                if (f.ok()) {
                    *started << axis;
                    Drive& d = m_drives[axis];
                    d.motionPending = true;
                    d.referencing = referenceRun;
                    if (referenceRun) {
                        AxisStatus& a = mutableStatus().axes[axis];
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
                tolerant(exchange(axis, "S", {}, NanotecBus::Priority::Urgent, 2))(
                    [](const Failure&) {});
        }
        updateStatus();
        publishStatus();
        finishWith(id, f);
    });
}

// ---------------------------------------------------------------- speed mode

NanotecController::Step NanotecController::setting(Axis axis, const QByteArray& body)
{
    // Settings are idempotent: a reply garbled by line noise is simply asked again.
    return exchange(axis, body, {}, NanotecBus::Priority::Command, 1);
}

NanotecController::Step NanotecController::startRun(Axis axis)
{
    // 'A' is not idempotent (a second 'A' could repeat a relative move). When its echo is
    // lost or garbled, the status tells whether it started: running means it did (5.21).
    return [this, axis](const Done& done) {
        exchange(axis, "A")([this, axis, done](const Failure& f) {
            if (f.ok() || (f.kind != ErrorKind::Protocol && f.kind != ErrorKind::Timeout))
                return done(f);
            auto running = std::make_shared<bool>(false);
            auto check = sink([this, axis, running](qint64 v) {
                applyStatusWord(m_drives[axis], v);
                *running = !decodeStatus(v).ready;
            });
            exchange(axis, "$", check, NanotecBus::Priority::Command,
                     1)([f, running, done](const Failure& read) {
                done(read.ok() && *running ? Failure{} : f);
            });
        });
    };
}

int NanotecController::rampTimeMs(const Drive& d, double fromHz) const
{
    // 6.11: acceleration in Hz/ms = 3000 / sqrt(b) - 11.7.
    const double perMs = 3000.0 / qSqrt(double(qMax<qint64>(1, d.ramp))) - 11.7;
    const double delta = qMax(0.0, fromHz - double(d.minFrequency));
    if (delta == 0)
        return 0;
    if (perMs <= 0.001)
        return kMaxRampWaitMs + 1;
    return int(qCeil(delta / perMs * 1.2)) + 10; // 20 % margin for the drive's rounding
}

QList<NanotecController::Step> NanotecController::rampDownSteps(Drive& d,
                                                                NanotecBus::Priority priority)
{
    // 6.2: 'S' stops without a ramp and may lose steps at speed, so in speed mode the speed
    // is first lowered to the start frequency (the drive ramps it) and 'S' follows.
    const Axis axis = d.axis;
    const int t = rampTimeMs(d, qAbs(d.jogApplied));
    const bool cut = t > kMaxRampWaitMs;
    QList<Step> steps{tolerant(exchange(axis, num("o", d.minFrequency), {}, priority, 1)),
                      wait(qMin(t, kMaxRampWaitMs)),
                      tolerant(exchange(axis, "S", {}, priority, 2))};
    if (cut) {
        steps << [this, axis](const Done& done) {
            AxisStatus& a = mutableStatus().axes[axis];
            a.referenced = a.positionKnown = false;
            Q_EMIT errorOccurred(tr("axis %1 was stopped at speed (ramp too long); its position "
                                    "is suspect until referenced")
                                     .arg(axisName(axis)));
            done({});
        };
    }
    if (d.savedMaxFrequency > 0)
        steps << tolerant(exchange(axis, num("o", d.savedMaxFrequency), {}, priority, 1));
    // The drive is ready now; later refusals must not go by the status from before 'S'.
    steps << tolerant(exchange(
        axis, "$", sink([this, axis](qint64 v) { applyStatusWord(m_drives[axis], v); }), priority));
    return steps;
}

QString NanotecController::belowStartFrequency(Axis axis, double stepsPerS) const
{
    // 6.6 speed mode runs between the start frequency 'u' and 'o'; a lower speed cannot be
    // run, and raising it silently would move faster than the operator asked.
    if (!m_drives.contains(axis))
        return {};
    const qint64 u = m_drives[axis].minFrequency;
    if (stepsPerS == 0 || qAbs(stepsPerS) >= double(u))
        return {};
    return tr("axis %1: %2 steps/s is below the drive's start frequency u=%3 steps/s; refused")
        .arg(axisName(axis))
        .arg(qAbs(stepsPerS))
        .arg(u);
}

QString NanotecController::jogAxisRefusal(Axis axis, double target) const
{
    return belowStartFrequency(axis, target);
}

double NanotecController::jogStopDistance(Axis axis, double speed) const
{
    // Soft limits. In speed mode the drive ramps by itself (6.6), so a jog target of zero
    // ends in rampDownSteps(): the zero must persist for 2 jog ticks (+10 ms), 'o' = u goes out
    // behind at most one poll exchange, the drive ramps from speed down to u at its ramp b
    // (6.11), runs at u for the rest of the waited ramp time, then 'S' (the bus again).
    // The position the host checks is the last 'C' plus its own estimate, at most one sweep
    // old. Conservative on purpose: the axis stops short of the limit, never beyond it.
    const Drive d = m_drives.value(axis);
    const double u = double(d.minFrequency);
    const double v = qMax(speed, u);
    const double perS2 = (3000.0 / qSqrt(double(qMax<qint64>(1, d.ramp))) - 11.7) * 1000.0;
    const double braking =
        perS2 > 1.0 ? (v * v - u * u) / (2 * perS2) : v * kMaxRampWaitMs / 1000.0;
    const double latencyS =
        (2.0 * options().jogTickMs + 10 + qMax(m_userPollMs, sweepBudgetMs()) + 40) / 1000.0;
    const double atStartFrequencyS = (rampTimeMs(d, v) + 40) / 1000.0;
    return v * latencyS + 1.2 * braking + u * atStartFrequencyS;
}

void NanotecController::applyJogVelocity(const AxisVelocities& stepsPerS)
{
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        if (!m_drives.contains(it.key()))
            continue;
        Drive& d = m_drives[it.key()];
        if (d.velocityMove) {
            if (it.value() != 0)
                Q_EMIT jogRefused(
                    tr("axis %1 is in a velocity move; stop it first").arg(axisName(it.key())));
            continue;
        }
        d.jogDesired = it.value();
        pumpJog(it.key());
    }
}

void NanotecController::pumpJog(Axis axis, bool zeroConfirmed)
{
    Drive& d = m_drives[axis];
    if (d.jogBusy || linkState() != LinkState::Connected)
        return;
    const double want = d.jogDesired;
    const qint64 hz = qBound<qint64>(d.minFrequency, qRound64(qAbs(want)), kMaxFrequency);
    const double signedHz = want < 0 ? -double(hz) : double(hz);
    auto after = [this, axis](Jog next, double applied) {
        return [this, axis, next, applied](const Failure& f) {
            Drive& dd = m_drives[axis];
            dd.jogBusy = false;
            dd.jog = f.ok() ? next : Jog::Idle;
            dd.jogApplied = f.ok() ? applied : 0;
            if (!f.ok() && f.kind != ErrorKind::Cancelled) {
                dd.jogDesired = 0;
                // A drive that refused is a refusal; silence or garbage is a communication
                // fault, which the poller judges (one fault, one exit code).
                const bool commFault = f.kind == ErrorKind::Timeout ||
                                       f.kind == ErrorKind::Protocol ||
                                       f.kind == ErrorKind::LinkDown;
                if (commFault)
                    Q_EMIT errorOccurred(tr("jog on axis %1: %2").arg(axisName(axis), f.message));
                else
                    Q_EMIT jogRefused(f.message);
                // 'A' or a speed change may have reached the drive: never leave it running
                // at a rate nobody controls.
                if (next == Jog::Running)
                    tolerant(exchange(axis, "S", {}, NanotecBus::Priority::Urgent, 2))(
                        [](const Failure&) {});
            }
            updateStatus();
            publishStatus();
            pumpJog(axis);
        };
    };
    if (d.jog == Jog::Idle) {
        if (want == 0)
            return;
        const QString why = motionRefusal(axis, false);
        if (!why.isEmpty()) {
            d.jogDesired = 0;
            Q_EMIT jogRefused(why);
            return;
        }
        d.savedMaxFrequency = d.maxFrequency;
        d.jog = Jog::Starting;
        d.jogBusy = true;
        // 6.6, speed mode p=1: speed and direction changes are ramped by the drive.
        runSteps({setting(axis, "!2"), setting(axis, "p1"), setting(axis, num("o", hz)),
                  setting(axis, num("d", want > 0)), startRun(axis)},
                 after(Jog::Running, signedHz));
        return;
    }
    if (d.jog != Jog::Running)
        return;
    if (want == 0) {
        // The host ramp passes through zero for one tick on a reversal; the drive reverses
        // by itself (6.6), so only a zero that persists stops the run.
        if (!zeroConfirmed) {
            if (!d.stopScheduled) {
                d.stopScheduled = true;
                QTimer::singleShot(2 * options().jogTickMs + 10, this, [this, axis] {
                    m_drives[axis].stopScheduled = false;
                    pumpJog(axis, true);
                });
            }
            return;
        }
        d.jog = Jog::Stopping;
        d.jogBusy = true;
        runSteps(rampDownSteps(d, NanotecBus::Priority::Command), after(Jog::Idle, 0));
        return;
    }
    if (signedHz == d.jogApplied)
        return;
    QList<Step> steps{exchange(axis, num("o", hz))};
    if ((signedHz > 0) != (d.jogApplied > 0))
        steps << exchange(axis, num("d", want > 0));
    d.jogBusy = true;
    runSteps(steps, after(Jog::Running, signedHz));
}

void NanotecController::velocityMove(RequestId id, const AxisVector& stepsPerS)
{
    if (linkState() != LinkState::Connected)
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString bad = unknownAxes(stepsPerS.keys()); !bad.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, bad);
    QList<Step> steps;
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        if (qAbs(it.value()) > kMaxFrequency)
            return finishError(id, ErrorKind::InvalidValue,
                               tr("velocity of axis %1: %2 steps/s is outside 0..25000 (6.9)")
                                   .arg(axisName(it.key()))
                                   .arg(it.value()));
        if (it.value() == 0 && m_drives.contains(it.key()))
            continue;
        const QString why = motionRefusal(it.key(), false);
        if (!why.isEmpty())
            return finishError(id, ErrorKind::Refused, why);
        if (const QString slow = belowStartFrequency(it.key(), double(it.value())); !slow.isEmpty())
            return finishError(id, ErrorKind::Refused, slow);
        const Axis axis = it.key();
        const qint64 v = it.value();
        Drive& d = m_drives[axis];
        const qint64 hz = qBound<qint64>(d.minFrequency, qAbs(v), kMaxFrequency);
        d.savedMaxFrequency = d.maxFrequency;
        steps << setting(axis, "!2") << setting(axis, "p1") << setting(axis, num("o", hz))
              << exchange(axis, num("d", v > 0));
        steps << [this, axis, hz, v](const Done& done) {
            startRun(axis)([this, axis, hz, v, done](const Failure& f) {
                if (f.ok()) {
                    Drive& dd = m_drives[axis];
                    dd.jog = Jog::Running;
                    dd.velocityMove = true;
                    dd.jogApplied = dd.jogDesired = v < 0 ? -double(hz) : double(hz);
                }
                done(f);
            });
        };
    }
    runSteps(steps, [this, id](const Failure& f) {
        if (!f.ok() && f.kind != ErrorKind::Cancelled) {
            for (Drive& d : m_drives) {
                if (!d.velocityMove)
                    continue;
                d.velocityMove = false;
                d.jog = Jog::Idle;
                tolerant(exchange(d.axis, "S", {}, NanotecBus::Priority::Urgent, 2))(
                    [](const Failure&) {});
            }
        }
        updateStatus();
        publishStatus();
        finishWith(id, f);
    });
}

} // namespace stepdeck::nanotec
