#pragma once
#include <QHash>
#include <QMenu>

namespace stepdeck {
class ControllerSession;
}

namespace stepdeck::ui {

class MachineContext;

// The window's Simulator menu (issue 28): what the simulated machine itself does that no
// command of the protocol sets, for the in-process simulators (port "sim"). Today the inputs
// the machine drives (an EMIS part sensor on inputs 5..8, Simulator::settableInputs), one
// checkable action each. An action is checked as the controller last reported the input
// (MachineStatus::inputs), never as the menu last set it; it sets the simulated level, which
// the next status read brings back.
class SimulatorMenu : public QMenu
{
    Q_OBJECT
public:
    SimulatorMenu(MachineContext* context, QWidget* parent = nullptr);

    // The input actions shown now ("Input 5", with a machine "io1: input 5"): for tests.
    QList<QAction*> inputActions() const { return m_inputs; }
    // Builds the actions for what is known now and asks the simulators for what is not yet
    // (their answer rebuilds the menu); runs whenever the menu is about to show.
    void rebuild();

private:
    QList<QPair<QString, ControllerSession*>> simulatedSessions() const;
    void learn(ControllerSession* session);
    void addInputs(const QString& controller, ControllerSession* session, const QList<int>& inputs,
                   bool named);

    MachineContext* m_context;
    QHash<const ControllerSession*, QList<int>> m_settable; // as each simulator said
    QList<QAction*> m_inputs;
};

} // namespace stepdeck::ui
