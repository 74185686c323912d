#include "ParameterSchema.h"
#include "NearestName.h"
#include "NumberParsing.h"
#include <QJsonValue>

namespace stepdeck {

namespace {
// How an integer value's text failed to be a number at all (None: it is one, perhaps outside
// the parameter's range).
void readingProblem(const ParameterSpec& spec, const QString& raw, NumberError* numberError)
{
    qint64 ignored = 0;
    if (numberError && spec.type == ParameterType::Integer)
        *numberError = numbers::parseInteger(raw, &ignored);
}
} // namespace

QString ParameterSchema::rangeText(const ParameterSpec& spec)
{
    switch (spec.type) {
    case ParameterType::Integer:
        return QStringLiteral("%1..%2").arg(spec.minimum).arg(spec.maximum);
    case ParameterType::Boolean:
        return QStringLiteral("on|off");
    case ParameterType::Choice:
        return spec.choices.join(QLatin1Char('|'));
    }
    return {};
}

QString ParameterSchema::displayText(const QString& english)
{
    if (english.isEmpty())
        return {};
    return QCoreApplication::translate(kTranslationContext, english.toUtf8().constData());
}

QString ParameterSchema::displayUnitSuffix(const ParameterSpec& spec)
{
    return spec.unit.isEmpty() ? QString() : QStringLiteral(" ") + displayText(spec.unit);
}

QString ParameterSchema::displayUnitColumn(const ParameterSpec& spec)
{
    return displayText(spec.unit.isEmpty() ? spec.unitNote : spec.unit);
}

QString ParameterSchema::displayUnitToolTip(const ParameterSpec& spec)
{
    return spec.unit.isEmpty() ? displayText(spec.unitNoteDetail) : QString();
}

QString ParameterSchema::displayLabel(const QString& name) const
{
    const ParameterSpec* spec = find(name);
    return spec ? displayLabel(*spec) : name;
}

QString ParameterSchema::unknownNameText(const QString& name) const
{
    QStringList names;
    for (const ParameterSpec& spec : m_specs)
        names << spec.name;
    const QString close = names::nearest(name, names);
    return close.isEmpty() ? tr("unknown parameter '%1'").arg(name)
                           : tr("unknown parameter '%1' (did you mean %2?)").arg(name, close);
}

const ParameterSpec* ParameterSchema::find(const QString& name) const
{
    for (const ParameterSpec& spec : m_specs) {
        if (spec.name == name)
            return &spec;
    }
    return nullptr;
}

QStringList ParameterSchema::groups() const
{
    QStringList out;
    for (const ParameterSpec& spec : m_specs) {
        if (!out.contains(spec.group))
            out << spec.group;
    }
    return out;
}

QVariant ParameterSchema::normalise(const ParameterSpec& spec, const QVariant& value) const
{
    switch (spec.type) {
    case ParameterType::Integer: {
        qint64 v = 0;
        return numbers::integerFromVariant(value, &v) == NumberError::None ? QVariant(v)
                                                                           : QVariant();
    }
    case ParameterType::Boolean: {
        if (value.typeId() == QMetaType::Bool)
            return value;
        const QString s = value.toString().trimmed().toLower();
        if (s == "on" || s == "true" || s == "1" || s == "yes")
            return true;
        if (s == "off" || s == "false" || s == "0" || s == "no")
            return false;
        return {};
    }
    case ParameterType::Choice: {
        const QString s = value.toString().trimmed().toLower();
        for (const QString& c : spec.choices) {
            if (c.toLower() == s)
                return c;
        }
        return {};
    }
    }
    return {};
}

QString ParameterSchema::validateScalar(const ParameterSpec& spec, const QVariant& value) const
{
    return scalarError(displayLabel(spec), spec, value);
}

QString ParameterSchema::scalarError(const QString& who, const ParameterSpec& spec,
                                     const QVariant& value) const
{
    // The range and unit only for a message: a program's check validates millions of writes.
    const auto range = [&] { return rangeText(spec); };
    const auto unit = [&] { return displayUnitSuffix(spec); };
    if (spec.type == ParameterType::Integer) {
        qint64 v = 0;
        switch (numbers::integerFromVariant(value, &v)) {
        case NumberError::None:
            if (v >= spec.minimum && v <= spec.maximum)
                return {};
            break;
        case NumberError::Malformed:
            return tr("%1: '%2' is not a decimal integer (allowed: %3%4)")
                .arg(who, value.toString(), range(), unit());
        case NumberError::NonFinite:
            return tr("%1: '%2' is not a finite number (allowed: %3%4)")
                .arg(who, value.toString(), range(), unit());
        case NumberError::OutOfRange:
            break;
        }
    } else if (normalise(spec, value).isValid()) {
        return {};
    }
    return tr("%1: value '%2' is out of range (allowed: %3%4)")
        .arg(who, value.toString(), range(), unit());
}

QString ParameterSchema::validate(const ParameterSet& set, const QList<Axis>& axes) const
{
    return check(set, axes, false);
}

QString ParameterSchema::check(const ParameterSet& set, const QList<Axis>& axes, bool byKey) const
{
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = find(it.key());
        if (!spec)
            return unknownNameText(it.key());
        const QString who = byKey ? spec->name : displayLabel(*spec);
        if (!spec->writable)
            return tr("%1 is read-only").arg(who);
        const ParameterValue& value = it.value();
        if (spec->perAxis) {
            if (!value.isPerAxis())
                return tr("%1 needs one value per axis").arg(who);
            for (auto a = value.perAxis.cbegin(); a != value.perAxis.cend(); ++a) {
                if (!axes.contains(a.key()))
                    return tr("%1: this machine has no axis %2").arg(who, axisName(a.key()));
                const QString err = scalarError(who, *spec, a.value());
                if (!err.isEmpty())
                    return QStringLiteral("%1 (%2)").arg(err, axisName(a.key()));
            }
        } else {
            if (value.isPerAxis())
                return tr("%1 takes a single value, not one per axis").arg(who);
            const QString err = scalarError(who, *spec, value.global);
            if (!err.isEmpty())
                return err;
        }
    }
    return {};
}

