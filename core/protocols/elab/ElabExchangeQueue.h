#pragma once
#include "ElabCodec.h"
#include "ElabExpect.h"
#include "ElabWireWindow.h"
#include "model/CommandResult.h"
#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <deque>
#include <functional>

namespace stepdeck {
class Transport;
}

namespace stepdeck::elab {

// One request/reply pair on the E-LAB line.
struct ElabExchange
{
    QByteArray frame;                  // written as is, unless build is set
    std::function<QByteArray()> build; // builds the frame when it is written (jog coalescing)
    Expect expect = Expect::AckNak;
    quint64 owner = 0;          // the request it belongs to; 0: internal
    bool poll = false;          // status-poller traffic (the console may hide it)
    bool droppable = true;      // a stop drops it while it is still queued
    bool tolerateStray = false; // replies of another kind are skipped, not errors
    // Idempotent requests (status reads): re-sent after a resynchronisation when the reply was
    // of another kind or, outside polls, did not come in time. Polls count misses instead.
    int retries = 0;
    // Written only once this many bytes fit into the wire window (wireRoomBytes()); 0: any
    // time. A <DC2> chunk needs room for one pair and is built (build) to fill the room.
    qint64 wireRoom = 0;
    // Reads of one group (the same non-zero id) go out back to back: the first once nothing
    // is in flight, the others right behind it in the same pass, before any reply is read, at
    // most kMaxPipelined in flight (issue 21: a poll's RequestAxeState and RequestMachineState,
    // and every few polls RequestTemperature and RequestStart).
    // A group is never split: nothing can be written between its reads. The board answers in
    // the order it receives and its replies are self-delimiting with distinct lead bytes, so
    // they are still matched first in, first out. Only for idempotent reads with a reply.
    quint64 pipelineGroup = 0;
    // Expect::None: called with an empty Reply once the bytes have left the transport (also
    // when build made nothing to send).
    std::function<void(const Reply&)> onReply;
    std::function<void(ErrorKind, const QString&)> onError;
};

// The line discipline of the E-LAB adapter: one exchange in flight, replies matched in order,
// a timeout per exchange, at most one frame inside the transport, resynchronisation after a
// timeout or garbage, and overtaking for stop and panic.
//
// Frames without a reply (<DC2> chunks, <SYN> bursts) are complete when they are on the wire,
// not when the transport took them: when neither the driver (pendingOutputBytes: Qt's queue
// and TIOCOUTQ) nor the wire budget (WireBudget: what the line can have carried at its
// character rate since the bytes were written) leaves more than kWireLowWaterBytes on the way.
// (ElabWireWindow). The wire budget is the part that holds on a pseudo-terminal, which reports
// no queue, and on a USB adapter, whose own FIFO TIOCOUTQ does not count. A frame with wireRoom is
// written only while at most kWireWindowBytes - wireRoom are beyond the line by either count, so
// the stream never has more than one chunk on its way when the board says XOFF.
//
// Line noise: bytes the decoder cannot read as a reply are skipped while an exchange waits
// (noise in front of a reply must not cost the reply); a reply destroyed by noise then times
// out like any lost reply. Idempotent requests are retried after resynchronisation, so
// occasional noise is survived and only persistent garbage fails (polls miss, link lost).
//
// Pipelining: the reads of one group (ElabExchange::pipelineGroup) go out back to back;
// anything else still waits until nothing is in flight, so a command or a <DC2> chunk never goes
// out behind a read's pending reply, and stop and panic overtake as before. A reply that fits the
// read behind the one it should answer means that read's own reply was lost: it ends like a read
// without reply, and the reply is matched on.
//
// Overtaking: stop and panic are written at once, even with an exchange in flight. The board
// answers in the order it receives, so the overtaking exchange simply joins the in-flight list
// behind the exchange already written, and replies keep being matched first-in, first-out.
// For panic the in-flight exchanges are abandoned first (their bytes may have been discarded
// from the transport, so their replies may or may not come); the panic exchange and the status
// read behind it tolerate strays, which absorbs such late replies.
class ElabExchangeQueue : public QObject
{
    Q_OBJECT
public:
    static constexpr quint64 kResyncOwner = ~quint64(0);

    explicit ElabExchangeQueue(Transport* transport, QObject* parent = nullptr);

