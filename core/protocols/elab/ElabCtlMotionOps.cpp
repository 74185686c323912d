#include "ElabCtlMotionOps.h"
#include "Logging.h"
#include <QCoreApplication>
#include <QTimer>
#include <limits>
#include <memory>
#include <utility>

namespace stepdeck::elab {

using Rule = ElabCtlStatusMapper::Rule;
using Op = ElabCtlLine::Op;

namespace {
template <typename T> Triple<T> triple(const AxisVector& values)
{
    Triple<T> t{};
    for (Axis a : ElabCtlStatusMapper::axes())
        t[wireIndex(a)] = T(values.value(a));
    return t;
}

AxisVector nonZero(const AxisVector& values)
{
    AxisVector out;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        if (it.value() != 0)
            out.insert(it.key(), it.value());
    }
    return out;
}

constexpr int kReversalPollMs = 50;
constexpr qint64 kReversalWaitMs = 10000; // a braking ramp far longer than this is a fault
constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
constexpr qint64 kInt16Min = std::numeric_limits<qint16>::min();
constexpr qint64 kInt16Max = std::numeric_limits<qint16>::max();
} // namespace

bool ElabCtlMotionOps::checkAxes(RequestId id, const AxisVector& values, qint64 minimum,
                                 qint64 maximum, const QString& what)
{
    // Every value against its wire type; nothing is sent otherwise.
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        QString error;
        if (!ElabCtlStatusMapper::axes().contains(it.key()))
            error = tr("this machine has no axis %1").arg(axisName(it.key()));
        else if (it.value() < minimum || it.value() > maximum)
            error = tr("%1 %2 for axis %3 is out of range (allowed: %4..%5)")
                        .arg(what)
                        .arg(it.value())
                        .arg(axisName(it.key()))
                        .arg(minimum)
                        .arg(maximum);
        if (!error.isEmpty()) {
            m_line.hooks().fail(id, ErrorKind::InvalidValue, error);
            return false;
        }
    }
    return m_line.hooks().requireLink(id);
}

void ElabCtlMotionOps::accepted(ElabCtlMotion::Kind kind, const AxisVector& values)
{
    using K = ElabCtlMotion::Kind;
    m_motion.start(kind, values);
    if (kind == K::Velocity) {
        for (auto it = values.cbegin(); it != values.cend(); ++it) {
            if (it.value() != 0)
                m_velocitySign.insert(it.key(), it.value() > 0 ? 1 : -1);
        }
    }
    m_line.setHostPanic(false); // the operator has started again after a panic
    for (auto it = m_motion.values().cbegin(); it != m_motion.values().cend(); ++it) {
        AxisStatus& axis = m_line.status().axes[it.key()];
        axis.moving = true;
        if (kind == K::FastMove || kind == K::Feed)
            axis.position += it.value(); // relative steps; corrected after a stop
        else if (kind == K::Reference || kind == K::Velocity)
            axis.referenced = axis.positionKnown = false;
    }
    m_line.hooks().publish();
}

void ElabCtlMotionOps::onStatusRead()
{
    for (Axis a : m_velocitySign.keys()) {
        if (!ElabCtlStatusMapper::axisMoving(m_line.axeWord(), a))
            m_velocitySign.remove(a);
    }
    const AxisVector values = m_motion.values();
    const ElabCtlMotion::Outcome out = m_motion.update(m_line.machineWord(), m_line.axeWord());
    if (!out.limitMessage.isEmpty() && m_stream.isActive()) {
        // A limit switch ends a <DC2> stream at once ("Wenn eine Fahrt einen Endschalter
        // erreicht hat, dann wird diese auch immer sofort abgebrochen"): no more steps, the
        // board's buffer flushed and the feed ended.
        abortStream(ErrorKind::Refused, out.limitMessage);
        const ElabCtlLine::Op internal = m_line.op(0);
        m_line.sendCommand(internal, encode::flushBuffer(), [this, internal] {
            m_line.sendCommand(internal, encode::endOfFeed(), [] {});
        });
    }
    MachineStatus& s = m_line.status();
    for (Axis a : out.lostAxes)
        s.axes[a].referenced = s.axes[a].positionKnown = false;
    for (Axis a : out.referencedAxes) {
        AxisStatus& axis = s.axes[a];
        axis.referenced = axis.positionKnown = true;
        axis.position = 0;
        axis.positionEstimated = false;
    }
    if (!out.limitMessage.isEmpty())
        m_line.hooks().error(out.limitMessage);
    if (out.readRemaining)
        correctPositions(values);
    showHeldAtRest();
}

