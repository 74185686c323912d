// Link, status frames and the requests without motion of the laser-axis adapter.
#include "LaserAxisController.h"
#include "LaserLogging.h"
#include "LaserModel.h"
#include "Logging.h"
#include "transport/Transport.h"

namespace stepdeck::laser {

LaserAxisController::LaserAxisController(Transport* transport, const ControllerOptions& options,
                                         QObject* parent)
    : Controller(transport, options, parent), m_motion(*this, laser::capabilities().axes, this)
{
    for (Axis axis : laser::capabilities().axes)
        mutableStatus().axes.insert(axis, AxisStatus{});
    m_syncTimeout.setSingleShot(true);
    connect(&m_syncTimeout, &QTimer::timeout, this, [this] {
        for (RequestId id : std::exchange(m_syncs, {}))
            finishError(id, ErrorKind::Timeout, tr("the port did not take the bytes in time"));
    });
    if (transport) {
        connect(transport, &Transport::opened, this, &LaserAxisController::onTransportOpened);
        connect(transport, &Transport::failed, this, &LaserAxisController::handleTransportFailure);
        connect(transport, &Transport::dataReceived, this, &LaserAxisController::onData);
        connect(transport, &Transport::bytesWritten, this, &LaserAxisController::onBytesWritten);
    }
}

LaserAxisController::~LaserAxisController() = default;

Capabilities LaserAxisController::capabilities() const
{
    return laser::capabilities();
}

// ---------------------------------------------------------------- link

void LaserAxisController::openLink(RequestId id)
{
    if (!transport())
        return finishError(id, ErrorKind::LinkDown, tr("no transport"));
    if (linkState() == LinkState::Connected)
        return finishOk(id);
    if (m_openId != 0)
        return finishError(id, ErrorKind::Refused, tr("already connecting"));
    m_openId = id;
    setLinkState(LinkState::Connecting);
    if (transport()->isOpen())
        onTransportOpened();
    else
        transport()->open(lineSettings());
}

void LaserAxisController::onTransportOpened()
{
    // Nothing to ask: the axes have no status request. The link is up when the port is; what
    // the axes do becomes known from their status frames.
    m_decoder.reset();
    m_motion.resetRawDecoder();
    if (m_openId == 0)
        return;
    setLinkState(LinkState::Connected);
    finishOk(std::exchange(m_openId, 0));
}

// ---------------------------------------------------------------- safety contract

void LaserAxisController::sendSafetyStop(std::function<void(bool)> done)
{
    // "Move to home" and "move to position" are the only commands: there is no stop to send.
    // Acknowledged only when nothing was in motion to begin with.
    done(!motionMayBeRunning());
}

bool LaserAxisController::motionMayBeRunning() const
{
    return m_motion.mayBeRunning();
}

void LaserAxisController::abortHostSide(ErrorKind kind, const QString& message)
{
    // The host stops tracking: every request in flight ends; an axis with a target out stays
    // unconfirmed until a status frame from it proves it stopped.
    m_motion.stopDeadline();
    m_syncTimeout.stop();
    if (m_openId != 0)
        finishError(std::exchange(m_openId, 0), kind, message);
    for (RequestId id : std::exchange(m_syncs, {}))
        finishError(id, kind, message);
    const QStringList heading = m_motion.stopTracking();
    m_decoder.reset();
    m_motion.updateMachineFlags();
    publishStatus();
    m_motion.failPending(kind, message);
    // MachineStatus::motionUnconfirmed is set here (updateMachineFlags), before the base's
    // close could say "may still be moving": say it here, once, with the axes and why.
    // (A link loss is reported by the base with that text already.)
    if (!heading.isEmpty() && kind != ErrorKind::LinkDown) {
        Q_EMIT errorOccurred(tr("no longer tracking axis %1 on its way to a target: the protocol "
                                "has no stop command; it goes on unless the machine's emergency "
                                "stop is used")
                                 .arg(heading.join(QStringLiteral(", "))));
    }
}

bool LaserAxisController::sendFrames(const QByteArray& bytes)
{
    recordTraffic(TrafficRecord::Direction::Out, bytes, false);
    return transport()->write(bytes) >= 0;
}

void LaserAxisController::moveRelative(RequestId id, const AxisVector& steps)
{
    m_motion.moveRelative(id, steps);
}

void LaserAxisController::moveAbsolute(RequestId id, const AxisVector& targets)
{
    m_motion.moveAbsolute(id, targets);
}

void LaserAxisController::reference(RequestId id, const QMap<Axis, int>& directions)
{
    m_motion.reference(id, directions);
}

bool LaserAxisController::requireLink(RequestId id)
{
    if (linkState() == LinkState::Connected && transport() && transport()->isOpen())
        return true;
    finishError(id, ErrorKind::LinkDown, tr("not connected"));
    return false;
}

// ---------------------------------------------------------------- incoming

void LaserAxisController::onData(const QByteArray& bytes)
{
    recordTraffic(TrafficRecord::Direction::In, bytes, false);
    for (const DecodedStatus& d : m_decoder.feed(bytes)) {
        if (!d.ok()) {
            ++mutableStatus().resyncCount;
            qCWarning(lcLaser) << "malformed status frame" << d.raw << describeError(d.error);
            Q_EMIT errorOccurred(tr("malformed status frame from the axes ignored (%1): %2")
                                     .arg(genericFormatTraffic(d.raw), describeError(d.error)));
            continue;
        }
        m_motion.onStatusFrame(*d.frame);
    }
}

// ---------------------------------------------------------------- no motion

void LaserAxisController::readParameters(RequestId id, const QStringList&)
{
    finishError(id, ErrorKind::Unsupported,
                tr("the laser motor-axis protocol has no parameters: it only knows home and move "
                   "to position"));
}

void LaserAxisController::writeParameters(RequestId id, const ParameterSet& values, bool)
{
    if (values.isEmpty())
        return finishOk(id);
    readParameters(id, {});
}

void LaserAxisController::refreshStatus(RequestId id)
{
    if (!requireLink(id))
        return;
    // No status request exists: the status is what the axes last reported. Finish once all
    // bytes sent so far have left the process, so a caller that quits next loses no target.
    if (transport()->bytesToWrite() <= 0) {
        publishStatus();
        return finishOk(id);
    }
    m_syncs << id;
    if (!m_syncTimeout.isActive())
        m_syncTimeout.start(qMax(options().commandTimeoutMs, 200));
}

void LaserAxisController::onBytesWritten()
{
    if (m_syncs.isEmpty() || !transport() || transport()->bytesToWrite() > 0)
        return;
    m_syncTimeout.stop();
    publishStatus();
    for (RequestId id : std::exchange(m_syncs, {}))
        finishOk(id);
}

void LaserAxisController::sendRaw(RequestId id, const QByteArray& bytes)
{
    if (!requireLink(id))
        return;
    recordTraffic(TrafficRecord::Direction::Out, bytes, false);
    if (transport()->write(bytes) < 0)
        return finishError(id, ErrorKind::LinkDown, tr("not connected"));
    m_motion.trackRawCommands(bytes);
    finishOk(id);
}

QString LaserAxisController::jogRefusal() const
{
    const QString base = Controller::jogRefusal();
    if (!base.isEmpty())
        return base;
    return tr("jog refused: the laser motor axes have no jog command; jog moves them by short "
              "targets, one after the other");
}

} // namespace stepdeck::laser
