// Arrivals (<DCn>) of vector moves and reference runs, their deadlines, and the position
// bookkeeping built from them.
#include "EmisMotionTracker.h"
#include "EmisLogging.h"
#include "Logging.h"

namespace stepdeck::emis {

EmisMotionTracker::EmisMotionTracker(EmisHost& host, EmisKnownValues& known, QObject* owner,
                                     Hooks hooks)
    : m_host(host), m_known(known), m_hooks(std::move(hooks))
{
    for (Axis axis : emisAxes())
        m_tracks.insert(axis, Track{});
    m_deadlineTimer.setParent(owner);
    m_deadlineTimer.setSingleShot(true);
    QObject::connect(&m_deadlineTimer, &QTimer::timeout, owner, [this] { checkDeadlines(); });
    m_clock.start();
}

void EmisMotionTracker::settled()
{
    armDeadlineTimer();
    updateMotionUnconfirmed();
}

void EmisMotionTracker::startSession()
{
    for (Track& t : m_tracks) {
        // A new session: positions count from here, nothing referenced. An axis that may
        // still be moving stays unconfirmed until its arrival or a reference run proves it.
        const bool unconfirmed = t.unconfirmed;
        t = Track{};
        t.unconfirmed = unconfirmed;
    }
}

void EmisMotionTracker::forgetReferences()
{
    for (Track& t : m_tracks)
        t.referenced = false; // unknown until referenced in the new session
}

void EmisMotionTracker::stopTracking(const QString& reason)
{
    for (auto it = m_tracks.begin(); it != m_tracks.end(); ++it) {
        if (!it->awaiting)
            continue;
        it->awaiting = false;
        it->overdue = false;
        it->jogChunk = false;
        markLost(it.key());
        qCWarning(lcEmis) << "stopped tracking axis" << axisName(it.key())
                          << "while it moved:" << reason;
    }
    m_deadlineTimer.stop();
    updateMotionUnconfirmed();
}

bool EmisMotionTracker::mayBeRunning() const
{
    for (const Track& t : m_tracks) {
        if (t.awaiting || t.startPending || t.unconfirmed)
            return true;
    }
    return false;
}

bool EmisMotionTracker::anyAwaiting() const
{
    for (const Track& t : m_tracks) {
        if (t.awaiting && !t.overdue)
            return true;
    }
    return false;
}

void EmisMotionTracker::settleStart(Axis axis, const EmisLink::Result& r, bool reference, bool jog,
                                    qint64 steps, qint64 deadlineMs)
{
    Track& t = m_tracks[axis];
    t.startPending = false;
    const bool early = std::exchange(t.arrivedBeforeStart, false);
    const bool notTaken = r.outcome == EmisLink::Outcome::Refused ||
                          (r.outcome == EmisLink::Outcome::Cancelled && !r.sent);
    if (notTaken) {
        if (early)
            markLost(axis); // it moved although the command was not taken
        return;
    }
    t.awaiting = true;
    t.overdue = false;
    t.reference = reference;
    t.jogChunk = jog;
    t.pendingSteps = steps;
    t.deadlineMs = deadlineMs;
    if (reference)
        t.referenced = false;
    if (early) {
        completeMotion(axis); // its <DCn> overtook the missing <NAK>: the move is done
        return;
    }
    if (r.outcome != EmisLink::Outcome::Ok)
        markOverdue(axis); // no <NAK> (silence, garbage): it may have started
}

void EmisMotionTracker::onArrived(Axis axis)
{
    Track& t = m_tracks[axis];
    if (!t.awaiting && t.startPending) {
        t.arrivedBeforeStart = true; // settled when its <NAK> (or the timeout) comes
        return;
    }
    const bool wasUnconfirmed = std::exchange(t.unconfirmed, false); // <DCn> proves it stopped
    if (!t.awaiting) {
        if (!wasUnconfirmed) {
            // Nothing of ours was under way: an input program moved it (9.17), or a reply
            // belongs to an earlier session. Its position is no longer ours to know.
            qCWarning(lcEmis) << "arrival of axis" << axisName(axis) << "that nobody awaited";
            t.lost = true;
            t.referenced = false;
            m_known.speeds.forgetBoard(); // a program may have set its own speeds
        }
        updateMotionUnconfirmed();
        m_host.publish();
        return;
    }
    const bool chunk = completeMotion(axis);
    armDeadlineTimer();
    updateMotionUnconfirmed();
    m_host.publish();
    if (chunk)
        m_hooks.chunkArrived();
}

bool EmisMotionTracker::completeMotion(Axis axis)
{
    Track& t = m_tracks[axis];
    if (t.overdue) {
        // Late, but it came: the move is complete, what its loss suspected is undone.
        t.lost = t.lostBefore;
        t.referenced = t.referencedBefore;
    }
    t.unconfirmed = false;
    t.awaiting = false;
    t.overdue = false;
    if (t.reference) {
        // 9.9/9.10: the run ends after leaving the switch by the offset; that is 0.
        t.position = 0;
        t.referenced = true;
        t.lost = false;
        t.reference = false;
        for (Track& other : m_tracks) {
            if (other.awaiting && other.reference && !other.overdue)
                other.deadlineMs = m_clock.elapsed() + m_referenceDeadlineMs;
        }
    } else {
        t.position += t.pendingSteps;
    }
    t.pendingSteps = 0;
    return std::exchange(t.jogChunk, false);
}

void EmisMotionTracker::markOverdue(Axis axis)
{
    Track& t = m_tracks[axis];
    t.overdue = true;
    t.lostBefore = t.lost;
    t.referencedBefore = t.referenced;
    markLost(axis);
    suspectReset(); // a reset (5.8) ends a move without its <DCn>
}

void EmisMotionTracker::suspectReset()
{
    m_known.speeds.forgetBoard();
    m_known.interpolation.reset();
    for (Track& t : m_tracks)
        t.referenced = false;
    for (std::optional<bool>& output : m_host.statusToChange().outputs)
        output.reset();
}

void EmisMotionTracker::markLost(Axis axis)
{
    Track& t = m_tracks[axis];
    t.lost = true;
    t.referenced = false;
    t.unconfirmed = true;
}

void EmisMotionTracker::checkDeadlines()
{
    const qint64 now = m_clock.elapsed();
    for (auto it = m_tracks.begin(); it != m_tracks.end(); ++it) {
        Track& t = it.value();
        if (!t.awaiting || t.overdue || t.deadlineMs > now)
            continue;
        markOverdue(it.key());
        const QString why =
            tr("axis %1: its arrival <DC%2> did not come in time; it may still be moving (use "
               "the machine's emergency stop if it does); its position is unknown until it is "
               "referenced")
                .arg(axisName(it.key()))
                .arg(axisNumber(it.key()));
        Q_EMIT m_host.controller().errorOccurred(why);
        if (t.jogChunk)
            m_hooks.chunkLost(why);
    }
    armDeadlineTimer();
    updateMotionUnconfirmed();
    m_host.publish();
}

void EmisMotionTracker::armDeadlineTimer()
{
    std::optional<qint64> next;
    for (const Track& t : m_tracks) {
        if (t.awaiting && !t.overdue)
            next = next ? qMin(*next, t.deadlineMs) : t.deadlineMs;
    }
    if (!next) {
        m_deadlineTimer.stop();
        return;
    }
    m_deadlineTimer.start(int(qBound(qint64(0), *next - m_clock.elapsed(), qint64(86400000))));
}

void EmisMotionTracker::updateMotionUnconfirmed()
{
    bool unconfirmed = false;
    for (const Track& t : m_tracks)
        unconfirmed = unconfirmed || t.unconfirmed;
    if (unconfirmed)
        m_host.statusToChange().motionUnconfirmed = true; // said by the caller, naming the axis
    else if (m_host.controller().status().motionUnconfirmed)
        m_host.confirmStandstill(); // every awaited arrival came: the board proved standstill
}

} // namespace stepdeck::emis
