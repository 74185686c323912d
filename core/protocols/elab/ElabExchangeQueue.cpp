#include "ElabExchangeQueue.h"
#include "ElabLogging.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <QtMath>
#include <algorithm>
#include <atomic>

namespace stepdeck::elab {

namespace {
QString frameName(const QByteArray& frame)
{
    if (frame.isEmpty())
        return QStringLiteral("(empty)");
    const QString text = toMnemonics(frame.left(1));
    return frame.size() > 1 ? text + QStringLiteral("...") : text;
}
} // namespace

ElabExchangeQueue::ElabExchangeQueue(Transport* transport, QObject* parent)
    : QObject(parent), m_transport(transport),
      m_window([this] { return m_transport ? m_transport->pendingOutputBytes() : 0; })
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &ElabExchangeQueue::onTimeout);
    m_paceTimer.setSingleShot(true);
    m_paceTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_paceTimer, &QTimer::timeout, this, &ElabExchangeQueue::completeWritten);
    m_clock.start();
    if (transport) {
        connect(transport, &Transport::dataReceived, this, &ElabExchangeQueue::onData);
        connect(transport, &Transport::bytesWritten, this, &ElabExchangeQueue::onBytesWritten);
    }
}

void ElabExchangeQueue::enqueue(ElabExchange ex)
{
    m_queue.push_back(std::move(ex));
    pump();
}

void ElabExchangeQueue::enqueueNext(ElabExchange ex)
{
    m_queue.push_front(std::move(ex));
    pump();
}

void ElabExchangeQueue::enqueueNext(QList<ElabExchange> exs)
{
    for (auto it = exs.rbegin(); it != exs.rend(); ++it)
        m_queue.push_front(std::move(*it));
    pump();
}

void ElabExchangeQueue::overtake(ElabExchange ex, bool discardOutput)
{
    if (discardOutput && m_transport) {
        // Panic: bytes still waiting in the transport would go out before the stop byte.
        m_transport->discardOutput();
        m_outstanding = 0;
        m_paceTimer.stop();
    }
    write(std::move(ex));
    // Stop and panic leave the process now, not after the event loop's next pass.
    if (m_transport && m_transport->isOpen())
        m_transport->pushOutput();
}

void ElabExchangeQueue::pump()
{
    // A loop because a built frame may turn out empty and leave nothing in flight, and because
    // the reads of a pipeline group go out together.
    bool wrote = false;
    while (!m_held && m_transport && m_transport->isOpen() && !m_queue.empty() &&
           mayWriteNow(m_queue.front())) {
        const qint64 room = m_queue.front().wireRoom;
        if (room > 0 && wireRoomBytes() < room) {
            armPace(m_window.nsUntilOnTheWayAtMost(kWireWindowBytes - room));
            break;
        }
        ElabExchange ex = std::move(m_queue.front());
        m_queue.pop_front();
        write(std::move(ex)); // may complete synchronously only through callbacks that pump
        wrote = true;
    }
    // What was written leaves the process now rather than on the event loop's next pass: the
    // reply can come no sooner than the request is on the line (issue 21: polls back to back
    // on the wire). Once after the loop: what one pass wrote leaves in one write(2).
    if (wrote && m_transport && m_transport->isOpen())
        m_transport->pushOutput();
    const bool busy = !isIdle();
    if (m_busy && !busy) {
        m_busy = false;
        Q_EMIT idle();
    } else {
        m_busy = busy;
    }
}

bool ElabExchangeQueue::mayWriteNow(const ElabExchange& next) const
{
    if (m_inFlight.empty())
        return true;
    // Only the rest of the group whose reads are in flight: they are queued right behind the
    // first and written in the same pass (pump), so no reply is read in between.
    if (next.pipelineGroup == 0 || next.expect == Expect::None || next.wireRoom > 0 || next.build ||
        int(m_inFlight.size()) >= kMaxPipelined)
        return false;
    return std::all_of(m_inFlight.cbegin(), m_inFlight.cend(), [&next](const InFlight& f) {
        return f.ex.pipelineGroup == next.pipelineGroup;
    });
}

