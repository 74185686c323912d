// Stop and panic on a Nanotec bus: 'S' has no ramp (6.2), so speed-mode runs are lowered to
// the start frequency first; panic is one '#*S' to every drive (1.1), confirmed per drive.
#include "Logging.h"
#include "NanotecController.h"
#include "transport/Transport.h"

namespace stepdeck::nanotec {

namespace {

QByteArray num(const char* cmd, qint64 v)
{
    return QByteArray(cmd) + QByteArray::number(v);
}
} // namespace

void NanotecController::stop(RequestId id)
{
    if (linkState() != LinkState::Connected)
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
    const auto urgent = NanotecBus::Priority::Urgent;
    QList<Step> steps;
    int wait = 0;
    for (Axis a : speedMode) {
        steps << tolerant(exchange(a, num("o", m_drives[a].minFrequency), {}, urgent, 1));
        wait = qMax(wait, rampTimeMs(m_drives[a], speeds[a]));
    }
    if (wait > 0)
        steps << this->wait(qMin(wait, kMaxRampWaitMs));
    for (const Drive& d : m_drives) {
        if (d.responding)
            steps << tolerant(exchange(d.axis, "S", {}, urgent, 2));
    }
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
        if (!unconfirmed->isEmpty())
            return finishError(id, ErrorKind::Timeout,
                               tr("%1 sent; not confirmed by %2")
                                   .arg(context, unconfirmed->join(QStringLiteral(", "))));
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
