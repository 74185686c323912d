// ElabCtlMotionOps, its step streams: the <DC2> stream of pairs and contours (pacing, the
// lead kept ahead of the board, EndOfFeed, STOP during a contour) and how a held stream shows.
#include "ElabCtlMotionOps.h"
#include "Logging.h"
#include <QCoreApplication>
#include <QTimer>
#include <memory>
#include <utility>

namespace stepdeck::elab {

using Rule = ElabCtlStatusMapper::Rule;
using Op = ElabCtlLine::Op;

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

} // namespace stepdeck::elab
