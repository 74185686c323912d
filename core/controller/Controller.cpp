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
    m_jogTimer.setInterval(int(jogTickSeconds() * 1000));
    m_jogTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_jogTimer, &QTimer::timeout, this, &Controller::onJogTick);
    if (m_options.jogAccelerationStepsPerS2 > 0)
        m_jogRamp.setAcceleration(m_options.jogAccelerationStepsPerS2);
    m_jogClock.start();
    m_trafficClock.start();
    m_stepJogLease.setSingleShot(true);
    m_stepJogLease.setInterval(qMax(1, m_options.jogLeaseMs));
    connect(&m_stepJogLease, &QTimer::timeout, this, &Controller::endStepJog);
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

void Controller::feedContour(RequestId id, std::shared_ptr<motion::ContourFeed>)
{
    finishError(id, ErrorKind::Unsupported,
                tr("this controller cannot run a contour as a step "
                   "stream"));
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

double Controller::jogStopDistance(Axis axis, double speed) const
{
    Q_UNUSED(axis)
    return JogRamp::stopDistance(speed, m_jogRamp.acceleration(), jogTickSeconds());
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
    endStepJog();
}

void Controller::noteFinished(const CommandResult& result)
{
    if (m_jogStepId == 0 || result.id != m_jogStepId)
        return;
    m_jogStepId = 0;
    if (result.ok())
        m_stepJogLease.start(); // the next step comes at once while the input is held
    else
        endStepJog(); // refused, replaced or timed out: the jog ended here
}

void Controller::endStepJog()
{
    m_stepJogLease.stop();
    m_jogStepId = 0;
    bool changed = false;
    for (Axis axis : std::exchange(m_stepJogAxes, {})) {
        if (m_status.axes.contains(axis) && m_status.axes[axis].commandedVelocity != 0.0) {
            m_status.axes[axis].commandedVelocity = 0;
            changed = true;
        }
    }
    if (changed)
        publishStatus();
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
    keepJogInsideSoftLimits(qMax(dt, m_options.jogTickMs / 1000.0));
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
    // The device holds what it is sent until the next tick: while braking, the rate the ramp
    // reaches at the end of that tick (JogRamp::heldRates), so a release travels no further
    // than jogStopDistance() says (issue 28 item 6).
    const AxisVelocities held = m_jogRamp.heldRates(jogTickSeconds(), m_lastAppliedJog,
                                                    (now - m_lastAppliedJogMs) / 1000.0);
    AxisVelocities rounded;
    for (auto it = held.cbegin(); it != held.cend(); ++it)
        rounded.insert(it.key(), double(qRound64(it.value())));
    if (rounded != m_lastAppliedJog) {
        m_lastAppliedJog = rounded;
        m_lastAppliedJogMs = now;
        for (auto it = rounded.cbegin(); it != rounded.cend(); ++it) {
            if (m_status.axes.contains(it.key()))
                m_status.axes[it.key()].commandedVelocity = it.value();
        }
        applyJogVelocity(rounded);
    }
    if (m_jogRamp.isIdle())
        m_jogTimer.stop();
}

void Controller::keepJogInsideSoftLimits(double lookaheadS)
{
    if (m_softLimits.all().isEmpty())
        return;
    AxisVelocities targets;
    for (Axis a : capabilities().axes)
        targets.insert(a, m_jogRamp.target(a));
    QString why;
    const AxisVelocities limited = m_softLimits.limitJog(
        m_status, targets, m_jogRamp.currentVelocities(), m_jogRamp.acceleration(), lookaheadS,
        [this](Axis axis, double speed) { return jogStopDistance(axis, speed); }, &why);
    for (auto it = limited.cbegin(); it != limited.cend(); ++it) {
        if (it.value() != targets.value(it.key()))
            m_jogRamp.setTarget(it.key(), it.value()); // brakes now, stops inside the limit
    }
    if (!why.isEmpty() && why != m_softLimitNote)
        Q_EMIT jogRefused(why);
    m_softLimitNote = why;
}

void Controller::haltJogImmediately()
{
    m_jogRamp.reset();
    m_jogTimer.stop();
    m_lastAppliedJog.clear();
    m_stepJogLease.stop();
    m_jogStepId = 0;
    m_stepJogAxes.clear();
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
    // The status first: whoever reacts to the link state reads the status that goes with it.
    publishStatus();
    Q_EMIT linkStateChanged(state, reason);
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
    finish(CommandResult::success(id, value));
}

void Controller::finishError(RequestId id, ErrorKind kind, const QString& message)
{
    qCInfo(lcController) << "request" << id << "failed:" << message;
    finish(CommandResult::failure(id, kind, message));
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
