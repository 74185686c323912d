#include "UnitsDialog.h"
#include "machine/MachineContext.h"
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>

namespace stepdeck::ui {

UnitsDialog::UnitsDialog(MachineContext* context, QWidget* parent)
    : QDialog(parent), m_context(context)
{
    setWindowTitle(tr("Axis units"));
    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Axis")), 0, 0);
    grid->addWidget(new QLabel(tr("Steps per unit")), 0, 1);
    grid->addWidget(new QLabel(tr("Unit")), 0, 2);
    int row = 1;
    for (Axis axis : context->axes()) {
        const AxisUnits u = context->units(axis);
        auto* steps = new QDoubleSpinBox(this);
        steps->setRange(0, 1e7);
        steps->setDecimals(4);
        steps->setValue(u.stepsPerUnit);
        steps->setSpecialValueText(tr("steps only"));
        auto* unit = new QComboBox(this);
        unit->addItem(tr("mm"), QStringLiteral("mm"));
        unit->addItem(tr("\u00b0 (degree)"), QStringLiteral("\u00b0"));
        unit->addItem(tr("inch"), QStringLiteral("in"));
        unit->setCurrentIndex(qMax(0, unit->findData(u.unit)));
        grid->addWidget(new QLabel(axisName(axis)), row, 0);
        grid->addWidget(steps, row, 1);
        grid->addWidget(unit, row, 2);
        m_steps.insert(axis, steps);
        m_unit.insert(axis, unit);
        ++row;
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(grid);
    layout->addWidget(buttons);
}

void UnitsDialog::accept()
{
    for (auto it = m_steps.cbegin(); it != m_steps.cend(); ++it) {
        AxisUnits u = m_context->units(it.key());
        u.stepsPerUnit = it.value()->value();
        u.unit = m_unit.value(it.key())->currentData().toString();
        m_context->setUnits(it.key(), u);
    }
    QDialog::accept();
}

} // namespace stepdeck::ui
