// Parameters, records and the error memory of Nanotec drives. Every write is echoed by the
// drive even when the value is invalid, and invalid values are silently ignored ("Antwort der
// Firmware" of each command): only reading the value back with 'Z' confirms a write.
#include "NanotecParameters.h"
#include "Logging.h"
#include "NanotecController.h"

namespace stepdeck::nanotec {

namespace {
using Cache = NanotecParameters::Cache;

QByteArray readBody(const ParamDef& def)
{
    switch (def.read) {
    case ParamDef::Read::Z:
        return 'Z' + def.cmd;
    case ParamDef::Read::Long:
        return ':' + def.cmd;
    case ParamDef::Read::Direct:
        return def.cmd;
    case ParamDef::Read::LastError:
        return "E";
    }
    return {};
}

QByteArray writeBody(const ParamDef& def, qint64 wire)
{
    return def.isLong() ? ':' + def.cmd + '=' + QByteArray::number(wire)
                        : def.cmd + QByteArray::number(wire);
}

// "ZE<slot><code>" without a sign is ambiguous; the slot we asked for splits it.
std::optional<qint64> errorCode(const Reply& r, int slot)
{
    if (r.index == slot && r.value)
        return r.value;
    const QByteArray prefix = QByteArray::number(slot);
    qint64 code = 0;
    if (r.text.startsWith(prefix) && parseNumber(r.text.mid(prefix.size()), &code))
        return code;
    return std::nullopt;
}

QString text(const QVariant& v)
{
    return v.toString();
}
} // namespace

NanotecParameters::NanotecParameters(NanotecController& controller)
    : m_ctl(controller), m_link(controller.m_exchange)
{}

Step NanotecParameters::readStep(Axis axis, const ParamDef& def, std::function<void(qint64)> store,
                                 Cache cache)
{
    const QByteArray body = readBody(def);
    const QByteArray key = axisName(axis).toLatin1() + body;
    if (def.read == ParamDef::Read::LastError) {
        // 5.15: 'E' names the slot of the last error, "ZE<slot>" holds its code.
        return [this, axis, store](const Done& done) {
            auto slot = std::make_shared<qint64>(0);
            m_link.exchange(axis, "E",
                            sink([slot](qint64 v) { *slot = v; }))([=](const Failure& f) {
                if (!f.ok() || *slot <= 0) {
                    if (f.ok())
                        store(0);
                    return done(f);
                }
                const QByteArray zb = "ZE" + QByteArray::number(*slot);
                m_link.exchange(axis, zb, [=](const Reply& r) {
                    const auto code = errorCode(r, int(*slot));
                    if (!code)
                        return Failure{ErrorKind::Protocol, tr("malformed error memory reply '%1'")
                                                                .arg(QString::fromLatin1(r.raw))};
                    store(*code);
                    return Failure{};
                })(done);
            });
        };
    }
    return [this, axis, body, key, store, cache](const Done& done) {
        if (cache && cache->contains(key)) {
            store(cache->value(key));
            return done({});
        }
        m_link.exchange(axis, body, sink([key, store, cache](qint64 v) {
                            if (cache)
                                cache->insert(key, v);
                            store(v);
                        }),
                        NanotecBus::Priority::Command, 1)(done);
    };
}

Step NanotecParameters::writeStep(Axis axis, const ParamDef& def, qint64 wire)
{
    const QByteArray body = writeBody(def, wire);
    return [this, axis, &def, body, wire](const Done& done) {
        NanotecBus::Request r;
        r.address = m_ctl.m_drives[axis].address;
        r.body = body;
        r.retries = 1; // settings are idempotent
        // 5.4: after 'm' the drive may already answer at its new address.
        r.anyAddress = def.cmd == "m";
        r.done = [this, axis, &def, body, wire, done](NanotecBus::Outcome o, const Reply& rep) {
            if (o != NanotecBus::Outcome::Ok)
                return done(m_link.outcomeFailure(axis, body, o, rep));
            if (rep.value && *rep.value != wire)
                return done({ErrorKind::Protocol,
                             tr("%1 echoed '%2' to '%3'")
                                 .arg(m_ctl.driveName(axis), QString::fromLatin1(rep.raw),
                                      QString::fromLatin1(body))});
            noteWritten(m_ctl.m_drives[axis], def, wire);
            done({});
        };
        m_ctl.m_bus->submit(r);
    };
}

Step NanotecParameters::verifyStep(Axis axis, const ParamDef& def, qint64 expected, Cache cache)
{
    return [this, axis, &def, expected, cache](const Done& done) {
        if (cache)
            cache->remove(axisName(axis).toLatin1() + readBody(def));
        auto got = std::make_shared<qint64>(0);
        readStep(
            axis, def, [got](qint64 v) { *got = v; }, cache)([=, &def](const Failure& f) {
            if (!f.ok())
                return done(f);
            const qint64 mask = def.fieldMask ? def.fieldMask : ~qint64(0);
            if ((*got & mask) == (expected & mask))
                return done({});
            done({ErrorKind::VerifyFailed,
                  tr("%1 on %2: wrote %3, but the drive kept %4 (drives echo invalid values and "
                     "silently ignore them)")
                      .arg(ParameterSchema::displayLabel(def.spec), m_ctl.driveName(axis),
                           text(fromWire(def, expected)), text(fromWire(def, *got)))});
        });
    };
}

void NanotecParameters::noteWritten(HostDrive& d, const ParamDef& def, qint64 wire)
{
    if (def.cmd == "u")
        d.minFrequency = wire;
    else if (def.cmd == "o")
        d.maxFrequency = wire;
    else if (def.cmd == "b")
        d.ramp = wire;
    else if (def.cmd == "e")
        d.limitSwitchType = wire;
    else if (def.cmd == "m")
        d.address = int(wire); // 5.4: communication continues at the new address
}

QList<Step> NanotecParameters::motorAddressSteps(Axis axis, int address, bool verify)
{
    auto old = std::make_shared<int>(0);
    QList<Step> steps;
    // 5.4: a new address already in use on the bus would end all communication. Probe it.
    steps << [this, axis, address, old](const Done& done) {
        *old = m_ctl.m_drives[axis].address;
        if (address == *old)
            return done({});
        NanotecBus::Request probe;
        probe.address = address;
        probe.body = "v";
        probe.timeoutMs = qMin(m_ctl.options().commandTimeoutMs, 100);
        probe.done = [address, done](NanotecBus::Outcome o, const Reply&) {
            if (o == NanotecBus::Outcome::Cancelled)
                return done({ErrorKind::Cancelled, tr("cancelled")});
            if (o != NanotecBus::Outcome::Timeout)
                return done(
                    {ErrorKind::Refused, tr("%1 %2 is already used by another drive on the bus; no "
                                            "communication would be possible (manual 5.4)")
                                             .arg(ParameterSchema::displayLabel(
                                                 findParam(QStringLiteral("motor-address"))->spec))
                                             .arg(address)});
            done({});
        };
        m_ctl.m_bus->submit(probe);
    };
    steps << writeStep(axis, *findParam(QStringLiteral("motor-address")), address);
    if (!verify)
        return steps;
    steps << [this, axis, address, old](const Done& done) {
        const Check same = [this, axis, address](const Reply& r) {
            if (r.value == address)
                return Failure{};
            return Failure{ErrorKind::VerifyFailed,
                           tr("%1 reports %2 %3, not %4")
                               .arg(m_ctl.driveName(axis),
                                    ParameterSchema::displayLabel(
                                        findParam(QStringLiteral("motor-address"))->spec))
                               .arg(r.value.value_or(-1))
                               .arg(address)};
        };
        m_link.exchange(axis, "Zm", same, NanotecBus::Priority::Command, 1)([=](const Failure& f) {
            if (f.kind != ErrorKind::Timeout)
                return done(f);
            m_ctl.m_drives[axis].address = *old; // the drive ignored it and stayed where it was
            done({ErrorKind::VerifyFailed,
                  tr("%1 did not take %2 %3: nothing answers there")
                      .arg(m_ctl.driveName(axis),
                           ParameterSchema::displayLabel(
                               findParam(QStringLiteral("motor-address"))->spec))
                      .arg(address)});
        });
    };
    return steps;
}

void NanotecParameters::readParameters(RequestId id, const QStringList& names)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    QList<const ParamDef*> defs;
    for (const QString& name : names) {
        const ParamDef* def = findParam(name);
        if (!def)
            return m_ctl.finishError(id, ErrorKind::InvalidValue,
                                     tr("unknown parameter '%1'").arg(name));
        defs << def;
    }
    if (names.isEmpty()) {
        for (const ParamDef& def : parameterTable())
            defs << &def;
    }
    auto result = std::make_shared<ParameterSet>();
    auto cache = std::make_shared<QMap<QByteArray, qint64>>();
    QList<Step> steps;
    for (const ParamDef* def : defs) {
        for (Axis axis : m_ctl.m_drives.keys()) {
            steps << readStep(
                axis, *def,
                [result, def, axis](qint64 w) {
                    (*result)[def->spec.name].perAxis.insert(axis, fromWire(*def, w));
                },
                cache);
        }
    }
    runSteps(steps, [this, id, result](const Failure& f) {
        m_ctl.finishWith(id, f, QVariant::fromValue(*result));
    });
}

