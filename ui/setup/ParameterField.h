#pragma once
#include "model/ParameterSchema.h"
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLineEdit;

namespace stepdeck::ui {

// One editable value of a parameter (one axis of a per-axis parameter, or a global one).
// Integers are typed freely and checked against the schema, so an out-of-range entry stays
// visible, is marked, and says why instead of being silently clamped. Fields that differ
// from the last value known on the device are highlighted.
// A readable value that could not be read (silent drive, failed read) is UNKNOWN: empty,
// marked, never filled with a default, and written only once the technician sets it
// (explicit). Values typed, chosen, loaded from a file or set to the defaults are explicit.
class ParameterField : public QWidget
{
    Q_OBJECT
public:
    ParameterField(const ParameterSchema& schema, const ParameterSpec& spec,
                   std::optional<Axis> axis, QWidget* parent = nullptr);

    const ParameterSpec& spec() const { return m_spec; }
    std::optional<Axis> axis() const { return m_axis; }
    // The name its axis goes by in messages (the controller's; default: axisName).
    void setAxisName(const QString& name) { m_axisName = name; }

    QVariant value() const; // normalised; invalid when the entry is invalid or unknown
    // explicitValue: the technician's choice (typed, file, defaults), not a read-back.
    void setValue(const QVariant& value, bool explicitValue = false);
    void setUnknown(); // nothing known: empty and marked, not an error
    bool isUnknown() const;
    bool isExplicit() const { return m_explicit; }
    QString error() const; // empty when valid; names the parameter by its translated label
    bool isValid() const { return error().isEmpty(); }

    // The value known to be on the device (after a write or a read); invalid: unknown.
    void setBaseline(const QVariant& value);
    QVariant baseline() const { return m_baseline; }
    // Would Write send it? Differs from the device's known value; with none known: a
    // write-only value always, a readable one only when set explicitly.
    bool isChanged() const;

    QLineEdit* lineEdit() const { return m_line; }
    QWidget* editor() const;
    // The parameter's label and axis in the current language, e.g. "Max speed Y".
    QString displayName() const;
    static QString translatedChoice(const QString& choice);

Q_SIGNALS:
    void edited();

private:
    void refreshLook();
    QVariant rawValue() const;
    void userEdit();

    const ParameterSchema& m_schema;
    ParameterSpec m_spec;
    std::optional<Axis> m_axis;
    QString m_axisName; // empty: axisName(*m_axis)
    QLineEdit* m_line = nullptr;
    QCheckBox* m_check = nullptr;
    QComboBox* m_combo = nullptr;
    QVariant m_baseline;
    bool m_unknown = false;       // shown empty: nothing to show
    bool m_deviceUnknown = false; // the last read failed (stays after the technician types)
    bool m_explicit = false;
    QString m_tip;
};

} // namespace stepdeck::ui
