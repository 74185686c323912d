#include "IncrementalJogWidget.h"
#include "machine/MachineContext.h"
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QSpinBox>
#include <QToolButton>

namespace stepdeck::ui {

IncrementalJogWidget::IncrementalJogWidget(MachineContext* context, QWidget* parent)
    : QGroupBox(tr("Incremental jog"), parent), m_context(context), m_size(new QComboBox(this)),
      m_custom(new QSpinBox(this)), m_grid(new QGridLayout)
{
    for (int steps : {1, 10, 100, 1000})
        m_size->addItem(tr("%n step(s)", nullptr, steps), steps);
    m_size->addItem(tr("Custom"), -1);
    m_size->setCurrentIndex(2);
    m_custom->setRange(1, 10000000);
    m_custom->setValue(500);
    m_custom->setSuffix(tr(" steps"));
    m_custom->setVisible(false);
    m_size->setToolTip(tr("Steps per click of a +/- button"));

    auto* layout = new QVBoxLayout(this);
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(new QLabel(tr("Step:"), this));
    sizeRow->addWidget(m_size, 1);
    sizeRow->addWidget(m_custom, 1);
    layout->addLayout(sizeRow);
    layout->addLayout(m_grid);

    connect(m_size, &QComboBox::currentIndexChanged, this,
            [this] { m_custom->setVisible(m_size->currentData().toInt() < 0); });
    connect(context, &MachineContext::modelChanged, this, &IncrementalJogWidget::rebuild);
    rebuild();
}

qint64 IncrementalJogWidget::stepSize() const
{
    const int preset = m_size->currentData().toInt();
    return preset > 0 ? preset : m_custom->value();
}

void IncrementalJogWidget::setStepSize(qint64 steps)
{
    const int index = m_size->findData(int(steps));
    if (index >= 0) {
        m_size->setCurrentIndex(index);
    } else {
        m_size->setCurrentIndex(m_size->count() - 1);
        m_custom->setValue(int(steps));
    }
}

QToolButton* IncrementalJogWidget::button(Axis axis, int sign) const
{
    return sign < 0 ? m_minus.value(axis) : m_plus.value(axis);
}

void IncrementalJogWidget::rebuild()
{
    m_minus.clear();
    m_plus.clear();
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    int row = 0;
    for (Axis axis : m_context->axes()) {
        auto* label = new QLabel(axisName(axis), this);
        QFont f = label->font();
        f.setBold(true);
        label->setFont(f);
        auto make = [this, axis](int sign) {
            auto* b = new QToolButton(this);
            b->setText(sign < 0 ? QStringLiteral("\u2212") : QStringLiteral("+"));
            b->setToolTip(sign < 0 ? tr("Move %1 by minus one step size").arg(axisName(axis))
                                   : tr("Move %1 by plus one step size").arg(axisName(axis)));
            b->setMinimumSize(44, 30);
            b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
            b->setFocusPolicy(Qt::NoFocus);
            connect(b, &QToolButton::clicked, this, [this, axis, sign] { jog(axis, sign); });
            return b;
        };
        m_minus.insert(axis, make(-1));
        m_plus.insert(axis, make(+1));
        m_grid->addWidget(label, row, 0);
        m_grid->addWidget(m_minus.value(axis), row, 1);
        m_grid->addWidget(m_plus.value(axis), row, 2);
        ++row;
    }
}

void IncrementalJogWidget::jog(Axis axis, int sign)
{
    m_context->session()->moveRelative(AxisVector{{axis, sign * stepSize()}});
}

} // namespace stepdeck::ui
