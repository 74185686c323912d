// Step sequencing on the bus, console, bus scan, refresh and the model-specific operations.
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "NanotecLogging.h"
#include "NanotecModel.h"
#include "model/ModelOperations.h"
#include "transport/Transport.h"
#include <QSet>
#include <QTimer>
#include <algorithm>

namespace stepdeck::nanotec {

// ---------------------------------------------------------------- steps

void NanotecController::runSteps(QList<Step> steps, Done done)
{
    runFrom(std::make_shared<QList<Step>>(std::move(steps)), 0, std::move(done));
}

void NanotecController::runFrom(std::shared_ptr<QList<Step>> steps, int index, Done done)
{
    if (index >= steps->size()) {
        done({});
        return;
    }
    (*steps)[index]([steps, index, done](const Failure& f) {
        if (!f.ok())
            done(f);
        else
            runFrom(steps, index + 1, done);
    });
}

NanotecController::Step NanotecController::tolerant(Step step)
{
    return [step](const Done& done) {
        step([done](const Failure& f) {
            if (!f.ok() && f.kind != ErrorKind::Cancelled)
                qCInfo(lcNanotec) << "ignored:" << f.message;
            done(f.kind == ErrorKind::Cancelled ? f : Failure{});
        });
    };
}

namespace {
// Status reads are idempotent: one garbled or lost reply (line noise) is asked again before
// the request fails (issue 12: occasional noise is survived, persistent garbage fails).
constexpr NanotecBus::Priority kStatusPriority = NanotecBus::Priority::Command;
constexpr int kStatusRetries = 1;
} // namespace

NanotecController::Check NanotecController::sink(std::function<void(qint64)> store)
{
    return [store](const Reply& r) {
        if (!r.value)
            return Failure{ErrorKind::Protocol,
                           tr("reply '%1' carries no value").arg(QString::fromLatin1(r.raw))};
        store(*r.value);
        return Failure{};
    };
}

NanotecController::Step NanotecController::exchange(Axis axis, const QByteArray& body, Check check,
                                                    NanotecBus::Priority priority, int retries,
                                                    int timeoutMs)
{
    return [this, axis, body, check, priority, retries, timeoutMs](const Done& done) {
        if (!m_drives.contains(axis))
            return done(
                {ErrorKind::InvalidValue, tr("this machine has no axis %1").arg(axisName(axis))});
        NanotecBus::Request r;
        r.address = m_drives[axis].address; // looked up now: 'm' may have moved the drive
        r.body = body;
        r.priority = priority;
        r.retries = retries;
        r.timeoutMs = timeoutMs;
        r.done = [this, axis, body, check, done](NanotecBus::Outcome o, const Reply& reply) {
            if (o != NanotecBus::Outcome::Ok)
                return done(outcomeFailure(axis, body, o, reply));
            noteAnswer(m_drives[axis], true);
            done(check ? check(reply) : Failure{});
        };
        m_bus->submit(r);
    };
}

NanotecController::Step NanotecController::expectValue(Axis axis, const QByteArray& cmd,
                                                       qint64 expected)
{
    auto check = [this, axis, cmd, expected](const Reply& r) {
        if (r.value && *r.value == expected)
            return Failure{};
        return Failure{ErrorKind::VerifyFailed,
                       tr("%1 reads %2=%3 instead of %4 (the drive ignored the setting); not "
                          "started")
                           .arg(driveName(axis), QString::fromLatin1(cmd),
                                r.value ? QString::number(*r.value) : QStringLiteral("?"))
                           .arg(expected)};
    };
    return exchange(axis, "Z" + cmd, check, NanotecBus::Priority::Command, 1);
}

NanotecController::Step NanotecController::wait(int ms)
{
    return [this, ms](const Done& done) { QTimer::singleShot(ms, this, [done] { done({}); }); };
}

NanotecController::Failure NanotecController::outcomeFailure(Axis axis, const QByteArray& body,
                                                             NanotecBus::Outcome outcome,
                                                             const Reply& reply)
{
    const QString cmd = QString::fromLatin1(body);
    switch (outcome) {
    case NanotecBus::Outcome::Ok:
        return {};
    case NanotecBus::Outcome::Unknown:
        return {
            ErrorKind::Nak,
            tr("%1 does not know the command '%2' (it answered '?')").arg(driveName(axis), cmd)};
    case NanotecBus::Outcome::Timeout:
        return {ErrorKind::Timeout, tr("%1 did not answer '%2' in time").arg(driveName(axis), cmd)};
    case NanotecBus::Outcome::Garbled:
        return {ErrorKind::Protocol,
                tr("%1: garbled reply to '%2' (%3)").arg(driveName(axis), cmd, reply.error)};
    case NanotecBus::Outcome::Cancelled:
        return {ErrorKind::Cancelled,
                reply.error.isEmpty() ? tr("'%1' to %2 was cancelled (stop, panic or disconnect)")
                                            .arg(cmd, driveName(axis))
                                      : reply.error};
    }
    return {};
}

void NanotecController::finishWith(RequestId id, const Failure& failure, const QVariant& value)
{
    if (failure.ok())
        finishOk(id, value);
    else
        finishError(id, failure.kind, failure.message);
}

NanotecController::Drive* NanotecController::driveFor(const QVariantMap& args, RequestId id)
{
    const auto axis =
        axisFromName(args.value(QStringLiteral("axis"), QStringLiteral("X")).toString());
    if (!axis || !m_drives.contains(*axis)) {
        finishError(id, ErrorKind::InvalidValue,
                    tr("unknown axis '%1' (this machine has %2)")
                        .arg(args.value(QStringLiteral("axis")).toString())
                        .arg([this] {
                            QStringList n;
                            for (Axis a : m_drives.keys())
                                n << axisName(a);
                            return n.join(QLatin1Char(','));
                        }()));
        return nullptr;
    }
    if (linkState() != LinkState::Connected) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return nullptr;
    }
    return &m_drives[*axis];
}

