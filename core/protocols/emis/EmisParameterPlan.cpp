#include "EmisParameterPlan.h"
#include "EmisModel.h"
#include "model/NumberParsing.h"

namespace stepdeck::emis {

namespace {
using Plan = ParameterPlan;

// The values were normalised and range-checked by the schema before a plan is made; this
// reads them the one way numbers are read (decimal text or an integral value, never octal,
// never a double cast beyond qint64). Anything else reads as 0, which every range check of
// the plan's commands refuses.
qint64 intOf(const QVariant& v)
{
    qint64 n = 0;
    return numbers::integerFromVariant(v, &n) == NumberError::None ? n : 0;
}

QMap<Axis, qint64> perAxis(const ParameterValue& value)
{
    QMap<Axis, qint64> out;
    if (value.isPerAxis()) {
        for (auto it = value.perAxis.cbegin(); it != value.perAxis.cend(); ++it)
            out.insert(it.key(), intOf(it.value()));
    } else {
        for (Axis axis : emisAxes())
            out.insert(axis, intOf(value.global));
    }
    return out;
}

bool allEqualOnFourAxes(const QMap<Axis, qint64>& values)
{
    if (values.size() != emisAxes().size())
        return false;
    for (qint64 v : values) {
        if (v != values.first())
            return false;
    }
    return true;
}

void add(Plan* plan, const QByteArray& bytes, const QString& parameter, int storedMotors = 0)
{
    plan->frames << Plan::Frame{bytes, parameter, storedMotors};
}

// Run and idle current per axis, completed from the partners; false with the plan's error set.
bool currents(const ParameterSet& set, const CurrentPartners& partners,
              QMap<Axis, QPair<qint64, qint64>>* out, Plan* plan)
{
    const bool hasRun = set.contains(QStringLiteral("run-current"));
    const bool hasIdle = set.contains(QStringLiteral("idle-current"));
    if (!hasRun && !hasIdle)
        return true;
    const QMap<Axis, qint64> run =
        hasRun ? perAxis(set[QStringLiteral("run-current")]) : QMap<Axis, qint64>{};
    const QMap<Axis, qint64> idle =
        hasIdle ? perAxis(set[QStringLiteral("idle-current")]) : QMap<Axis, qint64>{};
    QList<Axis> axes = run.keys();
    for (Axis a : idle.keys()) {
        if (!axes.contains(a))
            axes << a;
    }
    std::sort(axes.begin(), axes.end());
    for (Axis a : axes) {
        const bool runKnown = run.contains(a) || partners.runKnown.contains(a);
        const bool idleKnown = idle.contains(a) || partners.idleKnown.contains(a);
        if (!runKnown || !idleKnown) {
            plan->error = ErrorKind::InvalidValue;
            plan->message =
                ParameterPlan::tr(
                    "%1 of axis %2 needs %3 in the same set: the SMC-IC4 sets run and idle "
                    "current with one command (c,x100,20, manual 9.8) and the value of %3 "
                    "is not known")
                    .arg(runKnown ? QStringLiteral("run-current") : QStringLiteral("idle-current"),
                         axisName(a),
                         runKnown ? QStringLiteral("idle-current") : QStringLiteral("run-current"));
            return false;
        }
        out->insert(a, {run.contains(a) ? run[a] : partners.runKnown[a],
                        idle.contains(a) ? idle[a] : partners.idleKnown[a]});
    }
    return true;
}

QMap<Axis, bool> switchTypes(const ParameterValue& value)
{
    QMap<Axis, bool> out;
    if (value.isPerAxis()) {
        for (auto it = value.perAxis.cbegin(); it != value.perAxis.cend(); ++it)
            out.insert(it.key(), it.value().toString().toUpper() == QLatin1String("NC"));
    } else {
        for (Axis axis : emisAxes())
            out.insert(axis, value.global.toString().toUpper() == QLatin1String("NC"));
    }
    return out;
}

QString names(const QStringList& list)
{
    return list.join(QStringLiteral(", "));
}
} // namespace

QStringList storableParameters()
{
    return {QStringLiteral("start-speed"),
            QStringLiteral("work-speed"),
            QStringLiteral("ramp"),
            QStringLiteral("reference-speed"),
            QStringLiteral("reference-switch-type"),
            QStringLiteral("step-resolution"),
            QStringLiteral("run-current"),
            QStringLiteral("idle-current")};
}

ParameterPlan planWorking(const ParameterSet& set, const CurrentPartners& partners)
{
    Plan plan;
    QMap<Axis, QPair<qint64, qint64>> runIdle;
    if (!currents(set, partners, &runIdle, &plan))
        return plan;
    const auto has = [&set](const char* name) { return set.contains(QLatin1String(name)); };
    const auto value = [&set](const char* name) { return set.value(QLatin1String(name)); };
    if (has("step-resolution")) {
        const QMap<Axis, qint64> v = perAxis(value("step-resolution"));
        for (auto it = v.cbegin(); it != v.cend(); ++it)
            add(&plan, encode::stepResolution(it.key(), it.value()), "step-resolution");
    }
    for (auto it = runIdle.cbegin(); it != runIdle.cend(); ++it) {
        add(&plan, encode::current(it.key(), it.value().first, it.value().second),
            QStringLiteral("run-current, idle-current"));
    }
    if (has("ramp"))
        add(&plan, encode::ramp(intOf(value("ramp").global)), "ramp");
    if (has("start-speed")) {
        const QMap<Axis, qint64> v = perAxis(value("start-speed"));
        if (allEqualOnFourAxes(v))
            add(&plan, encode::startSpeedAll(v.first()), "start-speed");
        else
            for (auto it = v.cbegin(); it != v.cend(); ++it)
                add(&plan, encode::startSpeed(it.key(), it.value()), "start-speed");
    }
    if (has("work-speed")) {
        const QMap<Axis, qint64> v = perAxis(value("work-speed"));
        if (allEqualOnFourAxes(v))
            add(&plan, encode::workSpeedAll(v.first()), "work-speed");
        else
            for (auto it = v.cbegin(); it != v.cend(); ++it)
                add(&plan, encode::workSpeed(it.key(), it.value()), "work-speed");
    }
    if (has("reference-speed"))
        add(&plan, encode::referenceSpeed(intOf(value("reference-speed").global)),
            "reference-speed");
    if (has("reference-offset")) {
        const QMap<Axis, qint64> v = perAxis(value("reference-offset"));
        for (auto it = v.cbegin(); it != v.cend(); ++it)
            add(&plan, encode::referenceOffset(it.key(), it.value()), "reference-offset");
    }
    if (has("interpolation"))
        add(&plan, encode::interpolation(value("interpolation").global.toBool()), "interpolation");
    if (has("reference-switch-type")) {
        const QMap<Axis, bool> nc = switchTypes(value("reference-switch-type"));
        add(&plan, encode::systemReferenceSwitches(nc), "reference-switch-type", int(nc.size()));
    }
    return plan;
}

ParameterPlan planStore(const ParameterSet& set, const CurrentPartners& partners)
{
    Plan plan;
    QStringList notStorable;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        if (!storableParameters().contains(it.key()))
            notStorable << it.key();
    }
    if (!notStorable.isEmpty()) {
        plan.error = ErrorKind::Unsupported;
        plan.message =
            ParameterPlan::tr("%1 cannot be stored: the SMC-IC4 has no system parameter for "
                              "it (manual 9.14); use set")
                .arg(names(notStorable));
        return plan;
    }
    QMap<Axis, QPair<qint64, qint64>> runIdle;
    if (!currents(set, partners, &runIdle, &plan))
        return plan;
    const auto has = [&set](const char* name) { return set.contains(QLatin1String(name)); };
    const auto value = [&set](const char* name) { return set.value(QLatin1String(name)); };
    const auto perAxisEntry = [&](const char* name, const QByteArray& key) {
        if (!has(name))
            return;
        const QMap<Axis, qint64> v = perAxis(value(name));
        add(&plan, encode::systemPerAxis(key, v), QLatin1String(name), int(v.size()));
    };
    perAxisEntry("step-resolution", "D");
    if (!runIdle.isEmpty()) {
        add(&plan, encode::systemCurrents(runIdle), QStringLiteral("run-current, idle-current"),
            int(runIdle.size()));
    }
    if (has("ramp"))
        add(&plan, encode::systemRamp(intOf(value("ramp").global)), QStringLiteral("ramp"), 4);
    perAxisEntry("start-speed", "S");
    perAxisEntry("work-speed", "E");
    perAxisEntry("reference-speed", "E9"); // one working value, stored for every motor
    if (has("reference-switch-type")) {
        const QMap<Axis, bool> nc = switchTypes(value("reference-switch-type"));
        add(&plan, encode::systemReferenceSwitches(nc), QStringLiteral("reference-switch-type"),
            int(nc.size()));
    }
    return plan;
}

