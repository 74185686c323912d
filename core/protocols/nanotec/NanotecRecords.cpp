// Records (section 4, 6.3-6.5) and the error memory (5.15) of a Nanotec drive.
#include "NanotecRecords.h"
#include "Logging.h"
#include "NanotecController.h"

namespace stepdeck::nanotec {

namespace {
QVariantMap recordValues(const RecordData& data)
{
    QVariantMap out;
    for (const auto& field : data.fields) {
        if (const ParamDef* def = findRecordField(field.first))
            out.insert(def->spec.name, fromWire(*def, field.second));
    }
    return out;
}

QVariantMap recordResult(Axis axis, int record, const QVariantMap& values)
{
    return {{"axis", axisName(axis)}, {"record", record}, {"values", values}};
}
} // namespace

NanotecRecords::NanotecRecords(NanotecController& controller)
    : m_ctl(controller), m_link(controller.m_exchange)
{}

Step NanotecRecords::readRecordStep(Axis axis, int record, std::shared_ptr<QVariantMap> out)
{
    // 6.4: "Z|" sends the record in RAM, "Z<n>|" record n from the EEPROM, in one piece.
    const QByteArray body = record > 0 ? "Z" + QByteArray::number(record) + "|" : "Z|";
    return m_link.exchange(
        axis, body,
        [this, axis, out](const Reply& r) {
            if (r.kind != Reply::Kind::Record)
                return Failure{ErrorKind::Protocol,
                               tr("%1 sent no record string: '%2'")
                                   .arg(m_ctl.driveName(axis), QString::fromLatin1(r.raw))};
            *out = recordValues(r.recordData);
            return Failure{};
        },
        NanotecBus::Priority::Command, 1);
}

void NanotecRecords::readRecord(RequestId id, Axis axis, int record)
{
    if (record < 0 || record > kRecordCount)
        return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                 tr("record must be 0 (RAM) or 1..32, not %1").arg(record));
    auto values = std::make_shared<QVariantMap>();
    runSteps({readRecordStep(axis, record, values)},
             [this, id, axis, record, values](const Failure& f) {
                 m_ctl.finishWith(id, f, recordResult(axis, record, *values));
             });
}

void NanotecRecords::readAllRecords(RequestId id, Axis axis)
{
    auto all = std::make_shared<QVariantList>();
    QList<Step> steps;
    for (int n = 1; n <= kRecordCount; ++n) {
        auto values = std::make_shared<QVariantMap>();
        steps << readRecordStep(axis, n, values);
        steps << [all, axis, n, values](const Done& done) {
            all->append(recordResult(axis, n, *values));
            done({});
        };
    }
    runSteps(steps, [this, id, all](const Failure& f) { m_ctl.finishWith(id, f, *all); });
}

void NanotecRecords::writeRecord(RequestId id, Axis axis, int record, const QVariantMap& values)
{
    if (record < 1 || record > kRecordCount)
        return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                 tr("record must be 1..32, not %1").arg(record));
    // 6.5: saving during a run stores values the run is changing.
    const QString why = m_ctl.m_motion.motionRefusal(axis, false);
    if (!why.isEmpty())
        return m_ctl.finishError(id, ErrorKind::Refused, why);
    const ParameterSchema s = m_ctl.schema();
    QMap<char, qint64> wires;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        const ParamDef* def = findParam(it.key());
        if (!def || !def->record)
            return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                     tr("'%1' is not a record setting (section 4)").arg(it.key()));
        const QString err = s.validateScalar(def->spec, it.value());
        if (!err.isEmpty())
            return m_ctl.finishError(id, ErrorKind::InvalidValue, err);
        wires.insert(def->cmd.at(0), *toWire(*def, it.value()));
    }
    // Load the record first so the fields not named keep their stored values.
    QList<Step> steps{m_link.exchange(axis, "y" + QByteArray::number(record))};
    for (char cmd : recordFieldOrder()) {
        if (!wires.contains(cmd))
            continue;
        const ParamDef& def = *findRecordField(cmd);
        steps << m_ctl.m_parameters.writeStep(axis, def, wires[cmd])
              << m_ctl.m_parameters.verifyStep(axis, def, wires[cmd], nullptr);
    }
    steps << m_link.exchange(axis, ">" + QByteArray::number(record));
    auto stored = std::make_shared<QVariantMap>();
    steps << readRecordStep(axis, record, stored);
    steps << [this, axis, record, values, stored](const Done& done) {
        for (auto it = values.cbegin(); it != values.cend(); ++it) {
            const ParamDef* def = findParam(it.key());
            const QVariant want = fromWire(*def, *toWire(*def, it.value()));
            if (stored->value(it.key()) != want)
                return done(
                    {ErrorKind::VerifyFailed,
                     tr("record %1 of %2: %3 is %4 in the EEPROM, not %5")
                         .arg(record)
                         .arg(m_ctl.driveName(axis), ParameterSchema::displayLabel(def->spec),
                              stored->value(it.key()).toString(), want.toString())});
        }
        done({});
    };
    runSteps(steps, [this, id, axis, record, stored](const Failure& f) {
        m_ctl.finishWith(id, f, recordResult(axis, record, *stored));
    });
}

