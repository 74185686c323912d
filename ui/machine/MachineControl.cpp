#include "MachineControl.h"
#include "controller/Controller.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "messages/StatusMessages.h"

namespace stepdeck::ui {

namespace {
const QString kListSeparator = QStringLiteral(", ");
} // namespace

MachineControl::MachineControl(MachineContext* context, StatusMessages* messages, QObject* parent)
    : QObject(parent), m_context(context), m_messages(messages)
{
    QObject::connect(context, &MachineContext::machineControllerFailed, this,
                     [this](const QString&, const QString& message) {
                         m_messages->show(StatusMessages::Owner::Link, message);
                     });
}

bool MachineControl::open(const QString& path)
{
    QString error;
    if (!m_context->openMachine(path, &error)) {
        m_messages->show(StatusMessages::Owner::General, error);
        return false;
    }
    m_messages->show(StatusMessages::Owner::General,
                     tr("Machine \"%1\" opened: %2 controllers, %3 axes.")
                         .arg(m_context->machine()->description().name)
                         .arg(m_context->machine()->description().controllers.size())
                         .arg(m_context->machine()->description().axes.size()),
                     StatusMessages::Severity::Info, 8000);
    return true;
}

void MachineControl::connect()
{
    m_context->connectMachine();
}

void MachineControl::connectedControllers(QStringList* stoppable, QStringList* unstoppable) const
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    for (const machine::MachineController& c : m->description().controllers) {
        const ControllerSession* s = m->session(c.id);
        if (!s || s->linkState() != LinkState::Connected)
            continue;
        (s->capabilities().stopCommand ? stoppable : unstoppable)->append(c.id);
    }
}

QString MachineControl::notStoppedText(const QStringList& unstoppable) const
{
    return tr("%1 cannot be stopped from here: %2")
        .arg(unstoppable.join(kListSeparator), Controller::noStopCommandText());
}

void MachineControl::stop()
{
    QStringList stoppable, unstoppable;
    connectedControllers(&stoppable, &unstoppable);
    m_context->stop(); // every session, connected or not: a connecting link may need it too
    if (stoppable.isEmpty() && unstoppable.isEmpty()) {
        m_messages->show(StatusMessages::Owner::General, tr("Stop: no controller is connected"));
        return;
    }
    // Sent, not confirmed: the position read-out shows each axis' motion as reported.
    QString text = stoppable.isEmpty() ? QString()
                                       : tr("Stop sent to %1.").arg(stoppable.join(kListSeparator));
    if (!unstoppable.isEmpty())
        text = (text.isEmpty() ? QString() : text + QLatin1Char(' ')) + notStoppedText(unstoppable);
    m_messages->show(StatusMessages::Owner::General, text,
                     unstoppable.isEmpty() ? StatusMessages::Severity::Info
                                           : StatusMessages::Severity::Error,
                     15000);
}

void MachineControl::panic()
{
    QStringList stoppable, unstoppable;
    connectedControllers(&stoppable, &unstoppable);
    m_context->panic();
    if (stoppable.isEmpty() && unstoppable.isEmpty()) {
        m_messages->show(StatusMessages::Owner::General, tr("Panic: no controller is connected"));
        return;
    }
    QString text = stoppable.isEmpty() ? QString()
                                       : tr("PANIC STOP sent to %1: positions are lost, reference "
                                            "all axes before moving.")
                                             .arg(stoppable.join(kListSeparator));
    if (!unstoppable.isEmpty())
        text = (text.isEmpty() ? QString() : text + QLatin1Char(' ')) + notStoppedText(unstoppable);
    m_messages->show(StatusMessages::Owner::Safety, text);
}

QString MachineControl::title() const
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return {};
    return QStringLiteral("StepDeck \u2014 ") + m->description().name;
}

} // namespace stepdeck::ui
