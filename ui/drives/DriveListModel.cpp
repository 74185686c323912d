#include "DriveListModel.h"
#include "common/AxisRowFilter.h"
#include <QColor>

namespace stepdeck::ui {

bool DriveListModel::Row::operator==(const Row& o) const
{
    return drive.address == o.drive.address && drive.axes == o.drive.axes &&
           drive.responding == o.drive.responding && drive.firmware == o.drive.firmware &&
           drive.detail == o.drive.detail && axisNames == o.axisNames && moving == o.moving;
}

DriveListModel::DriveListModel(QObject* parent) : QAbstractTableModel(parent) {}

bool DriveListModel::setRows(const QList<Row>& rows)
{
    bool sameDrives = rows.size() == m_rows.size();
    for (int r = 0; sameDrives && r < rows.size(); ++r)
        sameDrives = rows.at(r).drive.address == m_rows.at(r).drive.address;
    if (!sameDrives) {
        beginResetModel();
        m_rows = rows;
        endResetModel();
        return true;
    }
    bool changed = false;
    for (int r = 0; r < rows.size(); ++r) {
        if (rows.at(r) == m_rows.at(r))
            continue;
        m_rows[r] = rows.at(r);
        changed = true;
        Q_EMIT dataChanged(index(r, 0), index(r, ColumnCount - 1));
    }
    return changed;
}

int DriveListModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int DriveListModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant DriveListModel::displayData(const Row& row, int column) const
{
    switch (column) {
    case Address:
        return QString::number(row.drive.address);
    case Axes:
        return row.axisNames;
    case Responding:
        // A silent drive must stand out at a glance: red cell, cross mark, capitals.
        return row.drive.responding ? tr("\u2714 yes") : tr("\u2716 NOT RESPONDING");
    case Firmware:
        return row.drive.firmware;
    case Detail:
        return row.drive.detail;
    default:
        return {};
    }
}

QVariant DriveListModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row& row = m_rows.at(index.row());
    const bool silentCell = index.column() == Responding && !row.drive.responding;
    switch (role) {
    case Qt::DisplayRole:
        return displayData(row, index.column());
    case Qt::BackgroundRole:
        return silentCell ? QVariant(QColor(0xc6, 0x28, 0x28)) : QVariant();
    case Qt::ForegroundRole:
        return silentCell ? QVariant(QColor(Qt::white)) : QVariant();
    case Qt::ToolTipRole:
        return silentCell ? QVariant(tr("The drive stopped answering; check its power, address "
                                        "and the RS485 wiring. The other drives keep working."))
                          : QVariant();
    case AxisRowFilter::FilterTextRole:
        return QStringLiteral("%1 %2").arg(row.drive.address).arg(row.axisNames);
    case AxisRowFilter::MovingRole:
        return row.moving;
    case AxisRowFilter::AxesRole: {
        QVariantList axes;
        for (Axis a : row.drive.axes)
            axes << a.index();
        return axes;
    }
    default:
        return {};
    }
}

QVariant DriveListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Address:
        return tr("Address");
    case Axes:
        return tr("Axes");
    case Responding:
        return tr("Responding");
    case Firmware:
        return tr("Firmware");
    case Detail:
        return tr("State");
    default:
        return {};
    }
}

} // namespace stepdeck::ui
