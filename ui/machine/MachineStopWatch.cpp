#include "MachineStopWatch.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"

namespace stepdeck::ui {

bool MachineStopWatch::motionIn(const MachineStatus& status)
{
    if (status.busy || status.motionUnconfirmed)
        return true;
    for (const AxisStatus& a : status.axes) {
        if (a.moving || a.jogging || a.motionUnknown || a.commandedVelocity != 0.0)
            return true;
    }
    return false;
}

MachineStatus MachineStopWatch::statusOf(const CommandResult& result,
                                         const ControllerSession* session)
{
    if (result.value.canConvert<MachineStatus>())
        return result.value.value<MachineStatus>();
    return session ? session->status() : MachineStatus{};
}

MachineStopWatch::MachineStopWatch(QObject* parent) : QObject(parent)
{
    m_deadline.setSingleShot(true);
    m_deadline.setInterval(kConfirmMs);
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it) {
            if (it->stopped)
                continue;
            const QString seconds = QString::number(kConfirmMs / 1000);
            fail(it.key(), it->stopFailed ? it->stopError
                           : it->answered ? tr("no standstill reported within %1 s").arg(seconds)
                                          : tr("no answer to the stop within %1 s").arg(seconds));
            return;
        }
    });
    m_recheckTick.setInterval(kRecheckIntervalMs);
    connect(&m_recheckTick, &QTimer::timeout, this, &MachineStopWatch::recheckNow);
    m_recheckEnd.setSingleShot(true);
    m_recheckEnd.setInterval(kRecheckMs);
    connect(&m_recheckEnd, &QTimer::timeout, this, &MachineStopWatch::stopRechecking);
}

void MachineStopWatch::watch(const machine::Machine* machine,
                             const QMap<QString, RequestId>& requests)
{
    cancel();
    for (auto it = requests.cbegin(); it != requests.cend(); ++it) {
        ControllerSession* session = machine ? machine->session(it.key()) : nullptr;
        if (!session || it.value() == 0)
            continue;
        const QString id = it.key();
        Watched watched;
        watched.session = session;
        watched.stop = it.value();
        m_watched.insert(id, watched);
        m_connections << connect(session, &ControllerSession::requestFinished, this,
                                 [this, id](const CommandResult& r) { onResult(id, r); });
        m_connections << connect(session, &ControllerSession::statusChanged, this,
                                 [this, id] { onStatus(id); });
        m_connections << connect(session, &ControllerSession::linkStateChanged, this,
                                 [this, id](LinkState state, const QString& reason) {
                                     if (state != LinkState::Connected)
                                         fail(id,
                                              reason.isEmpty() ? tr("its link was lost") : reason);
                                 });
    }
    if (!m_watched.isEmpty())
        m_deadline.start();
}

void MachineStopWatch::cancel()
{
    for (const QMetaObject::Connection& c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_watched.clear();
    m_deadline.stop();
    stopRechecking();
}

void MachineStopWatch::onResult(const QString& id, const CommandResult& result)
{
    auto it = m_watched.find(id);
    if (it == m_watched.end() || result.id == 0 || it->stopped)
        return;
    if (result.id == it->stop) {
        it->answered = true;
        // Issue 47 item 7: the request's own end is not the verdict. Cancelled means a newer
        // stop (a program's abort, a failed move part, a second STOP) or a status read overtook
        // it -- the device may well stand; any other failure still gets one read, so that a
        // device that reports standstill is never said to have failed.
        if (!result.ok() && result.error != ErrorKind::Cancelled) {
            it->stopFailed = true;
            it->stopError =
                result.message.isEmpty() ? tr("the stop request failed") : result.message;
        }
        // A status read from before the request's end may predate the stop: read afresh.
        ControllerSession* session = it->session;
        const RequestId read = session->refreshStatus();
        it = m_watched.find(id);
        if (it != m_watched.end() && !it->stopped)
            it->read = read;
        return;
    }
    if (result.id != it->read)
        return;
    it->read = 0;
    if (!result.ok() || motionIn(statusOf(result, it->session))) {
        // A refused or unanswered stop whose read does not show standstill has failed; a read
        // cancelled in turn (by a newer stop) is no verdict.
        if (it->stopFailed && result.error != ErrorKind::Cancelled)
            fail(id, it->stopError);
        return; // otherwise read again with the controller's next status (onStatus)
    }
    it->stopped = true;
    for (const Watched& w : std::as_const(m_watched)) {
        if (!w.stopped)
            return;
    }
    const QStringList controllers = m_watched.keys();
    cancel();
    Q_EMIT confirmed(controllers);
}

void MachineStopWatch::onStatus(const QString& id)
{
    auto it = m_watched.find(id);
    if (it == m_watched.end() || !it->answered || it->stopped || it->read != 0)
        return;
    ControllerSession* session = it->session;
    const RequestId read = session->refreshStatus();
    it = m_watched.find(id);
    if (it != m_watched.end() && !it->stopped)
        it->read = read;
}

void MachineStopWatch::fail(QString id, QString reason)
{
    if (!m_watched.contains(id))
        return;
    // Every controller that has not confirmed yet is read again after the failure.
    QMap<QString, ControllerSession*> unconfirmed;
    for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it) {
        if (!it->stopped && it->session)
            unconfirmed.insert(it.key(), it->session);
    }
    cancel();
    startRecheck(unconfirmed);
    Q_EMIT notConfirmed(id, reason);
}

void MachineStopWatch::startRecheck(const QMap<QString, ControllerSession*>& sessions)
{
    for (auto it = sessions.cbegin(); it != sessions.cend(); ++it) {
        const QString id = it.key();
        m_recheck.insert(id, Recheck{it.value()});
        m_recheckConnections << connect(
            it.value(), &ControllerSession::requestFinished, this,
            [this, id](const CommandResult& r) { onRecheckResult(id, r); });
    }
    if (m_recheck.isEmpty())
        return;
    m_recheckTick.start();
    m_recheckEnd.start();
}

void MachineStopWatch::recheckNow()
{
    // At most one read per controller under way: a slow link is not flooded.
    const QStringList ids = m_recheck.keys();
    for (const QString& id : ids) {
        auto it = m_recheck.find(id);
        if (it == m_recheck.end() || it->stopped || it->read != 0 || !it->session ||
            !it->session->isCreated() || it->session->linkState() != LinkState::Connected)
            continue;
        ControllerSession* session = it->session;
        const RequestId read = session->refreshStatus();
        it = m_recheck.find(id);
        if (it != m_recheck.end())
            it->read = read;
    }
}

void MachineStopWatch::onRecheckResult(const QString& id, const CommandResult& result)
{
    auto it = m_recheck.find(id);
    if (it == m_recheck.end() || result.id == 0 || result.id != it->read)
        return;
    it->read = 0;
    if (!it->session || !result.ok() || motionIn(statusOf(result, it->session)))
        return; // no claim: the next tick reads again
    it->stopped = true;
    for (const Recheck& r : std::as_const(m_recheck)) {
        if (!r.stopped)
            return;
    }
    const QStringList controllers = m_recheck.keys();
    stopRechecking();
    Q_EMIT confirmedLater(controllers);
}

void MachineStopWatch::stopRechecking()
{
    for (const QMetaObject::Connection& c : std::as_const(m_recheckConnections))
        disconnect(c);
    m_recheckConnections.clear();
    m_recheck.clear();
    m_recheckTick.stop();
    m_recheckEnd.stop();
}

} // namespace stepdeck::ui
