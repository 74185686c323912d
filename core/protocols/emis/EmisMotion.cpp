// Vector moves (9.11) and reference runs (9.9): checked, their work speeds set, sent; their
// arrivals are EmisMotionTracker's.
#include "EmisMotion.h"
#include "Logging.h"
#include <QtMath>

namespace stepdeck::emis {

namespace {
constexpr double kDefaultStartSpeed = 200; // schema defaults, when nothing is known
constexpr double kDefaultRampMs = 100;
} // namespace

EmisMotion::EmisMotion(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
                       EmisMotionTracker& tracker, Hooks hooks)
    : m_host(host), m_exchange(exchange), m_known(known), m_tracker(tracker),
      m_hooks(std::move(hooks))
{}

QString EmisMotion::busyAxes(const QList<Axis>& axes, bool forReference) const
{
    for (Axis axis : axes) {
        const EmisMotionTracker::Track& t = m_tracker.tracks()[axis];
        if (t.awaiting && !t.overdue) {
            return tr("axis %1 is still moving (its arrival <DC%2> has not come; the board would "
                      "answer <BEL>)")
                .arg(axisName(axis))
                .arg(axisNumber(axis));
        }
        if (m_hooks.jogging(axis))
            return tr("axis %1 is jogging").arg(axisName(axis));
        if (t.unconfirmed && !forReference) {
            return tr("axis %1: the arrival of its last move never came, it may still be moving; "
                      "reference it first")
                .arg(axisName(axis));
        }
    }
    return {};
}

void EmisMotion::moveRelative(RequestId id, const AxisVector& steps)
{
    if (!m_host.requireLink(id))
        return;
    QList<VectorTarget> targets;
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        if (qAbs(it.value()) > limits::kVectorMax) {
            return m_host.fail(id, ErrorKind::InvalidValue,
                               tr("move of axis %1 by %2 steps is out of range (allowed: -%3..%3)")
                                   .arg(axisName(it.key()))
                                   .arg(it.value())
                                   .arg(limits::kVectorMax));
        }
        if (it.value() != 0)
            targets << VectorTarget{it.key(), it.value(), false};
    }
    if (targets.isEmpty())
        return m_host.succeed(id); // nothing to move: nothing sent
    startVector(id, targets, false);
}

void EmisMotion::moveAbsolute(RequestId id, const AxisVector& targets)
{
    if (!m_host.requireLink(id))
        return;
    QList<VectorTarget> list;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        if (qAbs(it.value()) > limits::kVectorMax) {
            return m_host.fail(id, ErrorKind::InvalidValue,
                               tr("target %1 of axis %2 is out of range (allowed: -%3..%3)")
                                   .arg(it.value())
                                   .arg(axisName(it.key()))
                                   .arg(limits::kVectorMax));
        }
        list << VectorTarget{it.key(), it.value(), true}; // "L1,X1000" (9.11)
    }
    if (const QString refusal = unknownAbsolute(list); !refusal.isEmpty())
        return m_host.fail(id, ErrorKind::Refused, refusal);
    QList<Axis> axes;
    for (const VectorTarget& t : list)
        axes << t.axis;
    if (const QString busy = busyAxes(axes, false); !busy.isEmpty())
        return m_host.fail(id, ErrorKind::Refused, tr("move refused: %1").arg(busy));
    // A target where the axis stands is left out, like a relative 0: whether the board answers
    // a move of no length with <NAK> and <DCn> the manual does not say (9.11).
    list.removeIf([this](const VectorTarget& t) { return t.value == m_tracker.position(t.axis); });
    if (list.isEmpty())
        return m_host.succeed(id); // nothing to move: nothing sent
    startVector(id, list, false);
}

QString EmisMotion::unknownAbsolute(const QList<VectorTarget>& targets) const
{
    for (const VectorTarget& t : targets) {
        if (t.absolute && !m_host.controller().status().axes.value(t.axis).positionKnown) {
            return tr("absolute move refused: position of axis %1 is unknown, reference it first")
                .arg(axisName(t.axis));
        }
    }
    return {};
}

void EmisMotion::startVector(RequestId id, const QList<VectorTarget>& targets, bool jog)
{
    QList<Axis> axes;
    for (const VectorTarget& t : targets)
        axes << t.axis;
    if (const QString busy = busyAxes(axes, false); !busy.isEmpty() && !jog)
        return m_host.fail(id, ErrorKind::Refused, tr("move refused: %1").arg(busy));
    if (m_exchange.inputProgramOpen() && !jog)
        return m_host.fail(id, ErrorKind::Refused,
                           tr("move refused: an input program is being "
                              "written"));
    // A jog chunk set its speed already; a positioning move sets its axes' work speeds first.
    const auto failed = jog ? std::make_shared<SpeedWriteFailure>()
                            : queueMoveSpeeds(m_exchange.link(), m_known.speeds, axes);
    const QByteArray bytes = encode::vector(targets);
    const qint64 deadline = moveDeadlineMs(targets);
    for (const VectorTarget& t : targets)
        m_tracker.markStartPending(t.axis);
    EmisLink::Request move;
    move.bytes = bytes;
    move.expect = EmisLink::Expect::Start;
    move.cancelIf = [failed] { return failed->has_value(); };
    move.done = [this, id, bytes, targets, jog, deadline, failed](const EmisLink::Result& r) {
        onVectorStarted(id, targets, jog, deadline, bytes, failed, r);
    };
    m_exchange.link().submit(std::move(move));
}

