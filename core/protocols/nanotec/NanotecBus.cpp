#include "NanotecBus.h"
#include "Logging.h"
#include "NanotecLogging.h"
#include "transport/Transport.h"

namespace stepdeck::nanotec {

NanotecBus::NanotecBus(Transport* transport, QObject* parent)
    : QObject(parent), m_transport(transport)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &NanotecBus::onTimeout);
    if (transport)
        connect(transport, &Transport::dataReceived, this, &NanotecBus::onData);
}

int NanotecBus::queued() const
{
    return int(m_queues[0].size() + m_queues[1].size() + m_queues[2].size());
}

void NanotecBus::submit(Request request)
{
    m_queues[int(request.priority)].push_back(std::move(request));
    pump();
}

void NanotecBus::cancelAll()
{
    m_timer.stop();
    std::optional<Request> current = std::move(m_current);
    m_current.reset();
    cancelQueued(Priority::Urgent);
    if (current && current->done)
        current->done(Outcome::Cancelled, Reply{});
}

void NanotecBus::cancelQueued(Priority lowest)
{
    std::deque<Request> dropped;
    for (int p = int(lowest); p <= int(Priority::Poll); ++p) {
        for (Request& r : m_queues[p])
            dropped.push_back(std::move(r));
        m_queues[p].clear();
    }
    for (Request& r : dropped) {
        if (r.done)
            r.done(Outcome::Cancelled, Reply{});
    }
}

void NanotecBus::discardOutput()
{
    if (m_transport)
        m_transport->discardOutput();
}

void NanotecBus::pump()
{
    if (m_current)
        return;
    for (auto& queue : m_queues) {
        if (!queue.empty()) {
            m_current = std::move(queue.front());
            queue.pop_front();
            transmit();
            return;
        }
    }
}

void NanotecBus::transmit()
{
    Request& r = *m_current;
    const QByteArray frame = encode::command(r.address, r.body);
    if (frame.isEmpty() || !m_transport || !m_transport->isOpen()) {
        // Forbidden bodies are refused by the callers already; this is the last line.
        Reply none;
        none.error = frame.isEmpty() ? forbiddenReason(r.body) : tr("link is not open");
        complete(Outcome::Cancelled, none);
        return;
    }
    m_expectedKey = commandKey(r.body);
    Q_EMIT traffic(TrafficRecord::Direction::Out, frame, r.poll);
    m_transport->write(frame);
    // Handed to the OS now, not on the event loop's next pass: the reply cannot come before
    // the request is on the line (issue 21, polls back to back).
    m_transport->pushOutput();
    const int timeout = r.address == kBroadcast
                            ? m_broadcastGuardMs
                            : (r.timeoutMs > 0 ? r.timeoutMs : m_defaultTimeoutMs);
    m_timer.start(timeout);
}

void NanotecBus::onData(const QByteArray& bytes)
{
    Q_EMIT traffic(TrafficRecord::Direction::In, bytes, m_current && m_current->poll);
    for (const Reply& reply : m_decoder.feed(bytes))
        onReply(reply);
}

bool NanotecBus::matches(const Reply& reply) const
{
    const Request& r = *m_current;
    if (r.address == kBroadcast)
        return false;
    const bool addressOk = r.anyAddress || reply.address == r.address ||
                           (reply.address == 0 && m_expectedKey.startsWith('Z'));
    if (!addressOk)
        return false;
    if (reply.kind == Reply::Kind::LongUnknown)
        return m_expectedKey.startsWith(':');
    return reply.key == m_expectedKey;
}

void NanotecBus::onReply(const Reply& reply)
{
    switch (reply.kind) {
    case Reply::Kind::HostEcho:
        return; // our own frame, echoed by a half-duplex adapter
    case Reply::Kind::Invalid:
        qCInfo(lcNanotec) << "garbled reply:" << reply.raw << reply.error;
        Q_EMIT garbage(reply);
        if (m_current && m_current->address != kBroadcast) {
            if (m_current->retries > 0) {
                --m_current->retries;
                transmit();
            } else {
                complete(Outcome::Garbled, reply);
            }
        }
        return;
    default:
        break;
    }
    if (m_current && matches(reply)) {
        const bool unknown =
            reply.kind == Reply::Kind::Unknown || reply.kind == Reply::Kind::LongUnknown;
        complete(unknown ? Outcome::Unknown : Outcome::Ok, reply);
        return;
    }
    if (m_current && m_current->address == kBroadcast)
        return; // answers to '*' collide on a real bus; they carry nothing we need
    Q_EMIT unsolicited(reply);
}

void NanotecBus::onTimeout()
{
    if (!m_current)
        return;
    if (m_current->address == kBroadcast) {
        complete(Outcome::Ok, Reply{});
        return;
    }
    if (m_current->retries > 0) {
        --m_current->retries;
        qCDebug(lcNanotec) << "no reply to" << m_current->body << "- retrying";
        transmit();
        return;
    }
    complete(Outcome::Timeout, Reply{});
}

void NanotecBus::complete(Outcome outcome, const Reply& reply)
{
    m_timer.stop();
    Request done = std::move(*m_current);
    m_current.reset();
    Q_EMIT exchanged(done.address, done.body, outcome == Outcome::Ok);
    if (done.done)
        done.done(outcome, reply);
    pump();
}

} // namespace stepdeck::nanotec