    void setTimeoutMs(int ms) { m_timeoutMs = qMax(1, ms); }
    int timeoutMs() const { return m_timeoutMs; }
    void setSyncBurst(int count) { m_syncBurst = qMax(1, count); }
    // The line's character time (57600 8N2: 191 us), for the wire budget.
    void setCharacterTimeUs(double us) { m_window.setCharacterTimeUs(us); }
    // Bytes that may still be on their way when a frame without a reply counts as sent: one
    // <DC2> pair.
    static constexpr qint64 kWireLowWaterBytes = 2;
    // The most of our bytes that may be beyond what the line can have carried when a frame
    // with wireRoom is written: one stream chunk (ElabCtlStream::kChunkSteps pairs).
    static constexpr qint64 kWireWindowBytes = 16;
    // Reads of one group in flight at most: a poll's two status words, the temperature and the
    // start button.
    static constexpr int kMaxPipelined = 4;
    // Bytes that fit into the wire window now: kWireWindowBytes less the larger of the wire
    // budget's backlog and what the transport reports still pending.
    qint64 wireRoomBytes() const;
    // The wire budget's monotonic clock in ns (ElabWireWindow::setClock).
    void setWireClock(std::function<qint64()> nowNs) { m_window.setClock(std::move(nowNs)); }

    void enqueue(ElabExchange ex);     // behind everything queued
    void enqueueNext(ElabExchange ex); // ahead of everything queued: the next step of a sequence
    void enqueueNext(QList<ElabExchange> exs); // the same for several, in their order
    static quint64 newPipelineGroup();         // a fresh id for ElabExchange::pipelineGroup
    void overtake(ElabExchange ex, bool discardOutput);

    // Queued (not yet written) exchanges finish with kind/message. all=false keeps
    // non-droppable ones (polls, resynchronisation).
    void dropQueued(ErrorKind kind, const QString& message, bool all);
    // Written exchanges whose reply is pending finish now; late replies become strays.
    void abandonInFlight(ErrorKind kind, const QString& message);
    void failAll(ErrorKind kind, const QString& message);
    // "RequestSync": a burst of <SYN>, then RequestMachineState; strays before its reply are
    // skipped. Runs ahead of queued work, after what is in flight.
    void resynchronise(const QString& reason);
    void restart();          // a new link: decoder, counters and pending state cleared
    void setHeld(bool held); // nothing is written while held (reset pulse)

    bool isIdle() const { return m_queue.empty() && m_inFlight.empty(); }
    bool isResyncing() const { return m_resyncing; }
    int inFlightCount() const { return int(m_inFlight.size()); }

Q_SIGNALS:
    void flowControl(bool resume); // the board's XON (true) / XOFF (false) during a DC2 stream
    void trafficOut(const QByteArray& bytes, bool poll);
    void trafficIn(const QByteArray& bytes, bool poll);
    void resyncStarted(const QString& reason);
    void resyncFinished(bool ok, quint16 machineState);
    void noise(const QByteArray& bytes); // skipped bytes that were no reply
    void idle();                         // nothing queued or in flight any more

private:
    struct InFlight
    {
        ElabExchange ex;
        qint64 deadlineMs = 0;
    };

    void pump();
    bool mayWriteNow(const ElabExchange& next) const; // one in flight, or one group's reads
    // The reply fits the read of the same group behind the target: the target's was lost.
    bool skipsLostReply(const Reply& reply);
    void write(ElabExchange ex);
    void onData(const QByteArray& bytes);
    void onBytesWritten(qint64 count);
    void onTimeout();
    void handleReply(const Reply& reply);
    void completeWritten();
    void armPace(qint64 ns);
    void armTimer();
    void failExchange(ElabExchange& ex, ErrorKind kind, const QString& message);
    // Resynchronises, then sends ex again right behind the resynchronisation.
    void retryAfterResync(ElabExchange ex, const QString& why);

    QPointer<Transport> m_transport;
    ReplyDecoder m_decoder;
    std::deque<ElabExchange> m_queue;
    std::deque<InFlight> m_inFlight;
    QTimer m_timer{this};
    QTimer m_paceTimer{this}; // re-checks the wire while what we wrote is on its way
    QElapsedTimer m_clock;
    ElabWireWindow m_window;
    qint64 m_outstanding = 0; // bytes handed to the transport and not yet reported written
    int m_timeoutMs = 500;
    int m_syncBurst = 16;
    bool m_held = false;
    bool m_resyncing = false;
    bool m_busy = false;
};

} // namespace stepdeck::elab
