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
    QString tip = QCoreApplication::translate("Parameters", spec.description.toUtf8().constData());
    switch (spec.type) {
    case ParameterType::Integer:
        m_line = new QLineEdit(this);
        m_line->setAlignment(Qt::AlignRight);
        m_line->setMinimumWidth(80);
        tip += QStringLiteral("\n") + tr("Allowed: %1 to %2").arg(spec.minimum).arg(spec.maximum);
        connect(m_line, &QLineEdit::textChanged, this, [this] {
            refreshLook();
            Q_EMIT edited();
        });
        layout->addWidget(m_line);
        break;
    case ParameterType::Boolean:
        m_check = new QCheckBox(tr("on"), this);
        connect(m_check, &QCheckBox::toggled, this, [this] {
            refreshLook();
            Q_EMIT edited();
        });
        layout->addWidget(m_check);
        break;
    case ParameterType::Choice:
        m_combo = new QComboBox(this);
        for (const QString& c : spec.choices)
            m_combo->addItem(QCoreApplication::translate("Parameters", c.toUtf8().constData()), c);
        connect(m_combo, &QComboBox::activated, this, [this] {
            refreshLook();
            Q_EMIT edited();
        });
        layout->addWidget(m_combo);
        break;
    }
    if (!spec.writable)
        editor()->setEnabled(false);
    editor()->setToolTip(tip);
    setValue(spec.defaultValue);
}

QWidget* ParameterField::editor() const
{
    if (m_line)
        return m_line;
    if (m_check)
        return m_check;
    return m_combo;
}

QVariant ParameterField::rawValue() const
{
    if (m_line)
        return m_line->text();
    if (m_check)
        return m_check->isChecked();
    return m_combo->currentData();
}

QVariant ParameterField::value() const
{
    return isValid() ? m_schema.normalise(m_spec, rawValue()) : QVariant();
}

void ParameterField::setValue(const QVariant& value)
{
    const QVariant v = m_schema.normalise(m_spec, value);
    if (m_line) {
        m_line->setText(v.isValid() ? QString::number(v.toLongLong()) : value.toString());
    } else if (m_check) {
        const QSignalBlocker block(m_check);
        m_check->setChecked(v.toBool());
    } else {
        m_combo->setCurrentIndex(qMax(0, m_combo->findData(v.toString())));
    }
    refreshLook();
}

QString ParameterField::error() const
{
    if (m_line && m_line->text().trimmed().isEmpty())
        return tr("%1: a value is required").arg(m_spec.name);
    return m_schema.validateScalar(m_spec, rawValue());
}

void ParameterField::setBaseline(const QVariant& value)
{
    m_baseline = m_schema.normalise(m_spec, value);
    refreshLook();
}

bool ParameterField::isChanged() const
{
    return !m_baseline.isValid() || value() != m_baseline;
}

void ParameterField::refreshLook()
{
    const QString err = error();
    QWidget* e = editor();
    if (!err.isEmpty()) {
        e->setStyleSheet(QStringLiteral("background: #ffcdd2; color: #8e0000;"));
        e->setProperty("fieldState", QStringLiteral("invalid"));
    } else if (m_baseline.isValid() && value() != m_baseline) {
        e->setStyleSheet(QStringLiteral("background: #fff59d;"));
        e->setProperty("fieldState", QStringLiteral("changed"));
    } else {
        e->setStyleSheet(QString());
        e->setProperty("fieldState", QStringLiteral("clean"));
    }
    if (m_line)
        m_line->setToolTip(err.isEmpty()
                               ? m_line->toolTip().section(QStringLiteral("\n\u26a0"), 0, 0)
                               : m_line->toolTip().section(QStringLiteral("\n\u26a0"), 0, 0) +
                                     QStringLiteral("\n\u26a0 ") + err);
}

} // namespace stepdeck::ui
