#include "Controller.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <QtMath>
#include <cmath>

namespace stepdeck {

QString linkStateName(LinkState state)
{
    switch (state) {
    case LinkState::Disconnected:
        return QStringLiteral("disconnected");
    case LinkState::Connecting:
        return QStringLiteral("connecting");
    case LinkState::Connected:
        return QStringLiteral("connected");
    case LinkState::Lost:
        return QStringLiteral("lost");
    }
    return {};
}

Controller::Controller(Transport* transport, const ControllerOptions& options, QObject* parent)
    : QObject(parent), m_transport(transport), m_options(options)
{
    qRegisterMetaType<stepdeck::LinkState>();
    qRegisterMetaType<stepdeck::MachineStatus>();
    qRegisterMetaType<stepdeck::CommandResult>();
    qRegisterMetaType<stepdeck::TrafficRecord>();
    qRegisterMetaType<stepdeck::ParameterSet>();
    m_jogTimer.setInterval(qMax(5, m_options.jogTickMs));
    m_jogTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_jogTimer, &QTimer::timeout, this, &Controller::onJogTick);
    if (m_options.jogAccelerationStepsPerS2 > 0)
        m_jogRamp.setAcceleration(m_options.jogAccelerationStepsPerS2);
    m_jogClock.start();
    m_trafficClock.start();
    m_safetyTimer.setSingleShot(true);
    connect(&m_safetyTimer, &QTimer::timeout, this, [this] {
        if (auto timeout = std::exchange(m_safetyTimeout, nullptr))
            timeout();
    });
}

Controller::~Controller() = default;

QString Controller::noStopCommandText()
{
    return tr("this controller has no stop command: use the machine's emergency stop to stop "
              "it; motion only ends when the current move arrives");
}

QString Controller::mayStillBeMovingText()
{
    return tr("the controller did not confirm the stop and may still be moving: use the "
              "machine's emergency stop");
}

void Controller::refuseNoStopCommand(RequestId id)
{
    finishError(id, ErrorKind::Unsupported, noStopCommandText());
}

// ------------------------------------------------------------------ safety contract

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
    abortHostSide(ErrorKind::LinkDown, tr("link lost: %1").arg(reason));
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

void Controller::moveAbsolute(RequestId id, const AxisVector& targets)
{
    AxisVector relative;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        const AxisStatus axis = m_status.axes.value(it.key());
        if (!m_status.axes.contains(it.key())) {
            finishError(id, ErrorKind::InvalidValue,
                        tr("this machine has no axis %1").arg(axisName(it.key())));
            return;
        }
        if (!axis.positionKnown) {
            finishError(id, ErrorKind::Refused,
                        tr("absolute move refused: position of axis %1 is unknown, reference it "
                           "first")
                            .arg(axisName(it.key())));
            return;
        }
        relative.insert(it.key(), it.value() - axis.position);
    }
    moveRelative(id, relative);
}

void Controller::feed(RequestId id, const AxisVector&)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no feed mode"));
}

void Controller::feedStream(RequestId id, const QVector<AxisVector>&)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no single-step feed stream"));
}

void Controller::velocityMove(RequestId id, const AxisVector&)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no velocity move"));
}

void Controller::reset(RequestId id)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no reset"));
}

void Controller::setSpindle(RequestId id, int)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no spindle output"));
}

void Controller::setCoolant(RequestId id, bool)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no coolant output"));
}

void Controller::setDrivePower(RequestId id, int)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no drive power setting"));
}

void Controller::scanBus(RequestId id)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no bus to scan"));
}

void Controller::modelOperation(RequestId id, const QString& name, const QVariantMap&)
{
    finishError(id, ErrorKind::Unsupported, tr("this controller has no operation '%1'").arg(name));
}

QString Controller::jogRefusal() const
{
    if (m_linkState != LinkState::Connected)
        return tr("jog refused: not connected");
    if (m_status.panic)
        return tr("jog refused: emergency stop is active");
    return {};
}

QString Controller::jogAxisRefusal(Axis, double) const
{
    return {};
}

void Controller::setJogVelocity(const AxisVelocities& targets)
{
    bool anyNonZero = false;
    for (double v : targets)
        anyNonZero = anyNonZero || v != 0.0;
    if (anyNonZero) {
        const QString refusal = jogRefusal();
        if (!refusal.isEmpty()) {
            m_jogRamp.releaseAll();
            Q_EMIT jogRefused(refusal);
            return;
        }
    }
    const Capabilities caps = capabilities();
    m_jogRamp.setMaxSpeed(caps.maxJogSpeed);
    if (m_options.jogAccelerationStepsPerS2 <= 0)
        m_jogRamp.setAcceleration(caps.defaultJogAcceleration);
    AxisVelocities known;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        if (!caps.axes.contains(it.key()))
            continue;
        double target = it.value();
        if (target != 0.0) {
            const QString why = jogAxisRefusal(it.key(), target);
            if (!why.isEmpty()) {
                target = 0.0;
                Q_EMIT jogRefused(why);
            }
        }
        known.insert(it.key(), target);
    }
    m_jogRamp.setTargets(known);
    m_leaseRenewedMs = m_jogClock.elapsed();
    if (!m_jogTimer.isActive() && !m_jogRamp.isIdle()) {
        m_lastJogTickMs = m_jogClock.elapsed();
        m_jogTimer.start();
        onJogTick(); // first step now, not one tick late
    }
}

