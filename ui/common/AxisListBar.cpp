#include "AxisListBar.h"
#include "common/AxisRowFilter.h"
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

namespace stepdeck::ui {

AxisListBar::AxisListBar(AxisRowFilter* filter, QWidget* parent)
    : QWidget(parent), m_filter(filter), m_edit(new QLineEdit(this)),
      m_movingFirst(new QCheckBox(tr("Moving first"), this)), m_count(new QLabel(this))
{
    m_edit->setObjectName(QStringLiteral("axisFilter"));
    m_edit->setPlaceholderText(tr("Filter: name or address"));
    m_edit->setClearButtonEnabled(true);
    m_edit->setToolTip(tr("Shows the drives whose name or bus address contains this text."));
    m_movingFirst->setObjectName(QStringLiteral("movingFirst"));
    m_movingFirst->setToolTip(tr("Lists the drives that move now above the others."));
    m_movingFirst->setChecked(filter->movingFirst());
    // "254 of 254" is the widest the count gets: reserved, so a new count re-flows nothing.
    m_count->setMinimumWidth(
        m_count->fontMetrics().horizontalAdvance(tr("%1 of %2").arg(254).arg(254)));
    m_count->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(m_edit, 1);
    h->addWidget(m_movingFirst);
    h->addWidget(m_count);
    connect(m_edit, &QLineEdit::textChanged, filter, &AxisRowFilter::setText);
    connect(m_movingFirst, &QCheckBox::toggled, filter, &AxisRowFilter::setMovingFirst);
    for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
        connect(filter, signal, this, &AxisListBar::updateCount);
    connect(filter, &QAbstractItemModel::modelReset, this, &AxisListBar::updateCount);
    connect(filter, &QAbstractItemModel::layoutChanged, this, &AxisListBar::updateCount);
    if (QAbstractItemModel* source = filter->sourceModel()) {
        // Rows the filter hides change the "of" count without a signal of the proxy.
        for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
            connect(source, signal, this, &AxisListBar::updateCount);
        connect(source, &QAbstractItemModel::modelReset, this, &AxisListBar::updateCount);
    }
    updateCount();
}

QString AxisListBar::countText() const
{
    return m_count->text();
}

void AxisListBar::updateCount()
{
    const int all = m_filter->sourceModel() ? m_filter->sourceModel()->rowCount() : 0;
    m_count->setText(tr("%1 of %2").arg(m_filter->rowCount()).arg(all));
}

} // namespace stepdeck::ui