// Issue 47 item 8: during a feed hold every axis read "≈ ... MOVING" for as long as the
// hold lasted. The board cannot say that its axes stand while the stream is open: its
// RequestAxeState bits taXMove/taYMove/taZMove mean "ist im FastMove oder Feed Mode", and a
// <DC2> stream is feed mode until EndOfFeed, with its buffer empty or not (the simulator's
// ElabSimBoard::axeState likewise, and tmBusy with it); applyAxeState took that for motion,
// and the read-out then estimated a ramp towards the count. The host knows more: since the
// hold it sent no pair, and the board "leert seinen XYZ Step Buffer mit der vorgegebenen
// Feedrate" (SetFeedStepXYZ), so once the ticks sent have had their time (heldAtRest) the
// buffer is empty, and feed mode stops "ohne dass Schrittverluste auftreten" ("a. Der
// Arbeits-Mode"). From the first status read after that the stream's axes are shown standing,
// at the host's count of the pairs it sent: no read-back exists (RequestRelPosition gives a
// FastMove's steps left), but the board ran every pair counted, so the count is where it
// stands -- not an estimate, as for every stream. What the board says stays as it says it
// (status.raw's axeState, busy). Not EndOfFeed at the hold, which would let the board confirm
// it: the resume would then be a new stream with its own pre-flight and SetClearPosition.
void ElabCtlMotionOps::showHeldAtRest()
{
    if (!heldAtRest())
        return;
    for (Axis a : m_stream.axes())
        m_line.status().axes[a].moving = false;
    m_restShown = true;
}

// The hold released: the pair about to go out moves the axes again (and the next status read
// shows the open stream's taXMove as before the hold).
void ElabCtlMotionOps::showStreamMoving()
{
    if (!std::exchange(m_restShown, false))
        return;
    for (Axis a : m_stream.axes())
        m_line.status().axes[a].moving = true;
    m_line.hooks().publish();
}

bool ElabCtlMotionOps::heldAtRest() const
{
    const std::shared_ptr<motion::ContourFeed>& contour = m_stream.contour();
    if (!m_stream.isActive() || !contour || !contour->isHeld() || m_stream.chunkInFlight ||
        m_stream.stopAsked || m_stream.sent() == 0 || !m_contourClock.isValid())
        return false; // a STOP's end is the board's to confirm (ElabController::stopContour)
    return contourAheadNow() <= -kHeldRestMarginSeconds;
}

void ElabCtlMotionOps::onStopAccepted()
{
    m_motion.markStopped();
    m_motion.endStream();
}

void ElabCtlMotionOps::correctPositions(const AxisVector& stopped)
{
    // ForceStopMove: "Dann kann er mit RequestRelPosition die jeweils noch verbleibenden
    // Schritte abfragen" -- the signed steps of the interrupted move that were not executed.
    // Until the answer the count is the interrupted move's target, not where the board stands:
    // estimated, so that no absolute move is computed from it (Machine::move refuses one; a
    // move computed from it once landed the whole remainder short, tst_machinestop).
    for (auto it = stopped.cbegin(); it != stopped.cend(); ++it)
        m_line.status().axes[it.key()].positionEstimated = true;
    ElabExchange etx = ElabCtlLine::exchange(0, encode::requestRelPosition(), Expect::RelPosition);
    etx.droppable = false;
    etx.onReply = [this, stopped](const Reply& r) {
        for (auto it = stopped.cbegin(); it != stopped.cend(); ++it) {
            AxisStatus& axis = m_line.status().axes[it.key()];
            axis.position -= r.positions[wireIndex(it.key())];
            axis.positionEstimated = false;
        }
        m_line.hooks().publish();
    };
    etx.onError = [this, stopped](ErrorKind, const QString& why) {
        for (auto it = stopped.cbegin(); it != stopped.cend(); ++it)
            m_line.status().axes[it.key()].positionKnown = false;
        m_line.hooks().error(tr("position after stop unknown: %1").arg(why));
        m_line.hooks().publish();
    };
    m_line.submit(std::move(etx), true);
}