void Controller::endJog()
{
    m_jogRamp.releaseAll();
}

void Controller::setJogAcceleration(double stepsPerS2)
{
    if (stepsPerS2 > 0) {
        m_options.jogAccelerationStepsPerS2 = stepsPerS2;
        m_jogRamp.setAcceleration(stepsPerS2);
    }
}

void Controller::onJogTick()
{
    const qint64 now = m_jogClock.elapsed();
    if (now - m_leaseRenewedMs > m_options.jogLeaseMs) {
        // The input stopped renewing (frozen GUI, crashed input, dropped key-up): ramp down.
        for (Axis a : capabilities().axes) {
            if (m_jogRamp.target(a) != 0.0) {
                qCInfo(lcJog) << "jog lease expired, ramping down";
                break;
            }
        }
        m_jogRamp.releaseAll();
    }
    const double dt = qMax<qint64>(1, now - m_lastJogTickMs) / 1000.0;
    m_lastJogTickMs = now;
    const AxisVelocities before = m_jogRamp.currentVelocities();
    const AxisVelocities rates = m_jogRamp.advance(dt);

    // Host-side position estimate: integrate the rates that were in force during dt. The
    // fraction of a step is carried over, so a slow jog (20 steps/s at 20 ms ticks is 0.4
    // steps a tick) still advances the estimate.
    for (auto it = before.cbegin(); it != before.cend(); ++it) {
        if (!m_status.axes.contains(it.key()))
            continue;
        AxisStatus& axis = m_status.axes[it.key()];
        const double avg = (it.value() + rates.value(it.key(), 0.0)) / 2.0;
        if (avg == 0.0)
            continue;
        double& carry = m_jogStepCarry[it.key()];
        carry += avg * dt;
        const double whole = std::trunc(carry);
        carry -= whole;
        axis.position += qint64(whole);
        axis.positionEstimated = true;
    }
    AxisVelocities rounded;
    for (auto it = rates.cbegin(); it != rates.cend(); ++it)
        rounded.insert(it.key(), double(qRound64(it.value())));
    if (rounded != m_lastAppliedJog) {
        m_lastAppliedJog = rounded;
        for (auto it = rounded.cbegin(); it != rounded.cend(); ++it) {
            if (m_status.axes.contains(it.key()))
                m_status.axes[it.key()].commandedVelocity = it.value();
        }
        applyJogVelocity(rounded);
    }
    if (m_jogRamp.isIdle())
        m_jogTimer.stop();
}

void Controller::haltJogImmediately()
{
    m_jogRamp.reset();
    m_jogTimer.stop();
    m_lastAppliedJog.clear();
    for (AxisStatus& axis : m_status.axes) {
        axis.commandedVelocity = 0;
        axis.jogging = false;
    }
}

void Controller::setLinkState(LinkState state, const QString& reason)
{
    if (state == m_linkState)
        return;
    m_linkState = state;
    qCInfo(lcController) << "link" << linkStateName(state) << reason;
    if (state != LinkState::Connected) {
        haltJogImmediately();
        m_status.commFault = state == LinkState::Lost;
        if (state == LinkState::Lost)
            ++m_status.commFaultCount;
    } else {
        m_status.commFault = false;
    }
    if (state == LinkState::Connecting || state == LinkState::Lost)
        markAllUnreferenced();
    Q_EMIT linkStateChanged(state, reason);
    publishStatus();
}

void Controller::publishStatus()
{
    Q_EMIT statusChanged(m_status);
}

void Controller::markAllUnreferenced()
{
    for (AxisStatus& axis : m_status.axes) {
        axis.referenced = false;
        axis.positionKnown = false;
    }
}

void Controller::finishOk(RequestId id, const QVariant& value)
{
    Q_EMIT requestFinished(CommandResult::success(id, value));
}

void Controller::finishError(RequestId id, ErrorKind kind, const QString& message)
{
    qCInfo(lcController) << "request" << id << "failed:" << message;
    Q_EMIT requestFinished(CommandResult::failure(id, kind, message));
}

void Controller::recordTraffic(TrafficRecord::Direction direction, const QByteArray& bytes,
                               bool poll)
{
    TrafficRecord record;
    record.direction = direction;
    record.timestampUs = m_trafficClock.nsecsElapsed() / 1000;
    record.bytes = bytes;
    record.poll = poll;
    Q_EMIT traffic(record);
}

} // namespace stepdeck
