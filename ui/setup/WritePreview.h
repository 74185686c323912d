#pragma once
#include "model/ParameterSchema.h"
#include <QDialog>

class QTableWidget;

namespace stepdeck::ui {

// Before a setup write: exactly what will be sent, per drive (multi-drive models: the
// drive's bus address), with the schema's warnings above it. Non-modal (shown with
// dialogs::showForPart); accepted() means "send it".
class WritePreview : public QDialog
{
    Q_OBJECT
public:
    struct Row
    {
        QString drive; // "Drive 2 (Y)", "X", or "all" for a global value
        QString parameter;
        QString value;
        QString unit;
    };
    // driveAddresses: bus address per axis (empty: rows name the axis only).
    static QList<Row> rows(const ParameterSchema& schema, const ParameterSet& set,
                           const QMap<Axis, int>& driveAddresses);

    WritePreview(const ParameterSchema& schema, const ParameterSet& set,
                 const QMap<Axis, int>& driveAddresses, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    int rowCount() const;

private:
    QTableWidget* m_table;
};

} // namespace stepdeck::ui