quint64 ElabExchangeQueue::newPipelineGroup()
{
    static std::atomic<quint64> next{0};
    return ++next;
}

void ElabExchangeQueue::write(ElabExchange ex)
{
    if (ex.build)
        ex.frame = ex.build();
    if (!m_transport || !m_transport->isOpen()) {
        failExchange(ex, ErrorKind::LinkDown, tr("not connected"));
        return;
    }
    if (ex.frame.isEmpty() && ex.expect == Expect::None) {
        // Built to nothing (a stream chunk after the board's XOFF): done without a write.
        if (ex.onReply)
            ex.onReply(Reply{});
        return;
    }
    const QByteArray bytes = ex.frame;
    const bool poll = ex.poll;
    m_inFlight.push_back(InFlight{std::move(ex), m_clock.elapsed() + m_timeoutMs});
    m_outstanding += bytes.size();
    m_busy = true;
    Q_EMIT trafficOut(bytes, poll);
    armTimer();
    if (m_transport->write(bytes) < 0) {
        qCWarning(lcElab) << "write failed";
        // The transport reports its own failure (failed()); the controller fails everything.
    }
}

void ElabExchangeQueue::onBytesWritten(qint64 count)
{
    // On the line from now on: until the transport handed them on (QSerialPort writes from
    // its own buffer in a later event-loop pass) they count as pending, not as carried.
    m_window.wrote(count);
    m_outstanding = qMax<qint64>(0, m_outstanding - count);
    if (m_outstanding == 0)
        completeWritten();
}

qint64 ElabExchangeQueue::wireRoomBytes() const
{
    return qMax<qint64>(0, kWireWindowBytes - m_window.onTheWay());
}

void ElabExchangeQueue::armPace(qint64 ns)
{
    m_paceTimer.start(qMax(1, qCeil(double(ns) / 1e6)));
}

void ElabExchangeQueue::completeWritten()
{
    // bytesWritten only means "the kernel took it": on a real port kilobytes can wait in the
    // tty/USB buffer, where the board's XOFF cannot hold them back and a stop would queue
    // behind them; a pty or a USB adapter's own FIFO does not even report them. So a frame
    // without a reply counts as sent once neither the driver nor the wire budget leaves more
    // than one <DC2> pair on its way; until then this looks again when the line should be there.
    const bool unanswered =
        std::any_of(m_inFlight.cbegin(), m_inFlight.cend(),
                    [](const InFlight& f) { return f.ex.expect == Expect::None; });
    if (unanswered && m_transport) {
        const qint64 wait = m_window.nsUntilOnTheWayAtMost(kWireLowWaterBytes);
        if (wait > 0) {
            armPace(wait);
            return;
        }
    }
    // Frames without a reply are done once nothing of ours is left inside the transport. Taken
    // out first: a callback may write the next frame, which has not left yet.
    std::deque<ElabExchange> done;
    for (auto it = m_inFlight.begin(); it != m_inFlight.end();) {
        if (it->ex.expect == Expect::None) {
            done.push_back(std::move(it->ex));
            it = m_inFlight.erase(it);
        } else {
            ++it;
        }
    }
    for (ElabExchange& ex : done) {
        if (ex.onReply)
            ex.onReply(Reply{});
    }
    armTimer();
    pump();
}

void ElabExchangeQueue::onData(const QByteArray& bytes)
{
    const QList<Reply> replies = m_decoder.feed(bytes);
    for (const Reply& reply : replies)
        handleReply(reply);
}