std::optional<AxisVector> ElabCtlMotionOps::stepsToSend(RequestId id, const AxisVector& steps)
{
    // Signed 32-bit step counts (manual: "Die Werte sind 32bit Integer"); an all-zero move has
    // nothing to send and succeeds at once.
    if (!checkAxes(id, steps, kInt32Min, kInt32Max, tr("step count")))
        return std::nullopt;
    const AxisVector move = nonZero(steps);
    if (move.isEmpty()) {
        m_line.hooks().ok(id, {});
        return std::nullopt;
    }
    return move;
}

void ElabCtlMotionOps::moveRelative(RequestId id, const AxisVector& steps)
{
    const std::optional<AxisVector> checked = stepsToSend(id, steps);
    if (!checked)
        return;
    const AxisVector& move = *checked;
    // The narrowest command: SetFastMoveZ <BS>, SetFastMoveXY <FF>, else SetFastMoveXYZ <EOT>.
    QByteArray frame;
    if (!move.contains(Axis::X) && !move.contains(Axis::Y))
        frame = encode::fastMoveZ(qint32(move.value(Axis::Z)));
    else if (!move.contains(Axis::Z))
        frame = encode::fastMoveXY(qint32(move.value(Axis::X)), qint32(move.value(Axis::Y)));
    else
        frame = encode::fastMoveXYZ(triple<qint32>(move));
    m_line.preflight(id, Rule::Move, [this, frame, move](Op op) {
        m_line.sendCommand(op, frame, [this, op, move] {
            accepted(ElabCtlMotion::Kind::FastMove, move);
            m_line.hooks().ok(op.id, {});
        });
    });
}

void ElabCtlMotionOps::feed(RequestId id, const AxisVector& steps)
{
    const std::optional<AxisVector> checked = stepsToSend(id, steps);
    if (!checked)
        return;
    const AxisVector& move = *checked;
    if (move.size() > 1) {
        startStream(id, {}, triple<qint64>(move));
        return;
    }
    const Axis axis = move.firstKey();
    const qint32 n = qint32(move.first());
    const QByteArray frame = axis == Axis::X   ? encode::feedStepsX(n)
                             : axis == Axis::Y ? encode::feedStepsY(n)
                                               : encode::feedStepsZ(n);
    m_line.preflight(id, Rule::Move, [this, frame, move](Op op) {
        // SetClearPosition: "Dieser Befehl sollte vor jedem Befehl im Feedmodus aufgerufen
        // werden."
        m_line.sendCommand(op, encode::clearPosition(), [this, op, frame, move] {
            if (m_line.stale(op))
                return;
            m_line.sendCommand(op, frame, [this, op, move] {
                accepted(ElabCtlMotion::Kind::Feed, move);
                m_line.hooks().ok(op.id, {});
            });
        });
    });
}

void ElabCtlMotionOps::feedStream(RequestId id, const QVector<AxisVector>& steps)
{
    const QString invalid = ElabCtlStream::validate(steps);
    if (!invalid.isEmpty()) {
        m_line.hooks().fail(id, ErrorKind::InvalidValue, invalid);
        return;
    }
    if (!m_line.hooks().requireLink(id))
        return;
    if (steps.isEmpty()) {
        m_line.hooks().ok(id, 0);
        return;
    }
    startStream(id, steps, {});
}