QString NanotecParameters::writeRefusal(const ParameterSet& values) const
{
    const QString invalid = m_ctl.schema().validate(values, m_ctl.axes());
    if (!invalid.isEmpty())
        return invalid;
    QMap<int, Axis> newAddresses; // 5.4: a used address would end all communication
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        const ParamDef* def = findParam(it.key());
        for (auto a = it.value().perAxis.cbegin(); a != it.value().perAxis.cend(); ++a) {
            const QString extra = extraValidation(*def, a.value());
            if (!extra.isEmpty())
                return extra;
            if (def->cmd == "m")
                newAddresses.insert(int(*toWire(*def, a.value())), a.key());
        }
    }
    for (auto it = newAddresses.cbegin(); it != newAddresses.cend(); ++it) {
        for (const HostDrive& d : m_ctl.m_drives) {
            if (d.address == it.key() && d.axis != it.value())
                return tr("%1 %2 is already used by %3")
                    .arg(ParameterSchema::displayLabel(
                        findParam(QStringLiteral("motor-address"))->spec))
                    .arg(it.key())
                    .arg(m_ctl.driveName(d.axis));
        }
    }
    return {};
}

namespace {
// What the message of a failed write may call written. Drives echo invalid values and ignore
// them, so only a value read back is "written"; one echoed but not read back (no verify, or
// the read-back itself failed) is only "sent"; one read back as something else is neither
// (the failure itself says what the drive kept).
struct WriteProgress
{
    QStringList written;
    QStringList sent;