bool ParameterSchema::parseAssignment(const QString& text, const QList<Axis>& axes, QString* name,
                                      ParameterValue* value, QString* error,
                                      NumberError* numberError) const
{
    if (numberError)
        *numberError = NumberError::None;
    const int eq = text.indexOf(QLatin1Char('='));
    if (eq <= 0) {
        *error = tr("expected NAME=VALUE, got '%1'").arg(text);
        return false;
    }
    *name = text.left(eq).trimmed();
    const ParameterSpec* spec = find(*name);
    if (!spec) {
        *error = unknownNameText(*name);
        return false;
    }
    const QStringList parts = text.mid(eq + 1).split(QLatin1Char(','));
    ParameterValue out;
    if (spec->perAxis) {
        // One value for all axes, or exactly one per axis in X,Y,Z(,U) order.
        if (parts.size() != 1 && parts.size() != axes.size()) {
            *error = tr("%1 needs 1 or %2 values (axes %3)").arg(*name).arg(axes.size()).arg([&] {
                QStringList n;
                for (Axis a : axes)
                    n << axisName(a);
                return n.join(QLatin1Char(','));
            }());
            return false;
        }
        for (int i = 0; i < axes.size(); ++i) {
            const QString& raw = parts.size() == 1 ? parts[0] : parts[i];
            const QString err = scalarError(*name, *spec, raw);
            if (!err.isEmpty()) {
                *error = QStringLiteral("%1 (%2)").arg(err, axisName(axes[i]));
                readingProblem(*spec, raw, numberError);
                return false;
            }
            out.perAxis.insert(axes[i], normalise(*spec, raw));
        }
    } else {
        if (parts.size() != 1) {
            *error = tr("%1 takes a single value").arg(*name);
            return false;
        }
        const QString err = scalarError(*name, *spec, parts[0]);
        if (!err.isEmpty()) {
            *error = err;
            readingProblem(*spec, parts[0], numberError);
            return false;
        }
        out.global = normalise(*spec, parts[0]);
    }
    *value = out;
    return true;
}

QString ParameterSchema::formatValue(const ParameterSpec& spec, const ParameterValue& value) const
{
    auto one = [&](const QVariant& v) {
        if (spec.type == ParameterType::Boolean)
            return v.toBool() ? QStringLiteral("on") : QStringLiteral("off");
        return v.toString();
    };
    if (!value.isPerAxis())
        return one(value.global);
    QStringList parts;
    for (auto it = value.perAxis.cbegin(); it != value.perAxis.cend(); ++it)
        parts << one(it.value());
    return parts.join(QLatin1Char(','));
}

QJsonObject ParameterSchema::toJson(const QString& modelId, const ParameterSet& set) const
{
    QJsonObject params;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        if (it.value().isPerAxis()) {
            QJsonObject perAxis;
            for (auto a = it.value().perAxis.cbegin(); a != it.value().perAxis.cend(); ++a)
                perAxis.insert(axisName(a.key()), QJsonValue::fromVariant(a.value()));
            params.insert(it.key(), perAxis);
        } else {
            params.insert(it.key(), QJsonValue::fromVariant(it.value().global));
        }
    }
    return QJsonObject{{"format", "stepdeck-parameters"},
                       {"version", 1},
                       {"model", modelId},
                       {"parameters", params}};
}

bool ParameterSchema::fromJson(const QJsonObject& json, const QString& modelId,
                               const QList<Axis>& axes, ParameterSet* set, QString* error) const
{
    if (json.value("format").toString() != QLatin1String("stepdeck-parameters")) {
        *error = tr("not a StepDeck parameter file");
        return false;
    }
    if (json.value("version").toInt() != 1) {
        *error = tr("unsupported parameter file version %1").arg(json.value("version").toInt());
        return false;
    }
    if (json.value("model").toString() != modelId) {
        *error = tr("parameter file is for model '%1', not '%2'")
                     .arg(json.value("model").toString(), modelId);
        return false;
    }
    const QJsonValue paramsValue = json.value("parameters");
    if (!paramsValue.isObject()) {
        *error = tr("parameter file has no \"parameters\" object");
        return false;
    }
    const QJsonObject params = paramsValue.toObject();
    ParameterSet out;
    for (auto it = params.constBegin(); it != params.constEnd(); ++it) {
        const ParameterSpec* spec = find(it.key());
        if (!spec) {
            *error = unknownNameText(it.key());
            return false;
        }
        ParameterValue value;
        if (it.value().isObject()) {
            const QJsonObject perAxis = it.value().toObject();
            for (auto a = perAxis.constBegin(); a != perAxis.constEnd(); ++a) {
                const auto axis = axisFromName(a.key());
                if (!axis) {
                    *error = tr("%1: '%2' is not an axis").arg(it.key(), a.key());
                    return false;
                }
                value.perAxis.insert(*axis, normalise(*spec, a.value().toVariant()).isValid()
                                                ? normalise(*spec, a.value().toVariant())
                                                : a.value().toVariant());
            }
        } else {
            const QVariant raw = it.value().toVariant();
            value.global = normalise(*spec, raw).isValid() ? normalise(*spec, raw) : raw;
        }
        out.insert(it.key(), value);
    }
    const QString err = check(out, axes, true); // names the keys, as the file does
    if (!err.isEmpty()) {
        *error = err;
        return false;
    }
    *set = out;
    return true;
}

} // namespace stepdeck
