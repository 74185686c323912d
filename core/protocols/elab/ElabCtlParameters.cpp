#include "ElabCtlParameters.h"
#include "ElabCodec.h"
#include "ElabCtlStatusMapper.h"
#include "ElabModel.h"
#include <QCoreApplication>

namespace stepdeck::elab {

namespace {
const QString kStart = QStringLiteral("start-speed");
const QString kFeed = QStringLiteral("feed-speed");

// Completes a per-axis value from the last written one; empty string when complete.
QString complete(const ParameterSchema& schema, const ParameterSpec& spec,
                 const ParameterValue& given, const ParameterSet& lastWritten, ParameterValue* out)
{
    ParameterValue full;
    if (!spec.perAxis) {
        full.global = schema.normalise(spec, given.global);
        *out = full;
        return {};
    }
    for (Axis a : ElabCtlStatusMapper::axes()) {
        QVariant v = given.perAxis.value(a);
        if (!v.isValid())
            v = lastWritten.value(spec.name).perAxis.value(a);
        if (!v.isValid())
            return ElabCtlParameters::tr(
                       "%1: no value for axis %2 and none written before; give all axes "
                       "(X,Y,Z)")
                .arg(ParameterSchema::displayLabel(spec), axisName(a));
        full.perAxis.insert(a, schema.normalise(spec, v));
    }
    *out = full;
    return {};
}

Triple<quint16> words(const ParameterValue& v)
{
    Triple<quint16> t{};
    for (Axis a : ElabCtlStatusMapper::axes())
        t[wireIndex(a)] = quint16(v.perAxis.value(a).toLongLong());
    return t;
}

Triple<bool> activeHigh(const ParameterValue& v)
{
    Triple<bool> t{};
    for (Axis a : ElabCtlStatusMapper::axes())
        t[wireIndex(a)] = v.perAxis.value(a).toString() == QLatin1String("high");
    return t;
}

QByteArray frameFor(const QString& name, const ParameterValue& v)
{
    if (name == QLatin1String("start-speed"))
        return encode::ramp(RampKind::StartSpeed, words(v));
    if (name == QLatin1String("max-speed"))
        return encode::ramp(RampKind::MaxSpeed, words(v));
    if (name == QLatin1String("acceleration"))
        return encode::ramp(RampKind::Acceleration, words(v));
    if (name == QLatin1String("feed-speed"))
        return encode::feedSpeed(words(v));
    if (name == QLatin1String("limit-polarity"))
        return encode::limitSwitchPolarity(activeHigh(v));
    if (name == QLatin1String("reference-polarity"))
        return encode::referenceSwitchPolarity(activeHigh(v));
    if (name == QLatin1String("drive-power"))
        return encode::drivePower(quint8(v.global.toLongLong()));
    if (name == QLatin1String("spindle-rpm"))
        return encode::spindleRpm(quint32(v.global.toLongLong()));
    if (name == QLatin1String("coolant"))
        return encode::coolant(v.global.toBool());
    return {};
}

// SetFeedSpeed: "die Arbeitsgeschwindigkeit [muss] unterhalb der Startgeschwindigkeit des
// Motors sein, da hier keine Rampe gefahren wird."
QString checkFeedBelowStart(const ParameterSchema& schema, const QList<ElabParameterWrite>& plan,
                            const ParameterSet& last)
{
    ParameterValue start = last.value(kStart);
    ParameterValue feed = last.value(kFeed);
    bool touched = false;
    for (const ElabParameterWrite& w : plan) {
        if (w.name == kStart)
            start = w.value;
        if (w.name == kFeed)
            feed = w.value;
        touched = touched || w.name == kStart || w.name == kFeed;
    }
    if (!touched || feed.perAxis.isEmpty())
        return {};
    if (start.perAxis.isEmpty())
        return ElabCtlParameters::tr("%1 must be below %2 (feed mode has no ramp), but %2 is not "
                                     "known: write %2 in the same set")
            .arg(schema.displayLabel(kFeed), schema.displayLabel(kStart));
    for (Axis a : ElabCtlStatusMapper::axes()) {
        const qint64 f = feed.perAxis.value(a).toLongLong();
        const qint64 s = start.perAxis.value(a).toLongLong();
        if (f >= s)
            return ElabCtlParameters::tr("%1 %2 on axis %3 must be below %4 %5 (feed mode has no "
                                         "ramp)")
                .arg(schema.displayLabel(kFeed))
                .arg(f)
                .arg(axisName(a), schema.displayLabel(kStart))
                .arg(s);
    }
    return {};
}
} // namespace

const QStringList& ElabCtlParameters::order()
{
    static const QStringList names{
        QStringLiteral("start-speed"),    QStringLiteral("max-speed"),
        QStringLiteral("acceleration"),   QStringLiteral("feed-speed"),
        QStringLiteral("limit-polarity"), QStringLiteral("reference-polarity"),
        QStringLiteral("drive-power"),    QStringLiteral("spindle-rpm"),
        QStringLiteral("coolant")};
    return names;
}

QString ElabCtlParameters::plan(const ParameterSchema& schema, const ParameterSet& set,
                                const ParameterSet& lastWritten, QList<ElabParameterWrite>* out)
{
    const QString invalid = schema.validate(set, ElabCtlStatusMapper::axes());
    if (!invalid.isEmpty())
        return invalid;
    QList<ElabParameterWrite> plan;
    for (const QString& name : order()) {
        if (!set.contains(name))
            continue;
        const ParameterSpec* spec = schema.find(name);
        if (!spec)
            return tr("unknown parameter '%1'").arg(name);
        ElabParameterWrite w;
        w.name = name;
        const QString missing = complete(schema, *spec, set.value(name), lastWritten, &w.value);
        if (!missing.isEmpty())
            return missing;
        w.frame = frameFor(name, w.value);
        plan << w;
    }
    if (plan.size() != set.size())
        return tr("parameter set names a parameter the E-LAB board has no command for");
    const QString rule = checkFeedBelowStart(schema, plan, lastWritten);
    if (!rule.isEmpty())
        return rule;
    *out = plan;
    return {};
}

QString ElabCtlParameters::setupIncompleteHint()
{
    const ParameterSchema schema = parameterSchema();
    return tr("write %1, %2 and %3 first")
        .arg(schema.displayLabel(kStart), schema.displayLabel(QStringLiteral("max-speed")),
             schema.displayLabel(QStringLiteral("acceleration")));
}

} // namespace stepdeck::elab
