#pragma once
#include "LaserAxisMotion.h"
#include "LaserCodec.h"
#include "controller/Controller.h"
#include <QElapsedTimer>
#include <QTimer>

namespace stepdeck::laser {

// StepDeck in the laser's place: drives up to three motor axes that speak the laser marker's
// motor-axis protocol (manual: laser-motoraxis-rs232.en.txt). The protocol has two commands
// and no replies to them; the axes send a status response "after having reached its last
// commanded target position or after it has stopped", and may send one at any time.
//
// - moveAbsolute(): one "2<axis><target>" frame per axis; the request finishes when every
//   axis reported '0' (an axis that reports '1', the end switch, ends its part early; the
//   result value names it: {"endSwitch": ["Y"]}), or with Timeout after
//   ControllerOptions::arrivalTimeoutMs. Targets outside 0..99999 are refused, nothing sent.
// - moveRelative(): a target from the position the axis last reported in this session (or the
//   target it is still heading for); refused while no status frame told the position.
// - reference(): "1<axis>00000" for every axis with a direction other than 0; finishes on '2'
//   (or '0').
// - A new target for an axis replaces the old one (manual): a request still waiting for that
//   axis finishes Cancelled.
// - stop()/panic(): the protocol has none; refused (Unsupported) with noStopCommandText().
// - refreshStatus(): there is no status request; finishes once everything sent has left the
//   process, with the status as last reported.
// - Status frames are read at any time: positions, the switch each axis last reported, the
//   door (MachineStatus::doorOpen after '3' / '4').
// - sendRaw() (the traffic console): command frames in the bytes are tracked like any target
//   (moving, motion unconfirmed until the axis reports, the arrival deadline), so a close
//   while such a move runs warns that the axis may still be moving.
// This class owns the link, the status frames' decoding, the requests without motion and the
// safety contract; the targets and their tracking are LaserAxisMotion's.
class LaserAxisController : public Controller, private LaserAxisHost
{
    Q_OBJECT
public:
    LaserAxisController(Transport* transport, const ControllerOptions& options,
                        QObject* parent = nullptr);
    ~LaserAxisController() override;

    Capabilities capabilities() const override;
    ParameterSchema schema() const override { return {}; }

    void openLink(RequestId id) override;
    void readParameters(RequestId id, const QStringList& names) override;
    void writeParameters(RequestId id, const ParameterSet& values, bool verify) override;
    void moveRelative(RequestId id, const AxisVector& steps) override;
    void moveAbsolute(RequestId id, const AxisVector& targets) override;
    void reference(RequestId id, const QMap<Axis, int>& directions) override;
    void stop(RequestId id) override { refuseNoStopCommand(id); }
    void panic(RequestId id) override { refuseNoStopCommand(id); }
    void refreshStatus(RequestId id) override;
    void sendRaw(RequestId id, const QByteArray& bytes) override;
    void setPollInterval(int) override {} // nothing to poll

protected:
    // The safety contract of the Controller base. The protocol has no stop command: nothing
    // can be sent; closing or losing the link while a target is out leaves the motion
    // unconfirmed (the axis goes on to its target) until a status frame proves it stopped.
    void sendSafetyStop(std::function<void(bool acknowledged)> done) override;
    void abortHostSide(ErrorKind kind, const QString& message) override;
    bool motionMayBeRunning() const override;
    void applyJogVelocity(const AxisVelocities&) override {} // never non-zero: no jog stream
    QString jogRefusal() const override;

private:
    // --- LaserAxisHost: what the motion asks of the adapter ---
    Controller& controller() override { return *this; }
    const Controller& controller() const override { return *this; }
    bool requireLink(RequestId id) override;
    void succeed(RequestId id, const QVariant& value) override { finishOk(id, value); }
    void fail(RequestId id, ErrorKind kind, const QString& message) override
    {
        finishError(id, kind, message);
    }
    MachineStatus& statusToChange() override { return mutableStatus(); }
    void publish() override { publishStatus(); }
    void confirmStandstill() override { noteStandstillConfirmed(); }
    bool sendFrames(const QByteArray& bytes) override;
    void abort(ErrorKind kind, const QString& message) override { abortHostSide(kind, message); }

    void onTransportOpened();
    void onBytesWritten();
    void onData(const QByteArray& bytes);

    StatusDecoder m_decoder;
    LaserAxisMotion m_motion;
    QList<RequestId> m_syncs; // refreshStatus() waiting for the output to drain
    RequestId m_openId = 0;
    QTimer m_syncTimeout{this};
};

} // namespace stepdeck::laser
