#include "AxisRowFilter.h"

namespace stepdeck::ui {

AxisRowFilter::AxisRowFilter(QObject* parent) : QSortFilterProxyModel(parent)
{
    // Rows follow the status as it changes: a drive that starts moving moves up when the
    // operator asked for moving ones first, and a filtered-out drive stays out.
    setDynamicSortFilter(true);
    sort(0, Qt::AscendingOrder);
}

void AxisRowFilter::setText(const QString& text)
{
    const QString trimmed = text.trimmed();
    if (trimmed == m_text)
        return;
    m_text = trimmed;
    invalidateFilter();
}

void AxisRowFilter::setMovingFirst(bool on)
{
    if (on == m_movingFirst)
        return;
    m_movingFirst = on;
    invalidate();
}

bool AxisRowFilter::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const
{
    if (m_text.isEmpty())
        return true;
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    return index.data(FilterTextRole).toString().contains(m_text, Qt::CaseInsensitive);
}

bool AxisRowFilter::lessThan(const QModelIndex& left, const QModelIndex& right) const
{
    if (m_movingFirst) {
        const bool l = left.siblingAtColumn(0).data(MovingRole).toBool();
        const bool r = right.siblingAtColumn(0).data(MovingRole).toBool();
        if (l != r)
            return l;
    }
    return left.row() < right.row(); // the controller's order
}

} // namespace stepdeck::ui
