// Stop, panic, reset and the safety contract of the E-LAB adapter (docs/architecture.md,
// "Safety contract"). Manual sections: "Stop Befehle", "Befehle im Jogbetrieb",
// "SetFeedStepXYZ", "RS232-C" (reset).
#include "ElabController.h"
#include "ElabLogging.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <QDeadlineTimer>
#include <QTimer>
#include <utility>

namespace stepdeck::elab {

namespace {
// RS232-C: "Der Reset wird durch eine Logische 1 auf der RTS-Leitung ausgelöst. Diese muss
// mindestens für 100msec im High Zustand verharren ... Nachdem die Leitung auf Low gezogen
// wurde, sind weitere 100mSec zu warten." A margin on both.
constexpr int kResetPulseMs = 120;
constexpr int kResetSettleMs = 120;

constexpr quint8 kMotionBits = axe::XMove | axe::YMove | axe::ZMove;
constexpr quint8 kJogBits = axe::XJog | axe::YJog | axe::ZJog;

// STOP during a contour (stopContour): the board runs out at most kContourLeadSeconds of ticks
// after the EndOfFeed; a board still moving this long after it is a fault, and the documented
// stop follows. The status is read this often meanwhile.
constexpr int kContourStandstillMs = 1000;
constexpr int kContourStandstillPollMs = 10;

// What one stop sequence has heard back so far.
struct StopReplies
{
    bool needXoff = true; // a move, feed, stream or velocity/reference run may be running
    bool needJog = false; // the board may be in jog mode
    bool xoffAck = false;
    bool jogAck = false;
    ErrorKind failure = ErrorKind::None; // Nak: refused; Timeout, Protocol, ...: no answer
    QString failureText;
    int pending = 0;
    std::function<void(bool, ErrorKind, const QString&)> done;

