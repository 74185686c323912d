// Model operations, bus scan and console of a Nanotec bus (NanotecOperations.h).
#include "NanotecOperations.h"
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "NanotecModel.h"
#include "model/ModelOperations.h"
#include "transport/Transport.h"
#include <QSet>
#include <algorithm>

namespace stepdeck::nanotec {

NanotecOperations::NanotecOperations(NanotecController& controller)
    : m_ctl(controller), m_link(controller.m_exchange)
{}

void NanotecOperations::sendRaw(RequestId id, const QByteArray& bytes)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    CommandDecoder decoder;
    QList<Command> frames = decoder.feed(bytes.endsWith('\r') ? bytes : bytes + '\r');
    if (frames.isEmpty())
        return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                 tr("not a Nanotec frame: expected '#<address><command>\\r'"));
    for (const Command& c : frames) {
        if (!c.valid)
            return m_ctl.finishError(id, ErrorKind::InvalidValue, c.error);
        const QString forbidden = forbiddenReason(c.body);
        if (!forbidden.isEmpty())
            return m_ctl.finishError(id, ErrorKind::Refused, forbidden);
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
            m_ctl.m_bus->submit(r);
        };
    }
    runSteps(steps, [this, id, replies](const Failure& f) {
        m_ctl.finishWith(id, f, replies->join(QLatin1Char('\n')));
    });
}

void NanotecOperations::scan(RequestId id, int first, int last, int timeoutMs)
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
        for (HostDrive& d : m_ctl.m_drives) {
            if (d.address == reply.address) {
                d.firmware = reply.firmware.text;
                m_ctl.m_sweep.noteAnswer(d, true);
            }
        }
    };
    // The per-address timeout is short (254 addresses): a drive that answers a little late
    // (a loaded host, a slow USB adapter) is still found -- its 'v' reply arrives while the
    // next address is probed and would otherwise be dropped as unsolicited.
    const QMetaObject::Connection late =
        QObject::connect(m_ctl.m_bus, &NanotecBus::unsolicited, &m_ctl, note);
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
            m_ctl.m_bus->submit(r);
        };
    }
    runSteps(steps, [this, id, found, late](const Failure& f) {
        QObject::disconnect(late);
        std::sort(found->begin(), found->end(), [](const QVariant& a, const QVariant& b) {
            return a.toMap().value(QStringLiteral("address")).toInt() <
                   b.toMap().value(QStringLiteral("address")).toInt();
        });
        if (m_ctl.linkState() != LinkState::Connected && m_ctl.transport() &&
            m_ctl.transport()->isOpen())
            m_ctl.transport()->close(); // the port was opened for the scan only
        m_ctl.finishWith(id, f, *found);
    });
}

void NanotecOperations::runPendingScan()
{
    const NanotecController::PendingScan p = *m_ctl.m_pendingScan;
    m_ctl.m_pendingScan.reset();
    scan(p.id, p.first, p.last, p.timeoutMs);
}

void NanotecOperations::startScan(RequestId id, const QVariantMap& args)
{
    auto intArg = [&](QLatin1String key, int def) { return args.value(key, def).toInt(); };
    NanotecController::PendingScan p{id, intArg(operation::arg::kFirst, kMinAddress),
                                     intArg(operation::arg::kLast, kMaxAddress),
                                     intArg(operation::arg::kTimeoutMs, 40)};
    if (!isValidAddress(p.first) || !isValidAddress(p.last) || p.first > p.last)
        return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                 tr("scan range must lie within 1..254"));
    if (!m_ctl.transport())
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("no transport"));
    m_ctl.m_pendingScan = p;
    if (m_ctl.transport()->isOpen())
        return runPendingScan();
    m_ctl.transport()->open(lineSettings()); // a scan needs no configured drive
}

