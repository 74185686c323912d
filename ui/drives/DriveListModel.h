#pragma once
#include "model/MachineStatus.h"
#include <QAbstractTableModel>

namespace stepdeck::ui {

// The drives on a controller's link as rows (Nanotec: one per bus address, up to 254; issue
// 32, step 5): address, axis names, whether it answers (a silent one red), firmware, state.
// For AxisRowFilter: FilterTextRole (address, names), MovingRole, AxesRole.
class DriveListModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { Address, Axes, Responding, Firmware, Detail, ColumnCount };

    struct Row
    {
        DriveStatus drive;
        QString axisNames; // "feeder" or "X,Y"
        bool moving = false;
        bool operator==(const Row& o) const;
    };

    explicit DriveListModel(QObject* parent = nullptr);

    // Each poll. Returns true when anything shown changed; only the changed rows are
    // signalled, and a new set of drives resets the list (issue 21: the idle GUI does not
    // rebuild what it shows).
    bool setRows(const QList<Row>& rows);
    const QList<Row>& rows() const { return m_rows; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    QVariant displayData(const Row& row, int column) const;

    QList<Row> m_rows;
};

} // namespace stepdeck::ui