    void settle()
    {
        if (--pending > 0 || !done)
            return;
        const bool acknowledged = (!needXoff || xoffAck) && (!needJog || jogAck);
        std::exchange(done, nullptr)(acknowledged, failure, failureText);
    }
};

// "Der Modus wird automatisch wieder verlassen, wenn alle 3 Achsen eine Steprate mit dem Wert 0
// erhalten." The only documented way to stop a jog short of a panic.
ElabExchange jogZero(RequestId owner, const std::shared_ptr<StopReplies>& replies, bool streaming)
{
    ElabExchange zero = ElabCtlLine::exchange(owner, encode::jogSpeed({}), Expect::AckNak);
    zero.droppable = false;
    zero.tolerateStray = streaming;
    ++replies->pending;
    zero.onReply = [replies](const Reply& r) {
        replies->jogAck = r.kind == Reply::Kind::Ack;
        if (!replies->jogAck)
            replies->failure = ErrorKind::Nak;
        replies->settle();
    };
    zero.onError = [replies](ErrorKind kind, const QString& why) {
        replies->failure = kind;
        replies->failureText = why;
        replies->settle();
    };
    return zero;
}
} // namespace

bool ElabController::jogMayRun() const
{
    return jogActive() || m_jog.mayRun() || (m_line.axeWord() & kJogBits) != 0;
}

bool ElabController::motionMayBeRunning() const
{
    return jogMayRun() || m_ops.motionTracked() || m_ops.streaming() ||
           (m_line.axeWord() & kMotionBits) != 0 || status().motionUnconfirmed;
}

void ElabController::writeStop(RequestId owner, StopDone done, bool endFeed)
{
    const bool streaming = m_ops.streaming();
    endFeed = endFeed || streaming;
    auto replies = std::make_shared<StopReplies>();
    replies->needJog = jogMayRun();
    replies->needXoff = !replies->needJog || m_ops.motionTracked() || streaming ||
                        (m_line.axeWord() & kMotionBits) != 0;
    replies->done = std::move(done);

    m_line.newEpoch();
    // Work not yet written is dropped; polls and status reads stay (they only observe: a read
    // asked for before the stop returns what the board reports after it, never "cancelled").
    // A pre-flight read goes with the command it guards (ElabCtlLine::StatusRead).
    m_queue.dropQueued(ErrorKind::Cancelled, tr("cancelled by stop"), false);
    m_ops.abortStream(ErrorKind::Cancelled, tr("feed stream stopped"));
    // The host ramp stops at once: the board brakes (XOFF) or stops (zero jog rates) itself.
    haltJogImmediately();
    m_jog.reset();

    if (streaming) {
        // Step bytes still queued in the process or the kernel would run before the stop
        // (and past the board's XOFF): discard them. A <DC2> pair may have been cut after its
        // control byte, so that the board takes the next byte as step data. <ENQ> (0x05) has
        // no step bit as data and is a harmless RequestMachineState as a command; its reply,
        // if any, and replies of abandoned requests are skipped as strays.
        m_queue.abandonInFlight(ErrorKind::Cancelled, tr("cancelled by stop"));
        ElabExchange filler =
            ElabCtlLine::exchange(owner, encode::requestMachineState(), Expect::None);
        filler.droppable = false;
        m_queue.overtake(std::move(filler), true);
    }

    // ForceStopMove: "stoppt sofort jegliche Bewegung mit Bremsrampen ohne Schrittverluste".
    ElabExchange xoff = ElabCtlLine::exchange(owner, encode::stopMove(), Expect::AckNak);
    xoff.droppable = false;
    xoff.tolerateStray = streaming;
    ++replies->pending;
    xoff.onReply = [this, replies, endFeed](const Reply& r) {
        replies->xoffAck = r.kind == Reply::Kind::Ack;
        if (!replies->xoffAck && replies->needXoff)
            replies->failure = ErrorKind::Nak;
        if (replies->xoffAck)
            m_ops.onStopAccepted(); // after the reply of what was in flight (FIFO)
        if (!endFeed || !replies->xoffAck) {
            replies->settle();
            return;
        }
        flushAndEndFeed([replies] { replies->settle(); });
    };
    xoff.onError = [replies](ErrorKind kind, const QString& why) {
        replies->failure = kind;
        replies->failureText = why;
        replies->settle();
    };
    m_queue.overtake(std::move(xoff), false);
    if (replies->needJog)
        m_queue.overtake(jogZero(owner, replies, streaming), false);
    publishStatus();
}

// A stop during <DC2>: the buffer still holds single steps; flush it and end the feed ("Der
// Buffer kann jetzt mit folgendem Kommando geleert werden": <GS>; "Den Abschluss ... muss immer
// ein EndOfFeed Kommando sein"). then() once both are answered, ACK or NAK (a NAK, e.g. with a
// limit switch active, changes nothing about the stop the board acknowledged), or not at all.
void ElabController::flushAndEndFeed(std::function<void()> then)
{
    ElabExchange gs = ElabCtlLine::exchange(0, encode::flushBuffer(), Expect::AckNak);
    ElabExchange cr = ElabCtlLine::exchange(0, encode::endOfFeed(), Expect::AckNak);
    gs.droppable = cr.droppable = false;
    m_line.chain({gs, cr}, true, then, [then](ErrorKind, const QString&) { then(); });
}

void ElabController::sendSafetyStop(std::function<void(bool)> done)
{
    m_poller.stop(); // nothing but the stop goes out from here on
    writeStop(0, [done](bool acknowledged, ErrorKind, const QString&) { done(acknowledged); });
}

void ElabController::abortHostSide(ErrorKind kind, const QString& message)
{
    m_poller.stop();
    cancelEverything(kind, message);
    if (m_openId != 0)
        finishError(std::exchange(m_openId, 0),
                    kind == ErrorKind::Cancelled ? ErrorKind::Cancelled : ErrorKind::LinkDown,
                    message);
}

void ElabController::checkUntrackedMotion()
{
    const quint8 word = m_line.axeWord();
    if ((word & (kMotionBits | kJogBits)) == 0) {
        m_untrackedStopSent = false;
        noteStandstillConfirmed();
        return;
    }
    const bool tracked = jogActive() || m_jog.mayRun() || m_ops.motionTracked() ||
                         m_ops.streaming() || m_untrackedStopSent;
    if (tracked)
        return;
    stopUntracked(tr("the board reports motion the host did not command (%1): stopping it")
                      .arg(describeAxeState(word & (kMotionBits | kJogBits))));
}

void ElabController::stopUntracked(const QString& why)
{
    if (!canWriteStop() || isClosing() || isLosingLink())
        return;
    m_untrackedStopSent = true;
    qCWarning(lcElab) << why;
    Q_EMIT errorOccurred(why);
    writeStop(0, [this](bool acknowledged, ErrorKind, const QString&) {
        if (!acknowledged)
            markMotionUnconfirmed();
        // Read back what the board does now; the watchdog looks at it again.
        ElabCtlLine::StatusRead how;
        how.continuation = how.tolerant = true;
        m_line.readStatus(
            0, how, [] {}, [](ErrorKind, const QString&) {});
    });
}

void ElabController::trackLimitSwitches()
{
    const quint16 word = m_line.machineWord();
    for (Axis a : ElabCtlStatusMapper::axes()) {
        if (!ElabCtlStatusMapper::limitSwitch(word, a)) {
            m_limitApproach.remove(a);
            continue;
        }
        if (m_limitApproach.contains(a))
            continue;
        // Newly active: remember the direction that ran into it (0: unknown, e.g. active
        // since before this session; jogging off it is then allowed either way).
        const double rate = jogRate(a);
        int dir = rate > 0 ? 1 : rate < 0 ? -1 : 0;
        if (dir == 0)
            dir = m_ops.direction(a);
        m_limitApproach.insert(a, dir);
        if (rate != 0.0) {
            // "Wenn eine Fahrt einen Endschalter erreicht hat, dann wird diese auch immer
            // sofort abgebrochen, ausgenommen wiederum die Jog Bewegungen": the board keeps
            // jogging into the switch, so the host stops that axis at once.
            haltJogAxis(a);
            const QString why = tr("the limit switch of axis %1 turned active: jog stopped; only "
                                   "jogging away from it is allowed")
                                    .arg(axisName(a));
            Q_EMIT errorOccurred(why);
            Q_EMIT jogRefused(why);
        }
    }
}

QString ElabController::jogAxisRefusal(Axis axis, double target) const
{
    const int dir = m_limitApproach.value(axis, 0);
    if (dir == 0 || (target > 0) != (dir > 0))
        return {};
    return tr("jog refused: axis %1 is on its limit switch; only jogging away from it (%2) is "
              "allowed")
        .arg(axisName(axis), dir > 0 ? QStringLiteral("-") : QStringLiteral("+"));
}

// ------------------------------------------------------------------ stop, panic, reset

void ElabController::stop(RequestId id)
{
    if (!canWriteStop()) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return;
    }
    // A contour stops as a feed hold does, every position kept (issue 47; PANIC stays the
    // immediate stop). A STOP while one such stop is under way joins it.
    const bool linkUp = linkState() == LinkState::Connected && !isClosing() && !isLosingLink();
    if (!m_contourStops.isEmpty() || (linkUp && m_ops.contourStreaming() && !jogMayRun())) {
        stopContour(id);
        return;
    }
    writeStop(id, stopResult(id));
}