void ElabExchangeQueue::handleReply(const Reply& reply)
{
    if (reply.kind == Reply::Kind::XOn || reply.kind == Reply::Kind::XOff) {
        // Flow control of the <DC2> buffer may arrive between any two replies; never a reply.
        Q_EMIT trafficIn(reply.raw, false);
        Q_EMIT flowControl(reply.kind == Reply::Kind::XOn);
        return;
    }
    auto target = m_inFlight.begin();
    while (target != m_inFlight.end() && target->ex.expect == Expect::None)
        ++target;
    if (target == m_inFlight.end()) {
        Q_EMIT trafficIn(reply.raw, false);
        qCWarning(lcElab) << "stray reply with nothing pending:" << toMnemonics(reply.raw);
        return;
    }
    if (!expectMatches(target->ex.expect, reply.kind) && skipsLostReply(reply)) {
        handleReply(reply); // now for the read it belongs to
        return;
    }
    Q_EMIT trafficIn(reply.raw, target->ex.poll);
    if (!expectMatches(target->ex.expect, reply.kind)) {
        if (target->ex.tolerateStray) {
            qCInfo(lcElab) << "skipped stray reply" << toMnemonics(reply.raw);
            return;
        }
        if (reply.kind == Reply::Kind::Invalid) {
            // Noise, or the reply itself destroyed: keep waiting; a destroyed reply times out.
            qCInfo(lcElab) << "skipped noise" << toMnemonics(reply.raw) << reply.error;
            Q_EMIT noise(reply.raw);
            return;
        }
        ElabExchange ex = std::move(target->ex);
        m_inFlight.erase(target);
        const QString why =
            tr("unexpected reply %1 to %2 (expected %3)")
                .arg(toMnemonics(reply.raw), frameName(ex.frame), expectName(ex.expect));
        if (ex.retries > 0 && ex.owner != kResyncOwner) {
            retryAfterResync(std::move(ex), why);
        } else {
            const bool resync = ex.owner != kResyncOwner;
            failExchange(ex, ErrorKind::Protocol, why);
            if (resync)
                resynchronise(why);
        }
        armTimer();
        pump();
        return;
    }
    ElabExchange ex = std::move(target->ex);
    m_inFlight.erase(target);
    armTimer();
    if (ex.onReply)
        ex.onReply(reply);
    pump();
}

bool ElabExchangeQueue::skipsLostReply(const Reply& reply)
{
    // A group's reads are in flight only among themselves (mayWriteNow), so the reply's target
    // is the front. A tolerant read skips strays instead: a late reply after a panic may look
    // like the next read's reply.
    if (m_inFlight.size() < 2)
        return false;
    const ElabExchange& first = m_inFlight.front().ex;
    const ElabExchange& second = std::next(m_inFlight.begin())->ex;
    if (first.pipelineGroup == 0 || second.pipelineGroup != first.pipelineGroup ||
        first.tolerateStray || !expectMatches(second.expect, reply.kind))
        return false;
    ElabExchange lost = std::move(m_inFlight.front().ex);
    m_inFlight.pop_front();
    const QString why =
        tr("no reply to %1 (the reply to the request behind it came)").arg(frameName(lost.frame));
    qCInfo(lcElab) << why;
    if (lost.retries > 0 && !lost.poll && lost.owner != kResyncOwner) {
        // The line is in step (the next reply came): asked again, no resynchronisation.
        --lost.retries;
        m_queue.push_front(std::move(lost));
    } else {
        failExchange(lost, ErrorKind::Timeout, why);
    }
    return true;
}

void ElabExchangeQueue::onTimeout()
{
    const qint64 now = m_clock.elapsed();
    std::deque<ElabExchange> expired;
    for (auto it = m_inFlight.begin(); it != m_inFlight.end();) {
        if (it->deadlineMs <= now) {
            expired.push_back(std::move(it->ex));
            it = m_inFlight.erase(it);
        } else {
            ++it;
        }
    }
    QString reason;
    for (ElabExchange& ex : expired) {
        if (ex.expect == Expect::None && m_transport && m_transport->bytesToWrite() == 0) {
            // A transport that reports no bytesWritten: nothing is left inside it, so it left.
            m_outstanding = 0;
            if (ex.onReply)
                ex.onReply(Reply{});
            continue;
        }
        const QString why =
            tr("no reply to %1 within %2 ms").arg(frameName(ex.frame)).arg(m_timeoutMs);
        if (ex.retries > 0 && !ex.poll && ex.owner != kResyncOwner) {
            retryAfterResync(std::move(ex), why);
            continue;
        }
        if (ex.owner != kResyncOwner && ex.expect != Expect::None && reason.isEmpty())
            reason = why;
        failExchange(ex, ErrorKind::Timeout, why);
    }
    if (!reason.isEmpty())
        resynchronise(reason);
    armTimer();
    pump();
}

