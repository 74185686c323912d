// The safety contract of every adapter (docs/architecture.md, "Safety contract"): the stop
// goes out before the host lets go of a motion, the bytes leave the process before the port
// closes, a link loss keeps the port open for STOP and PANIC, and the screen never claims a
// stop the device did not confirm.
#include "Controller.h"
#include "Logging.h"
#include "transport/Transport.h"

namespace stepdeck {

namespace {
// Bytes written just before a close must leave the process (QSerialPort::close() drops its
// buffer). A few stop bytes take well under a millisecond at 9600 baud and up.
constexpr int kFlushBeforeCloseMs = 200;
} // namespace

bool Controller::canWriteStop() const
{
    const Transport* t = m_transport;
    return t && t->isOpen() &&
           (m_linkState == LinkState::Connected || m_linkState == LinkState::Lost);
}

void Controller::runSafetyStop(std::function<void(bool, bool)> then)
{
    const bool mayMove = motionMayBeRunning();
    const quint64 token = ++m_safetyToken;
    auto finish = [this, token, mayMove, then](bool acknowledged) {
        if (token != m_safetyToken)
            return; // timed out (or superseded) already
        ++m_safetyToken;
        m_safetyTimer.stop();
        m_safetyTimeout = nullptr;
        then(mayMove, acknowledged);
    };
    m_safetyTimeout = [finish] {
        qCWarning(lcController) << "safety stop not acknowledged in time";
        finish(false);
    };
    m_safetyTimer.start(qMax(1, safetyStopTimeoutMs()));
    qCInfo(lcController) << "safety stop" << (mayMove ? "(motion possible)" : "(idle)");
    sendSafetyStop(finish);
}

void Controller::closeLink()
{
    if (m_closing)
        return;
    if (!canWriteStop()) {
        // Never connected, still connecting (nothing commanded yet) or the port is gone (the
        // failure already said that motion may continue): nothing can or need be sent.
        completeClose(false, true);
        return;
    }
    m_closing = true;
    m_losing = false; // a close overrides a link-loss attempt in progress
    runSafetyStop(
        [this](bool mayMove, bool acknowledged) { completeClose(mayMove, acknowledged); });
}

void Controller::completeClose(bool mayMove, bool acknowledged)
{
    m_closing = false;
    ++m_safetyToken;
    m_safetyTimer.stop();
    m_safetyTimeout = nullptr;
    abortHostSide(ErrorKind::Cancelled, tr("link closed"));
    if (Transport* t = m_transport) {
        if (t->isOpen() && !t->flushOutput(kFlushBeforeCloseMs))
            qCWarning(lcController) << "close: output not flushed";
        t->close();
    }
    if (mayMove && !acknowledged)
        markMotionUnconfirmed();
    setLinkState(LinkState::Disconnected, tr("closed"));
    Q_EMIT closeFinished();
}

void Controller::loseLink(const QString& reason)
{
    if (m_linkState != LinkState::Connected || m_losing || m_closing)
        return;
    m_losing = true;
    runSafetyStop([this, reason](bool mayMove, bool acknowledged) {
        m_losing = false;
        abortHostSide(ErrorKind::LinkDown, tr("link lost: %1").arg(reason));
        const bool unconfirmed = mayMove && !acknowledged;
        if (unconfirmed)
            m_status.motionUnconfirmed = true;
        setLinkState(LinkState::Lost, reason);
        reportLinkLoss(reason, unconfirmed);
    });
}

void Controller::handleTransportFailure(const QString& reason)
{
    const bool mayMove = motionMayBeRunning();
    const bool wasClosing = m_closing;
    ++m_safetyToken; // a safety stop in progress can no longer be answered
    m_safetyTimer.stop();
    m_safetyTimeout = nullptr;
    m_closing = m_losing = false;
    // A port that failed while opening ("no such port: /dev/ttyUSB9") never had a link to lose.
    const bool opening = m_linkState == LinkState::Connecting;
    abortHostSide(ErrorKind::LinkDown, opening ? reason : tr("link lost: %1").arg(reason));
    if (wasClosing) {
        completeClose(mayMove, false);
        return;
    }
    if (m_linkState == LinkState::Connecting) {
        setLinkState(LinkState::Disconnected, reason);
        return;
    }
    if (m_linkState != LinkState::Connected && m_linkState != LinkState::Lost)
        return;
    if (mayMove)
        m_status.motionUnconfirmed = true;
    setLinkState(LinkState::Lost, reason);
    reportLinkLoss(reason, mayMove);
}

void Controller::reportLinkLoss(const QString& reason, bool motionUnconfirmed)
{
    // One line per outage, saying all that is known.
    Q_EMIT errorOccurred(motionUnconfirmed
                             ? tr("link lost: %1; %2").arg(reason, mayStillBeMovingText())
                             : tr("link lost: %1").arg(reason));
}

void Controller::noteStandstillConfirmed()
{
    if (!m_status.motionUnconfirmed)
        return;
    m_status.motionUnconfirmed = false;
    qCInfo(lcController) << "standstill confirmed by the device";
}

void Controller::markMotionUnconfirmed()
{
    const bool changed = !m_status.motionUnconfirmed;
    m_status.motionUnconfirmed = true;
    if (changed) {
        qCWarning(lcController) << "motion unconfirmed";
        Q_EMIT errorOccurred(mayStillBeMovingText());
    }
    publishStatus();
}

} // namespace stepdeck
