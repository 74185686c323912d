#include "DigitalIoGroup.h"
#include "common/LedIndicator.h"
#include "machine/MachineContext.h"
#include "model/ModelOperations.h"
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolButton>

namespace stepdeck::ui {

DigitalIoGroup::DigitalIoGroup(MachineContext* context, int inputs, int outputs, QWidget* parent)
    : QGroupBox(tr("Inputs and outputs"), parent), m_context(context)
{
    setObjectName(QStringLiteral("digitalIo"));
    // Four per row under their heading: eight inputs in one row were cut off by a dock at
    // 1366x768 (issue 16). An output's switch is as wide as its widest text ("7 off"), so a
    // new state never moves its neighbours.
    constexpr int kPerRow = 4;
    auto* grid = new QGridLayout(this);
    grid->addWidget(new QLabel(tr("Inputs:"), this), 0, 0, 1, kPerRow);
    const int inputRows = (inputs + kPerRow - 1) / kPerRow;
    for (int i = 0; i < inputs; ++i) {
        auto* lamp = new LedIndicator(QString::number(i + 1), this);
        lamp->setToolTip(tr("Input %1: level as last read (lit: high)").arg(i + 1));
        m_inputs << lamp;
        grid->addWidget(lamp, 1 + i / kPerRow, i % kPerRow);
    }
    const int outputsRow = 1 + inputRows;
    grid->addWidget(new QLabel(tr("Outputs:"), this), outputsRow, 0, 1, kPerRow);
    for (int i = 0; i < outputs; ++i) {
        auto* button = new QToolButton(this);
        button->setCheckable(true);
        button->setFocusPolicy(Qt::NoFocus);
        button->ensurePolished();
        int width = 0;
        for (const QString& text :
             {outputText(i + 1, true), outputText(i + 1, false), outputText(i + 1, std::nullopt)}) {
            button->setText(text);
            width = qMax(width, button->sizeHint().width());
        }
        button->setFixedWidth(width);
        connect(button, &QToolButton::clicked, this, [this, i] { toggle(i + 1); });
        m_outputs << button;
        m_known << std::nullopt;
        grid->addWidget(button, outputsRow + 1 + i / kPerRow, i % kPerRow);
    }
    grid->setColumnStretch(kPerRow, 1);
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
        QToolButton* b = m_outputs[i];
        const QSignalBlocker block(b);
        b->setEnabled(live);
        b->setChecked(m_known[i].value_or(false));
        b->setText(outputText(i + 1, m_known[i]));
        b->setToolTip(m_known[i] ? (*m_known[i] ? tr("Output %1: on; click to switch it off")
                                                : tr("Output %1: off; click to switch it on"))
                                       .arg(i + 1)
                                 : tr("Output %1: state unknown (not switched in this session; "
                                      "the controller cannot report it); click to switch it on")
                                       .arg(i + 1));
    }
}

QString DigitalIoGroup::outputText(int number, std::optional<bool> on)
{
    return on ? QStringLiteral("%1 %2").arg(number).arg(*on ? tr("on") : tr("off"))
              : QStringLiteral("%1 ?").arg(number);
}

void DigitalIoGroup::toggle(int number)
{
    const bool on = !m_known.value(number - 1).value_or(false);
    m_context->session()->modelOperation(
        operation::kSetOutput, {{operation::arg::kOutput, number}, {operation::arg::kOn, on}});
    // The switch shows the confirmed state: undo the click until the status says otherwise.
    setStatus(m_context->status(), m_context->isConnected());
}

} // namespace stepdeck::ui