ParameterSet storedValues(const SystemParameters& stored, QStringList* notes)
{
    ParameterSet out;
    const auto perAxisValue = [](const QMap<Axis, qint64>& values, bool asText) {
        ParameterValue v;
        for (auto it = values.cbegin(); it != values.cend(); ++it)
            v.perAxis.insert(it.key(),
                             asText ? QVariant(QString::number(it.value())) : QVariant(it.value()));
        return v;
    };
    using Key = SystemEntry::Key;
    for (Key key : {Key::StepResolution, Key::Currents, Key::ReferenceSwitch, Key::StartSpeed,
                    Key::WorkSpeed, Key::ReferenceSpeed, Key::Ramp, Key::SmcFlex}) {
        const SystemEntry* e = stored.find(key);
        if (!e)
            continue;
        switch (key) {
        case Key::StepResolution:
            out.insert(QStringLiteral("step-resolution"), perAxisValue(e->values, true));
            break;
        case Key::Currents:
            out.insert(QStringLiteral("run-current"), perAxisValue(e->values, false));
            out.insert(QStringLiteral("idle-current"), perAxisValue(e->idle, false));
            break;
        case Key::ReferenceSwitch: {
            ParameterValue v;
            for (auto it = e->normallyClosed.cbegin(); it != e->normallyClosed.cend(); ++it)
                v.perAxis.insert(it.key(),
                                 it.value() ? QStringLiteral("NC") : QStringLiteral("NO"));
            out.insert(QStringLiteral("reference-switch-type"), v);
            break;
        }
        case Key::StartSpeed:
            out.insert(QStringLiteral("start-speed"), perAxisValue(e->values, false));
            break;
        case Key::WorkSpeed:
            out.insert(QStringLiteral("work-speed"), perAxisValue(e->values, false));
            break;
        case Key::ReferenceSpeed: {
            // One working value for all motors (9.5), but stored per motor (9.14).
            const qint64 first = e->values.first();
            bool same = true;
            for (qint64 v : e->values)
                same = same && v == first;
            out.insert(QStringLiteral("reference-speed"), ParameterValue{first, {}});
            if (!same && notes) {
                *notes << ParameterPlan::tr("%1 is stored per motor (%2); %3 is the first")
                              .arg(
                                  parameterSchema().displayLabel(QStringLiteral("reference-speed")),
                                  QString::fromLatin1(formatSystemEntry(*e)))
                              .arg(first);
            }
            break;
        }
        case Key::Ramp:
            out.insert(QStringLiteral("ramp"), ParameterValue{e->ramp, {}});
            break;
        case Key::SmcFlex:
            if (notes) {
                *notes << ParameterPlan::tr(
                              "an SMCflex compatibility entry is stored (%1); store --clear "
                              "(*PESYS) erases it")
                              .arg(QString::fromLatin1(formatSystemEntry(*e)));
            }
            break;
        }
    }
    if (notes && !stored.unparsed.isEmpty()) {
        QStringList raw;
        for (const QByteArray& u : stored.unparsed)
            raw << QString::fromLatin1(u);
        *notes << ParameterPlan::tr("not understood in the *PRSYS answer: %1")
                      .arg(raw.join(QLatin1Char(' ')));
    }
    return out;
}

} // namespace stepdeck::emis