void NanotecOperations::modelOperation(RequestId id, const QString& name, const QVariantMap& args)
{
    if (name == operation::kScan)
        return startScan(id, args);
    if (name == operation::kReference) {
        QMap<Axis, int> dirs;
        const QVariantMap axes = args.value(operation::arg::kAxes).toMap();
        for (auto it = axes.cbegin(); it != axes.cend(); ++it) {
            if (const auto axis = m_ctl.options().axisNames.find(it.key()))
                dirs.insert(*axis, it.value().toInt());
        }
        return m_ctl.m_motion.referenceWithType(
            id, dirs, args.value(operation::arg::kType).toString() == QLatin1String("internal"));
    }
    HostDrive* d = m_ctl.driveFor(args, id);
    if (!d)
        return;
    if (NanotecClosedLoop::isOperation(name))
        return m_ctl.m_closedLoop->operation(id, name, d->axis, args);
    driveOperation(id, name, d->axis, args);
}

void NanotecOperations::driveOperation(RequestId id, const QString& name, Axis axis,
                                       const QVariantMap& args)
{
    const int record = args.value(operation::arg::kRecord, 0).toInt();
    if (name == operation::kReadRecord)
        return m_ctl.m_records.readRecord(id, axis, record);
    if (name == operation::kReadAllRecords)
        return m_ctl.m_records.readAllRecords(id, axis);
    if (name == operation::kWriteRecord)
        return m_ctl.m_records.writeRecord(id, axis, record,
                                           args.value(operation::arg::kValues).toMap());
    if (name == operation::kLoadRecord || name == operation::kSaveRecord)
        return m_ctl.m_records.loadOrSaveRecord(id, axis, record, name == operation::kSaveRecord);
    if (name == operation::kReadErrorMemory)
        return m_ctl.m_records.readErrorMemory(id, axis);
    if (name == operation::kResetPositionError)
        return simple(id, axis, "D");
    if (name == operation::kTrigger)
        return simple(id, axis, "T");
    if (name == operation::kSpeedStep)
        return simple(id, axis, args.value(operation::arg::kUp, true).toBool() ? "+" : "-");
    if (name == operation::kResetPosition)
        return resetPosition(id, axis);
    if (name == operation::kStartRecord)
        return startRecord(id, axis, record);
    m_ctl.finishError(id, ErrorKind::Unsupported, tr("unknown Nanotec operation '%1'").arg(name));
}

void NanotecOperations::simple(RequestId id, Axis axis, const QByteArray& body)
{
    runSteps({m_link.exchange(axis, body)},
             [this, id](const Failure& f) { m_ctl.finishWith(id, f); });
}

void NanotecOperations::resetPosition(RequestId id, Axis axis)
{
    // 5.18: the current position becomes the reference position.
    runSteps({m_link.exchange(axis, "c")}, [this, id, axis](const Failure& f) {
        if (f.ok()) {
            AxisStatus& a = m_ctl.mutableStatus().axes[axis];
            a.referenced = a.positionKnown = true;
            m_ctl.m_drives[axis].position = 0;
            m_ctl.m_sweep.updateStatus();
            m_ctl.publishStatus();
        }
        m_ctl.finishWith(id, f);
    });
}

void NanotecOperations::startRecord(RequestId id, Axis axis, int record)
{
    const QString why = m_ctl.m_motion.motionRefusal(axis, false);
    if (!why.isEmpty())
        return m_ctl.finishError(id, ErrorKind::Refused, why);
    if (record < 0 || record > kRecordCount)
        return m_ctl.finishError(id, ErrorKind::InvalidValue, tr("record must be 0..32"));
    // '!1' first: a drive left in speed mode by a jog would run the record in speed mode
    // (the mode is not part of a record, 6.3/5.5).
    QMap<Axis, QList<QByteArray>> setup;
    setup[axis] = {"!1"};
    if (record > 0)
        setup[axis] << "y" + QByteArray::number(record);
    m_ctl.m_motion.startPositioning(id, setup, false, {{axis, {{"!", 1}}}});
}

} // namespace stepdeck::nanotec