void NanotecRecords::loadOrSaveRecord(RequestId id, Axis axis, int record, bool save)
{
    if (record < 1 || record > kRecordCount)
        return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                 tr("record must be 1..32, not %1").arg(record));
    if (save) {
        const QString why = m_ctl.m_motion.motionRefusal(axis, false);
        if (!why.isEmpty())
            return m_ctl.finishError(id, ErrorKind::Refused, why);
    }
    // 6.3 'y' loads record n into RAM, 6.5 '>' stores RAM as record n; either way RAM and
    // record n must agree afterwards.
    auto ram = std::make_shared<QVariantMap>();
    auto stored = std::make_shared<QVariantMap>();
    QList<Step> steps{m_link.exchange(axis, (save ? ">" : "y") + QByteArray::number(record)),
                      readRecordStep(axis, 0, ram), readRecordStep(axis, record, stored)};
    runSteps(steps, [this, id, axis, record, ram, stored, save](const Failure& f) {
        if (!f.ok())
            return m_ctl.finishWith(id, f);
        if (*ram != *stored)
            return m_ctl.finishError(
                id, ErrorKind::VerifyFailed,
                tr("%1 of record %2 on %3 did not take effect (the drive ignores "
                   "invalid record numbers)")
                    .arg(save ? tr("saving") : tr("loading"))
                    .arg(record)
                    .arg(m_ctl.driveName(axis)));
        HostDrive& d = m_ctl.m_drives[axis];
        d.minFrequency = ram->value(QStringLiteral("min-frequency"), d.minFrequency).toLongLong();
        d.maxFrequency = ram->value(QStringLiteral("max-frequency"), d.maxFrequency).toLongLong();
        d.ramp = ram->value(QStringLiteral("ramp"), d.ramp).toLongLong();
        m_ctl.finishOk(id, recordResult(axis, record, *ram));
    });
}

void NanotecRecords::readErrorMemory(RequestId id, Axis axis)
{
    auto last = std::make_shared<qint64>(0);
    auto entries = std::make_shared<QVariantList>();
    QList<Step> steps{m_link.exchange(axis, "E", sink([last](qint64 v) { *last = v; }))};
    for (int slot = 1; slot <= kErrorSlots; ++slot) {
        steps << m_link.exchange(
            axis, "ZE" + QByteArray::number(slot),
            [slot, entries](const Reply& r) {
                // "ZE<slot><code>": the slot we asked for splits an unsigned reply.
                qint64 code = 0;
                const QByteArray prefix = QByteArray::number(slot);
                if (r.index == slot && r.value)
                    code = *r.value;
                else if (!r.text.startsWith(prefix) ||
                         !parseNumber(r.text.mid(prefix.size()), &code))
                    return Failure{
                        ErrorKind::Protocol,
                        tr("malformed error memory reply '%1'").arg(QString::fromLatin1(r.raw))};
                entries->append(QVariantMap{{"slot", slot},
                                            {"code", code},
                                            {"name", errorCodeName(int(code))},
                                            {"description", errorCodeDescription(int(code))}});
                return Failure{};
            },
            NanotecBus::Priority::Command, 1);
    }
    runSteps(steps, [this, id, axis, last, entries](const Failure& f) {
        m_ctl.finishWith(
            id, f, QVariantMap{{"axis", axisName(axis)}, {"last", *last}, {"entries", *entries}});
    });
}

} // namespace stepdeck::nanotec