    void echoed(const QStringList& labels) { sent << labels; }
    void readBack(const QStringList& labels, bool kept)
    {
        for (const QString& label : labels) {
            sent.removeOne(label);
            if (kept)
                written << label;
        }
    }
    QString describe(const QString& failure) const
    {
        QString text = failure;
        if (!written.isEmpty())
            text = NanotecController::tr("%1; already written: %2")
                       .arg(text, written.join(QStringLiteral(", ")));
        if (!sent.isEmpty())
            text = NanotecController::tr("%1; sent but not read back: %2")
                       .arg(text, sent.join(QStringLiteral(", ")));
        return text;
    }
};

// A step whose success (the drive's echo) makes `labels` "sent".
template <typename Step>
auto echoing(std::shared_ptr<WriteProgress> progress, Step step, QStringList labels)
{
    return [progress, step, labels](const auto& done) {
        step([progress, labels, done](const auto& f) {
            if (f.ok())
                progress->echoed(labels);
            done(f);
        });
    };
}

// A read-back step: its result decides whether `labels` are "written".
template <typename Step>
auto readingBack(std::shared_ptr<WriteProgress> progress, Step step, QStringList labels)
{
    return [progress, step, labels](const auto& done) {
        step([progress, labels, done](const auto& f) {
            if (f.ok() || f.kind == ErrorKind::VerifyFailed)
                progress->readBack(labels, f.ok());
            done(f);
        });
    };
}

// The whole 'l' mask (5.6) as one integer, for the read-modify-write of its groups.
const ParamDef& wholeLimitMask()
{
    static const ParamDef wholeMask = [] {
        ParamDef d = *findParam(QStringLiteral("limit-switch-behaviour-internal-reference"));
        d.spec.name = QStringLiteral("limit-switch-behaviour");
        d.spec.type = ParameterType::Integer;
        d.fieldMask = 0;
        return d;
    }();
    return wholeMask;
}

// The groups of the 'l' mask (5.6) named in a write, as one read-modify-write of the whole
// mask: the other groups and undocumented bits keep their values.
QList<Step> limitMaskSteps(NanotecParameters& parameters, Axis axis, qint64 mask, qint64 bits,
                           const QStringList& labels, bool verify, Cache cache,
                           std::shared_ptr<WriteProgress> progress)
{
    const ParamDef& wholeMask = wholeLimitMask();
    auto current = std::make_shared<qint64>(0);
    NanotecParameters* p = &parameters;
    return {p->readStep(
                axis, wholeMask, [current](qint64 v) { *current = v; }, cache),
            [p, axis, mask, bits, labels, current, verify, cache, progress,
             &wholeMask](const Done& done) {
                const qint64 merged = (*current & ~mask) | bits;
                QList<Step> s{echoing(progress, p->writeStep(axis, wholeMask, merged), labels)};
                if (verify)
                    s << readingBack(progress, p->verifyStep(axis, wholeMask, merged, cache),
                                     labels);
                runSteps(s, done);
            }};
}
} // namespace

