#include "SimulatorMenu.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QCoreApplication>
#include <QPointer>

namespace stepdeck::ui {

SimulatorMenu::SimulatorMenu(MachineContext* context, QWidget* parent)
    : QMenu(tr("Si&mulator"), parent), m_context(context)
{
    setObjectName(QStringLiteral("simulatorMenu"));
    connect(this, &QMenu::aboutToShow, this, &SimulatorMenu::rebuild);
    // Another connection or machine: other simulators (a new session may reuse an address).
    connect(m_context, &MachineContext::modelChanged, this, [this] { m_settable.clear(); });
    connect(m_context, &MachineContext::machineChanged, this, [this] { m_settable.clear(); });
}

// Every controller of the machine that runs on an in-process simulator, with its id.
QList<QPair<QString, ControllerSession*>> SimulatorMenu::simulatedSessions() const
{
    QList<QPair<QString, ControllerSession*>> out;
    if (const machine::Machine* machine = m_context->machine()) {
        for (const machine::MachineController& c : machine->description().controllers) {
            ControllerSession* s = machine->session(c.id);
            if (s && s->isSimulated())
                out.append({c.id, s});
        }
    }
    return out;
}

void SimulatorMenu::rebuild()
{
    clear();
    m_inputs.clear();
    const QList<QPair<QString, ControllerSession*>> sessions = simulatedSessions();
    for (const auto& [id, session] : sessions) {
        if (!m_settable.contains(session)) {
            learn(session);
            continue;
        }
        addInputs(id, session, m_settable.value(session), sessions.size() > 1);
    }
    if (actions().isEmpty()) {
        QAction* none =
            addAction(sessions.isEmpty() ? tr("No built-in simulator is connected")
                                         : tr("The simulated machine has no inputs to set"));
        none->setEnabled(false);
    }
}

// The simulator lives in its controller's thread: it is asked there, the answer comes back
// to this thread.
void SimulatorMenu::learn(ControllerSession* session)
{
    QPointer<SimulatorMenu> self(this);
    session->withSimulator([self, session](Simulator* sim) {
        const QList<int> inputs = sim->settableInputs();
        QMetaObject::invokeMethod(qApp, [self, session, inputs] {
            if (!self)
                return;
            self->m_settable.insert(session, inputs);
            self->rebuild();
        });
    });
}

void SimulatorMenu::addInputs(const QString& controller, ControllerSession* session,
                              const QList<int>& inputs, bool named)
{
    const std::optional<QList<bool>>& levels = session->status().inputs;
    for (int n : inputs) {
        QAction* a = addAction(named ? tr("%1: input %2 high").arg(controller).arg(n)
                                     : tr("Input %1 high").arg(n));
        a->setCheckable(true);
        a->setChecked(levels && n <= levels->size() && levels->at(n - 1));
        a->setToolTip(tr("Checked as the controller last reported the input"));
        connect(a, &QAction::triggered, this, [session, n](bool high) {
            session->withSimulator([n, high](Simulator* sim) { sim->setSettableInput(n, high); });
        });
        m_inputs << a;
    }
}

} // namespace stepdeck::ui
