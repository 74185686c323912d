#pragma once
#include "controller/ControllerOptions.h"
#include "controller/JogRamp.h"
#include "controller/SoftLimits.h"
#include "model/Capabilities.h"
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include "model/ParameterSchema.h"
#include "model/Traffic.h"
#include "transport/Transport.h"
#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <functional>
#include <memory>

namespace stepdeck::motion {
class ContourFeed;
}

namespace stepdeck {

enum class LinkState { Disconnected, Connecting, Connected, Lost };
QString linkStateName(LinkState state);

// The protocol adapter for one link (one board, or one bus of addressed drives).
// Lives in the controller thread (see ControllerSession); never blocks. Every operation that
// takes a RequestId ends with exactly one requestFinished() carrying that id.
//
// The base class owns what is the same for every model: link state, the normalised status,
// the jog lease and the host-side JogRamp. Adapters implement the protocol.
class Controller : public QObject
{
    Q_OBJECT
public:
    Controller(Transport* transport, const ControllerOptions& options, QObject* parent = nullptr);
    ~Controller() override;

    virtual Capabilities capabilities() const = 0;
    virtual ParameterSchema schema() const = 0;

    // What the operator reads when the model has no stop command (Capabilities::stopCommand).
    static QString noStopCommandText();

    LinkState linkState() const { return m_linkState; }
    const MachineStatus& status() const { return m_status; }
    Transport* transport() const { return m_transport; }
    const ControllerOptions& options() const { return m_options; }

    // --- link ---
    virtual void openLink(RequestId id) = 0;
    // Closes the link under the safety contract (docs/architecture.md): the model's stop for
    // anything that may move goes out first, overtaking queued work; the transport is flushed
    // (bounded) and only then closed. Asynchronous and bounded by safetyStopTimeoutMs();
    // closeFinished() follows exactly once. One policy for every model, hence not virtual.
    void closeLink();
    bool isClosing() const { return m_closing; }
    // What the operator reads when the host lost track of a motion the device did not
    // confirm as stopped.
    static QString mayStillBeMovingText();

    // --- parameters (validated against schema(); invalid values are never sent) ---
    virtual void readParameters(RequestId id, const QStringList& names) = 0;
    virtual void writeParameters(RequestId id, const ParameterSet& values, bool verify) = 0;

    // --- motion; refused with ErrorKind::Refused where the manual forbids it ---
    virtual void moveRelative(RequestId id, const AxisVector& steps) = 0;
    // Default: converts to a relative move from the host-tracked positions; refused for axes
    // whose position is unknown.
    virtual void moveAbsolute(RequestId id, const AxisVector& targets);
    virtual void feed(RequestId id, const AxisVector& steps);
    // A stream of single steps: per axis -1, 0 or +1 per step (E-LAB DC2). Default: unsupported.
    virtual void feedStream(RequestId id, const QVector<AxisVector>& steps);
    // A contour laid on ticks (issue 30, motion::ContourFeed): one stream for as long as the
    // contour gives ticks; finished when it is closed and every tick ran out at the device.
    // Default: unsupported.
    virtual void feedContour(RequestId id, std::shared_ptr<motion::ContourFeed> contour);
    virtual void reference(RequestId id, const QMap<Axis, int>& directions) = 0;
    virtual void velocityMove(RequestId id, const AxisVector& stepsPerS);
    // Stop and panic overtake everything queued.
    virtual void stop(RequestId id) = 0;
    virtual void panic(RequestId id) = 0;
    virtual void reset(RequestId id);

    // --- auxiliaries (default: unsupported) ---
    virtual void setSpindle(RequestId id, int rpm);
    virtual void setCoolant(RequestId id, bool on);
    virtual void setDrivePower(RequestId id, int percent);

    // --- status and console ---
    virtual void refreshStatus(RequestId id) = 0; // one complete status read
    virtual void sendRaw(RequestId id, const QByteArray& bytes) = 0;
    virtual void setPollInterval(int ms) = 0;

    // --- model-specific (default: unsupported) ---
    // Lists the drives on a multi-drive bus. Result value: QVariantList of QVariantMaps
    // {address, hardware, interface, date, firmware}.
    virtual void scanBus(RequestId id);
    // A named operation only some models offer (records, error memory, ...); names, args and
    // result values are documented by the model's controller header.
    virtual void modelOperation(RequestId id, const QString& name, const QVariantMap& args);