ElabController::StopDone ElabController::stopResult(RequestId id)
{
    return [this, id](bool acknowledged, ErrorKind failure, const QString& why) {
        if (acknowledged) {
            finishOk(id);
            return;
        }
        markMotionUnconfirmed();
        if (failure == ErrorKind::Nak) {
            m_line.failWithNak(m_line.op(id), encode::stopMove());
            return;
        }
        finishError(id, failure == ErrorKind::None ? ErrorKind::Timeout : failure,
                    tr("stop sent, not acknowledged by the board (%1): %2")
                        .arg(why, mayStillBeMovingText()));
    };
}

// STOP during a contour (issue 47 item 3). ForceStopMove would halt the board with single steps
// in its buffer; ForceFlushBuffer then throws an unknown number of them away, and no reply says
// how many pairs ran, so every axis would be unknown (ElabCtlMotion: a stopped stream loses its
// axes). Instead no further pair is sent and the stream ends with EndOfFeed: the board runs
// the pairs it holds, at most ElabCtlMotionOps::kContourLeadSeconds of ticks, at its feed rate
// below the start ramp, "ohne dass Schrittverluste auftreten", and stands where the host's
// count of the pairs it sent says. The stop is confirmed by a status read that shows the axes
// at rest; if the board does not end the stream or come to rest, the documented stop follows
// (contourStopFailed) and its positions are unknown, never claimed.
void ElabController::stopContour(RequestId id)
{
    m_contourStops << id;
    if (m_contourStops.size() > 1)
        return; // joins the one under way
    // A sequence under way (a pre-flight and its command) ends here; polls stay.
    m_line.newEpoch();
    m_queue.dropQueued(ErrorKind::Cancelled, tr("cancelled by stop"), false);
    const quint64 epoch = m_line.epoch();
    m_ops.stopContour([this, epoch](bool ended) {
        if (m_contourStops.isEmpty())
            return;
        if (epoch != m_line.epoch()) {
            finishContourStops(false);
            return;
        }
        if (!ended) {
            contourStopFailed(tr("the stopped contour did not end with EndOfFeed"));
            return;
        }
        awaitContourStandstill(epoch, QDeadlineTimer(kContourStandstillMs));
    });
    publishStatus();
}