void ElabCtlMotionOps::feedContour(RequestId id, std::shared_ptr<motion::ContourFeed> contour)
{
    if (!m_line.hooks().requireLink(id))
        return;
    if (!contour) {
        m_line.hooks().fail(id, ErrorKind::InvalidValue, tr("no contour to run"));
        return;
    }
    startStream(id, {}, {}, std::move(contour));
}

void ElabCtlMotionOps::startStream(RequestId id, const QVector<AxisVector>& steps,
                                   const Triple<qint64>& line,
                                   std::shared_ptr<motion::ContourFeed> contour)
{
    const QString busy = tr("refused: a feed stream is already running");
    if (m_stream.isActive()) {
        m_line.hooks().fail(id, ErrorKind::Refused, busy);
        return;
    }
    // "Hier muss nur vor dem ersten Kommando die Abfrage erfolgen": one pre-flight, then <RS>.
    m_line.preflight(id, Rule::Move, [this, steps, line, busy, contour](Op op) {
        if (m_stream.isActive()) {
            m_line.hooks().fail(op.id, ErrorKind::Refused, busy);
            return;
        }
        m_line.sendCommand(op, encode::clearPosition(), [this, op, steps, line, contour] {
            if (m_line.stale(op))
                return;
            if (contour) {
                m_stream.startContour(contour);
                m_contourBase = 0;
                m_contourClock.invalidate();
            } else if (steps.isEmpty())
                m_stream.startLine(line);
            else
                m_stream.startSteps(steps);
            m_stream.requestId = op.id;
            m_restShown = false; // a hold of an earlier stream's is over
            AxisVector axes;
            for (Axis a : m_stream.axes())
                axes.insert(a, 1);
            accepted(ElabCtlMotion::Kind::Stream, axes);
            streamChanged();
            pumpStream();
        });
    });
}

void ElabCtlMotionOps::onFlowControl(bool resume)
{
    if (!m_stream.isActive())
        return; // XON/XOFF outside a stream: nothing to pause
    m_stream.pausedByDevice = !resume;
    pumpStream();
}

