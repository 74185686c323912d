// Stop and panic on a Nanotec bus (NanotecStop.h).
#include "NanotecStop.h"
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "NanotecLogging.h"
#include "transport/Transport.h"

namespace stepdeck::nanotec {

NanotecStop::NanotecStop(NanotecController& controller)
    : m_ctl(controller), m_link(controller.m_exchange)
{}

bool NanotecStop::mayMove(const HostDrive& d) const
{
    // A silent drive is unknown: whatever it did last may still go on.
    return !d.responding || d.jog != JogPhase::Idle || d.velocityMove || d.motionPending ||
           d.referencing || (d.status && !decodeStatus(*d.status).ready);
}

bool NanotecStop::motionMayBeRunning() const
{
    if (m_ctl.jogActive() || m_ctl.status().motionUnconfirmed)
        return true;
    for (const HostDrive& d : m_ctl.m_drives) {
        if (mayMove(d))
            return true;
    }
    return false;
}

int NanotecStop::safetyStopTimeoutMs() const
{
    // One short exchange per drive (a silent one costs its timeout) plus the broadcast guard.
    return int(m_ctl.m_drives.size()) * (m_ctl.m_sweep.pollTimeoutMs() + 20) + 150;
}

void NanotecStop::sendSafetyStop(std::function<void(bool)> done)
{
    m_ctl.haltJogImmediately();
    m_ctl.m_poller.stop();
    m_ctl.m_bus->cancelAll();
    QList<Axis> targets;
    for (const HostDrive& d : m_ctl.m_drives) {
        if (mayMove(d))
            targets << d.axis;
    }
    if (targets.isEmpty() && !m_ctl.jogActive())
        return done(true);
    // 6.2: 'S' is the only way to end speed mode. Written to every drive that may move, silent
    // or not, without a ramp (there is no time for one when the host lets go); then '#*S' to
    // every drive on the bus as the last resort for one whose address or echo was lost.
    auto echoed = std::make_shared<int>(0);
    QList<Step> steps;
    for (Axis a : targets) {
        steps << tolerant([this, a, echoed](const Done& stepDone) {
            m_link.exchange(a, "S", {}, NanotecBus::Priority::Urgent, 0,
                            m_ctl.m_sweep.pollTimeoutMs())([echoed, stepDone](const Failure& f) {
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
        m_ctl.m_bus->submit(all);
    };
    for (HostDrive& d : m_ctl.m_drives) {
        d.jogDesired = 0;
        d.forgetMotion();
        if (targets.contains(d.axis)) {
            AxisStatus& st = m_ctl.mutableStatus().axes[d.axis];
            st.referenced = st.positionKnown = false; // 6.2: no ramp, steps may be lost
        }
    }
    const int expected = int(targets.size());
    runSteps(steps, [echoed, expected, done](const Failure&) { done(*echoed == expected); });
}

void NanotecStop::abortHostSide(ErrorKind kind, const QString& message)
{
    m_ctl.m_poller.stop();
    m_ctl.m_bus->cancelAll();
    m_ctl.haltJogImmediately();
    m_ctl.m_closedLoop->abortAll(kind, message);
    for (HostDrive& d : m_ctl.m_drives) {
        d.jogDesired = 0;
        d.forgetMotion();
    }
    m_ctl.m_initialising = false;
    if (m_ctl.m_pendingOpen)
        m_ctl.finishError(std::exchange(m_ctl.m_pendingOpen, 0), kind, message);
    if (m_ctl.m_pendingScan) {
        m_ctl.finishError(m_ctl.m_pendingScan->id, kind, message);
        m_ctl.m_pendingScan.reset();
    }
}

void NanotecStop::stop(RequestId id)
{
    if (!m_ctl.canWriteStop())
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    m_ctl.haltJogImmediately();
    // Snapshot first: cancelling the bus ends jog sequences, whose callbacks reset the state.
    QList<Axis> speedMode, positioning;
    for (HostDrive& d : m_ctl.m_drives) {
        d.jogDesired = 0;
        if (!d.responding)
            continue;
        if (d.jog != JogPhase::Idle)
            speedMode << d.axis;
        else if (d.motionPending || (d.status && !decodeStatus(*d.status).ready))
            positioning << d.axis;
    }
    QMap<Axis, double> speeds;
    for (Axis a : speedMode)
        speeds[a] = qAbs(m_ctl.m_drives[a].jogApplied);
    // A stop still confirming is taken over (NanotecStop.h): its request ends with this run's
    // confirmation, not "cancelled" by the cancelAll() below, which drops its exchanges.
    m_stopIds << id;
    const quint64 run = ++m_stopRun;
    m_ctl.m_bus->cancelAll();
    m_ctl.m_closedLoop->abortAll(ErrorKind::Cancelled, tr("stopped"));
    const auto urgent = NanotecBus::Priority::Urgent;
    QList<Step> steps;
    int wait = 0;
    for (Axis a : speedMode) {
        steps << tolerant(m_link.exchange(a, commandWithValue("o", m_ctl.m_drives[a].minFrequency),
                                          {}, urgent, 1));
        wait = qMax(wait, m_ctl.m_jog.rampTimeMs(m_ctl.m_drives[a], speeds[a]));
    }
    if (wait > 0)
        steps << m_link.wait(qMin(wait, NanotecJog::kMaxRampWaitMs));
    // Every drive, a silent one included: it may have stopped answering but still listen.
    for (const HostDrive& d : m_ctl.m_drives)
        steps << tolerant(m_link.exchange(d.axis, "S", {}, urgent, d.responding ? 2 : 0));
    // An older stop's drives still waiting for their encoder check are checked by this one.
    QList<Axis> encoderChecked = m_stopEncoderChecked;
    for (Axis a : positioning) {
        // 6.2: no ramp; steps may be lost at speed, so the position is suspect until the
        // drive's encoder confirms it (confirmByEncoder).
        AxisStatus& st = m_ctl.mutableStatus().axes[a];
        if (st.referenced && st.positionKnown && !st.positionEstimated &&
            !encoderChecked.contains(a))
            encoderChecked << a;
        st.referenced = st.positionKnown = false;
    }
    m_stopEncoderChecked = encoderChecked;
    if (wait > NanotecJog::kMaxRampWaitMs)
        positioning << speedMode;
    for (Axis a : speedMode) {
        HostDrive& d = m_ctl.m_drives[a];
        if (d.savedMaxFrequency > 0)
            steps << tolerant(
                m_link.exchange(a, commandWithValue("o", d.savedMaxFrequency), {}, urgent, 1));
    }
    for (HostDrive& d : m_ctl.m_drives) {
        d.forgetMotion();
    }
    if (!positioning.isEmpty())
        qCInfo(lcNanotec) << "stopped without ramp; positions suspect:" << positioning.size();
    runSteps(steps, [this, run, encoderChecked](const Failure& f) {
        if (run != m_stopRun)
            return; // a newer stop took this one over: it ends it
        if (!f.ok())
            return finishStops(run, f);
        confirmStopped([this, run](const Failure& done) { finishStops(run, done); },
                       m_ctl.m_drives.keys(), tr("stop"), encoderChecked);
    });
}

void NanotecStop::finishStops(quint64 run, const Failure& f)
{
    if (run != m_stopRun)
        return; // taken over by a newer stop, which ends these requests
    const QList<RequestId> ids = std::exchange(m_stopIds, {});
    m_stopEncoderChecked.clear();
    for (RequestId id : ids)
        m_ctl.finishWith(id, f);
}

void NanotecStop::panic(RequestId id)
{
    if (!m_ctl.transport() || !m_ctl.transport()->isOpen())
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    m_ctl.haltJogImmediately();
    for (HostDrive& d : m_ctl.m_drives)
        d.jogDesired = 0;
    // A stop still confirming is taken over as by a newer stop: its request ends with the
    // panic's confirmation, and after a panic no encoder check gives a position back.
    const QList<RequestId> stops = std::exchange(m_stopIds, {});
    ++m_stopRun;
    m_stopEncoderChecked.clear();
    m_ctl.m_bus->cancelAll();
    m_ctl.m_bus->discardOutput(); // the stop must not wait behind queued bytes
    m_ctl.m_panic = true;
    m_ctl.m_closedLoop->abortAll(ErrorKind::Cancelled, tr("emergency stop"));
    m_ctl.markAllUnreferenced();
    QList<Axis> restore;
    for (HostDrive& d : m_ctl.m_drives) {
        if (d.jog != JogPhase::Idle && d.savedMaxFrequency > 0)
            restore << d.axis;
        d.forgetMotion();
    }
    m_ctl.m_sweep.updateStatus();
    m_ctl.publishStatus();
    NanotecBus::Request r;
    r.address = kBroadcast; // '#*S': every drive on the bus stops at once (1.1, 6.2)
    r.body = "S";
    r.priority = NanotecBus::Priority::Urgent;
    r.done = [this, id, stops, restore](NanotecBus::Outcome, const Reply&) {
        confirmStopped(
            [this, id, stops](const Failure& f) {
                m_ctl.finishWith(id, f);
                for (RequestId taken : stops)
                    m_ctl.finishWith(taken, f);
            },
            m_ctl.m_drives.keys(), tr("emergency stop"));
        for (Axis a : restore) {
            tolerant(
                m_link.exchange(a, commandWithValue("o", m_ctl.m_drives[a].savedMaxFrequency)))(
                [](const Failure&) {});
        }
    };
    m_ctl.m_bus->submit(r);
}

void NanotecStop::confirmStopped(Finish finish, QList<Axis> axes, const QString& context,
                                 QList<Axis> encoderChecked)
{
    // Per drive: ready ('$' bit 0) means stopped; otherwise stop it individually, ask again.
    auto unconfirmed = std::make_shared<QStringList>();
    QList<Step> steps;
    const auto urgent = NanotecBus::Priority::Urgent;
    for (Axis axis : axes) {
        steps << [this, axis, unconfirmed, urgent](const Done& done) {
            auto ready = std::make_shared<bool>(false);
            auto check = sink([this, axis, ready](qint64 v) {
                m_ctl.m_sweep.applyStatusWord(m_ctl.m_drives[axis], v);
                *ready = decodeStatus(v).ready;
            });
            m_link.exchange(axis, "$", check, urgent, 1)([=](const Failure& f) {
                if (f.kind == ErrorKind::Cancelled)
                    return done(f);
                if (f.ok() && *ready)
                    return done({});
                runSteps({m_link.exchange(axis, "S", {}, urgent, 1),
                          m_link.exchange(axis, "$", check, urgent)},
                         [=](const Failure& f2) {
                             if (!f2.ok() || !*ready)
                                 *unconfirmed << m_ctl.driveName(axis);
                             done(f2.kind == ErrorKind::Cancelled ? f2 : Failure{});
                         });
            });
        };
    }
    // Once every drive stands: the encoder's word on the drives stopped mid-positioning.
    for (Axis axis : encoderChecked)
        steps << [this, axis, unconfirmed](const Done& done) {
            if (!unconfirmed->isEmpty())
                return done({}); // a drive may still move: no position is confirmed now
            confirmByEncoder(axis)(done);
        };
    runSteps(steps, [this, finish, unconfirmed, context](const Failure& f) {
        m_ctl.m_sweep.updateStatus();
        m_ctl.publishStatus();
        if (!f.ok())
            return finish(f);
        if (!unconfirmed->isEmpty()) {
            m_ctl.markMotionUnconfirmed();
            return finish(
                {ErrorKind::Timeout, tr("%1 sent; not confirmed by %2: %3")
                                         .arg(context, unconfirmed->join(QStringLiteral(", ")),
                                              m_ctl.mayStillBeMovingText())});
        }
        finish({});
    });
}

Step NanotecStop::confirmByEncoder(Axis axis)
{
    return [this, axis](const Done& done) {
        struct Read
        {
            qint64 mode = 0, tolerance = 0, count = 0, encoder = 0;
        };
        auto read = std::make_shared<Read>();
        const auto urgent = NanotecBus::Priority::Urgent;
        // 5.9: error correction on means the drive has an encoder (without one 'U' must be 0);
        // 5.16/5.17: while no step was lost, 'C' and 'I' agree within the tolerance 'X' (5.13).
        runSteps(
            {m_link.exchange(axis, "ZU", sink([read](qint64 v) { read->mode = v; }), urgent, 1),
             m_link.exchange(axis, "ZX", sink([read](qint64 v) { read->tolerance = v; }), urgent,
                             1),
             m_link.exchange(axis, "C", sink([read](qint64 v) { read->count = v; }), urgent, 1),
             m_link.exchange(axis, "I", sink([read](qint64 v) { read->encoder = v; }), urgent, 1)},
            [this, axis, read, done](const Failure& f) {
                if (f.kind == ErrorKind::Cancelled)
                    return done(f);
                const bool confirmed = f.ok() && read->mode != 0 &&
                                       qAbs(read->count - read->encoder) <= read->tolerance;
                qCInfo(lcNanotec) << "stop: encoder check of" << axisName(axis) << "mode"
                                  << read->mode << "count" << read->count << "encoder"
                                  << read->encoder << "->" << confirmed;
                if (confirmed) {
                    m_ctl.m_drives[axis].position = read->count;
                    AxisStatus& st = m_ctl.mutableStatus().axes[axis];
                    st.referenced = st.positionKnown = true;
                    st.positionEstimated = false;
                }
                done({});
            });
    };
}

void NanotecStop::reset(RequestId id)
{
    m_ctl.m_panic = false;
    m_ctl.m_sweep.updateStatus();
    m_ctl.publishStatus();
    m_ctl.finishOk(id);
}

} // namespace stepdeck::nanotec