void ElabController::awaitContourStandstill(quint64 epoch, QDeadlineTimer deadline)
{
    if (m_contourStops.isEmpty())
        return;
    ElabCtlLine::StatusRead how; // observes: a stop or panic leaves it queued
    m_line.readStatus(
        0, how,
        [this, epoch, deadline] {
            if (m_contourStops.isEmpty())
                return;
            if (epoch != m_line.epoch()) {
                finishContourStops(false);
            } else if ((m_line.axeWord() & (kMotionBits | kJogBits)) == 0) {
                finishContourStops(true);
            } else if (deadline.hasExpired()) {
                contourStopFailed(tr("the board still moved %1 ms after the stopped contour "
                                     "ended")
                                      .arg(kContourStandstillMs));
            } else {
                QTimer::singleShot(kContourStandstillPollMs, this, [this, epoch, deadline] {
                    awaitContourStandstill(epoch, deadline);
                });
            }
        },
        [this, epoch](ErrorKind, const QString& why) {
            if (m_contourStops.isEmpty())
                return;
            if (epoch != m_line.epoch())
                finishContourStops(false);
            else
                contourStopFailed(tr("no status after the stopped contour ended: %1").arg(why));
        });
}

// The board did not end the stopped contour or come to rest: ForceStopMove, ForceFlushBuffer
// and EndOfFeed as for any stream (writeStop), and the stream's axes are unknown from there
// (ElabCtlMotion: a stopped stream) -- the host cannot know which pairs ran.
void ElabController::contourStopFailed(const QString& why)
{
    qCWarning(lcElab) << why;
    Q_EMIT errorOccurred(tr("%1: ForceStopMove sent, positions unknown").arg(why));
    const QList<RequestId> ids = std::exchange(m_contourStops, {});
    writeStop(
        ids.first(),
        [this, ids](bool acknowledged, ErrorKind failure, const QString& text) {
            for (RequestId id : ids)
                stopResult(id)(acknowledged, failure, text);
        },
        true);
}