void ElabCtlMotionOps::pumpStream()
{
    if (!m_stream.isActive() || m_stream.chunkInFlight || m_stream.pausedByDevice)
        return;
    const RequestId id = m_stream.requestId;
    if (m_stream.stopAsked) {
        endStream(id); // STOP during a contour (stopContour): nothing more, not even if held
        return;
    }
    if (m_stream.waiting())
        return; // the contour's next move is not given yet: its wake-up pumps again
    if (m_stream.atEnd()) {
        endStream(id);
        return;
    }
    // A feed hold (issue 30): not even the ticks taken already go out; the board runs dry and
    // stands. They go first when the hold is released (its wake-up pumps again).
    if (m_stream.contour() && m_stream.contour()->isHeld())
        return;
    // A contour's first <DC2> starts the board at once: it goes out with a whole window of
    // pairs behind it, not squeezed beside the bytes before it (else the board runs dry
    // before the second chunk arrives).
    if (m_stream.contour() && m_stream.sent() == 0 &&
        m_line.queue().wireRoomBytes() < ElabExchangeQueue::kWireWindowBytes) {
        QTimer::singleShot(1, &m_line.queue(), [this, id] {
            if (m_stream.isActive() && m_stream.requestId == id)
                pumpStream();
        });
        return;
    }
    const double lead = contourLead(id);
    if (lead <= 0)
        return; // pumped again once the board has run some of what it holds
    // One chunk at a time, and never more than one chunk beyond what the line can have
    // carried (the queue's wire window): after the board's XOFF at most that is on its way.
    // The chunk is built when it is written, as many pairs as fit the window then, and none if
    // the board said XOFF (or the stream ended) while it waited behind a poll.
    static_assert(2 * ElabCtlStream::kChunkSteps == ElabExchangeQueue::kWireWindowBytes);
    auto delta = std::make_shared<Triple<qint64>>();
    ElabExchange ex = ElabCtlLine::exchange(id, {}, Expect::None);
    ex.wireRoom = 2; // one <DC2> pair
    // A stop does not drop it: it builds nothing once the stream ended or stops, and a STOP
    // during a contour keeps the stream alive until its end (stopContour).
    ex.droppable = false;
    ex.build = [this, id, delta, lead] {
        if (!m_stream.isActive() || m_stream.requestId != id || m_stream.pausedByDevice ||
            m_stream.stopAsked)
            return QByteArray();
        qint64 pairs = m_line.queue().wireRoomBytes() / 2;
        if (m_stream.contour() && m_stream.sent() == 0) {
            m_contourClock.start(); // the board starts with the first <DC2>
            m_contourBase = 0;
        } else if (m_stream.contour()) {
            pairs = std::min(pairs, qint64(lead * m_stream.contour()->tickRate()));
        }
        return m_stream.nextChunk(int(qBound<qint64>(1, pairs, qint64(ElabCtlStream::kChunkSteps))),
                                  delta.get());
    };
    m_stream.chunkInFlight = true;
    ex.onReply = [this, id, delta](const Reply&) {
        for (Axis a : ElabCtlStatusMapper::axes())
            m_line.status().axes[a].position += (*delta)[wireIndex(a)];
        if (!m_stream.isActive() || m_stream.requestId != id)
            return; // that stream has ended
        m_stream.chunkInFlight = false;
        pumpStream();
    };
    ex.onError = [this, id](ErrorKind kind, const QString& why) {
        if (!m_stream.isActive() || m_stream.requestId != id)
            return;
        m_stream.chunkInFlight = false;
        abortStream(kind, why);
    };
    showStreamMoving();
    m_line.submit(std::move(ex), false);
}

// The seconds of a contour's ticks that may still go out now (kContourLeadSeconds less what
// runs ahead of the board); <= 0: none, and a pump is scheduled for when some may. Streams of
// step vectors given whole are not limited (kContourLeadSeconds).
double ElabCtlMotionOps::contourLead(RequestId id)
{
    if (!m_stream.contour() || m_stream.sent() == 0)
        return kContourLeadSeconds;
    const double lead = kContourLeadSeconds - contourAhead();
    if (lead * m_stream.contour()->tickRate() >= 1)
        return lead;
    if (!std::exchange(m_leadWait, true))
        QTimer::singleShot(5, &m_line.queue(), [this, id] {
            m_leadWait = false;
            if (m_stream.isActive() && m_stream.requestId == id)
                pumpStream();
        });
    return 0;
}

double ElabCtlMotionOps::contourAheadNow() const
{
    return double(m_stream.sent() - m_contourBase) / m_stream.contour()->tickRate() -
           double(m_contourClock.nsecsElapsed()) / 1e9;
}

double ElabCtlMotionOps::contourAhead()
{
    const double ahead = contourAheadNow();
    if (ahead >= 0)
        return ahead;
    m_contourBase = m_stream.sent();
    m_contourClock.restart();
    return 0;
}

bool ElabCtlMotionOps::contourNeedsWire() const
{
    const std::shared_ptr<motion::ContourFeed>& contour = m_stream.contour();
    if (!m_stream.isActive() || !contour || m_stream.pausedByDevice || m_stream.stopAsked)
        return false; // after an XOFF the board holds a full buffer; after a STOP none follow
    if (m_stream.sent() == 0 || !m_contourClock.isValid())
        return m_stream.total() > 0; // about to start; not while its first move is not given
    const double ahead = contourAheadNow();
    // Far behind (the contour waits for its next move, the board ran dry): polls go on, so
    // that limit switches and positions are read while nothing can be sent anyway.
    return ahead < kContourReserveSeconds && ahead > -kContourReserveSeconds && !m_stream.atEnd();
}

