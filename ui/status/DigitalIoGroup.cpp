#include "DigitalIoGroup.h"
#include "common/LedIndicator.h"
#include "main/MachineContext.h"
#include "model/ModelOperations.h"
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>

namespace stepdeck::ui {

DigitalIoGroup::DigitalIoGroup(MachineContext* context, int inputs, int outputs, QWidget* parent)
    : QGroupBox(tr("Inputs and outputs"), parent), m_context(context)
{
    setObjectName(QStringLiteral("digitalIo"));
    auto* grid = new QGridLayout(this);
    grid->addWidget(new QLabel(tr("Inputs:"), this), 0, 0);
    for (int i = 0; i < inputs; ++i) {
        auto* lamp = new LedIndicator(QString::number(i + 1), this);
        lamp->setToolTip(tr("Input %1: level as last read (lit: high)").arg(i + 1));
        m_inputs << lamp;
        grid->addWidget(lamp, 0, 1 + i);
    }
    grid->addWidget(new QLabel(tr("Outputs:"), this), 1, 0);
    for (int i = 0; i < outputs; ++i) {
        auto* button = new QPushButton(this);
        button->setCheckable(true);
        button->setFocusPolicy(Qt::NoFocus);
        button->setMinimumWidth(36);
        connect(button, &QPushButton::clicked, this, [this, i] { toggle(i + 1); });
        m_outputs << button;
        m_known << std::nullopt;
        grid->addWidget(button, 1, 1 + i);
    }
    grid->setColumnStretch(qMax(inputs, outputs) + 1, 1);
    setStatus(MachineStatus{}, false);
}

void DigitalIoGroup::setStatus(const MachineStatus& status, bool live)
{
    for (int i = 0; i < m_inputs.size(); ++i) {
        const bool known = live && status.inputs && i < status.inputs->size();
        m_inputs[i]->setState(!known                 ? LedIndicator::State::Unknown
                              : status.inputs->at(i) ? LedIndicator::State::On
                                                     : LedIndicator::State::Off);
    }
    for (int i = 0; i < m_outputs.size(); ++i) {
        m_known[i] = i < status.outputs.size() ? status.outputs.at(i) : std::nullopt;
        QPushButton* b = m_outputs[i];
        const QSignalBlocker block(b);
        b->setEnabled(live);
        b->setChecked(m_known[i].value_or(false));
        b->setText(m_known[i]
                       ? QStringLiteral("%1 %2").arg(i + 1).arg(*m_known[i] ? tr("on") : tr("off"))
                       : QStringLiteral("%1 ?").arg(i + 1));
        b->setToolTip(m_known[i] ? (*m_known[i] ? tr("Output %1: on; click to switch it off")
                                                : tr("Output %1: off; click to switch it on"))
                                       .arg(i + 1)
                                 : tr("Output %1: state unknown (not switched in this session; "
                                      "the controller cannot report it); click to switch it on")
                                       .arg(i + 1));
    }
}

void DigitalIoGroup::toggle(int number)
{
    const bool on = !m_known.value(number - 1).value_or(false);
    m_context->session()->modelOperation(
        operation::kSetOutput, {{QStringLiteral("output"), number}, {QStringLiteral("on"), on}});
    // The switch shows the confirmed state: undo the click until the status says otherwise.
    setStatus(m_context->status(), m_context->isConnected());
}

} // namespace stepdeck::ui
