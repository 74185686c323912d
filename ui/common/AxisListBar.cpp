#include "AxisListBar.h"
#include "common/AxisRowFilter.h"
#include <QCheckBox>
#include <QGridLayout>
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
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setColumnStretch(0, 1);
    arrange(false);
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

void AxisListBar::arrange(bool twoRows)
{
    if (m_grid->count() > 0 && twoRows == m_twoRows)
        return;
    m_twoRows = twoRows;
    for (QWidget* w : {static_cast<QWidget*>(m_edit), static_cast<QWidget*>(m_movingFirst),
                       static_cast<QWidget*>(m_count)})
        m_grid->removeWidget(w);
    if (twoRows) {
        m_grid->addWidget(m_edit, 0, 0, 1, 2);
        m_grid->addWidget(m_movingFirst, 1, 0);
        m_grid->addWidget(m_count, 1, 1);
    } else {
        m_grid->addWidget(m_edit, 0, 0);
        m_grid->addWidget(m_movingFirst, 0, 1);
        m_grid->addWidget(m_count, 0, 2);
    }
}

void AxisListBar::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    // A narrow dock (room for less than ~16 typed characters): the filter field gets the whole
    // width, the rest a row below. Only a resize changes it; what the bar shows never does.
    const int oneRow = 16 * fontMetrics().averageCharWidth() + m_movingFirst->sizeHint().width() +
                       m_count->minimumWidth() + 2 * m_grid->horizontalSpacing();
    arrange(width() < oneRow);
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