void ElabCtlMotionOps::endStream(RequestId id)
{
    // "Den Abschluss eines solchen Arbeitsvorgangs muss immer ein EndOfFeed Kommando sein."
    m_stream.chunkInFlight = true; // nothing more until EndOfFeed is answered
    // Cut short by STOP (a STOP after the last pair leaves the contour whole).
    const bool stopped = m_stream.stopAsked;
    ElabExchange end = ElabCtlLine::exchange(id, encode::endOfFeed(), Expect::AckNak);
    end.droppable = false; // a STOP during a contour waits for it (stopContour)
    end.onReply = [this, id, stopped](const Reply& r) {
        if (!m_stream.isActive() || m_stream.requestId != id)
            return; // ended otherwise meanwhile (abortStream: a stop, a limit switch)
        const qint64 sent = m_stream.sent();
        // A contour that ended short of a soft limit: ended, but the request fails with why.
        const QString fault = m_stream.contour() ? m_stream.contour()->fault() : QString();
        m_stream.clear();
        m_motion.endStream();
        streamChanged();
        const bool ack = r.kind == Reply::Kind::Ack;
        if (ack && stopped)
            m_line.hooks().fail(id, ErrorKind::Cancelled,
                                tr("contour stopped after %1 ticks: the board runs out the ticks "
                                   "it holds, every position stays known")
                                    .arg(sent));
        else if (ack && !fault.isEmpty())
            m_line.hooks().fail(id, ErrorKind::Refused, fault);
        else if (ack)
            m_line.hooks().ok(id, sent);
        else
            m_line.failWithNak(m_line.op(id), encode::endOfFeed());
        notifyContourStopped(ack);
    };
    end.onError = [this](ErrorKind kind, const QString& why) { abortStream(kind, why); };
    m_line.submit(std::move(end), false);
}

void ElabCtlMotionOps::stopContour(std::function<void(bool ended)> done)
{
    if (!contourStreaming()) {
        done(false);
        return;
    }
    // Why not ForceStopMove: after an <XOFF> the buffer "enthält ... mit grosser
    // Wahrscheinlichkeit noch Einzelschritte" (manual, ForceStopMove), ForceFlushBuffer
    // discards an unknown number of them, and no reply says how many pairs the board ran
    // (RequestRelPosition gives the steps left of a FastMove), so every axis of the stream
    // would be unknown. Feed mode runs below the start ramp ("a. Der Arbeits-Mode": "Er kann
    // jederzeit sofort gestartet und gestoppt werden, ohne dass Schrittverluste auftreten") and
    // the board "leert seinen XYZ Step Buffer mit der vorgegebenen Feedrate" (SetFeedStepXYZ):
    // without new pairs it stops where the last pair the host counted puts it, within
    // kContourLeadSeconds. EndOfFeed closes the stream ("Den Abschluss eines solchen
    // Arbeitsvorgangs muss immer ein EndOfFeed Kommando sein").
    m_contourStopped.append(std::move(done));
    m_stream.stopAsked = true;
    // Ends it now, unless a chunk is on its way (its completion pumps again) or the board said
    // XOFF (its XON does).
    pumpStream();
}

void ElabCtlMotionOps::notifyContourStopped(bool ended)
{
    const QList<std::function<void(bool)>> waiting = std::exchange(m_contourStopped, {});
    for (const std::function<void(bool)>& done : waiting)
        done(ended);
}

void ElabCtlMotionOps::streamChanged()
{
    if (m_line.hooks().streamChanged)
        m_line.hooks().streamChanged();
}

void ElabCtlMotionOps::abortStream(ErrorKind kind, const QString& message)
{
    if (!m_stream.isActive())
        return;
    const RequestId id = m_stream.requestId;
    const QString text =
        tr("%1 after %2 of %3 steps").arg(message).arg(m_stream.sent()).arg(m_stream.total());
    m_stream.clear();
    m_motion.markStopped();
    m_motion.endStream();
    streamChanged();
    m_line.hooks().fail(id, kind, text);
    notifyContourStopped(false); // a STOP under way falls back to ForceStopMove (if still due)
}

