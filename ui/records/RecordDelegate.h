#pragma once
#include "model/ParameterSchema.h"
#include <QStyledItemDelegate>

namespace stepdeck::ui {

// Cells of the records table shown and edited as the schema says: choices in the current
// language with a drop-down of the allowed values, yes/no for flags, a spin box within the
// parameter's range for numbers. The model keeps the schema's values (e.g. "left", 1000).
class RecordDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    explicit RecordDelegate(QObject* parent = nullptr);

    // The parameter of each column, in column order.
    void setColumns(const QList<ParameterSpec>& specs) { m_specs = specs; }

    QString displayText(const QVariant& value, const QLocale& locale) const override;
    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override;

private:
    const ParameterSpec* specAt(const QModelIndex& index) const;

    QList<ParameterSpec> m_specs;
};

} // namespace stepdeck::ui
