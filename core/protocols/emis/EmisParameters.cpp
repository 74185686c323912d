// Working values (set), system parameters (store, *PRSYS, *PESYS).
#include "EmisParameters.h"
#include "EmisModel.h"
#include "EmisMotionTracker.h"
#include "Logging.h"
#include "model/ModelOperations.h"
#include "model/NumberParsing.h"

namespace stepdeck::emis {

namespace {
constexpr int kReadSystemTimeoutMs = 2000;

QVariantList texts(const QStringList& list)
{
    QVariantList out;
    for (const QString& s : list)
        out << s;
    return out;
}

// Read back and normalised values; decimal only, like every number (NumberParsing).
qint64 integerOf(const QVariant& v)
{
    qint64 n = 0;
    return numbers::integerFromVariant(v, &n) == NumberError::None ? n : 0;
}

QMap<Axis, qint64> intsOf(const ParameterValue& v)
{
    QMap<Axis, qint64> out;
    for (auto it = v.perAxis.cbegin(); it != v.perAxis.cend(); ++it)
        out.insert(it.key(), integerOf(it.value()));
    return out;
}
} // namespace

EmisParameters::EmisParameters(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
                               const EmisMotionTracker& tracker)
    : m_host(host), m_exchange(exchange), m_known(known), m_tracker(tracker)
{}

bool EmisParameters::busy() const
{
    return m_tracker.anyAwaiting() || m_host.jogInputActive() || m_exchange.inputProgramOpen();
}

void EmisParameters::noteStoredEntry(const SystemEntry& entry)
{
    m_stored.store(entry);
    noteStored(m_stored);
}

void EmisParameters::runFrames(RequestId id, const QList<ParameterPlan::Frame>& frames, int index,
                               std::function<void()> onDone)
{
    if (index >= frames.size())
        return onDone();
    const ParameterPlan::Frame& f = frames[index];
    const bool stored = f.storedMotors > 0;
    m_exchange.request(
        f.bytes, stored ? EmisLink::Expect::Stored : EmisLink::Expect::Ack,
        [this, id, frames, index, onDone](const EmisLink::Result& r) {
            if (r.outcome == EmisLink::Outcome::Ok)
                return runFrames(id, frames, index + 1, onDone);
            QString text = tr("%1: %2").arg(frames[index].parameter,
                                            m_exchange.failureText(frames[index].bytes, r));
            if (index > 0)
                text += tr(" (%n command(s) before it were accepted)", nullptr, index);
            m_host.fail(id, m_exchange.failureKind(r), text);
        },
        stored ? kStoreTimeoutMs : 0, f.storedMotors);
}

void EmisParameters::write(RequestId id, const ParameterSet& values)
{
    if (!m_host.requireLink(id))
        return;
    if (const QString e = parameterSchema().validate(values, emisAxes()); !e.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, e);
    if (busy()) {
        return m_host.fail(id, ErrorKind::Refused,
                           tr("parameters are written while every axis stands still"));
    }
    // The partner of a lone run or idle current: written in this session, else the stored
    // power-on value (*PRSYS at connect).
    const ParameterPlan plan =
        planWorking(values, CurrentPartners{m_known.runCurrent, m_known.idleCurrent});
    if (!plan.ok())
        return m_host.fail(id, plan.error, plan.message);
    if (values.contains(QStringLiteral("work-speed")))
        m_known.speeds.forgetBoard(); // until the writes are confirmed (a failure says no more)
    if (values.contains(QStringLiteral("interpolation")))
        m_known.interpolation.reset(); // the same
    runFrames(id, plan.frames, 0, [this, id, values] {
        noteWritten(values);
        m_host.publish();
        m_host.succeed(id);
    });
}

void EmisParameters::noteWritten(const ParameterSet& set)
{
    const ParameterSchema s = parameterSchema();
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        // Per-axis values are kept per axis, so a later set of one axis keeps the others.
        ParameterValue& kept = m_written[it.key()];
        const ParameterSpec* spec = s.find(it.key());
        if (spec && spec->perAxis) {
            for (auto a = it.value().perAxis.cbegin(); a != it.value().perAxis.cend(); ++a)
                kept.perAxis.insert(a.key(), s.normalise(*spec, a.value()));
        } else if (spec) {
            kept.global = s.normalise(*spec, it.value().global);
        }
    }
    const auto axisInts = [this](const char* name) {
        return intsOf(m_written.value(QLatin1String(name)));
    };
    m_known.startSpeed.insert(axisInts("start-speed"));
    const QMap<Axis, qint64> work = intsOf(set.value(QStringLiteral("work-speed")));
    for (auto it = work.cbegin(); it != work.cend(); ++it)
        m_known.speeds.setWritten(it.key(), it.value()); // the board acknowledged it just now
    m_known.runCurrent.insert(axisInts("run-current"));
    m_known.idleCurrent.insert(axisInts("idle-current"));
    if (m_written.contains(QStringLiteral("ramp")))
        m_known.ramp = integerOf(m_written.value(QStringLiteral("ramp")).global);
    if (set.contains(QStringLiteral("interpolation")))
        m_known.interpolation = set.value(QStringLiteral("interpolation")).global.toBool();
    const ParameterValue types = m_written.value(QStringLiteral("reference-switch-type"));
    for (auto it = types.perAxis.cbegin(); it != types.perAxis.cend(); ++it)
        m_known.switchNc.insert(it.key(), it.value().toString() == QLatin1String("NC"));
}

