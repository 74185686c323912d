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

MachineStopWatch::MachineStopWatch(QObject* parent) : QObject(parent)
{
    m_deadline.setSingleShot(true);
    m_deadline.setInterval(kConfirmMs);
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it) {
            if (!it->stopped) {
                fail(it.key(),
                     it->answered ? tr("no standstill reported within %1 s").arg(kConfirmMs / 1000)
                                  : tr("no answer to the stop within %1 s").arg(kConfirmMs / 1000));
                return;
            }
        }
    });
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
        m_watched.insert(id, Watched{session, it.value()});
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
}

void MachineStopWatch::onResult(const QString& id, const CommandResult& result)
{
    auto it = m_watched.find(id);
    if (it == m_watched.end() || result.id == 0 || it->stopped)
        return;
    if (result.id == it->stop) {
        if (!result.ok()) {
            fail(id, result.message.isEmpty() ? tr("the stop request failed") : result.message);
            return;
        }
        it->answered = true;
        // A status read before the acknowledgement may predate the stop: read afresh.
        it->read = it->session->refreshStatus();
        return;
    }
    if (result.id != it->read)
        return;
    it->read = 0;
    const MachineStatus status = result.value.canConvert<MachineStatus>()
                                     ? result.value.value<MachineStatus>()
                                     : it->session->status();
    if (!result.ok() || motionIn(status))
        return; // read again with the controller's next status (onStatus)
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
    if (it != m_watched.end() && it->answered && !it->stopped && it->read == 0)
        it->read = it->session->refreshStatus();
}

void MachineStopWatch::fail(const QString& id, const QString& reason)
{
    if (!m_watched.contains(id))
        return;
    cancel();
    Q_EMIT notConfirmed(id, reason);
}

} // namespace stepdeck::ui
