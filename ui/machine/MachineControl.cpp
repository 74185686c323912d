#include "MachineControl.h"
#include "controller/Controller.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineStopWatch.h"
#include "messages/StatusMessages.h"
#include <algorithm>

namespace stepdeck::ui {

namespace {
const QString kListSeparator = QStringLiteral(", ");
} // namespace

StatusMessages::Owner MachineControl::ownerOf(Kind kind)
{
    return kind == Kind::Panic ? StatusMessages::Owner::Safety : StatusMessages::Owner::General;
}

MachineControl::MachineControl(MachineContext* context, StatusMessages* messages, QObject* parent)
    : QObject(parent), m_context(context), m_messages(messages), m_watch(new MachineStopWatch(this))
{
    QObject::connect(m_watch, &MachineStopWatch::confirmed, this, &MachineControl::onConfirmed);
    QObject::connect(m_watch, &MachineStopWatch::notConfirmed, this,
                     &MachineControl::onNotConfirmed);
    QObject::connect(m_watch, &MachineStopWatch::confirmedLater, this,
                     &MachineControl::onConfirmedLater);
    // Another machine (or none): its requests are not this one's to confirm.
    QObject::connect(context, &MachineContext::machineChanged, m_watch, &MachineStopWatch::cancel);
    QObject::connect(context, &MachineContext::machineChanged, this,
                     &MachineControl::onMachineChanged);
    onMachineChanged();
    QObject::connect(context, &MachineContext::machineControllerFailed, this,
                     [this](const QString&, const QString& message) {
                         m_messages->show(StatusMessages::Owner::Link, message);
                     });
    // Spindle and coolant off after STOP, PANIC or M2/M30 (issue 47): a failure is a safety
    // error (the spindle may still turn). Success shows on the spindle's indicator; the stop's
    // own line ("stopped") stays.
    QObject::connect(context, &MachineContext::machineSpindleAndCoolantOff, this,
                     [this](bool ok, const QString& message) {
                         if (!ok)
                             m_messages->show(StatusMessages::Owner::Safety, message);
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

void MachineControl::onConfirmed(const QStringList& controllers)
{
    // A "not confirmed" line of an earlier STOP or PANIC is over too (issue 47 item 7), when
    // every controller it was about has confirmed standstill now.
    const bool covered =
        std::all_of(m_notConfirmed.controllers.cbegin(), m_notConfirmed.controllers.cend(),
                    [&](const QString& id) { return controllers.contains(id); });
    if (covered)
        clearNotConfirmed();
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
    // A PANIC's line replaces an older STOP's (and the other way round): one is followed.
    if (notConfirmedShown() && m_notConfirmed.owner != ownerOf(m_kind))
        m_messages->clear(m_notConfirmed.owner);
    m_notConfirmed.kind = m_kind;
    m_notConfirmed.owner = ownerOf(m_kind);
    // Every controller that had not confirmed (the watch reads them again), not only the first.
    m_notConfirmed.controllers = m_watch->rechecking();
    if (!m_notConfirmed.controllers.contains(controllerId))
        m_notConfirmed.controllers << controllerId;
    m_notConfirmed.text =
        m_kind == Kind::Panic
            ? tr("PANIC STOP not confirmed by \"%1\": %2").arg(controllerId, reason)
            : tr("STOP not confirmed by \"%1\": %2").arg(controllerId, reason);
    m_messages->show(m_notConfirmed.owner, m_notConfirmed.text);
}

void MachineControl::onConfirmedLater(const QStringList& controllers)
{
    // Said only while the "not confirmed" line is still up: a line that expired or that another
    // message replaced is not brought back to be corrected.
    if (!notConfirmedShown()) {
        m_notConfirmed = {};
        return;
    }
    const QString stood = controllers.join(kListSeparator);
    if (m_notConfirmed.kind == Kind::Panic)
        m_messages->show(StatusMessages::Owner::Safety,
                         tr("PANIC STOP: %1 confirmed standstill since; positions are lost, "
                            "reference all axes before moving.")
                             .arg(stood));
    else
        m_messages->show(StatusMessages::Owner::General,
                         tr("STOP: %1 confirmed standstill since.").arg(stood),
                         StatusMessages::Severity::Info, 15000);
    m_notConfirmed = {};
}

void MachineControl::onMachineChanged()
{
    // A reference run that ended well ends a "not confirmed" line (it must not outlive the
    // next referencing), provided every controller the line names is connected and its status
    // shows standstill (motionUnconfirmed is cleared only by a device's read): a run of other
    // axes says nothing of a controller that may still move. The line stays followed across a
    // reopened machine: its reference run ends it just as well.
    QObject::disconnect(m_referenceConnection);
    m_referenceConnection = {};
    machine::Machine* m = m_context->machine();
    if (!m)
        return;
    m_referenceConnection = QObject::connect(
        m, &machine::Machine::referenceFinished, this, [this, m](quint64, bool ok, const QString&) {
            if (!ok || m_notConfirmed.text.isEmpty())
                return;
            for (const QString& id : std::as_const(m_notConfirmed.controllers)) {
                const ControllerSession* s = m->session(id);
                if (!s || s->linkState() != LinkState::Connected ||
                    MachineStopWatch::motionIn(s->status()))
                    return;
            }
            clearNotConfirmed();
        });
}

bool MachineControl::notConfirmedShown() const
{
    return !m_notConfirmed.text.isEmpty() &&
           m_messages->text(m_notConfirmed.owner) == m_notConfirmed.text;
}

void MachineControl::clearNotConfirmed()
{
    if (notConfirmedShown())
        m_messages->clear(m_notConfirmed.owner);
    m_notConfirmed = {};
    m_watch->stopRechecking();
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
