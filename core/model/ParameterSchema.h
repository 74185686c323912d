#pragma once
#include "Axis.h"
#include "NumberParsing.h"
#include <QCoreApplication>
#include <QJsonObject>
#include <QStringList>
#include <QVariant>

namespace stepdeck {

enum class ParameterType { Integer, Boolean, Choice };

// One device parameter as data: forms, the CLI and import/export are generated from these.
struct ParameterSpec
{
    QString name; // kebab-case id, e.g. "start-speed"
    // label, group, unit, choices, description and warning are English data, marked with
    // QT_TRANSLATE_NOOP("Parameters", ...) where the model's table is written; show them through
    // ParameterSchema::displayText() and friends.
    QString label; // e.g. "Start speed"
    QString group; // "Speeds", "Acceleration", "Switch polarity", "Power & spindle", ...
    QString unit;  // "steps/s", "%", "rpm", ...
    // A parameter whose manual names no unit: what the unit column shows instead ("(no unit)")
    // and, as its tooltip, what the manual does say about the scale. Never a guessed unit.
    QString unitNote;
    QString unitNoteDetail;
    ParameterType type = ParameterType::Integer;
    qint64 minimum = 0;
    qint64 maximum = 0;
    QStringList choices; // Choice: the allowed values, as written in files and on the CLI
    bool perAxis = false;
    bool readable = false; // the protocol can read the value back from the device
    bool writable = true;
    QVariant defaultValue;
    QString description; // plain words, shown as tooltip/help
    QString warning;     // shown before writing (e.g. "communication continues at new address")
};

// A value for every parameter named: global values as QVariant, per-axis values per axis.
struct ParameterValue
{
    QVariant global;
    QMap<Axis, QVariant> perAxis;
    bool isPerAxis() const { return !perAxis.isEmpty(); }
    bool operator==(const ParameterValue& o) const
    {
        return global == o.global && perAxis == o.perAxis;
    }
    bool operator!=(const ParameterValue& o) const { return !(*this == o); }
};
using ParameterSet = QMap<QString, ParameterValue>;

class ParameterSchema
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ParameterSchema)
public:
    ParameterSchema() = default;
    explicit ParameterSchema(QList<ParameterSpec> specs) : m_specs(std::move(specs)) {}

    // The one translation context of every model's schema words: the same word ("Idle
    // current", "steps/s") is translated once for all models.
    static constexpr const char* kTranslationContext = "Parameters";
    // A schema word (label, group, unit, choice, description, warning) in the language of the
    // installed translator; "" stays "".
    static QString displayText(const QString& english);
    static QString displayLabel(const ParameterSpec& spec) { return displayText(spec.label); }
    // " steps/s" (translated, with its leading space) or "" for parameters without a unit.
    static QString displayUnitSuffix(const ParameterSpec& spec);
    // The unit column's text: the translated unit, or the unit note when there is no unit.
    static QString displayUnitColumn(const ParameterSpec& spec);
    // Its tooltip: what the manual says when the parameter has no unit ("" otherwise).
    static QString displayUnitToolTip(const ParameterSpec& spec);

    const QList<ParameterSpec>& specs() const { return m_specs; }
    const ParameterSpec* find(const QString& name) const;
    // The translated label of the named parameter, or the name itself if the schema has none.
    QString displayLabel(const QString& name) const;
    // "unknown parameter 'strat-speed' (did you mean start-speed?)": for a key the user typed
    // or a file holds, with the nearest parameter name when one is close (NearestName.h).
    QString unknownNameText(const QString& name) const;
    QStringList groups() const;

    // Checks type and range of one scalar value; returns an empty string when valid, else a
    // sentence naming the parameter by its translated label, with its range and unit.
    QString validateScalar(const ParameterSpec& spec, const QVariant& value) const;
    // The same, naming the parameter `who` (the setup page's "Max speed X"): the form and the
    // files say the same about the same text ("'abc' is not a decimal integer").
    QString validateScalar(const ParameterSpec& spec, const QVariant& value,
                           const QString& who) const
    {
        return scalarError(who, spec, value);
    }
    // Checks every entry of a set (unknown names, per-axis shape, type, range, writability).
    // Messages name parameters by their translated label; an unknown one by the key given.
    // (parseAssignment() and fromJson() name the key instead: it is what the user typed or
    // what the file holds.)
    QString validate(const ParameterSet& set, const QList<Axis>& axes) const;
    // Normalises a scalar to its canonical type (qint64, bool or QString); invalid -> null.
    // Integers: decimal text only ("0100" is 100, "0x40" invalid), doubles only when finite,
    // whole and within qint64 (NumberParsing.h).
    QVariant normalise(const ParameterSpec& spec, const QVariant& value) const;

    // "NAME=V[,V,V]" as typed on the CLI; per-axis values in the order of `axes`. Numbers
    // are decimal (NumberParsing.h). Messages name the parameter by the key, as typed. On a refused
    // integer value, *numberError (if given) says whether its text was a number at all (None: it
    // was, but outside the range).
    bool parseAssignment(const QString& text, const QList<Axis>& axes, QString* name,
                         ParameterValue* value, QString* error,
                         NumberError* numberError = nullptr) const;
    QString formatValue(const ParameterSpec& spec, const ParameterValue& value) const;
    // "0..65535", "on|off" or "high|low": what a value may be, for messages and listings.
    static QString rangeText(const ParameterSpec& spec);

    // The JSON file format shared by CLI export/import and the setup pages:
    // {"format":"stepdeck-parameters","version":1,"model":"elab",
    //  "parameters":{"start-speed":{"X":100,"Y":100,"Z":100},"drive-power":100}}
    QJsonObject toJson(const QString& modelId, const ParameterSet& set) const;
    // Parses and validates everything before returning; on error returns false and says why.
    bool fromJson(const QJsonObject& json, const QString& modelId, const QList<Axis>& axes,
                  ParameterSet* set, QString* error) const;

private:
    // validateScalar() naming the parameter `who` (its label, or the key the user typed).
    QString scalarError(const QString& who, const ParameterSpec& spec, const QVariant& value) const;
    // validate(), naming parameters by key (byKey) or by translated label.
    QString check(const ParameterSet& set, const QList<Axis>& axes, bool byKey) const;

    QList<ParameterSpec> m_specs;
};

} // namespace stepdeck

Q_DECLARE_METATYPE(stepdeck::ParameterSet)
