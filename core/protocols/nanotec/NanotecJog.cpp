// Jog in speed mode (NanotecJog.h).
#include "NanotecJog.h"
#include "NanotecController.h"
#include <QTimer>
#include <QtMath>

namespace stepdeck::nanotec {

NanotecJog::NanotecJog(NanotecController& controller)
    : m_ctl(controller), m_link(controller.m_exchange)
{}

int NanotecJog::rampTimeMs(const HostDrive& d, double fromHz) const
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

QList<Step> NanotecJog::rampDownSteps(HostDrive& d, NanotecBus::Priority priority)
{
    // 6.2: 'S' stops without a ramp and may lose steps at speed, so in speed mode the speed
    // is first lowered to the start frequency (the drive ramps it) and 'S' follows.
    const Axis axis = d.axis;
    const int t = rampTimeMs(d, qAbs(d.jogApplied));
    const bool cut = t > kMaxRampWaitMs;
    QList<Step> steps{
        tolerant(m_link.exchange(axis, commandWithValue("o", d.minFrequency), {}, priority, 1)),
        m_link.wait(qMin(t, kMaxRampWaitMs)),
        tolerant(m_link.exchange(axis, "S", {}, priority, 2))};
    if (cut) {
        steps << [this, axis](const Done& done) {
            AxisStatus& a = m_ctl.mutableStatus().axes[axis];
            a.referenced = a.positionKnown = false;
            Q_EMIT m_ctl.errorOccurred(
                tr("axis %1 was stopped at speed (ramp too long); its position "
                   "is suspect until referenced")
                    .arg(m_ctl.nameOf(axis)));
            done({});
        };
    }
    if (d.savedMaxFrequency > 0)
        steps << tolerant(
            m_link.exchange(axis, commandWithValue("o", d.savedMaxFrequency), {}, priority, 1));
    // The drive is ready now; later refusals must not go by the status from before 'S'.
    steps << tolerant(m_link.exchange(axis, "$", sink([this, axis](qint64 v) {
                                          m_ctl.m_sweep.applyStatusWord(m_ctl.m_drives[axis], v);
                                      }),
                                      priority));
    return steps;
}

double NanotecJog::jogStopDistance(Axis axis, double speed) const
{
    // Soft limits. In speed mode the drive ramps by itself (6.6), so a jog target of zero
    // ends in rampDownSteps(): the zero must persist for 2 jog ticks (+10 ms), 'o' = u goes out
    // behind at most one poll exchange, the drive ramps from speed down to u at its ramp b
    // (6.11), runs at u for the rest of the waited ramp time, then 'S' (the bus again).
    // The position the host checks is the last 'C' plus its own estimate, at most one sweep
    // old. Conservative on purpose: the axis stops short of the limit, never beyond it.
    const HostDrive d = m_ctl.m_drives.value(axis);
    const double u = double(d.minFrequency);
    const double v = qMax(speed, u);
    const double perS2 = (3000.0 / qSqrt(double(qMax<qint64>(1, d.ramp))) - 11.7) * 1000.0;
    const double braking =
        perS2 > 1.0 ? (v * v - u * u) / (2 * perS2) : v * kMaxRampWaitMs / 1000.0;
    const double latencyS = (2.0 * m_ctl.options().jogTickMs + 10 +
                             qMax(m_ctl.m_userPollMs, m_ctl.m_sweep.sweepBudgetMs()) + 40) /
                            1000.0;
    const double atStartFrequencyS = (rampTimeMs(d, v) + 40) / 1000.0;
    return v * latencyS + 1.2 * braking + u * atStartFrequencyS;
}

void NanotecJog::applyJogVelocity(const AxisVelocities& stepsPerS)
{
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        if (!m_ctl.m_drives.contains(it.key()))
            continue;
        HostDrive& d = m_ctl.m_drives[it.key()];
        if (d.velocityMove) {
            if (it.value() != 0)
                Q_EMIT m_ctl.jogRefused(
                    tr("axis %1 is in a velocity move; stop it first").arg(m_ctl.nameOf(it.key())));
            continue;
        }
        d.jogDesired = it.value();
        pumpJog(it.key());
    }
}