void NanotecParameters::writeParameters(RequestId id, const ParameterSet& values, bool verify)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    if (const QString refusal = writeRefusal(values); !refusal.isEmpty())
        return m_ctl.finishError(id, ErrorKind::InvalidValue, refusal);
    auto cache = std::make_shared<QMap<QByteArray, qint64>>();
    auto progress = std::make_shared<WriteProgress>();
    QList<Step> steps, last;
    QMap<Axis, QPair<qint64, qint64>> bitFields; // 'l': mask, bits (5.6)
    QMap<Axis, QStringList> bitFieldLabels;
    for (const ParamDef& def : parameterTable()) {
        if (!values.contains(def.spec.name))
            continue;
        const ParameterValue& v = values[def.spec.name];
        for (auto a = v.perAxis.cbegin(); a != v.perAxis.cend(); ++a) {
            const qint64 wire = *toWire(def, a.value());
            const QStringList label{tr("%1 (%2)").arg(ParameterSchema::displayLabel(def.spec),
                                                      m_ctl.driveName(a.key()))};
            if (def.isBitField()) {
                bitFields[a.key()].first |= def.fieldMask;
                bitFields[a.key()].second |= wire;
                bitFieldLabels[a.key()] << label;
                continue;
            }
            if (def.cmd == "m") { // address changes go last: probe, write, read back
                QList<Step> address = motorAddressSteps(a.key(), int(wire), verify);
                Q_ASSERT(address.size() == (verify ? 3 : 2)); // probe, write[, read back]
                address[1] = echoing(progress, address[1], label);
                if (verify)
                    address[2] = readingBack(progress, address[2], label);
                last << address;
                continue;
            }
            steps << echoing(progress, writeStep(a.key(), def, wire), label);
            if (verify)
                steps << readingBack(progress, verifyStep(a.key(), def, wire, cache), label);
        }
    }
    for (auto it = bitFields.cbegin(); it != bitFields.cend(); ++it)
        steps << limitMaskSteps(*this, it.key(), it.value().first, it.value().second,
                                bitFieldLabels.value(it.key()), verify, cache, progress);
    runSteps(steps + last, [this, id, progress](const Failure& f) {
        m_ctl.m_sweep.updateStatus();
        m_ctl.publishStatus();
        m_ctl.finishWith(id, f.ok() ? f : Failure{f.kind, progress->describe(f.message)});
    });
}

} // namespace stepdeck::nanotec
