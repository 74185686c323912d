#include "PositionPanel.h"
#include "machine/MachineContext.h"
#include "machine/MachineDro.h"
#include "machine/MachineGoTo.h"
#include "machine/SpindleCoolantBar.h"
#include <QHBoxLayout>
#include <QToolButton>

namespace stepdeck::ui {

PositionPanel::PositionPanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_machineDro(new MachineDro(context, context->workOffsets(), this)),
      m_machineGoTo(new MachineGoTo(context, context->workOffsets(), this)),
      m_spindleCoolant(new SpindleCoolantBar(context, this))
{
    auto* outer = new QVBoxLayout(this);
    outer->addWidget(m_machineDro);
    outer->addWidget(m_machineGoTo);
    auto* buttons = new QHBoxLayout;
    auto* edit = new QToolButton(this);
    edit->setObjectName(QStringLiteral("editMachineAxes"));
    edit->setText(tr("Units and limits\u2026"));
    edit->setToolTip(tr("Steps per unit, soft limits and referencing of each axis: the "
                        "machine editor (a controller of the connection bar is saved as a "
                        "machine file of its own)"));
    edit->setFocusPolicy(Qt::NoFocus);
    buttons->addWidget(edit);
    buttons->addStretch(1);
    outer->addLayout(buttons);
    outer->addWidget(m_spindleCoolant);
    outer->addStretch(1);
    connect(edit, &QToolButton::clicked, this, &PositionPanel::editMachineRequested);
}

} // namespace stepdeck::ui
