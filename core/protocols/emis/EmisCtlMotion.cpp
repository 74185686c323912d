// Vector moves (9.11), reference runs (9.9), arrivals and their deadlines.
#include "EmisController.h"
#include "EmisLogging.h"
#include "EmisWorkSpeedWrites.h"
#include "Logging.h"
#include <QtMath>

namespace stepdeck::emis {

namespace {
constexpr double kDefaultStartSpeed = 200; // schema defaults, when nothing is known
constexpr double kDefaultRampMs = 100;
} // namespace

bool EmisController::anyAwaiting() const
{
    for (const Track& t : m_tracks) {
        if (t.awaiting && !t.overdue)
            return true;
    }
    return false;
}

QString EmisController::busyAxes(const QList<Axis>& axes, bool forReference) const
{
    for (Axis axis : axes) {
        const Track& t = m_tracks[axis];
        if (t.awaiting && !t.overdue) {
            return tr("axis %1 is still moving (its arrival <DC%2> has not come; the board would "
                      "answer <BEL>)")
                .arg(axisName(axis))
                .arg(int(axis) + 1);
        }
        if (m_jogRates.value(axis, 0.0) != 0.0)
            return tr("axis %1 is jogging").arg(axisName(axis));
        if (t.unconfirmed && !forReference) {
            return tr("axis %1: the arrival of its last move never came, it may still be moving; "
                      "reference it first")
                .arg(axisName(axis));
        }
    }
    return {};
}

void EmisController::moveRelative(RequestId id, const AxisVector& steps)
{
    if (!requireLink(id))
        return;
    QList<VectorTarget> targets;
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        if (qAbs(it.value()) > limits::kVectorMax) {
            return finishError(id, ErrorKind::InvalidValue,
                               tr("move of axis %1 by %2 steps is out of range (allowed: -%3..%3)")
                                   .arg(axisName(it.key()))
                                   .arg(it.value())
                                   .arg(limits::kVectorMax));
        }
        if (it.value() != 0)
            targets << VectorTarget{it.key(), it.value(), false};
    }
    if (targets.isEmpty())
        return finishOk(id); // nothing to move: nothing sent
    startVector(id, targets, false);
}

void EmisController::moveAbsolute(RequestId id, const AxisVector& targets)
{
    if (!requireLink(id))
        return;
    QList<VectorTarget> list;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        if (qAbs(it.value()) > limits::kVectorMax) {
            return finishError(id, ErrorKind::InvalidValue,
                               tr("target %1 of axis %2 is out of range (allowed: -%3..%3)")
                                   .arg(it.value())
                                   .arg(axisName(it.key()))
                                   .arg(limits::kVectorMax));
        }
        list << VectorTarget{it.key(), it.value(), true}; // "L1,X1000" (9.11)
    }
    if (const QString refusal = unknownAbsolute(list); !refusal.isEmpty())
        return finishError(id, ErrorKind::Refused, refusal);
    QList<Axis> axes;
    for (const VectorTarget& t : list)
        axes << t.axis;
    if (const QString busy = busyAxes(axes, false); !busy.isEmpty())
        return finishError(id, ErrorKind::Refused, tr("move refused: %1").arg(busy));
    // A target where the axis stands is left out, like a relative 0: whether the board answers
    // a move of no length with <NAK> and <DCn> the manual does not say (9.11).
    list.removeIf([this](const VectorTarget& t) { return t.value == m_tracks[t.axis].position; });
    if (list.isEmpty())
        return finishOk(id); // nothing to move: nothing sent
    startVector(id, list, false);
}

QString EmisController::unknownAbsolute(const QList<VectorTarget>& targets) const
{
    for (const VectorTarget& t : targets) {
        if (t.absolute && !status().axes.value(t.axis).positionKnown) {
            return tr("absolute move refused: position of axis %1 is unknown, reference it first")
                .arg(axisName(t.axis));
        }
    }
    return {};
}

void EmisController::startVector(RequestId id, const QList<VectorTarget>& targets, bool jog)
{
    QList<Axis> axes;
    for (const VectorTarget& t : targets)
        axes << t.axis;
    if (const QString busy = busyAxes(axes, false); !busy.isEmpty() && !jog)
        return finishError(id, ErrorKind::Refused, tr("move refused: %1").arg(busy));
    if (m_programming && !jog)
        return finishError(id, ErrorKind::Refused,
                           tr("move refused: an input program is being "
                              "written"));
    // A jog chunk set its speed already; a positioning move sets its axes' work speeds first.
    const auto failed =
        jog ? std::make_shared<SpeedWriteFailure>() : queueMoveSpeeds(*m_link, m_speeds, axes);
    const QByteArray bytes = encode::vector(targets);
    const qint64 deadline = moveDeadlineMs(targets);
    for (const VectorTarget& t : targets)
        m_tracks[t.axis].startPending = true;
    EmisLink::Request move;
    move.bytes = bytes;
    move.expect = EmisLink::Expect::Start;
    move.cancelIf = [failed] { return failed->has_value(); };
    move.done = [this, id, bytes, targets, jog, deadline, failed](const EmisLink::Result& r) {
        const qint64 due = m_clock.elapsed() + deadline;
        for (const VectorTarget& t : targets) {
            const qint64 steps = t.absolute ? t.value - m_tracks[t.axis].position : t.value;
            settleStart(t.axis, r, false, jog, steps, due);
        }
        armDeadlineTimer();
        updateMotionUnconfirmed();
        publish();
        if (jog) {
            m_jogSending = false;
            if (r.outcome != EmisLink::Outcome::Ok)
                haltJog(failureText(bytes, r));
            else
                pumpJog(); // axes that became ready meanwhile
            return;
        }
        if (r.outcome == EmisLink::Outcome::Ok)
            finishOk(id);
        else if (*failed && !r.sent)
            finishFailure(id, (*failed)->first, (*failed)->second);
        else
            finishFailure(id, bytes, r);
    };
    m_link->submit(std::move(move));
}

