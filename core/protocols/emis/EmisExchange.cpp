// Requests onto the SMC-IC4 link and the meaning of their failures.
#include "EmisExchange.h"
#include "EmisModel.h"

namespace stepdeck::emis {

EmisExchange::EmisExchange(Transport* transport, QObject* owner)
    : m_link(new EmisLink(transport, owner))
{}

void EmisExchange::request(const QByteArray& bytes, EmisLink::Expect expect, Handler done,
                           int timeoutMs, int storedMotors, bool exclusive)
{
    EmisLink::Request r;
    r.bytes = bytes;
    r.expect = expect;
    r.timeoutMs = timeoutMs;
    r.storedMotors = storedMotors;
    r.exclusive = exclusive;
    r.done = std::move(done);
    m_link->submit(std::move(r));
}

void EmisExchange::cancelAll(ErrorKind kind, const QString& message)
{
    m_abort = qMakePair(kind, message);
    m_link->cancelAll(); // every pending request finishes with kind and message
    m_abort.reset();
}

ErrorKind EmisExchange::failureKind(const EmisLink::Result& r) const
{
    if (m_abort && r.outcome == EmisLink::Outcome::Cancelled)
        return m_abort->first;
    switch (r.outcome) {
    case EmisLink::Outcome::Ok:
        return ErrorKind::None;
    case EmisLink::Outcome::Refused:
        return ErrorKind::Nak;
    case EmisLink::Outcome::Timeout:
        return ErrorKind::Timeout;
    case EmisLink::Outcome::Protocol:
        return ErrorKind::Protocol;
    case EmisLink::Outcome::Cancelled:
        return ErrorKind::Cancelled;
    }
    return ErrorKind::Protocol;
}

QString EmisExchange::failureText(const QByteArray& bytes, const EmisLink::Result& r) const
{
    if (m_abort && r.outcome == EmisLink::Outcome::Cancelled)
        return m_abort->second;
    const QString command = formatTraffic(bytes);
    switch (r.outcome) {
    case EmisLink::Outcome::Ok:
        return {};
    case EmisLink::Outcome::Refused:
        return tr("the SMC-IC4 refused '%1' (<BEL>: invalid value, or the motor is still "
                  "moving)")
            .arg(command);
    case EmisLink::Outcome::Timeout:
        return r.detail.isEmpty()
                   ? tr("no reply to '%1' in time").arg(command)
                   : tr("no complete reply to '%1' in time: %2").arg(command, r.detail);
    case EmisLink::Outcome::Protocol:
        return tr("unexpected reply to '%1': %2").arg(command, r.detail);
    case EmisLink::Outcome::Cancelled:
        return r.detail.isEmpty() ? tr("'%1' was cancelled (disconnect)").arg(command) : r.detail;
    }
    return {};
}

} // namespace stepdeck::emis
