#pragma once
#include "NanotecCodec.h"
#include "model/Traffic.h"
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <deque>
#include <functional>
#include <optional>

namespace stepdeck {
class Transport;
}

namespace stepdeck::nanotec {

// The bus master of one half-duplex RS485 link: at most one request is on the bus at any
// time, its reply is matched by address and command (1.1), everything else that arrives is
// handed on as unsolicited (the auto status 'j' of 5.31, late replies). Requests wait in three
// priority queues so stop and panic overtake commands, and commands overtake status polls.
class NanotecBus : public QObject
{
    Q_OBJECT
public:
    enum class Priority { Urgent = 0, Command = 1, Poll = 2 };
    enum class Outcome {
        Ok,        // the matching reply arrived
        Unknown,   // the drive answered with '?': it does not know the command
        Timeout,   // no matching reply in time (after the retries)
        Garbled,   // a malformed frame arrived instead of the reply
        Cancelled, // dropped by cancelAll() (stop, panic, disconnect)
    };
    using Handler = std::function<void(Outcome, const Reply&)>;

    struct Request
    {
        int address = 1; // kBroadcast for '*'
        QByteArray body; // without '#', address and CR
        Priority priority = Priority::Command;
        int timeoutMs = 0; // 0: defaultTimeout()
        int retries = 0;   // resend after a timeout or a garbled reply (idempotent bodies only)
        bool poll = false; // marked in the traffic console
        bool anyAddress = false; // accept the reply from any address (changing 'm', 5.4)
        Handler done;
    };

    explicit NanotecBus(Transport* transport, QObject* parent = nullptr);

    void setDefaultTimeout(int ms) { m_defaultTimeoutMs = qMax(1, ms); }
    int defaultTimeout() const { return m_defaultTimeoutMs; }
    // Broadcasts get no usable reply (several drives would answer at once): after sending,
    // the bus stays quiet this long so collisions and late echoes pass.
    void setBroadcastGuard(int ms) { m_broadcastGuardMs = ms; }

    void submit(Request request);
    // Every queued request and the one on the bus end with Cancelled; a late reply to the
    // latter is then passed on as unsolicited.
    void cancelAll();
    // Cancels queued requests whose priority is at or below `lowest` (e.g. polls only).
    void cancelQueued(Priority lowest);
    bool isIdle() const { return !m_current && queued() == 0; }
    bool hasQueued(Priority p) const { return !m_queues[int(p)].empty(); }
    int queued() const;
    // Drops what the transport has not sent yet (panic: the stop must not wait behind it).
    void discardOutput();
    void resetDecoder() { m_decoder.reset(); }

Q_SIGNALS:
    void unsolicited(const stepdeck::nanotec::Reply& reply);
    void garbage(const stepdeck::nanotec::Reply& reply);
    void traffic(stepdeck::TrafficRecord::Direction direction, const QByteArray& bytes, bool poll);
    // Every request as it ends, before its handler runs; answered: the drive's own reply came
    // (NanotecHeldSettings).
    void exchanged(int address, const QByteArray& body, bool answered);

private:
    void onData(const QByteArray& bytes);
    void onReply(const Reply& reply);
    void onTimeout();
    void pump();
    void transmit();
    void complete(Outcome outcome, const Reply& reply);
    bool matches(const Reply& reply) const;

    QPointer<Transport> m_transport;
    ReplyDecoder m_decoder;
    std::deque<Request> m_queues[3];
    std::optional<Request> m_current;
    QByteArray m_expectedKey;
    QTimer m_timer{this};
    int m_defaultTimeoutMs = 500;
    int m_broadcastGuardMs = 30;
};

} // namespace stepdeck::nanotec