void ElabExchangeQueue::armTimer()
{
    if (m_inFlight.empty()) {
        m_timer.stop();
        return;
    }
    qint64 earliest = m_inFlight.front().deadlineMs;
    for (const InFlight& f : m_inFlight)
        earliest = qMin(earliest, f.deadlineMs);
    m_timer.start(int(qMax<qint64>(0, earliest - m_clock.elapsed())));
}

void ElabExchangeQueue::failExchange(ElabExchange& ex, ErrorKind kind, const QString& message)
{
    if (ex.onError)
        ex.onError(kind, message);
}

void ElabExchangeQueue::resynchronise(const QString& reason)
{
    if (m_resyncing)
        return;
    m_resyncing = true;
    qCWarning(lcElab) << "resynchronising:" << reason;
    Q_EMIT resyncStarted(reason);
    ElabExchange burst;
    burst.frame = encode::requestSync(m_syncBurst);
    burst.expect = Expect::None;
    burst.owner = kResyncOwner;
    burst.droppable = false;
    ElabExchange enq;
    enq.frame = encode::requestMachineState();
    enq.expect = Expect::MachineState;
    enq.owner = kResyncOwner;
    enq.droppable = false;
    enq.tolerateStray = true; // late replies of the timed-out exchange come first
    enq.onReply = [this](const Reply& r) {
        m_resyncing = false;
        Q_EMIT resyncFinished(true, r.machineState);
    };
    enq.onError = [this](ErrorKind, const QString&) {
        m_resyncing = false;
        Q_EMIT resyncFinished(false, 0);
    };
    burst.onError = [this](ErrorKind, const QString&) {
        // The burst could not be written: the status request behind it is pointless too.
        for (auto it = m_queue.begin(); it != m_queue.end(); ++it) {
            if (it->owner == kResyncOwner) {
                m_queue.erase(it);
                break;
            }
        }
        m_resyncing = false;
        Q_EMIT resyncFinished(false, 0);
    };
    m_queue.push_front(std::move(enq));
    m_queue.push_front(std::move(burst));
    pump();
}

void ElabExchangeQueue::retryAfterResync(ElabExchange ex, const QString& why)
{
    --ex.retries;
    qCInfo(lcElab) << "retrying" << frameName(ex.frame) << "after:" << why;
    resynchronise(why);
    // Right behind the resynchronisation's own exchanges (if still queued), ahead of the rest.
    auto it = m_queue.begin();
    while (it != m_queue.end() && it->owner == kResyncOwner)
        ++it;
    m_queue.insert(it, std::move(ex));
}

void ElabExchangeQueue::dropQueued(ErrorKind kind, const QString& message, bool all)
{
    std::deque<ElabExchange> dropped;
    for (auto it = m_queue.begin(); it != m_queue.end();) {
        if (all || it->droppable) {
            dropped.push_back(std::move(*it));
            it = m_queue.erase(it);
        } else {
            ++it;
        }
    }
    if (all)
        m_resyncing = false;
    for (ElabExchange& ex : dropped)
        failExchange(ex, kind, message);
    pump();
}

void ElabExchangeQueue::abandonInFlight(ErrorKind kind, const QString& message)
{
    std::deque<InFlight> abandoned;
    abandoned.swap(m_inFlight);
    m_timer.stop();
    for (InFlight& f : abandoned) {
        if (f.ex.owner == kResyncOwner)
            m_resyncing = false;
        failExchange(f.ex, kind, message);
    }
}

void ElabExchangeQueue::failAll(ErrorKind kind, const QString& message)
{
    m_paceTimer.stop();
    abandonInFlight(kind, message);
    dropQueued(kind, message, true);
    m_decoder.reset();
    m_outstanding = 0;
    m_resyncing = false;
}

void ElabExchangeQueue::restart()
{
    failAll(ErrorKind::Cancelled, tr("link restarted"));
    m_window.clear();
    m_held = false;
    m_busy = false;
}

void ElabExchangeQueue::setHeld(bool held)
{
    m_held = held;
    if (!held)
        pump();
}

} // namespace stepdeck::elab
