#include "RecordDelegate.h"
#include <QComboBox>
#include <QCoreApplication>
#include <QSpinBox>

namespace stepdeck::ui {

RecordDelegate::RecordDelegate(QObject* parent) : QStyledItemDelegate(parent) {}

const ParameterSpec* RecordDelegate::specAt(const QModelIndex& index) const
{
    if (index.column() < 0 || index.column() >= m_specs.size())
        return nullptr;
    const ParameterSpec& spec = m_specs.at(index.column());
    return spec.name.isEmpty() ? nullptr : &spec; // a field the schema does not know
}

QString RecordDelegate::displayText(const QVariant& value, const QLocale& locale) const
{
    if (value.typeId() == QMetaType::Bool)
        return value.toBool() ? tr("yes") : tr("no");
    if (value.typeId() == QMetaType::QString)
        return ParameterSchema::displayText(value.toString());
    return QStyledItemDelegate::displayText(value, locale);
}

QWidget* RecordDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                      const QModelIndex& index) const
{
    const ParameterSpec* spec = specAt(index);
    if (!spec)
        return QStyledItemDelegate::createEditor(parent, option, index);
    switch (spec->type) {
    case ParameterType::Choice: {
        auto* combo = new QComboBox(parent);
        for (const QString& c : spec->choices)
            combo->addItem(ParameterSchema::displayText(c), c);
        return combo;
    }
    case ParameterType::Boolean: {
        auto* combo = new QComboBox(parent);
        combo->addItem(tr("no"), false);
        combo->addItem(tr("yes"), true);
        return combo;
    }
    case ParameterType::Integer: {
        // The schema's range (manual section 6); the drive ignores values outside it.
        auto* spin = new QSpinBox(parent);
        spin->setRange(int(qMax<qint64>(spec->minimum, INT_MIN)),
                       int(qMin<qint64>(spec->maximum, INT_MAX)));
        return spin;
    }
    }
    return QStyledItemDelegate::createEditor(parent, option, index);
}

void RecordDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const
{
    const QVariant value = index.data(Qt::EditRole);
    if (auto* combo = qobject_cast<QComboBox*>(editor))
        combo->setCurrentIndex(qMax(0, combo->findData(value)));
    else if (auto* spin = qobject_cast<QSpinBox*>(editor))
        spin->setValue(value.toInt());
    else
        QStyledItemDelegate::setEditorData(editor, index);
}

void RecordDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                  const QModelIndex& index) const
{
    if (auto* combo = qobject_cast<QComboBox*>(editor))
        model->setData(index, combo->currentData(), Qt::EditRole);
    else if (auto* spin = qobject_cast<QSpinBox*>(editor))
        model->setData(index, qint64(spin->value()), Qt::EditRole);
    else
        QStyledItemDelegate::setModelData(editor, model, index);
}

} // namespace stepdeck::ui