void EmisController::settleStart(Axis axis, const EmisLink::Result& r, bool reference, bool jog,
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

qint64 EmisController::moveDeadlineMs(const QList<VectorTarget>& targets) const
{
    // The slowest axis at start speed the whole way, plus both ramps, doubled, plus a margin of
    // four command timeouts (2 s by default): generous, because the working values may have
    // been changed outside this session.
    const double ramp = double(m_known.ramp.value_or(qint64(kDefaultRampMs)));
    double longest = 0;
    for (const VectorTarget& t : targets) {
        const double start = double(m_known.startSpeed.value(t.axis, qint64(kDefaultStartSpeed)));
        const double work = double(m_speeds.moveSpeed(t.axis)); // set right before the move
        const double distance =
            double(qAbs(t.absolute ? t.value - m_tracks[t.axis].position : t.value));
        longest = qMax(longest, 1000.0 * distance / qMax(1.0, qMin(start, work)));
    }
    return qint64(2 * (longest + 2 * ramp)) + 4 * qint64(options().commandTimeoutMs);
}

void EmisController::reference(RequestId id, const QMap<Axis, int>& directions)
{
    if (!requireLink(id))
        return;
    QList<Axis> axes;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it) {
        if (it.value() < 0 || it.value() > 1) {
            return finishError(id, ErrorKind::InvalidValue,
                               tr("axis %1: the SMC-IC4 chooses the direction of its reference "
                                  "run itself (9.9); use 1 to reference the axis, 0 to leave it "
                                  "out")
                                   .arg(axisName(it.key())));
        }
        if (it.value() == 1)
            axes << it.key();
    }
    if (axes.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, tr("name at least one axis to reference"));
    startHome(id, axes, false);
}

void EmisController::startHome(RequestId id, const QList<Axis>& axes, bool simultaneous)
{
    if (const QString busy = busyAxes(axes, true); !busy.isEmpty())
        return finishError(id, ErrorKind::Refused, tr("reference run refused: %1").arg(busy));
    if (m_programming)
        return finishError(id, ErrorKind::Refused,
                           tr("reference run refused: an input program "
                              "is being written"));
    const QByteArray bytes = encode::home(axes, simultaneous);
    for (Axis axis : axes)
        m_tracks[axis].startPending = true;
    request(bytes, EmisLink::Expect::Start,
            [this, id, bytes, axes, simultaneous](const EmisLink::Result& r) {
                const qint64 now = m_clock.elapsed();
                int index = 0;
                for (Axis axis : allAxes()) { // $Hxyzu runs in X, Y, Z, U order (9.9)
                    if (axes.contains(axis)) {
                        const qint64 due =
                            now + qint64(m_referenceDeadlineMs) * (simultaneous ? 1 : ++index);
                        settleStart(axis, r, true, false, 0, due);
                    }
                }
                armDeadlineTimer();
                updateMotionUnconfirmed();
                publish();
                if (r.outcome == EmisLink::Outcome::Ok)
                    finishOk(id);
                else
                    finishFailure(id, bytes, r);
            });
}

void EmisController::onArrived(Axis axis)
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
            m_speeds.forgetBoard(); // a program may have set its own speeds
        }
        updateMotionUnconfirmed();
        publish();
        return;
    }
    const bool chunk = completeMotion(axis);
    armDeadlineTimer();
    updateMotionUnconfirmed();
    publish();
    if (chunk)
        pumpJog();
}

bool EmisController::completeMotion(Axis axis)
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

void EmisController::markOverdue(Axis axis)
{
    Track& t = m_tracks[axis];
    t.overdue = true;
    t.lostBefore = t.lost;
    t.referencedBefore = t.referenced;
    markLost(axis);
    suspectReset(); // a reset (5.8) ends a move without its <DCn>
}

void EmisController::suspectReset()
{
    m_speeds.forgetBoard();
    for (Track& t : m_tracks)
        t.referenced = false;
    for (std::optional<bool>& output : mutableStatus().outputs)
        output.reset();
}

void EmisController::markLost(Axis axis)
{
    Track& t = m_tracks[axis];
    t.lost = true;
    t.referenced = false;
    t.unconfirmed = true;
}

void EmisController::checkDeadlines()
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
                .arg(int(it.key()) + 1);
        Q_EMIT errorOccurred(why);
        if (t.jogChunk)
            haltJog(why);
    }
    armDeadlineTimer();
    updateMotionUnconfirmed();
    publish();
}

void EmisController::armDeadlineTimer()
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

void EmisController::updateMotionUnconfirmed()
{
    bool unconfirmed = false;
    for (const Track& t : m_tracks)
        unconfirmed = unconfirmed || t.unconfirmed;
    if (unconfirmed)
        mutableStatus().motionUnconfirmed = true; // said by the caller, naming the axis
    else if (status().motionUnconfirmed)
        noteStandstillConfirmed(); // every awaited arrival came: the board proved standstill
}

} // namespace stepdeck::emis