void EmisParameters::read(RequestId id, const QStringList& names)
{
    ParameterSet out;
    QStringList unknown;
    for (const QString& name : names) {
        if (!parameterSchema().find(name))
            return m_host.fail(id, ErrorKind::InvalidValue, tr("unknown parameter '%1'").arg(name));
        if (m_written.contains(name))
            out.insert(name, m_written.value(name));
        else
            unknown << name;
    }
    if (!unknown.isEmpty()) {
        return m_host.fail(id, ErrorKind::Unsupported,
                           tr("%1 cannot be read back: the SMC-IC4 reports no working values "
                              "(only the stored system parameters, *PRSYS)")
                               .arg(unknown.join(QStringLiteral(", "))));
    }
    m_host.succeed(id, QVariant::fromValue(out)); // the values written in this session
}

void EmisParameters::noteStored(const SystemParameters& stored)
{
    m_stored = stored;
    const ParameterSet values = storedValues(stored, nullptr);
    const auto fill = [&values, this](const char* name, QMap<Axis, qint64>* known) {
        if (m_written.contains(QLatin1String(name)))
            return; // written in this session: that is the working value
        known->insert(intsOf(values.value(QLatin1String(name))));
    };
    fill("start-speed", &m_known.startSpeed);
    m_known.speeds.setStored(intsOf(values.value(QStringLiteral("work-speed"))));
    fill("run-current", &m_known.runCurrent);
    fill("idle-current", &m_known.idleCurrent);
    if (!m_written.contains(QStringLiteral("ramp")) && values.contains(QStringLiteral("ramp")))
        m_known.ramp = integerOf(values.value(QStringLiteral("ramp")).global);
    // ##REFSW is the only way to set the switch type: the stored value is the working one.
    if (const SystemEntry* e = stored.find(SystemEntry::Key::ReferenceSwitch))
        m_known.switchNc.insert(e->normallyClosed);
}

void EmisParameters::readStored(RequestId id, EmisLink::Handler after)
{
    if (!after && !m_host.requireLink(id))
        return;
    m_exchange.request(
        encode::readSystem(), EmisLink::Expect::Ack,
        [this, id, after](const EmisLink::Result& r) {
            if (r.outcome == EmisLink::Outcome::Ok)
                noteStored(parseSystemParameters(r.text));
            if (after)
                return after(r);
            if (r.outcome != EmisLink::Outcome::Ok)
                return m_host.failExchange(id, encode::readSystem(), r);
            QStringList notes;
            const ParameterSet values = storedValues(m_stored, &notes);
            QStringList entries;
            for (const SystemEntry& e : m_stored.entries)
                entries << QStringLiteral("##") + QString::fromLatin1(formatSystemEntry(e));
            m_host.succeed(id,
                           QVariantMap{{QStringLiteral("parameters"), QVariant::fromValue(values)},
                                       {QStringLiteral("entries"), texts(entries)},
                                       {QStringLiteral("notes"), texts(notes)}});
        },
        kReadSystemTimeoutMs);
}

void EmisParameters::store(RequestId id, const QVariantMap& args)
{
    if (!m_host.requireLink(id))
        return;
    ParameterSet set = args.value(operation::arg::kParameters).value<ParameterSet>();
    // skipUnstorable: a whole setup form; what has no system entry is left out and named.
    QStringList skipped;
    if (args.value(operation::arg::kSkipUnstorable).toBool()) {
        for (const QString& name : set.keys()) {
            if (!storableParameters().contains(name)) {
                set.remove(name);
                skipped << name;
            }
        }
    }
    if (set.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, tr("no parameters to store"));
    if (const QString e = parameterSchema().validate(set, emisAxes()); !e.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, e);
    if (busy()) {
        return m_host.fail(id, ErrorKind::Refused,
                           tr("system parameters are stored while every axis stands still"));
    }
    CurrentPartners partners;
    if (const SystemEntry* c = m_stored.find(SystemEntry::Key::Currents)) {
        partners.runKnown = c->values;
        partners.idleKnown = c->idle;
    }
    const ParameterPlan plan = planStore(set, partners);
    if (!plan.ok())
        return m_host.fail(id, plan.error, plan.message);
    runFrames(id, plan.frames, 0, [this, id, plan, set, skipped] {
        QStringList written;
        for (const ParameterPlan::Frame& f : plan.frames) {
            written << QString::fromLatin1(f.bytes.chopped(1));
            if (const auto entry = parseSystemEntry(f.bytes.mid(2).chopped(1), nullptr))
                m_stored.store(*entry); // keeps the motors the entry does not name
        }
        noteStored(m_stored);
        if (set.contains(QStringLiteral("reference-switch-type")))
            m_host.publish(); // the switch type applies at once
        m_host.succeed(id, QVariantMap{{QStringLiteral("commands"), texts(written)},
                                       {QStringLiteral("skipped"), texts(skipped)}});
    });
}

void EmisParameters::clearStored(RequestId id)
{
    if (!m_host.requireLink(id))
        return;
    m_exchange.request(
        encode::clearSystem(), EmisLink::Expect::Ack,
        [this, id](const EmisLink::Result& r) {
            if (r.outcome != EmisLink::Outcome::Ok)
                return m_host.failExchange(id, encode::clearSystem(), r);
            // 9.16: erases the SMCflex compatibility entry; the others stay.
            m_stored.entries.erase(std::remove_if(m_stored.entries.begin(), m_stored.entries.end(),
                                                  [](const SystemEntry& e) {
                                                      return e.key == SystemEntry::Key::SmcFlex;
                                                  }),
                                   m_stored.entries.end());
            m_host.succeed(id);
        },
        kStoreTimeoutMs);
}

} // namespace stepdeck::emis
