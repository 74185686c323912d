// Stop and panic on a Nanotec bus: 'S' has no ramp (6.2), so speed-mode runs are lowered to
// the start frequency first; panic is one '#*S' to every drive (1.1), confirmed per drive.
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "NanotecLogging.h"
#include "transport/Transport.h"

namespace stepdeck::nanotec {

namespace {

QByteArray num(const char* cmd, qint64 v)
{
    return QByteArray(cmd) + QByteArray::number(v);
}
} // namespace

bool NanotecController::mayMove(const Drive& d) const
{
    // A silent drive is unknown: whatever it did last may still go on.
    return !d.responding || d.jog != Jog::Idle || d.velocityMove || d.motionPending ||
           d.referencing || (d.status && !decodeStatus(*d.status).ready);
}

bool NanotecController::motionMayBeRunning() const
{
    if (jogActive() || status().motionUnconfirmed)
        return true;
    for (const Drive& d : m_drives) {
        if (mayMove(d))
            return true;
    }
    return false;
}

int NanotecController::safetyStopTimeoutMs() const
{
    // One short exchange per drive (a silent one costs its timeout) plus the broadcast guard.
    return int(m_drives.size()) * (pollTimeoutMs() + 20) + 150;
}

void NanotecController::sendSafetyStop(std::function<void(bool)> done)
{
    haltJogImmediately();
    m_poller.stop();
    m_bus->cancelAll();
    QList<Axis> targets;
    for (const Drive& d : m_drives) {
        if (mayMove(d))
            targets << d.axis;
    }
    if (targets.isEmpty() && !jogActive())
        return done(true);
    // 6.2: 'S' is the only way to end speed mode. Written to every drive that may move, silent
    // or not, without a ramp (there is no time for one when the host lets go); then '#*S' to
    // every drive on the bus as the last resort for one whose address or echo was lost.
    auto echoed = std::make_shared<int>(0);
    QList<Step> steps;
    for (Axis a : targets) {
        steps << tolerant([this, a, echoed](const Done& stepDone) {
            exchange(a, "S", {}, NanotecBus::Priority::Urgent, 0,
                     pollTimeoutMs())([echoed, stepDone](const Failure& f) {
                if (f.ok())
                    ++*echoed;
                stepDone(f);
            });
        });
    }
    steps << [this](const Done& stepDone) {
        NanotecBus::Request all;
        all.address = kBroadcast;
        all.body = "S";
        all.priority = NanotecBus::Priority::Urgent;
        all.done = [stepDone](NanotecBus::Outcome, const Reply&) { stepDone({}); };
        m_bus->submit(all);
    };
    for (Drive& d : m_drives) {
        d.jogDesired = 0;
        d.jog = Jog::Idle;
        d.jogBusy = false;
        d.velocityMove = false;
        d.motionPending = false;
        d.referencing = false;
        if (targets.contains(d.axis)) {
            AxisStatus& st = mutableStatus().axes[d.axis];
            st.referenced = st.positionKnown = false; // 6.2: no ramp, steps may be lost
        }
    }
    const int expected = int(targets.size());
    runSteps(steps, [echoed, expected, done](const Failure&) { done(*echoed == expected); });
}

void NanotecController::abortHostSide(ErrorKind kind, const QString& message)
{
    m_poller.stop();
    m_bus->cancelAll();
    haltJogImmediately();
    m_closedLoop->abortAll(kind, message);
    for (Drive& d : m_drives) {
        d.jogDesired = 0;
        d.jog = Jog::Idle;
        d.jogBusy = false;
        d.velocityMove = false;
        d.motionPending = false;
        d.referencing = false;
    }
    m_initialising = false;
    if (m_pendingOpen)
        finishError(std::exchange(m_pendingOpen, 0), kind, message);
    if (m_pendingScan) {
        finishError(m_pendingScan->id, kind, message);
        m_pendingScan.reset();
    }
}

void NanotecController::stop(RequestId id)
{
    if (!canWriteStop())
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    haltJogImmediately();
    // Snapshot first: cancelling the bus ends jog sequences, whose callbacks reset the state.
    QList<Axis> speedMode, positioning;
    for (Drive& d : m_drives) {
        d.jogDesired = 0;
        if (!d.responding)
            continue;
        if (d.jog != Jog::Idle)
            speedMode << d.axis;
        else if (d.motionPending || (d.status && !decodeStatus(*d.status).ready))
            positioning << d.axis;
    }
    QMap<Axis, double> speeds;
    for (Axis a : speedMode)
        speeds[a] = qAbs(m_drives[a].jogApplied);
    m_bus->cancelAll();
    m_closedLoop->abortAll(ErrorKind::Cancelled, tr("stopped"));
    const auto urgent = NanotecBus::Priority::Urgent;
    QList<Step> steps;
    int wait = 0;
    for (Axis a : speedMode) {
        steps << tolerant(exchange(a, num("o", m_drives[a].minFrequency), {}, urgent, 1));
        wait = qMax(wait, rampTimeMs(m_drives[a], speeds[a]));
    }
    if (wait > 0)
        steps << this->wait(qMin(wait, kMaxRampWaitMs));
    // Every drive, a silent one included: it may have stopped answering but still listen.
    for (const Drive& d : m_drives)
        steps << tolerant(exchange(d.axis, "S", {}, urgent, d.responding ? 2 : 0));
    for (Axis a : positioning) {
        // 6.2: no ramp; steps may be lost at speed, so the position is suspect.
        AxisStatus& st = mutableStatus().axes[a];
        st.referenced = st.positionKnown = false;
    }
    if (wait > kMaxRampWaitMs)
        positioning << speedMode;
    for (Axis a : speedMode) {
        Drive& d = m_drives[a];
        if (d.savedMaxFrequency > 0)
            steps << tolerant(exchange(a, num("o", d.savedMaxFrequency), {}, urgent, 1));
    }
    for (Drive& d : m_drives) {
        d.jog = Jog::Idle;
        d.jogBusy = false;
        d.velocityMove = false;
        d.motionPending = false;
        d.referencing = false;
    }
    if (!positioning.isEmpty())
        qCInfo(lcNanotec) << "stopped without ramp; positions suspect:" << positioning.size();
    runSteps(steps, [this, id](const Failure& f) {
        if (!f.ok())
            return finishWith(id, f);
        confirmStopped(id, m_drives.keys(), tr("stop"));
    });
}

void NanotecController::panic(RequestId id)
{
    if (!transport() || !transport()->isOpen())
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    haltJogImmediately();
    for (Drive& d : m_drives)
        d.jogDesired = 0;
    m_bus->cancelAll();
    m_bus->discardOutput(); // the stop must not wait behind queued bytes
    m_panic = true;
    m_closedLoop->abortAll(ErrorKind::Cancelled, tr("emergency stop"));
    markAllUnreferenced();
    QList<Axis> restore;
    for (Drive& d : m_drives) {
        if (d.jog != Jog::Idle && d.savedMaxFrequency > 0)
            restore << d.axis;
        d.jog = Jog::Idle;
        d.jogBusy = false;
        d.velocityMove = false;
        d.motionPending = false;
        d.referencing = false;
    }
    updateStatus();
    publishStatus();
    NanotecBus::Request r;
    r.address = kBroadcast; // '#*S': every drive on the bus stops at once (1.1, 6.2)
    r.body = "S";
    r.priority = NanotecBus::Priority::Urgent;
    r.done = [this, id, restore](NanotecBus::Outcome, const Reply&) {
        confirmStopped(id, m_drives.keys(), tr("emergency stop"));
        for (Axis a : restore) {
            tolerant(exchange(a, num("o", m_drives[a].savedMaxFrequency)))([](const Failure&) {});
        }
    };
    m_bus->submit(r);
}

void NanotecController::confirmStopped(RequestId id, QList<Axis> axes, const QString& context)
{
    // Per drive: ready ('$' bit 0) means stopped; otherwise stop it individually, ask again.
    auto unconfirmed = std::make_shared<QStringList>();
    QList<Step> steps;
    const auto urgent = NanotecBus::Priority::Urgent;
    for (Axis axis : axes) {
        steps << [this, axis, unconfirmed, urgent](const Done& done) {
            auto ready = std::make_shared<bool>(false);
            auto check = sink([this, axis, ready](qint64 v) {
                applyStatusWord(m_drives[axis], v);
                *ready = decodeStatus(v).ready;
            });
            exchange(axis, "$", check, urgent, 1)([=](const Failure& f) {
                if (f.kind == ErrorKind::Cancelled)
                    return done(f);
                if (f.ok() && *ready)
                    return done({});
                runSteps({exchange(axis, "S", {}, urgent, 1), exchange(axis, "$", check, urgent)},
                         [=](const Failure& f2) {
                             if (!f2.ok() || !*ready)
                                 *unconfirmed << driveName(axis);
                             done(f2.kind == ErrorKind::Cancelled ? f2 : Failure{});
                         });
            });
        };
    }
    runSteps(steps, [this, id, unconfirmed, context](const Failure& f) {
        updateStatus();
        publishStatus();
        if (!f.ok())
            return finishWith(id, f);
        if (!unconfirmed->isEmpty()) {
            markMotionUnconfirmed();
            return finishError(
                id, ErrorKind::Timeout,
                tr("%1 sent; not confirmed by %2: %3")
                    .arg(context, unconfirmed->join(QStringLiteral(", ")), mayStillBeMovingText()));
        }
        finishOk(id);
    });
}

void NanotecController::reset(RequestId id)
{
    m_panic = false;
    updateStatus();
    publishStatus();
    finishOk(id);
}

QString NanotecController::jogRefusal() const
{
    return Controller::jogRefusal();
}

} // namespace stepdeck::nanotec
