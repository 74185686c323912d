#include "MachineControl.h"
#include "controller/Controller.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineStopWatch.h"
#include "messages/StatusMessages.h"

namespace stepdeck::ui {

namespace {
const QString kListSeparator = QStringLiteral(", ");
} // namespace

MachineControl::MachineControl(MachineContext* context, StatusMessages* messages, QObject* parent)
    : QObject(parent), m_context(context), m_messages(messages), m_watch(new MachineStopWatch(this))
{
    QObject::connect(m_watch, &MachineStopWatch::confirmed, this, &MachineControl::onConfirmed);
    QObject::connect(m_watch, &MachineStopWatch::notConfirmed, this,
                     &MachineControl::onNotConfirmed);
    // Another machine (or none): its requests are not this one's to confirm.
    QObject::connect(context, &MachineContext::machineChanged, m_watch, &MachineStopWatch::cancel);
    QObject::connect(context, &MachineContext::machineControllerFailed, this,
                     [this](const QString&, const QString& message) {
                         m_messages->show(StatusMessages::Owner::Link, message);
                     });
    // The machine file's setup, written on every connect: said either way (issue 28, item 1).
    QObject::connect(context, &MachineContext::machineSetupWritten, this,
                     [this](const QString&, bool ok, const QString& message) {
                         m_messages->show(StatusMessages::Owner::Link, message,
                                          ok ? StatusMessages::Severity::Info
                                             : StatusMessages::Severity::Error,
                                          ok ? 8000 : StatusMessages::kLifetimeMs);
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
    // Every session, connected or not: a connecting link may need it too.
    const QMap<QString, RequestId> requests = m_context->stop();
    if (stoppable.isEmpty() && unstoppable.isEmpty()) {
        m_watch->cancel();
        m_messages->show(StatusMessages::Owner::General, tr("Stop: no controller is connected"));
        return;
    }
    // Sent, not confirmed: "stopped" follows once every controller reported standstill.
    QString text = stoppable.isEmpty() ? QString()
                                       : tr("Stop sent to %1: waiting for standstill\u2026")
                                             .arg(stoppable.join(kListSeparator));
    if (!unstoppable.isEmpty())
        text = (text.isEmpty() ? QString() : text + QLatin1Char(' ')) + notStoppedText(unstoppable);
    m_messages->show(StatusMessages::Owner::General, text,
                     unstoppable.isEmpty() ? StatusMessages::Severity::Info
                                           : StatusMessages::Severity::Error,
                     15000);
    follow(Kind::Stop, requests, stoppable, unstoppable);
}

void MachineControl::panic()
{
    QStringList stoppable, unstoppable;
    connectedControllers(&stoppable, &unstoppable);
    const QMap<QString, RequestId> requests = m_context->panic();
    if (stoppable.isEmpty() && unstoppable.isEmpty()) {
        m_watch->cancel();
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
    follow(Kind::Panic, requests, stoppable, unstoppable);
}

void MachineControl::follow(Kind kind, const QMap<QString, RequestId>& requests,
                            const QStringList& stoppable, const QStringList& unstoppable)
{
    m_kind = kind;
    m_stoppable = stoppable;
    m_unstoppable = unstoppable;
    QMap<QString, RequestId> watched; // controllers without a stop command confirm nothing
    for (const QString& id : stoppable)
        watched.insert(id, requests.value(id));
    if (watched.isEmpty())
        m_watch->cancel();
    else
        m_watch->watch(m_context->machine(), watched);
}

void MachineControl::onConfirmed()
{
    const QString stopped = m_stoppable.join(kListSeparator);
    if (m_kind == Kind::Panic) {
        QString text = tr("PANIC STOP: %1 confirmed standstill; positions are lost, reference all "
                          "axes before moving.")
                           .arg(stopped);
        if (!m_unstoppable.isEmpty())
            text += QLatin1Char(' ') + notStoppedText(m_unstoppable);
        m_messages->show(StatusMessages::Owner::Safety, text);
        return;
    }
    if (m_unstoppable.isEmpty()) {
        m_messages->show(StatusMessages::Owner::General,
                         tr("Stopped: every controller confirmed standstill (%1).").arg(stopped),
                         StatusMessages::Severity::Info, 15000);
        return;
    }
    m_messages->show(StatusMessages::Owner::General,
                     tr("Stopped: %1 confirmed standstill.").arg(stopped) + QLatin1Char(' ') +
                         notStoppedText(m_unstoppable));
}

void MachineControl::onNotConfirmed(const QString& controllerId, const QString& reason)
{
    m_messages->show(m_kind == Kind::Panic ? StatusMessages::Owner::Safety
                                           : StatusMessages::Owner::General,
                     m_kind == Kind::Panic
                         ? tr("PANIC STOP not confirmed by \"%1\": %2").arg(controllerId, reason)
                         : tr("STOP not confirmed by \"%1\": %2").arg(controllerId, reason));
}

bool MachineControl::isFollowingStop() const
{
    return m_watch->isWatching();
}

QString MachineControl::title() const
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return {};
    return QStringLiteral("StepDeck \u2014 ") + m->description().name;
}

} // namespace stepdeck::ui
