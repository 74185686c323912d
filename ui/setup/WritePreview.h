#pragma once
#include "model/AxisNames.h"
#include "model/ParameterSchema.h"
#include <QDialog>

class QTableWidget;

namespace stepdeck::ui {

// Before a setup write: exactly what will be sent, per drive (multi-drive models: the
// drive's bus address), old -> new, with the schema's warnings above it. Non-modal (shown
// with dialogs::showForPart); accepted() means "send it".
class WritePreview : public QDialog
{
    Q_OBJECT
public:
    struct Row
    {
        QString drive; // "Drive 2 (Y)", "X", or "all" for a global value
        QString parameter;
        QString old; // what the device last reported, or why that is not known
        QString value;
        QString unit;
    };
    // What is known of the values on the device now (MachineContext): the values last read
    // back, and everything written or read in this link session.
    struct OnDevice
    {
        ParameterSet readBack;
        ParameterSet known;
    };
    // driveAddresses: bus address per axis (empty: rows name the axis only); names: the
    // controller's names of its axes.
    static QList<Row> rows(const ParameterSchema& schema, const ParameterSet& set,
                           const QMap<Axis, int>& driveAddresses, const OnDevice& onDevice = {},
                           const AxisNames& names = {});

    WritePreview(const ParameterSchema& schema, const ParameterSet& set,
                 const QMap<Axis, int>& driveAddresses, const OnDevice& onDevice,
                 const AxisNames& names, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    int rowCount() const;

private:
    QTableWidget* m_table;
};

} // namespace stepdeck::ui
