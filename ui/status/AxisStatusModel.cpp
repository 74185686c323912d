#include "AxisStatusModel.h"
#include "common/AxisRowFilter.h"
#include <QColor>

namespace stepdeck::ui {

namespace {
using State = LedIndicator::State;

const char* const kHeaders[] = {
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Axis"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Moving"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Jog"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Limit"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Ref. switch"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Referenced"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Position"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Drive"),
};
const char* const kLampTips[] = {
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel",
                      "Positioning, feed, reference or velocity move"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "Jogging at a non-zero rate"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "A limit switch of this axis is active"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel", "The reference switch is active"),
    QT_TRANSLATE_NOOP("stepdeck::ui::AxisStatusModel",
                      "Referenced since the last panic, reset or reconnect"),
};
} // namespace

bool AxisStatusModel::Shown::operator==(const Shown& o) const
{
    const AxisStatus& a = axis;
    const AxisStatus& b = o.axis;
    return live == o.live && responding == o.responding && address == o.address &&
           a.moving == b.moving && a.jogging == b.jogging && a.limitSwitch == b.limitSwitch &&
           a.referenceSwitch == b.referenceSwitch && a.referenced == b.referenced &&
           a.positionKnown == b.positionKnown && a.positionEstimated == b.positionEstimated &&
           a.position == b.position && a.motionUnknown == b.motionUnknown;
}

AxisStatusModel::AxisStatusModel(QObject* parent) : QAbstractTableModel(parent) {}

void AxisStatusModel::setRows(const QList<Row>& rows)
{
    beginResetModel();
    m_rows = rows;
    m_shown = QList<Shown>(rows.size());
    endResetModel();
}

void AxisStatusModel::setStatus(const MachineStatus& status, bool live)
{
    QMap<Axis, const DriveStatus*> drives;
    for (const DriveStatus& d : status.drives) {
        for (Axis a : d.axes)
            drives.insert(a, &d);
    }
    for (int r = 0; r < m_rows.size(); ++r) {
        const Axis axis = m_rows.at(r).axis;
        const DriveStatus* drive = drives.value(axis);
        const Shown now{status.axes.value(axis), !drive || drive->responding, live,
                        drive && status.drives.size() > 1 ? drive->address : 0};
        if (now == m_shown.at(r))
            continue;
        m_shown[r] = now;
        Q_EMIT dataChanged(index(r, 0), index(r, ColumnCount - 1));
    }
}

int AxisStatusModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int AxisStatusModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

LedIndicator::State AxisStatusModel::lampState(int row, int column) const
{
    const Shown& s = m_shown.at(row);
    // A drive that stopped answering may still be moving: never shown as idle.
    if (!s.live || (s.axis.motionUnknown && (column == Moving || column == Jogging)))
        return State::Unknown;
    switch (column) {
    case Moving:
        return s.axis.moving ? State::On : State::Off;
    case Jogging:
        return s.axis.jogging ? State::On : State::Off;
    case Limit:
        return s.axis.limitSwitch ? State::Fault : State::Off;
    case RefSwitch:
        return s.axis.referenceSwitch ? State::Warning : State::Off;
    case Referenced:
        return s.axis.referenced ? State::On : State::Off;
    default:
        return State::Unknown;
    }
}

QVariant AxisStatusModel::displayData(int row, int column) const
{
    const Row& r = m_rows.at(row);
    const Shown& s = m_shown.at(row);
    switch (column) {
    case Name:
        return r.name;
    case Position:
        if (!s.live)
            return QStringLiteral("\u2013");
        // How the count is known: "~" estimated from rates, "?" not referenced.
        return QStringLiteral("%1%2%3")
            .arg(s.axis.positionEstimated ? QStringLiteral("~") : QString())
            .arg(s.axis.position)
            .arg(s.axis.positionKnown ? QString() : QStringLiteral(" ?"));
    case Drive:
        if (s.address == 0)
            return {};
        return s.responding || !s.live ? QString::number(s.address)
                                       : tr("%1 \u2716 silent").arg(s.address);
    default:
        return {};
    }
}

QVariant AxisStatusModel::toolTipData(int row, int column) const
{
    const Shown& s = m_shown.at(row);
    if (column == Position) {
        if (s.axis.positionEstimated)
            return tr("Estimated from the commanded rates, not read back.");
        if (!s.axis.positionKnown)
            return tr("Not referenced: the count is not tied to the machine's zero.");
        return tr("Referenced: the count is tied to the machine's zero.");
    }
    if (column == Drive && !s.responding)
        return tr("The drive stopped answering; check its power, address and the RS485 "
                  "wiring. The other drives keep working.");
    if (column >= Moving && column <= Referenced)
        return QStringLiteral("%1: %2").arg(m_rows.at(row).name, tr(kLampTips[column - Moving]));
    return {};
}

QVariant AxisStatusModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const int row = index.row();
    const int column = index.column();
    const bool lamp = column >= Moving && column <= Referenced;
    switch (role) {
    case Qt::DisplayRole:
        return displayData(row, column);
    case Qt::DecorationRole:
        return lamp ? QVariant(LedIndicator::colorFor(lampState(row, column))) : QVariant();
    case StateRole:
        return lamp ? QVariant(int(lampState(row, column))) : QVariant();
    case Qt::ToolTipRole:
        return toolTipData(row, column);
    case Qt::BackgroundRole:
        if (column == Drive && m_shown.at(row).live && !m_shown.at(row).responding)
            return QColor(0xc6, 0x28, 0x28);
        return {};
    case Qt::ForegroundRole:
        if (column == Drive && m_shown.at(row).live && !m_shown.at(row).responding)
            return QColor(Qt::white);
        return {};
    case AxisRowFilter::FilterTextRole: {
        const int address = m_shown.at(row).address;
        return address ? QStringLiteral("%1 %2").arg(m_rows.at(row).name).arg(address)
                       : m_rows.at(row).name;
    }
    case AxisRowFilter::MovingRole:
        return m_shown.at(row).axis.moving || m_shown.at(row).axis.jogging;
    case AxisRowFilter::AxesRole:
        return QVariantList{m_rows.at(row).axis.index()};
    default:
        return {};
    }
}

QVariant AxisStatusModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || section < 0 || section >= ColumnCount)
        return {};
    if (role == Qt::DisplayRole)
        return tr(kHeaders[section]);
    return {};
}

} // namespace stepdeck::ui
