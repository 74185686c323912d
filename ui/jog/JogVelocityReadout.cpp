#include "JogVelocityReadout.h"
#include "common/LayoutItems.h"
#include "jog/JogAxisMap.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QCoreApplication>
#include <QGridLayout>
#include <QLabel>

namespace stepdeck::ui {

JogVelocityReadout::JogVelocityReadout(MachineContext* context, QWidget* parent)
    : QGroupBox(tr("Commanded jog velocity"), parent), m_context(context), m_grid(new QGridLayout)
{
    setLayout(m_grid);
    connect(context, &MachineContext::modelChanged, this, &JogVelocityReadout::rebuild);
    connect(context, &MachineContext::machineChanged, this, &JogVelocityReadout::rebuild);
    connect(context->session(), &ControllerSession::statusChanged, this,
            &JogVelocityReadout::refresh);
    connect(context, &MachineContext::machineStatusChanged, this, &JogVelocityReadout::refresh);
    rebuild();
}

QString JogVelocityReadout::valueText(const QString& axis) const
{
    const Row row = m_rows.value(axis);
    return row.value ? row.value->text() : QString();
}

QString JogVelocityReadout::unitText(const QString& axis) const
{
    const Row row = m_rows.value(axis);
    return row.unit ? row.unit->text() : QString();
}

void JogVelocityReadout::rebuild()
{
    deleteLayoutItems(m_grid);
    m_rows.clear();
    if (const machine::Machine* machine = m_context->machine()) {
        for (const machine::MachineAxis& a : machine->description().axes) {
            // An axis in the controller's count says what that counts (laser axes:
            // "units/s", issue 16).
            const QString count = QCoreApplication::translate(
                "Units", machine->session(a.controller)->capabilities().positionUnit);
            addRow(a.name,
                   a.unit == machine::AxisUnit::Step ? tr("%1/s").arg(count) : rateUnitName(a));
        }
    }
    refresh();
}

void JogVelocityReadout::addRow(const QString& axis, const QString& unit)
{
    const int row = m_grid->rowCount();
    auto* name = new QLabel(axis, this);
    QFont bold = name->font();
    bold.setBold(true);
    name->setFont(bold);
    auto* value = new QLabel(QStringLiteral("0"), this);
    value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    mono.setPointSizeF(bold.pointSizeF() * 1.3);
    value->setFont(mono);
    value->setMinimumWidth(90);
    auto* unitLabel = new QLabel(unit, this);
    m_grid->addWidget(name, row, 0);
    m_grid->addWidget(value, row, 1);
    m_grid->addWidget(unitLabel, row, 2);
    m_rows.insert(axis, {value, unitLabel});
}

void JogVelocityReadout::refresh()
{
    if (const machine::Machine* machine = m_context->machine()) {
        for (const machine::MachineAxis& a : machine->description().axes) {
            const Row row = m_rows.value(a.name);
            if (!row.value)
                continue;
            const double v = commandedUnitsPerSecond(m_context, a);
            // Steps are whole; mm and degrees to a hundredth.
            row.value->setText(a.unit == machine::AxisUnit::Step ? QString::asprintf("%+.0f", v)
                                                                 : QString::asprintf("%+.2f", v));
        }
    }
}

} // namespace stepdeck::ui
