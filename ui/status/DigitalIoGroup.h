#pragma once
#include "model/MachineStatus.h"
#include <QGroupBox>

class QToolButton;

namespace stepdeck::ui {

class LedIndicator;
class MachineContext;

// The controller's own digital inputs and outputs (Capabilities::digitalInputs / Outputs):
// one lamp per input level, one switch per output. An output shows what the host last
// switched in this session ("?" until then: such controllers cannot report their outputs);
// clicking sends operation::kSetOutput and the switch follows the confirmed status.
class DigitalIoGroup : public QGroupBox
{
    Q_OBJECT
public:
    DigitalIoGroup(MachineContext* context, int inputs, int outputs, QWidget* parent = nullptr);

    void setStatus(const MachineStatus& status, bool live);
    LedIndicator* inputLamp(int number) const { return m_inputs.value(number - 1); }
    QToolButton* outputSwitch(int number) const { return m_outputs.value(number - 1); }

private:
    void toggle(int number);
    static QString outputText(int number, std::optional<bool> on);

    MachineContext* m_context;
    QList<LedIndicator*> m_inputs;
    QList<QToolButton*> m_outputs;
    QList<std::optional<bool>> m_known;
};

} // namespace stepdeck::ui