// ---------------------------------------------------------------- status, console

void NanotecController::refreshStatus(RequestId id)
{
    if (linkState() != LinkState::Connected)
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    QList<Step> steps;
    auto answered = std::make_shared<int>(0);
    for (Axis axis : m_drives.keys()) {
        auto ok = std::make_shared<bool>(false);
        steps << tolerant([this, axis, ok, answered](const Done& done) {
            runSteps(
                {exchange(axis, "$", sink([this, axis, ok, answered](qint64 v) {
                              applyStatusWord(m_drives[axis], v);
                              *ok = true;
                              ++*answered;
                          }),
                          kStatusPriority, kStatusRetries),
                 exchange(axis, "C", sink([this, axis](qint64 v) { m_drives[axis].position = v; }),
                          kStatusPriority, kStatusRetries),
                 exchange(axis, "ZY", sink([this, axis](qint64 v) { m_drives[axis].inputs = v; }),
                          kStatusPriority, kStatusRetries)},
                [this, axis, ok, done](const Failure& f) {
                    if (!*ok && f.kind == ErrorKind::Timeout)
                        noteAnswer(m_drives[axis], false);
                    done(f);
                });
        });
    }
    runSteps(steps, [this, id, answered](const Failure& f) {
        updateStatus();
        publishStatus();
        if (!f.ok())
            return finishWith(id, f);
        if (*answered == 0)
            return finishError(id, ErrorKind::Timeout, tr("no drive answered the status request"));
        finishOk(id, QVariant::fromValue(status()));
    });
}