void ElabCtlMotionOps::reference(RequestId id, const AxisVector& directions)
{
    // SetReferenceMoveXYZ: "Die Werte sind 16bit Integer (-1/0/+1)".
    if (!checkAxes(id, directions, -1, 1, tr("reference direction")))
        return;
    const AxisVector run = nonZero(directions);
    if (run.isEmpty()) {
        m_line.hooks().ok(id, {});
        return;
    }
    m_line.preflight(id, Rule::Move, [this, run](Op op) {
        m_line.sendCommand(op, encode::referenceMove(triple<qint16>(run)), [this, op, run] {
            accepted(ElabCtlMotion::Kind::Reference, run);
            m_line.hooks().ok(op.id, {});
        });
    });
}

void ElabCtlMotionOps::velocityMove(RequestId id, const AxisVector& stepsPerS)
{
    if (!checkAxes(id, stepsPerS, kInt16Min, kInt16Max, tr("velocity")))
        return;
    const bool running = velocityRunning();
    AxisVector rates = running ? m_motion.values() : AxisVector();
    QList<Axis> reversing;
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        const qint64 before = rates.value(it.key());
        if (before != 0 && it.value() != 0 && (before > 0) != (it.value() > 0)) {
            // "Eine Drehrichtungs Umkehr ist bei laufendem Motor hier nicht möglich."
            m_line.hooks().fail(id, ErrorKind::Refused,
                                tr("refused: axis %1 cannot reverse during a velocity move; set "
                                   "it to 0 and wait for standstill first")
                                    .arg(axisName(it.key())));
            return;
        }
        // Commanded 0 but maybe still braking: the new sign waits for its standstill.
        const int lastSign = m_velocitySign.value(it.key(), 0);
        if (before == 0 && it.value() != 0 && lastSign != 0 && (it.value() > 0) != (lastSign > 0))
            reversing << it.key();
        rates.insert(it.key(), it.value());
    }
    if (!running && nonZero(rates).isEmpty()) {
        m_line.hooks().ok(id, {});
        return;
    }
    sendVelocity(id, rates, running, reversing, m_clock.elapsed() + kReversalWaitMs,
                 m_line.epoch());
}

void ElabCtlMotionOps::sendVelocity(RequestId id, const AxisVector& rates, bool running,
                                    const QList<Axis>& reversing, qint64 deadlineMs, quint64 epoch)
{
    if (epoch != m_line.epoch()) {
        m_line.hooks().fail(id, ErrorKind::Cancelled, tr("cancelled by a stop, panic or reset"));
        return;
    }
    // The first VelocityMove needs standstill; later ones only change the rates, except for an
    // axis that reverses: "dann muss gewartet werden, bis diese Achse zum Stillstand gekommen
    // ist (pollen des Achsen Status)".
    m_line.preflight(
        id, running ? Rule::VelocityUpdate : Rule::Move,
        [this, rates, running, reversing, deadlineMs](Op op) {
            for (Axis a : reversing) {
                if (!ElabCtlStatusMapper::axisMoving(m_line.axeWord(), a))
                    continue;
                if (m_clock.elapsed() > deadlineMs) {
                    m_line.hooks().fail(op.id, ErrorKind::Timeout,
                                        tr("axis %1 did not come to a standstill; the reversed "
                                           "velocity was not sent")
                                            .arg(axisName(a)));
                    return;
                }
                QTimer::singleShot(kReversalPollMs, &m_line.queue(), [=] {
                    sendVelocity(op.id, rates, running, reversing, deadlineMs, op.epoch);
                });
                return;
            }
            const QByteArray frame = encode::velocityMove(triple<qint16>(rates));
            m_line.sendCommand(op, frame, [this, op, rates] {
                accepted(ElabCtlMotion::Kind::Velocity, rates);
                m_line.hooks().ok(op.id, {});
            });
        });
}

} // namespace stepdeck::elab
