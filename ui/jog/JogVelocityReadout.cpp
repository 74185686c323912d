#include "JogVelocityReadout.h"
#include "common/LayoutItems.h"
#include "jog/JogAxisMap.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
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
        for (const machine::MachineAxis& a : machine->description().axes)
            addRow(a.name, rateUnitName(a));
    } else {
        // The model's position unit (laser axes: "units/s", issue 16).
        for (Axis axis : m_context->axes())
            addRow(axisName(axis), tr("%1/s").arg(m_context->machineUnitName()));
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
        return;
    }
    const MachineStatus& status = m_context->status();
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        if (const std::optional<Axis> axis = axisFromName(it.key())) {
            const double v = status.axes.value(*axis).commandedVelocity;
            it.value().value->setText(QString::asprintf("%+.0f", v));
        }
    }
}

} // namespace stepdeck::ui