Done NanotecJog::jogDone(Axis axis, JogPhase next, double applied)
{
    return [this, axis, next, applied](const Failure& f) {
        HostDrive& dd = m_ctl.m_drives[axis];
        dd.jogBusy = false;
        dd.jog = f.ok() ? next : JogPhase::Idle;
        dd.jogApplied = f.ok() ? applied : 0;
        if (!f.ok() && f.kind != ErrorKind::Cancelled) {
            dd.jogDesired = 0;
            // A drive that refused is a refusal; silence or garbage is a communication
            // fault, which the poller judges (one fault, one exit code).
            const bool commFault = f.kind == ErrorKind::Timeout || f.kind == ErrorKind::Protocol ||
                                   f.kind == ErrorKind::LinkDown;
            if (commFault)
                Q_EMIT m_ctl.errorOccurred(
                    tr("jog on axis %1: %2").arg(m_ctl.nameOf(axis), f.message));
            else
                Q_EMIT m_ctl.jogRefused(f.message);
            // 'A' or a speed change may have reached the drive: never leave it running
            // at a rate nobody controls.
            if (next == JogPhase::Running)
                tolerant(m_link.exchange(axis, "S", {}, NanotecBus::Priority::Urgent, 2))(
                    [](const Failure&) {});
        }
        m_ctl.m_sweep.updateStatus();
        m_ctl.publishStatus();
        pumpJog(axis);
    };
}

void NanotecJog::pumpJog(Axis axis, bool zeroConfirmed)
{
    HostDrive& d = m_ctl.m_drives[axis];
    if (d.jogBusy || m_ctl.linkState() != LinkState::Connected)
        return;
    const double want = d.jogDesired;
    const qint64 hz = qBound<qint64>(d.minFrequency, qRound64(qAbs(want)), kMaxFrequency);
    const double signedHz = want < 0 ? -double(hz) : double(hz);
    if (d.jog == JogPhase::Idle) {
        if (want != 0)
            startJog(d, want, hz, signedHz);
        return;
    }
    if (d.jog != JogPhase::Running)
        return;
    if (want == 0)
        return stopJog(d, zeroConfirmed);
    if (signedHz == d.jogApplied)
        return;
    QList<Step> steps{m_link.exchange(axis, commandWithValue("o", hz))};
    if ((signedHz > 0) != (d.jogApplied > 0))
        steps << m_link.exchange(axis, commandWithValue("d", want > 0));
    d.jogBusy = true;
    runSteps(steps, jogDone(axis, JogPhase::Running, signedHz));
}

void NanotecJog::startJog(HostDrive& d, double want, qint64 hz, double signedHz)
{
    const Axis axis = d.axis;
    const QString why = m_ctl.m_motion.motionRefusal(axis, false);
    if (!why.isEmpty()) {
        d.jogDesired = 0;
        Q_EMIT m_ctl.jogRefused(why);
        return;
    }
    d.savedMaxFrequency = d.maxFrequency;
    d.jog = JogPhase::Starting;
    d.jogBusy = true;
    // 6.6, speed mode p=1: speed and direction changes are ramped by the drive.
    runSteps({m_link.setting(axis, "!2"), m_link.setting(axis, "p1"),
              m_link.setting(axis, commandWithValue("o", hz)),
              m_link.setting(axis, commandWithValue("d", want > 0)), m_link.startRun(axis)},
             jogDone(axis, JogPhase::Running, signedHz));
}

void NanotecJog::stopJog(HostDrive& d, bool zeroConfirmed)
{
    const Axis axis = d.axis;
    // The host ramp passes through zero for one tick on a reversal; the drive reverses
    // by itself (6.6), so only a zero that persists stops the run.
    if (!zeroConfirmed) {
        if (!d.stopScheduled) {
            d.stopScheduled = true;
            QTimer::singleShot(2 * m_ctl.options().jogTickMs + 10, &m_ctl, [this, axis] {
                m_ctl.m_drives[axis].stopScheduled = false;
                pumpJog(axis, true);
            });
        }
        return;
    }
    d.jog = JogPhase::Stopping;
    d.jogBusy = true;
    runSteps(rampDownSteps(d, NanotecBus::Priority::Command), jogDone(axis, JogPhase::Idle, 0));
}

} // namespace stepdeck::nanotec
