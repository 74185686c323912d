// Jog without a stop command: a chain of short relative vector moves (9.11).
#include "EmisJog.h"
#include "EmisLogging.h"
#include "Logging.h"
#include <QtMath>

namespace stepdeck::emis {

EmisJog::EmisJog(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
                 EmisMotionTracker& tracker, EmisMotion& motion)
    : m_host(host), m_exchange(exchange), m_known(known), m_tracker(tracker), m_motion(motion)
{}

QString EmisJog::refusal() const
{
    if (m_exchange.inputProgramOpen())
        return tr("jog refused: an input program is being written");
    if (m_host.controller().status().motionUnconfirmed)
        return tr("jog refused: an axis may still be moving (its arrival never came); "
                  "reference it first");
    return {};
}

void EmisJog::apply(const AxisVelocities& stepsPerS)
{
    // No stale rate may keep a chunk chain going.
    m_jogRates = stepsPerS;
    pump();
    m_host.publish();
}

void EmisJog::end()
{
    m_jogRates.clear();
    m_host.haltJogInput();
}

void EmisJog::abort()
{
    m_host.haltJogInput();
    m_jogRates.clear();
    m_sending = false;
}

void EmisJog::pump()
{
    if (m_sending || m_host.controller().linkState() != LinkState::Connected)
        return;
    // Every axis that stands still and has a rate gets its next chunk; axes ready together
    // share one vector command. An axis whose chunk is under way is never sent another (the
    // board would answer <BEL>): it gets its next chunk when its <DCn> arrives.
    QList<VectorTarget> chunk;
    QList<EmisWorkSpeeds::Write> speedWrites;
    QMap<Axis, QString> atLimit;
    for (auto it = m_jogRates.cbegin(); it != m_jogRates.cend(); ++it) {
        const Axis axis = it.key();
        const double rate = it.value();
        const EmisMotionTracker::Track& t = m_tracker.tracks()[axis];
        if (!held(axis, rate) || t.awaiting || t.unconfirmed)
            continue;
        // At most kJogChunkSeconds of travel at the commanded rate; a chunk of one step at a
        // very low rate runs fast enough to end within that time too.
        const qint64 steps = qMax<qint64>(1, qint64(std::floor(qAbs(rate) * kJogChunkSeconds)));
        // Soft limits: a chunk ends at the limit at the latest (no ramp to wait for: the
        // board ramps each chunk down by itself before its target). From the bookkeeping of
        // arrived moves, which is exact here: the next chunk only goes after an arrival.
        QString why;
        const qint64 clipped = clipToSoftLimit(axis, rate > 0 ? steps : -steps, &why);
        if (clipped == 0) {
            atLimit.insert(axis, why);
            continue;
        }
        const qint64 speed =
            qBound(limits::kSpeedMin,
                   qMax(qRound64(qAbs(rate)), qint64(std::ceil(double(steps) / kJogChunkSeconds))),
                   limits::kSpeedMax);
        if (m_known.speeds.jogNeedsWrite(axis, speed))
            speedWrites << EmisWorkSpeeds::Write{axis, speed};
        chunk << VectorTarget{axis, clipped, false};
    }
    for (auto it = atLimit.cbegin(); it != atLimit.cend(); ++it) {
        m_jogRates.insert(it.key(), 0.0);
        m_host.haltJogInputAxis(it.key()); // the operator pushes again to move back inside
        if (it.value() != m_softLimitSaid)
            Q_EMIT m_host.controller().jogRefused(it.value());
    }
    m_softLimitSaid = atLimit.isEmpty() ? QString() : atLimit.first();
    if (chunk.isEmpty()) {
        finishIfIdle();
        return;
    }
    m_sending = true;
    sendChunk(speedWrites, chunk);
}

bool EmisJog::held(Axis axis, double direction) const
{
    // Both the ramp's rate and the input's target (the lease) in this direction. After a
    // release the host ramp still runs down for a while; a chunk started then would move the
    // axis after the operator let go (the board ramps the chunk under way down by itself).
    const double rate = m_jogRates.value(axis, 0.0);
    const double target = m_host.controller().jogRamp().target(axis);
    return rate * direction > 0.0 && target * direction > 0.0;
}

qint64 EmisJog::clipToSoftLimit(Axis axis, qint64 steps, QString* why) const
{
    const Controller& ctl = m_host.controller();
    MachineStatus bookkept = ctl.status();
    const EmisMotionTracker::Track t = m_tracker.tracks().value(axis);
    AxisStatus& a = bookkept.axes[axis];
    a.position = t.position;
    a.referenced = a.positionKnown = t.referenced && !t.lost;
    return ctl.softLimits().clipRelative(bookkept, {{axis, steps}}, why).value(axis);
}

void EmisJog::sendChunk(QList<EmisWorkSpeeds::Write> speedWrites, QList<VectorTarget> chunk)
{
    if (!speedWrites.isEmpty()) {
        const EmisWorkSpeeds::Write write = speedWrites.takeFirst();
        writeWorkSpeed(
            m_exchange.link(), m_known.speeds, write,
            [this, write, speedWrites, chunk](const EmisLink::Result& r) {
                if (r.outcome == EmisLink::Outcome::Ok)
                    return sendChunk(speedWrites, chunk);
                m_sending = false;
                if (r.outcome != EmisLink::Outcome::Cancelled)
                    halt(m_exchange.failureText(encode::workSpeed(write.axis, write.speed), r));
            });
        return;
    }
    // The lease is checked again right before the move goes out: an axis released meanwhile
    // gets no new chunk.
    QList<VectorTarget> still;
    for (const VectorTarget& t : chunk) {
        if (held(t.axis, double(t.value)))
            still << t;
    }
    if (still.isEmpty() || m_host.controller().linkState() != LinkState::Connected) {
        m_sending = false;
        finishIfIdle();
        return;
    }
    m_motion.startVector(0, still, true);
}

void EmisJog::onChunkSettled(bool ok, const QString& why)
{
    m_sending = false;
    if (!ok)
        halt(why);
    else
        pump(); // axes that became ready meanwhile
}

void EmisJog::finishIfIdle()
{
    if (m_sending)
        return;
    for (auto it = m_jogRates.cbegin(); it != m_jogRates.cend(); ++it) {
        if (it.value() != 0.0 || m_tracker.tracks()[it.key()].jogChunk)
            return;
    }
    // The jog is over: every jogged axis gets its move speed back (9.5), for the board's own
    // input programs and the next session. Moves do not depend on it: each sets its speed.
    for (const EmisWorkSpeeds::Write& w : m_known.speeds.writesToRestore()) {
        writeWorkSpeed(m_exchange.link(), m_known.speeds, w, [this, w](const EmisLink::Result& r) {
            if (r.outcome != EmisLink::Outcome::Ok && r.outcome != EmisLink::Outcome::Cancelled)
                Q_EMIT m_host.controller().errorOccurred(
                    m_exchange.failureText(encode::workSpeed(w.axis, w.speed), r));
        });
    }
}

void EmisJog::halt(const QString& reason)
{
    qCInfo(lcEmis) << "jog halted:" << reason;
    m_jogRates.clear();
    m_host.haltJogInput();
    Q_EMIT m_host.controller().jogRefused(reason);
    finishIfIdle();
    m_host.publish();
}

} // namespace stepdeck::emis
