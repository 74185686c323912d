#pragma once
#include "EmisCodec.h"
#include "model/Traffic.h"
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <deque>
#include <functional>

namespace stepdeck {
class Transport;
}

namespace stepdeck::emis {

// The line discipline of one SMC-IC4 link: one command on the line at a time, its reply
// matched by what it must end with (chapter 9), a timeout per command, and the <DCn> arrival
// bytes, which may come at any time, handed on as arrived().
//
// While the link is exclusive (an input program being written, 9.17: every byte until <ETX>
// belongs to the program), only requests marked exclusive go out; the others wait.
class EmisLink : public QObject
{
    Q_OBJECT
public:
    enum class Expect {
        Ack,   // <ACK>, text optional (echo or answer)
        Start, // <NAK>: a move or reference run started (9.9, 9.11)
        // <ACK>, "Ready!" <ACK>, then more <ACK>s (9.14): done at kStoredAcks after "Ready!",
        // or at storedMotors or more when the line then stays quiet for the timeout (a board
        // that acknowledges per motor named). Never earlier: an <ACK> still to come would be
        // taken as the reply to the next command.
        Stored,
    };
    enum class Outcome {
        Ok,
        Refused,   // <BEL>
        Timeout,   // no (complete) reply in time
        Protocol,  // a reply that does not fit the command
        Cancelled, // dropped by cancelAll()
    };
    struct Result
    {
        Outcome outcome = Outcome::Ok;
        QByteArray text;    // the text of the reply (Stored: of the first <ACK>)
        int storedAcks = 0; // Stored: the <ACK>s after "Ready!" that arrived
        QString detail;     // Protocol / Timeout: what was seen
        bool sent = true;   // Cancelled: false when it never left the queue
    };
    using Handler = std::function<void(const Result&)>;
    struct Request
    {
        QByteArray bytes; // with its terminator
        Expect expect = Expect::Ack;
        int storedMotors = 0; // Stored: the motors the entry names (SystemEntry::motorCount)
        int timeoutMs = 0;    // 0: defaultTimeout()
        bool poll = false;
        bool exclusive = false;
        // Asked when it is its turn: true ends it Cancelled, never sent (a move whose work
        // speed write, queued right before it, was not taken).
        std::function<bool()> cancelIf;
        Handler done;
    };

    explicit EmisLink(Transport* transport, QObject* parent = nullptr);

    void setDefaultTimeout(int ms) { m_defaultTimeoutMs = qMax(1, ms); }
    int defaultTimeout() const { return m_defaultTimeoutMs; }
    void submit(Request request);
    void setExclusive(bool exclusive);
    bool isExclusive() const { return m_exclusive; }
    // Every queued request and the one on the line end with Cancelled.
    void cancelAll();
    bool isIdle() const { return !m_current && m_queue.empty() && !m_guard.isActive(); }
    bool busy() const { return m_current.has_value(); }
    void reset(); // after (re)opening: fresh decoder, nothing pending
    // Drops whatever arrives in the next ms (stale replies of an earlier session waiting in
    // the port's buffers) before the first command goes out.
    void settle(int ms) { m_guard.start(ms); }

Q_SIGNALS:
    void arrived(stepdeck::Axis axis);
    void stray(const QString& what); // a reply nobody waited for, or garbage
    void timedOut();                 // a request (poll or command) got no complete reply in time
    void traffic(stepdeck::TrafficRecord::Direction direction, const QByteArray& bytes, bool poll);

private:
    void onData(const QByteArray& bytes);
    void onEvent(const Event& event);
    void onStoredEvent(const Event& event);
    void onTimeout();
    void pump();
    void complete(const Result& result);

    QPointer<Transport> m_transport;
    ReplyDecoder m_decoder;
    std::deque<Request> m_queue;
    std::optional<Request> m_current;
    int m_stage = 0; // Stored: 0 before the first <ACK>, 1 waiting for "Ready!", 2 counting
    int m_acks = 0;
    QByteArray m_firstText;
    bool m_exclusive = false;
    bool m_cancelling = false;
    QTimer m_timer{this};
    // After a timeout the line stays quiet briefly, so a late reply is not taken for the
    // answer to the next command.
    QTimer m_guard{this};
    int m_defaultTimeoutMs = 500;
};

} // namespace stepdeck::emis
