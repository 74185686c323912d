#include "ParameterField.h"
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLineEdit>

namespace stepdeck::ui {

ParameterField::ParameterField(const ParameterSchema& schema, const ParameterSpec& spec,
                               std::optional<Axis> axis, QWidget* parent)
    : QWidget(parent), m_schema(schema), m_spec(spec), m_axis(axis)
{
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_tip = ParameterSchema::displayText(spec.description);
    switch (spec.type) {
    case ParameterType::Integer:
        m_line = new QLineEdit(this);
        m_line->setAlignment(Qt::AlignRight);
        m_line->setMinimumWidth(80);
        m_tip += QStringLiteral("\n") + tr("Allowed: %1 to %2 %3")
                                            .arg(spec.minimum)
                                            .arg(spec.maximum)
                                            .arg(ParameterSchema::displayText(spec.unit));
        connect(m_line, &QLineEdit::textEdited, this, &ParameterField::userEdit);
        connect(m_line, &QLineEdit::textChanged, this, [this] {
            refreshLook();
            Q_EMIT edited();
        });
        layout->addWidget(m_line);
        break;
    case ParameterType::Boolean:
        m_check = new QCheckBox(tr("on"), this);
        connect(m_check, &QCheckBox::clicked, this, &ParameterField::userEdit);
        connect(m_check, &QCheckBox::toggled, this, [this] {
            refreshLook();
            Q_EMIT edited();
        });
        layout->addWidget(m_check);
        break;
    case ParameterType::Choice:
        m_combo = new QComboBox(this);
        for (const QString& c : spec.choices)
            m_combo->addItem(translatedChoice(c), c);
        connect(m_combo, &QComboBox::activated, this, [this] {
            userEdit();
            refreshLook();
            Q_EMIT edited();
        });
        layout->addWidget(m_combo);
        break;
    }
    if (!spec.writable)
        editor()->setEnabled(false);
    setValue(spec.defaultValue);
}

QString ParameterField::translatedChoice(const QString& choice)
{
    return ParameterSchema::displayText(choice);
}

QString ParameterField::displayName() const
{
    const QString label = ParameterSchema::displayText(m_spec.label);
    if (!m_axis)
        return label;
    return QStringLiteral("%1 %2").arg(label,
                                       m_axisName.isEmpty() ? axisName(*m_axis) : m_axisName);
}

QWidget* ParameterField::editor() const
{
    if (m_line)
        return m_line;
    if (m_check)
        return m_check;
    return m_combo;
}

void ParameterField::userEdit()
{
    m_explicit = true;
    if (m_unknown && !m_line) {
        m_unknown = false; // a check box or choice has a value as soon as it is touched
        if (m_check)
            m_check->setTristate(false);
        refreshLook();
    }
}

QVariant ParameterField::rawValue() const
{
    if (m_line)
        return m_line->text();
    if (m_check)
        return m_check->isChecked();
    return m_combo->currentData();
}

bool ParameterField::isUnknown() const
{
    return m_unknown && (!m_line || m_line->text().trimmed().isEmpty());
}

QVariant ParameterField::value() const
{
    if (isUnknown())
        return {};
    return isValid() ? m_schema.normalise(m_spec, rawValue()) : QVariant();
}

void ParameterField::setValue(const QVariant& value, bool explicitValue)
{
    m_unknown = false;
    if (!explicitValue)
        m_deviceUnknown = false; // read back
    m_explicit = explicitValue;
    const QVariant v = m_schema.normalise(m_spec, value);
    if (m_line) {
        m_line->setPlaceholderText(QString());
        m_line->setText(v.isValid() ? QString::number(v.toLongLong()) : value.toString());
    } else if (m_check) {
        const QSignalBlocker block(m_check);
        m_check->setTristate(false);
        m_check->setChecked(v.toBool());
    } else {
        m_combo->setCurrentIndex(qMax(0, m_combo->findData(v.toString())));
    }
    refreshLook();
}

void ParameterField::setUnknown()
{
    m_explicit = false;
    if (m_line) {
        const QSignalBlocker block(m_line);
        m_line->clear();
        m_line->setPlaceholderText(tr("unknown"));
    } else if (m_check) {
        const QSignalBlocker block(m_check);
        m_check->setTristate(true);
        m_check->setCheckState(Qt::PartiallyChecked);
    } else {
        m_combo->setCurrentIndex(-1);
    }
    m_unknown = true;
    m_deviceUnknown = true;
    refreshLook();
}

QString ParameterField::error() const
{
    if (isUnknown())
        return {};
    const QString name = displayName();
    if (m_line && m_line->text().trimmed().isEmpty())
        return tr("%1: a value is required").arg(name);
    // The schema's words, as for a file or the CLI: "not a decimal integer" for "abc", "out
    // of range" only for a number outside the range.
    return m_schema.validateScalar(m_spec, rawValue(), name);
}

void ParameterField::setBaseline(const QVariant& value)
{
    m_baseline = m_schema.normalise(m_spec, value);
    refreshLook();
}

bool ParameterField::isChanged() const
{
    // The last read of this value failed: what the device holds is unknown, whatever an
    // earlier read said; only the technician's own choice goes out.
    if (m_deviceUnknown)
        return m_explicit && value().isValid();
    if (!m_baseline.isValid())
        return !m_spec.readable || (m_explicit && value().isValid());
    return value() != m_baseline;
}

void ParameterField::refreshLook()
{
    const QString err = error();
    QWidget* e = editor();
    QString state;
    if (!err.isEmpty()) {
        e->setStyleSheet(QStringLiteral("background: #ffcdd2; color: #8e0000;"));
        state = QStringLiteral("invalid");
    } else if (isUnknown()) {
        e->setStyleSheet(QStringLiteral("background: #eceff1; color: #607d8b;"));
        state = QStringLiteral("unknown");
    } else if ((m_baseline.isValid() || m_deviceUnknown) && isChanged()) {
        e->setStyleSheet(QStringLiteral("background: #fff59d;"));
        state = QStringLiteral("changed");
    } else {
        e->setStyleSheet(QString());
        state = QStringLiteral("clean");
    }
    e->setProperty("fieldState", state);
    QString tip = m_tip;
    if (state == QLatin1String("unknown"))
        tip += QStringLiteral("\n") + tr("Unknown: the value could not be read. It is written "
                                         "only if you set it.");
    if (!err.isEmpty())
        tip += QStringLiteral("\n\u26a0 ") + err;
    e->setToolTip(tip);
}

} // namespace stepdeck::ui
