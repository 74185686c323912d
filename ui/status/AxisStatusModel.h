#pragma once
#include "common/LedIndicator.h"
#include "model/MachineStatus.h"
#include <QAbstractTableModel>

namespace stepdeck::ui {

// The axes of a controller with many of them (a Nanotec bus of up to 254 drives; issue 32,
// step 5) as rows: name, the normalised flags as lamps, the position and, on a bus, the drive's
// address and whether it answers. For AxisRowFilter: FilterTextRole (name, address),
// MovingRole, AxesRole. A flag's lamp state is StateRole (LedIndicator::State as int).
class AxisStatusModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        Name,
        Moving,
        Jogging,
        Limit,
        RefSwitch,
        Referenced,
        Position,
        Drive,
        ColumnCount
    };
    static constexpr int StateRole = Qt::UserRole + 1;

    struct Row
    {
        Axis axis;
        QString name;
    };

    explicit AxisStatusModel(QObject* parent = nullptr);

    void setRows(const QList<Row>& rows); // the controller's axes, once per connection
    // Each poll: only the rows whose shown values changed are signalled (issue 21, idle cost).
    void setStatus(const MachineStatus& status, bool live);
    Axis axisAt(int row) const { return m_rows.at(row).axis; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    struct Shown
    {
        AxisStatus axis;
        bool responding = true;
        bool live = false;
        int address = 0; // its drive's bus address (MachineStatus::drives); 0: none reported
        bool operator==(const Shown& o) const;
    };
    LedIndicator::State lampState(int row, int column) const;
    QVariant displayData(int row, int column) const;
    QVariant toolTipData(int row, int column) const;

    QList<Row> m_rows;
    QList<Shown> m_shown;
};

} // namespace stepdeck::ui