void EmisMotion::onVectorStarted(RequestId id, const QList<VectorTarget>& targets, bool jog,
                                 qint64 deadline, const QByteArray& bytes,
                                 const std::shared_ptr<SpeedWriteFailure>& failed,
                                 const EmisLink::Result& r)
{
    const qint64 due = m_tracker.now() + deadline;
    for (const VectorTarget& t : targets) {
        const qint64 steps = t.absolute ? t.value - m_tracker.position(t.axis) : t.value;
        m_tracker.settleStart(t.axis, r, false, jog, steps, due);
    }
    m_tracker.settled();
    m_host.publish();
    if (jog) {
        const bool ok = r.outcome == EmisLink::Outcome::Ok;
        m_hooks.chunkSettled(ok, ok ? QString() : m_exchange.failureText(bytes, r));
        return;
    }
    if (r.outcome == EmisLink::Outcome::Ok)
        m_host.succeed(id);
    else if (*failed && !r.sent)
        m_host.failExchange(id, (*failed)->first, (*failed)->second);
    else
        m_host.failExchange(id, bytes, r);
}

qint64 EmisMotion::moveDeadlineMs(const QList<VectorTarget>& targets) const
{
    // The slowest axis at start speed the whole way, plus both ramps, doubled, plus a margin of
    // four command timeouts (2 s by default): generous, because the working values may have
    // been changed outside this session.
    const double ramp = double(m_known.ramp.value_or(qint64(kDefaultRampMs)));
    double longest = 0;
    for (const VectorTarget& t : targets) {
        const double start = double(m_known.startSpeed.value(t.axis, qint64(kDefaultStartSpeed)));
        const double work = double(m_known.speeds.moveSpeed(t.axis)); // set right before the move
        const double distance =
            double(qAbs(t.absolute ? t.value - m_tracker.position(t.axis) : t.value));
        longest = qMax(longest, 1000.0 * distance / qMax(1.0, qMin(start, work)));
    }
    return qint64(2 * (longest + 2 * ramp)) +
           4 * qint64(m_host.controller().options().commandTimeoutMs);
}

void EmisMotion::reference(RequestId id, const QMap<Axis, int>& directions)
{
    if (!m_host.requireLink(id))
        return;
    QList<Axis> axes;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it) {
        if (it.value() < 0 || it.value() > 1) {
            return m_host.fail(id, ErrorKind::InvalidValue,
                               tr("axis %1: the SMC-IC4 chooses the direction of its reference "
                                  "run itself (9.9); use 1 to reference the axis, 0 to leave it "
                                  "out")
                                   .arg(axisName(it.key())));
        }
        if (it.value() == 1)
            axes << it.key();
    }
    if (axes.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, tr("name at least one axis to reference"));
    startHome(id, axes, false);
}

void EmisMotion::startHome(RequestId id, const QList<Axis>& axes, bool simultaneous)
{
    if (const QString busy = busyAxes(axes, true); !busy.isEmpty())
        return m_host.fail(id, ErrorKind::Refused, tr("reference run refused: %1").arg(busy));
    if (m_exchange.inputProgramOpen())
        return m_host.fail(id, ErrorKind::Refused,
                           tr("reference run refused: an input program "
                              "is being written"));
    const QByteArray bytes = encode::home(axes, simultaneous);
    for (Axis axis : axes)
        m_tracker.markStartPending(axis);
    m_exchange.request(bytes, EmisLink::Expect::Start,
                       [this, id, bytes, axes, simultaneous](const EmisLink::Result& r) {
                           const qint64 now = m_tracker.now();
                           int index = 0;
                           for (Axis axis : emisAxes()) { // $Hxyzu runs in X, Y, Z, U order (9.9)
                               if (axes.contains(axis)) {
                                   const qint64 due =
                                       now + qint64(m_tracker.referenceDeadlineMs()) *
                                                 (simultaneous ? 1 : ++index);
                                   m_tracker.settleStart(axis, r, true, false, 0, due);
                               }
                           }
                           m_tracker.settled();
                           m_host.publish();
                           if (r.outcome == EmisLink::Outcome::Ok)
                               m_host.succeed(id);
                           else
                               m_host.failExchange(id, bytes, r);
                       });
}

} // namespace stepdeck::emis