void NanotecController::sendRaw(RequestId id, const QByteArray& bytes)
{
    if (linkState() != LinkState::Connected)
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    CommandDecoder decoder;
    QList<Command> frames = decoder.feed(bytes.endsWith('\r') ? bytes : bytes + '\r');
    if (frames.isEmpty())
        return finishError(id, ErrorKind::InvalidValue,
                           tr("not a Nanotec frame: expected '#<address><command>\\r'"));
    for (const Command& c : frames) {
        if (!c.valid)
            return finishError(id, ErrorKind::InvalidValue, c.error);
        const QString forbidden = forbiddenReason(c.body);
        if (!forbidden.isEmpty())
            return finishError(id, ErrorKind::Refused, forbidden);
    }
    auto replies = std::make_shared<QStringList>();
    QList<Step> steps;
    for (const Command& c : frames) {
        steps << [this, c, replies](const Done& done) {
            NanotecBus::Request r;
            r.address = c.broadcast ? kBroadcast : c.address;
            r.body = c.body;
            r.done = [c, replies, done](NanotecBus::Outcome o, const Reply& reply) {
                if (o == NanotecBus::Outcome::Timeout)
                    return done({ErrorKind::Timeout, tr("no reply to '%1' from address %2")
                                                         .arg(QString::fromLatin1(c.body))
                                                         .arg(c.address)});
                if (o == NanotecBus::Outcome::Cancelled)
                    return done({ErrorKind::Cancelled, tr("cancelled")});
                *replies << QString::fromLatin1(reply.raw);
                done({});
            };
            m_bus->submit(r);
        };
    }
    runSteps(steps, [this, id, replies](const Failure& f) {
        finishWith(id, f, replies->join(QLatin1Char('\n')));
    });
}

// ---------------------------------------------------------------- scan

void NanotecController::scanBus(RequestId id)
{
    modelOperation(id, operation::kScan, {});
}

void NanotecController::scan(RequestId id, int first, int last, int timeoutMs)
{
    auto found = std::make_shared<QVariantList>();
    auto seen = std::make_shared<QSet<int>>();
    auto note = [this, first, last, found, seen](const Reply& reply) {
        if (reply.kind != Reply::Kind::Firmware || reply.address < first || reply.address > last ||
            seen->contains(reply.address))
            return;
        seen->insert(reply.address);
        found->append(QVariantMap{{"address", reply.address},
                                  {"hardware", reply.firmware.hardware},
                                  {"interface", reply.firmware.interface},
                                  {"date", reply.firmware.date},
                                  {"firmware", reply.firmware.text}});
        for (Drive& d : m_drives) {
            if (d.address == reply.address) {
                d.firmware = reply.firmware.text;
                noteAnswer(d, true);
            }
        }
    };
    // The per-address timeout is short (254 addresses): a drive that answers a little late
    // (a loaded host, a slow USB adapter) is still found -- its 'v' reply arrives while the
    // next address is probed and would otherwise be dropped as unsolicited.
    const QMetaObject::Connection late = connect(m_bus, &NanotecBus::unsolicited, this, note);
    QList<Step> steps;
    for (int address = first; address <= last; ++address) {
        steps << [this, address, timeoutMs, note](const Done& done) {
            NanotecBus::Request r;
            r.address = address;
            r.body = "v"; // 5.22: answers with hardware, interface and release date
            r.timeoutMs = timeoutMs;
            r.done = [note, done](NanotecBus::Outcome o, const Reply& reply) {
                if (o == NanotecBus::Outcome::Cancelled)
                    return done({ErrorKind::Cancelled, tr("scan cancelled")});
                if (o == NanotecBus::Outcome::Ok)
                    note(reply);
                done({});
            };
            m_bus->submit(r);
        };
    }
    runSteps(steps, [this, id, found, late](const Failure& f) {
        disconnect(late);
        std::sort(found->begin(), found->end(), [](const QVariant& a, const QVariant& b) {
            return a.toMap().value(QStringLiteral("address")).toInt() <
                   b.toMap().value(QStringLiteral("address")).toInt();
        });
        if (linkState() != LinkState::Connected && transport() && transport()->isOpen())
            transport()->close(); // the port was opened for the scan only
        finishWith(id, f, *found);
    });
}

void NanotecController::runPendingScan()
{
    const PendingScan p = *m_pendingScan;
    m_pendingScan.reset();
    scan(p.id, p.first, p.last, p.timeoutMs);
}

// ---------------------------------------------------------------- model operations

