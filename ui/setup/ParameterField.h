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
class ParameterField : public QWidget
{
    Q_OBJECT
public:
    ParameterField(const ParameterSchema& schema, const ParameterSpec& spec,
                   std::optional<Axis> axis, QWidget* parent = nullptr);

    const ParameterSpec& spec() const { return m_spec; }
    std::optional<Axis> axis() const { return m_axis; }

    QVariant value() const; // normalised; invalid when the entry is invalid
    void setValue(const QVariant& value);
    QString error() const; // empty when valid
    bool isValid() const { return error().isEmpty(); }

    // The value known to be on the device (after a write or a read); invalid: unknown.
    void setBaseline(const QVariant& value);
    QVariant baseline() const { return m_baseline; }
    bool isChanged() const; // differs from the baseline, or the baseline is unknown

    QLineEdit* lineEdit() const { return m_line; }
    QWidget* editor() const;

Q_SIGNALS:
    void edited();

private:
    void refreshLook();
    QVariant rawValue() const;

    const ParameterSchema& m_schema;
    ParameterSpec m_spec;
    std::optional<Axis> m_axis;
    QLineEdit* m_line = nullptr;
    QCheckBox* m_check = nullptr;
    QComboBox* m_combo = nullptr;
    QVariant m_baseline;
};

} // namespace stepdeck::ui