// standstill: a status read showed the axes at rest; else a panic, reset or lost link came
// first (it stopped the board its own way).
void ElabController::finishContourStops(bool standstill)
{
    const QList<RequestId> ids = std::exchange(m_contourStops, {});
    for (RequestId id : ids) {
        if (standstill)
            finishOk(id);
        else
            finishError(id, ErrorKind::Cancelled,
                        tr("stop overtaken by a panic stop, a reset or a lost link"));
    }
}

void ElabController::panic(RequestId id)
{
    Transport* t = transport();
    if (!t || !t->isOpen()) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return;
    }
    const bool streaming = m_ops.streaming();
    const QString why = tr("cancelled by panic stop");
    m_line.newEpoch();
    m_ops.abortStream(ErrorKind::Cancelled, why);
    m_ops.clear();
    haltJogImmediately();
    m_jog.reset();
    m_queue.dropQueued(ErrorKind::Cancelled, why, true);
    m_queue.abandonInFlight(ErrorKind::Cancelled, why);
    // "Beim Wiederanlauf muss das System neu initialisiert werden, da ... Schritte verloren
    // gehen."
    markAllUnreferenced();
    m_line.setHostPanic(true);
    // Mid-stream the board may wait for the data byte of a <DC2> pair whose data byte was
    // discarded: a first <BEL> is then taken as the step byte 0x07 (no step bit set, harmless)
    // and the second one is the panic. Outside a stream the second <BEL> is a second panic.
    const QByteArray frame =
        streaming ? encode::panicStop() + encode::panicStop() : encode::panicStop();
    ElabExchange ex = ElabCtlLine::exchange(id, frame, Expect::Ack);
    ex.tolerateStray = true; // replies of abandoned exchanges may still come
    ex.onReply = [this, id](const Reply&) {
        finishOk(id);
        ElabCtlLine::StatusRead how;
        how.continuation = how.tolerant = true;
        m_line.readStatus(
            0, how, [] {}, [](ErrorKind, const QString&) {});
    };
    ex.onError = [this, id](ErrorKind kind, const QString& message) {
        markMotionUnconfirmed();
        finishError(id, kind, message);
    };
    m_queue.overtake(std::move(ex), true);
    publishStatus();
}

void ElabController::reset(RequestId id)
{
    Transport* t = transport();
    if (!t || !t->isOpen() || linkState() != LinkState::Connected) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return;
    }
    cancelEverything(ErrorKind::Cancelled, tr("cancelled by reset"));
    markAllUnreferenced();
    publishStatus();
    QString error;
    if (!t->setResetLine(true, &error)) {
        finishError(id, ErrorKind::Unsupported, tr("reset not possible: %1").arg(error));
        return;
    }
    m_poller.stop();
    m_queue.setHeld(true);
    const quint64 epoch = m_line.epoch();
    QTimer::singleShot(kResetPulseMs, this, [this, id, epoch] {
        if (epoch != m_line.epoch() || !transport())
            return; // link lost meanwhile: the request was already finished
        QString ignored;
        transport()->setResetLine(false, &ignored);
        QTimer::singleShot(kResetSettleMs, this, [this, id, epoch] { finishReset(id, epoch); });
    });
}

void ElabController::finishReset(RequestId id, quint64 epoch)
{
    if (epoch != m_line.epoch())
        return;
    m_queue.setHeld(false);
    m_line.setHostPanic(false);
    forgetWritten(); // a reset board has lost its setup
    ElabCtlLine::StatusRead how;
    how.temperature = how.tolerant = true;
    m_line.readStatus(
        id, how,
        [this, id] {
            m_poller.start();
            finishOk(id);
        },
        [this, id](ErrorKind kind, const QString& why) {
            m_poller.start();
            finishError(id, kind, tr("no status after reset: %1").arg(why));
        });
}

} // namespace stepdeck::elab