    // --- jog: a velocity lease, ramped by the core JogRamp in this thread ---
    // Renews the lease; axes not named keep their target. Unless renewed within
    // options().jogLeaseMs, every target drops to zero and the axes ramp down by themselves.
    void setJogVelocity(const AxisVelocities& targets);
    void endJog(); // release every axis (ramps down)
    void setJogAcceleration(double stepsPerS2);
    const JogRamp& jogRamp() const { return m_jogRamp; }

    // --- soft limits (issue 11, ControllerLimits.cpp): the jog ramp keeps inside them on
    // every tick; ControllerSession sends every move through the guarded calls, which refuse
    // (ErrorKind::Refused, nothing sent) a target beyond an active limit ---
    void setSoftLimits(const SoftLimits& limits) { m_softLimits = limits; }
    const SoftLimits& softLimits() const { return m_softLimits; }
    void guardedMoveRelative(RequestId id, const AxisVector& steps);
    void guardedMoveAbsolute(RequestId id, const AxisVector& targets);
    void guardedFeed(RequestId id, const AxisVector& steps);
    void guardedFeedStream(RequestId id, const QVector<AxisVector>& steps);
    void guardedVelocityMove(RequestId id, const AxisVector& stepsPerS); // no end: refused
    // One short jog move (Capabilities::jogByTargets): shortened to end at the limit;
    // refused with the reason once every axis named stands at its limit. stepsPerS: the jog
    // rate each target stands for; it is the axes' commandedVelocity while the host jogs by
    // targets (until endJog(), a failed step, or no next step within the jog lease).
    void jogStep(RequestId id, const AxisVector& steps, const AxisVelocities& stepsPerS = {});
    // refusal non-empty: finishes id as Refused with it and returns true.
    bool refuse(RequestId id, const QString& refusal);

Q_SIGNALS:
    void linkStateChanged(stepdeck::LinkState state, const QString& reason);
    void statusChanged(const stepdeck::MachineStatus& status);
    void requestFinished(const stepdeck::CommandResult& result);
    void errorOccurred(const QString& message);
    void traffic(const stepdeck::TrafficRecord& record);
    void pollRateChanged(double hz);
    void jogRefused(const QString& reason);
    void closeFinished();

protected:
    // ---- the safety contract: what every adapter provides ----
    // Sends this model's documented stop for everything that may be moving: drops queued work,
    // ends host-driven motion (jog ramp, streams) and writes the stop ahead of anything else.
    // Calls done(acknowledged) at most once; acknowledged = the device confirmed the stop.
    // A model without a stop command calls done(false) at once unless nothing is in motion.
    virtual void sendSafetyStop(std::function<void(bool acknowledged)> done) = 0;
    // Ends everything host-side without I/O: queues, poller, jog, streams; every pending
    // request (an open in progress included) finishes with kind and message.
    virtual void abortHostSide(ErrorKind kind, const QString& message) = 0;
    // Whether anything may move as far as the host can tell (tracked motion, jog, status bits
    // of the last read, an unanswered motion command).
    virtual bool motionMayBeRunning() const = 0;
    // How long the safety stop may take before the host gives up waiting for its reply.
    virtual int safetyStopTimeoutMs() const { return 400; }

    // Replies stopped (polls unanswered, persistent garbage) while the port is still open:
    // the safety stop goes out first, then the link counts as Lost. The port stays open so
    // that STOP and PANIC can still be written.
    void loseLink(const QString& reason);
    // The transport failed (port vanished, unplugged): nothing can be written any more.
    void handleTransportFailure(const QString& reason);
    bool isLosingLink() const { return m_losing; }
    // The port is open and the link Connected or Lost: a stop or panic can be written.
    bool canWriteStop() const;
    // A status read from the device showed every axis standing still.
    void noteStandstillConfirmed();
    // The host stopped tracking a motion that the device did not confirm as stopped.
    void markMotionUnconfirmed();

