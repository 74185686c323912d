#include "EmisLink.h"
#include "EmisLogging.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <QScopedValueRollback>

namespace stepdeck::emis {

namespace {
constexpr int kGuardMs = 30;

QString printable(const QByteArray& text)
{
    return QString::fromLatin1(text.left(60));
}
} // namespace

EmisLink::EmisLink(Transport* transport, QObject* parent) : QObject(parent), m_transport(transport)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &EmisLink::onTimeout);
    m_guard.setSingleShot(true);
    connect(&m_guard, &QTimer::timeout, this, &EmisLink::pump);
    if (transport)
        connect(transport, &Transport::dataReceived, this, &EmisLink::onData);
}

void EmisLink::reset()
{
    cancelAll();
    m_decoder.reset();
    m_exclusive = false;
    m_guard.stop();
}

void EmisLink::submit(Request request)
{
    if (m_cancelling) {
        // A callback of cancelAll() asked for more: it is cancelled as well, never sent.
        if (request.done)
            request.done(Result{Outcome::Cancelled, {}, 0, {}, false});
        return;
    }
    m_queue.push_back(std::move(request));
    pump();
}

void EmisLink::setExclusive(bool exclusive)
{
    m_exclusive = exclusive;
    pump();
}

void EmisLink::cancelAll()
{
    m_timer.stop();
    std::optional<Request> current = std::move(m_current);
    m_current.reset();
    std::deque<Request> dropped = std::move(m_queue);
    m_queue.clear();
    const QScopedValueRollback<bool> cancelling(m_cancelling, true);
    // The one on the line was sent: the board may be executing it.
    if (current && current->done)
        current->done(Result{Outcome::Cancelled, {}, 0, {}, true});
    for (Request& r : dropped) {
        if (r.done)
            r.done(Result{Outcome::Cancelled, {}, 0, {}, false});
    }
}

void EmisLink::pump()
{
    if (m_current || m_guard.isActive())
        return;
    auto it = m_queue.begin();
    if (m_exclusive) {
        while (it != m_queue.end() && !it->exclusive)
            ++it;
    }
    if (it == m_queue.end())
        return;
    m_current = std::move(*it);
    m_queue.erase(it);
    if (!m_transport || !m_transport->isOpen()) {
        complete(Result{Outcome::Cancelled, {}, 0, tr("the link is not open"), false});
        return;
    }
    if (m_current->cancelIf && m_current->cancelIf()) {
        complete(Result{Outcome::Cancelled, {}, 0, {}, false});
        return;
    }
    m_stage = 0;
    m_acks = 0;
    m_firstText.clear();
    Q_EMIT traffic(TrafficRecord::Direction::Out, m_current->bytes, m_current->poll);
    m_transport->write(m_current->bytes);
    // Handed to the OS now, not on the event loop's next pass: the reply cannot come before
    // the request is on the line (issue 21, polls back to back).
    m_transport->pushOutput();
    m_timer.start(m_current->timeoutMs > 0 ? m_current->timeoutMs : m_defaultTimeoutMs);
}

void EmisLink::onData(const QByteArray& bytes)
{
    Q_EMIT traffic(TrafficRecord::Direction::In, bytes, m_current && m_current->poll);
    for (const Event& e : m_decoder.feed(bytes))
        onEvent(e);
}

void EmisLink::onEvent(const Event& e)
{
    if (e.kind == Event::Kind::Arrived) {
        Q_EMIT arrived(e.axis);
        return;
    }
    if (e.kind == Event::Kind::Invalid) {
        Q_EMIT stray(tr("garbage on the line: %1").arg(e.error));
        if (m_current)
            complete(Result{Outcome::Protocol, {}, m_acks, e.error});
        return;
    }
    if (m_guard.isActive() || !m_current) {
        Q_EMIT stray(tr("reply nobody waited for: '%1' (late, or sent by the board by itself)")
                         .arg(printable(e.text)));
        return;
    }
    if (e.kind == Event::Kind::Bell) {
        complete(Result{Outcome::Refused, e.text, m_acks, {}});
        return;
    }
    switch (m_current->expect) {
    case Expect::Ack:
        if (e.kind == Event::Kind::Ack)
            complete(Result{Outcome::Ok, e.text, 0, {}});
        else
            complete(Result{Outcome::Protocol, e.text, 0, tr("<NAK> instead of <ACK>")});
        return;
    case Expect::Start:
        if (e.kind == Event::Kind::Nak)
            complete(Result{Outcome::Ok, e.text, 0, {}});
        else
            complete(Result{Outcome::Protocol, e.text, 0, tr("<ACK> instead of <NAK>")});
        return;
    case Expect::Stored:
        onStoredEvent(e);
        return;
    }
}

void EmisLink::onStoredEvent(const Event& e)
{
    // 9.14: "<ACK> Ready! <ACK> <ACK> <ACK> <ACK>". The <ACK> that closes "Ready!" is the
    // first of the entries' <ACK>s. Lenient: a "Ready!" already in the first text counts too.
    if (e.kind != Event::Kind::Ack) {
        complete(Result{Outcome::Protocol, e.text, m_acks, tr("<NAK> while storing")});
        return;
    }
    if (m_stage == 0 && !isReady(e.text)) {
        m_firstText = e.text;
        m_stage = 1;
    } else if (m_stage <= 1) {
        if (!isReady(e.text)) {
            complete(Result{Outcome::Protocol, e.text, 0,
                            tr("'%1' where \"Ready!\" was expected").arg(printable(e.text))});
            return;
        }
        m_stage = 2;
        m_acks = 1;
    } else {
        ++m_acks;
    }
    if (m_stage == 2 && m_acks >= kStoredAcks) {
        complete(Result{Outcome::Ok, m_firstText, m_acks, {}});
        return;
    }
    // Writing the flash takes its time per entry: every step restarts the timeout. Past
    // storedMotors, the timeout is the quiet line that ends the write (onTimeout).
    m_timer.start(m_current->timeoutMs > 0 ? m_current->timeoutMs : m_defaultTimeoutMs);
}

void EmisLink::onTimeout()
{
    if (!m_current)
        return;
    QString detail;
    if (m_current->expect == Expect::Stored && m_stage == 2 &&
        m_acks >= qMax(1, m_current->storedMotors)) {
        complete(Result{Outcome::Ok, m_firstText, m_acks, {}}); // quiet after one per motor
        return;
    }
    if (m_current->expect == Expect::Stored && m_stage > 0) {
        detail =
            m_stage == 1
                ? tr("no \"Ready!\" after the first <ACK>")
                : tr("%1 of %2 entries acknowledged after \"Ready!\"").arg(m_acks).arg(kStoredAcks);
    }
    if (!m_current->poll)
        qCInfo(lcEmis) << "timeout; the line stays quiet for" << kGuardMs << "ms";
    m_guard.start(kGuardMs); // before complete(): the next request waits for it
    complete(Result{Outcome::Timeout, {}, m_acks, detail});
    Q_EMIT timedOut(); // after its own handler: what that settles comes first
}

void EmisLink::complete(const Result& result)
{
    m_timer.stop();
    Request done = std::move(*m_current);
    m_current.reset();
    if (done.done)
        done.done(result);
    pump();
}

} // namespace stepdeck::emis