void NanotecController::modelOperation(RequestId id, const QString& name, const QVariantMap& args)
{
    auto intArg = [&](const char* key, int def) {
        return args.value(QString::fromLatin1(key), def).toInt();
    };
    if (name == operation::kScan) {
        PendingScan p{id, intArg("first", kMinAddress), intArg("last", kMaxAddress),
                      intArg("timeoutMs", 40)};
        if (!isValidAddress(p.first) || !isValidAddress(p.last) || p.first > p.last)
            return finishError(id, ErrorKind::InvalidValue,
                               tr("scan range must lie within 1..254"));
        if (!transport())
            return finishError(id, ErrorKind::LinkDown, tr("no transport"));
        m_pendingScan = p;
        if (transport()->isOpen())
            return runPendingScan();
        transport()->open(lineSettings()); // a scan needs no configured drive
        return;
    }
    if (name == operation::kReference) {
        QMap<Axis, int> dirs;
        const QVariantMap axes = args.value(QStringLiteral("axes")).toMap();
        for (auto it = axes.cbegin(); it != axes.cend(); ++it) {
            if (const auto axis = axisFromName(it.key()))
                dirs.insert(*axis, it.value().toInt());
        }
        return referenceWithType(
            id, dirs, args.value(QStringLiteral("type")).toString() == QLatin1String("internal"));
    }
    Drive* d = driveFor(args, id);
    if (!d)
        return;
    const Axis axis = d->axis;
    if (NanotecClosedLoop::isOperation(name))
        return m_closedLoop->operation(id, name, axis, args);
    const int record = intArg("record", 0);
    auto simple = [&](const QByteArray& body, bool needsReady) {
        if (needsReady) {
            const QString why = motionRefusal(axis, false);
            if (!why.isEmpty())
                return finishError(id, ErrorKind::Refused, why);
        }
        runSteps({exchange(axis, body)}, [this, id](const Failure& f) { finishWith(id, f); });
    };
    if (name == operation::kReadRecord)
        return readRecord(id, axis, record);
    if (name == operation::kReadAllRecords)
        return readAllRecords(id, axis);
    if (name == operation::kWriteRecord)
        return writeRecord(id, axis, record, args.value(QStringLiteral("values")).toMap());
    if (name == operation::kLoadRecord || name == operation::kSaveRecord)
        return loadOrSaveRecord(id, axis, record, name == operation::kSaveRecord);
    if (name == operation::kReadErrorMemory)
        return readErrorMemory(id, axis);
    if (name == operation::kResetPositionError)
        return simple("D", false);
    if (name == operation::kTrigger)
        return simple("T", false);
    if (name == operation::kSpeedStep)
        return simple(args.value(QStringLiteral("up"), true).toBool() ? "+" : "-", false);
    if (name == operation::kResetPosition) {
        // 5.18: the current position becomes the reference position.
        return runSteps({exchange(axis, "c")}, [this, id, axis](const Failure& f) {
            if (f.ok()) {
                AxisStatus& a = mutableStatus().axes[axis];
                a.referenced = a.positionKnown = true;
                m_drives[axis].position = 0;
                updateStatus();
                publishStatus();
            }
            finishWith(id, f);
        });
    }
    if (name == operation::kStartRecord) {
        const QString why = motionRefusal(axis, false);
        if (!why.isEmpty())
            return finishError(id, ErrorKind::Refused, why);
        if (record < 0 || record > kRecordCount)
            return finishError(id, ErrorKind::InvalidValue, tr("record must be 0..32"));
        // '!1' first: a drive left in speed mode by a jog would run the record in speed mode
        // (the mode is not part of a record, 6.3/5.5).
        QMap<Axis, QList<QByteArray>> setup;
        setup[axis] = {"!1"};
        if (record > 0)
            setup[axis] << "y" + QByteArray::number(record);
        return startPositioning(id, setup, false, {{axis, {{"!", 1}}}});
    }
    finishError(id, ErrorKind::Unsupported, tr("unknown Nanotec operation '%1'").arg(name));
}

} // namespace stepdeck::nanotec