    // Sends the ramped jog rates (already limited by the ramp). Adapters coalesce: only the
    // newest rates matter. Returns false if the rates could not be sent (refusal reported).
    virtual void applyJogVelocity(const AxisVelocities& stepsPerS) = 0;
    // Non-empty: why a jog cannot start now (not connected, panic active, ...).
    virtual QString jogRefusal() const;
    // Non-empty: why this axis may not jog at this non-zero target (into an active limit
    // switch, below the drive's start frequency, ...). The axis then gets target 0.
    virtual QString jogAxisRefusal(Axis axis, double target) const;
    // Soft limits: how far (steps) an axis jogging at `speed` still travels after its jog
    // target drops to zero. Default: the host JogRamp's braking distance (E-LAB: the host
    // ramps, the board follows each rate; JogRamp::stopDistance with the jog tick). A model
    // whose drive ramps by itself overrides it.
    virtual double jogStopDistance(Axis axis, double speed) const;
    // The period of the jog tick: how long the device holds each rate it is sent.
    double jogTickSeconds() const { return qMax(5, m_options.jogTickMs) / 1000.0; }

    void setLinkState(LinkState state, const QString& reason = {});
    MachineStatus& mutableStatus() { return m_status; }
    void publishStatus();
    // After panic, reset, reconnect or an unexpected stop: nothing is referenced, positions
    // are unknown until a reference run.
    void markAllUnreferenced();
    // Link lost or panic: rates to zero at once, without sending anything.
    void haltJogImmediately();
    // One axis to zero at once (a limit switch turned active under it); the next jog tick
    // sends the new rates.
    void haltJogAxis(Axis axis) { m_jogRamp.stopAxis(axis); }
    double jogRate(Axis axis) const { return m_jogRamp.current(axis); }
    void finish(const CommandResult& result)
    {
        noteFinished(result);
        Q_EMIT requestFinished(result);
    }
    // stop()/panic() of a model without a stop command: Unsupported, noStopCommandText().
    void refuseNoStopCommand(RequestId id);
    void finishOk(RequestId id, const QVariant& value = {});
    void finishError(RequestId id, ErrorKind kind, const QString& message);
    void recordTraffic(TrafficRecord::Direction direction, const QByteArray& bytes, bool poll);
    bool jogActive() const { return !m_jogRamp.isIdle(); }
    // When the jog tick that computes the rates now being applied read its clock (ms on the
    // controller's jog clock): the ramp's own time base, for adapters that stamp their sends.
    qint64 jogTickMs() const { return m_lastJogTickMs; }

private:
    void onJogTick();
    // Runs sendSafetyStop() bounded by safetyStopTimeoutMs(), then `then(mayMove, acked)`.
    void runSafetyStop(std::function<void(bool mayMove, bool acknowledged)> then);
    void completeClose(bool mayMove, bool acknowledged);
    void reportLinkLoss(const QString& reason, bool motionUnconfirmed);
    void keepJogInsideSoftLimits(double dt);
    // Jogging by targets: a finished step starts the lease for the next one (ok) or ends the
    // commanded rates (failed); endStepJog() sets them back to zero.
    void noteFinished(const CommandResult& result);
    void endStepJog();

    QPointer<Transport> m_transport;
    ControllerOptions m_options;
    LinkState m_linkState = LinkState::Disconnected;
    MachineStatus m_status;
    JogRamp m_jogRamp;
    QTimer m_jogTimer{this}; // parented: moves with the controller to its thread
    QElapsedTimer m_jogClock;
    qint64 m_lastJogTickMs = 0;
    qint64 m_leaseRenewedMs = 0;
    AxisVelocities m_lastAppliedJog;
    qint64 m_lastAppliedJogMs = 0; // m_jogClock when m_lastAppliedJog was sent
    AxisVelocities m_jogStepCarry; // fractions of a step not yet added to the estimate
    RequestId m_jogStepId = 0;     // the jog step in flight (jogging by targets)
    QList<Axis> m_stepJogAxes;     // axes whose commandedVelocity a jog step set
    QTimer m_stepJogLease{this};
    SoftLimits m_softLimits;
    QString m_softLimitNote; // the last jog refusal said for a soft limit
    QElapsedTimer m_trafficClock;
    QTimer m_safetyTimer{this};
    std::function<void()> m_safetyTimeout;
    quint64 m_safetyToken = 0;
    bool m_closing = false;
    bool m_losing = false;
};

} // namespace stepdeck

Q_DECLARE_METATYPE(stepdeck::LinkState)
