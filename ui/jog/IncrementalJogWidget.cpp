#include "IncrementalJogWidget.h"
#include "common/LayoutItems.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QToolButton>

namespace stepdeck::ui {

IncrementalJogWidget::IncrementalJogWidget(MachineContext* context, QWidget* parent)
    : QGroupBox(tr("Incremental jog"), parent), m_context(context), m_size(new QComboBox(this)),
      m_customUnits(new QDoubleSpinBox(this)), m_grid(new QGridLayout)
{
    m_customUnits->setRange(0.001, 100000);
    m_customUnits->setDecimals(3);
    m_customUnits->setValue(0.5);
    m_customUnits->setToolTip(tr("In each axis' unit (mm, deg or steps)"));
    m_customUnits->setVisible(false);
    for (double units : {0.01, 0.1, 1.0, 10.0})
        m_size->addItem(QLocale().toString(units), units);
    m_size->setToolTip(tr("Per click of a +/- button, in each axis' unit (mm, deg or steps)"));
    m_size->addItem(tr("Custom"), -1);
    m_size->setCurrentIndex(2);

    auto* layout = new QVBoxLayout(this);
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(new QLabel(tr("Step:"), this));
    sizeRow->addWidget(m_size, 1);
    sizeRow->addWidget(m_customUnits, 1);
    layout->addLayout(sizeRow);
    layout->addLayout(m_grid);

    connect(m_size, &QComboBox::currentIndexChanged, this,
            [this] { m_customUnits->setVisible(m_size->currentData().toDouble() < 0); });
    connect(context, &MachineContext::machineChanged, this, &IncrementalJogWidget::rebuild);
    rebuild();
}

double IncrementalJogWidget::unitStepSize() const
{
    const double preset = m_size->currentData().toDouble();
    return preset > 0 ? preset : m_customUnits->value();
}

void IncrementalJogWidget::setUnitStepSize(double units)
{
    const int index = m_size->findData(units);
    if (index >= 0) {
        m_size->setCurrentIndex(index);
        return;
    }
    m_size->setCurrentIndex(m_size->count() - 1);
    m_customUnits->setValue(units);
}

QToolButton* IncrementalJogWidget::machineButton(const QString& axis, int sign) const
{
    return m_machineButtons.value(axis + (sign < 0 ? QLatin1Char('-') : QLatin1Char('+')));
}

QToolButton* IncrementalJogWidget::makeButton(const QString& axis, int sign)
{
    auto* b = new QToolButton(this);
    b->setText(sign < 0 ? QStringLiteral("\u2212") : QStringLiteral("+"));
    b->setToolTip(sign < 0 ? tr("Move %1 by minus one step size").arg(axis)
                           : tr("Move %1 by plus one step size").arg(axis));
    b->setMinimumSize(44, 30);
    b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    b->setFocusPolicy(Qt::NoFocus);
    return b;
}

void IncrementalJogWidget::rebuild()
{
    m_machineButtons.clear();
    deleteLayoutItems(m_grid);
    const machine::Machine* machine = m_context->machine();
    if (!machine)
        return;
    int row = 0;
    for (const machine::MachineAxis& a : machine->description().axes) {
        const QString name = a.name;
        auto* label = new QLabel(name, this);
        QFont f = label->font();
        f.setBold(true);
        label->setFont(f);
        m_grid->addWidget(label, row, 0);
        for (int sign : {-1, 1}) {
            QToolButton* b = makeButton(name, sign);
            m_grid->addWidget(b, row, sign < 0 ? 1 : 2);
            m_machineButtons.insert(name + (sign < 0 ? QLatin1Char('-') : QLatin1Char('+')), b);
            connect(b, &QToolButton::clicked, this,
                    [this, name, sign] { jogMachineAxis(name, sign); });
        }
        ++row;
    }
}

void IncrementalJogWidget::jogMachineAxis(const QString& axis, int sign)
{
    machine::Machine* machine = m_context->machine();
    if (!machine)
        return;
    QString refusal;
    if (!machine->move({{axis, sign * unitStepSize()}}, false, &refusal))
        Q_EMIT refused(tr("Incremental jog refused: %1").arg(refusal));
}

} // namespace stepdeck::ui
