// One exchange with the drive of an axis (NanotecExchange.h).
#include "NanotecExchange.h"
#include "NanotecController.h"
#include <QTimer>

namespace stepdeck::nanotec {

Step NanotecExchange::exchange(Axis axis, const QByteArray& body, Check check,
                               NanotecBus::Priority priority, int retries, int timeoutMs)
{
    return [this, axis, body, check, priority, retries, timeoutMs](const Done& done) {
        if (!m_ctl.m_drives.contains(axis))
            return done({ErrorKind::InvalidValue,
                         tr("this machine has no axis %1").arg(m_ctl.nameOf(axis))});
        NanotecBus::Request r;
        r.address = m_ctl.m_drives[axis].address; // looked up now: 'm' may have moved the drive
        r.body = body;
        r.priority = priority;
        r.retries = retries;
        r.timeoutMs = timeoutMs;
        r.done = [this, axis, body, check, done](NanotecBus::Outcome o, const Reply& reply) {
            if (o != NanotecBus::Outcome::Ok)
                return done(outcomeFailure(axis, body, o, reply));
            m_ctl.m_sweep.noteAnswer(m_ctl.m_drives[axis], true);
            done(check ? check(reply) : Failure{});
        };
        m_ctl.m_bus->submit(r);
    };
}

Step NanotecExchange::expectValue(Axis axis, const QByteArray& cmd, qint64 expected)
{
    auto check = [this, axis, cmd, expected](const Reply& r) {
        if (r.value && *r.value == expected) {
            if (cmd.size() == 1)
                m_ctl.m_held.confirm(m_ctl.m_drives[axis].address, cmd.at(0), expected,
                                     m_ctl.nowMs());
            return Failure{};
        }
        return Failure{ErrorKind::VerifyFailed,
                       tr("%1 reads %2=%3 instead of %4 (the drive ignored the setting); not "
                          "started")
                           .arg(m_ctl.driveName(axis), QString::fromLatin1(cmd),
                                r.value ? QString::number(*r.value) : QStringLiteral("?"))
                           .arg(expected)};
    };
    return exchange(axis, "Z" + cmd, check, NanotecBus::Priority::Command, 1);
}

Step NanotecExchange::learnValue(Axis axis, char cmd)
{
    auto check = [this, axis, cmd](const Reply& r) {
        if (r.value)
            m_ctl.m_held.confirm(m_ctl.m_drives[axis].address, cmd, *r.value, m_ctl.nowMs());
        return Failure{};
    };
    return tolerant(exchange(axis, QByteArray("Z") + cmd, check));
}

bool NanotecExchange::holds(Axis axis, char cmd, qint64 value) const
{
    return m_ctl.m_drives.contains(axis) &&
           m_ctl.m_held.holds(m_ctl.m_drives[axis].address, cmd, value, m_ctl.nowMs());
}

Step NanotecExchange::wait(int ms)
{
    return [this, ms](const Done& done) { QTimer::singleShot(ms, &m_ctl, [done] { done({}); }); };
}

Failure NanotecExchange::outcomeFailure(Axis axis, const QByteArray& body,
                                        NanotecBus::Outcome outcome, const Reply& reply)
{
    const QString cmd = QString::fromLatin1(body);
    switch (outcome) {
    case NanotecBus::Outcome::Ok:
        return {};
    case NanotecBus::Outcome::Unknown:
        return {ErrorKind::Nak, tr("%1 does not know the command '%2' (it answered '?')")
                                    .arg(m_ctl.driveName(axis), cmd)};
    case NanotecBus::Outcome::Timeout:
        return {ErrorKind::Timeout,
                tr("%1 did not answer '%2' in time").arg(m_ctl.driveName(axis), cmd)};
    case NanotecBus::Outcome::Garbled:
        return {ErrorKind::Protocol,
                tr("%1: garbled reply to '%2' (%3)").arg(m_ctl.driveName(axis), cmd, reply.error)};
    case NanotecBus::Outcome::Cancelled:
        return {ErrorKind::Cancelled,
                reply.error.isEmpty() ? tr("'%1' to %2 was cancelled (stop, panic or disconnect)")
                                            .arg(cmd, m_ctl.driveName(axis))
                                      : reply.error};
    }
    return {};
}

Step NanotecExchange::setting(Axis axis, const QByteArray& body)
{
    // Settings are idempotent: a reply garbled by line noise is simply asked again.
    return exchange(axis, body, {}, NanotecBus::Priority::Command, 1);
}

Step NanotecExchange::startRun(Axis axis)
{
    // 'A' is not idempotent (a second 'A' could repeat a relative move). When its echo is
    // lost or garbled, the status tells whether it started: running means it did (5.21).
    return [this, axis](const Done& done) {
        exchange(axis, "A")([this, axis, done](const Failure& f) {
            if (f.ok() || (f.kind != ErrorKind::Protocol && f.kind != ErrorKind::Timeout))
                return done(f);
            auto running = std::make_shared<bool>(false);
            auto check = sink([this, axis, running](qint64 v) {
                m_ctl.m_sweep.applyStatusWord(m_ctl.m_drives[axis], v);
                *running = !decodeStatus(v).ready;
            });
            exchange(axis, "$", check, NanotecBus::Priority::Command,
                     1)([f, running, done](const Failure& read) {
                done(read.ok() && *running ? Failure{} : f);
            });
        });
    };
}

} // namespace stepdeck::nanotec
