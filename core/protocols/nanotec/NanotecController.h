#pragma once
#include "NanotecBus.h"
#include "NanotecExchange.h"
#include "NanotecHeldSettings.h"
#include "NanotecHostDrive.h"
#include "NanotecJog.h"
#include "NanotecMotion.h"
#include "NanotecOperations.h"
#include "NanotecParameters.h"
#include "NanotecRecords.h"
#include "NanotecSchema.h"
#include "NanotecStatus.h"
#include "NanotecStop.h"
#include "controller/Controller.h"
#include "controller/StatusPoller.h"
#include <QElapsedTimer>

namespace stepdeck::nanotec {

class NanotecClosedLoop;

// Adapter for a bus of Nanotec SMCI33 / SMCI47-S drives: one drive per axis, each at its
// RS485 address (ControllerOptions::axisAddresses; default X=1, Y=2, Z=3), all behind one
// half-duplex link run by NanotecBus.
//
// Writes are verified by default: the drives echo even invalid values and silently ignore
// them (every "Antwort der Firmware" paragraph), so only a read-back with 'Z' confirms a write.
//
// This class owns the link, the drive table and the poller and implements Controller by
// handing each request to the part that does it:
//   NanotecExchange    one exchange with the drive of an axis: address, failure texts,
//                      read-back, the 'A' whose echo got lost
//   NanotecStatus      initialisation, status sweeps, auto status 'j', MachineStatus
//   NanotecMotion      positioning, reference runs, velocity moves, refusals
//   NanotecJog         speed-mode jog with the drive's own ramp
//   NanotecStop        stop, panic, the safety stop and its confirmation
//   NanotecParameters  parameter reads and verified writes
//   NanotecRecords     records (section 4) and the error memory (5.15)
//   NanotecOperations  modelOperation(), bus scan and the console
//   NanotecClosedLoop  the closed-loop workflow (manual 8.1)
//
// modelOperation() names (args -> result value):
//   "scan"               {first=1, last=254, timeoutMs=40} -> list of {address, hardware,
//                        interface, date, firmware}
//   "read-record"        {axis, record 0..32 (0: RAM)} -> {axis, record, values{name: value}}
//   "read-all-records"   {axis} -> list of the above for records 1..32
//   "write-record"       {axis, record 1..32, values{name: value}} -> written, saved, verified
//   "load-record"        {axis, record 1..32} -> the record now in RAM
//   "save-record"        {axis, record 1..32} -> RAM record stored in EEPROM ('>', 6.5)
//   "start-record"       {axis, record 0..32} -> load (unless 0) and start ('y', 'A')
//   "read-error-memory"  {axis} -> {axis, last, entries[{slot, code, name, description}]}
//   "reset-position-error" {axis}  'D' (5.14): position := encoder position
//   "reset-position"     {axis}    'c' (5.18): position := 0, counts as referenced
//   "trigger"            {axis}    'T' (7.8), flag positioning mode
//   "speed-step"         {axis, up=true}  '+' / '-' (7.6, 7.7), speed mode
//   "reference"          {axes{X:-1,...}, type="external"|"internal"} (6.6 p4 / p3)
//   the closed-loop workflow of model/ClosedLoop.h (manual 8.1), run by NanotecClosedLoop
class NanotecController : public Controller
{
    Q_OBJECT
    // The parts run requests on the controller's link, drive table and status.
    friend class NanotecExchange;
    friend class NanotecStatus;
    friend class NanotecMotion;
    friend class NanotecJog;
    friend class NanotecStop;
    friend class NanotecParameters;
    friend class NanotecRecords;
    friend class NanotecOperations;
    friend class NanotecClosedLoop;
    friend class NanotecClosedLoopRun;

public:
    NanotecController(Transport* transport, const ControllerOptions& options,
                      QObject* parent = nullptr);
    ~NanotecController() override;

    Capabilities capabilities() const override;
    ParameterSchema schema() const override;

    void openLink(RequestId id) override;
    void readParameters(RequestId id, const QStringList& names) override;
    void writeParameters(RequestId id, const ParameterSet& values, bool verify) override;
    void moveRelative(RequestId id, const AxisVector& steps) override;
    void moveAbsolute(RequestId id, const AxisVector& targets) override;
    void reference(RequestId id, const QMap<Axis, int>& directions) override;
    void velocityMove(RequestId id, const AxisVector& stepsPerS) override;
    void stop(RequestId id) override;
    void panic(RequestId id) override;
    void reset(RequestId id) override; // clears the emergency-stop latch after panic
    void refreshStatus(RequestId id) override;
    void sendRaw(RequestId id, const QByteArray& bytes) override;
    void setPollInterval(int ms) override;
    void scanBus(RequestId id) override;
    void modelOperation(RequestId id, const QString& name, const QVariantMap& args) override;

    QList<Axis> axes() const { return m_drives.keys(); }
    int addressOf(Axis axis) const { return m_drives.value(axis).address; }
    NanotecBus* bus() const { return m_bus; }
    // Minimum sweep period the line allows for the drives that answer (19200 8N1).
    int sweepBudgetMs() const { return m_sweep.sweepBudgetMs(); }
    int pollIntervalMs() const { return m_poller.interval(); } // start to start, as set

protected:
    void applyJogVelocity(const AxisVelocities& stepsPerS) override;
    QString jogRefusal() const override;
    QString jogAxisRefusal(Axis axis, double target) const override;
    // The drive's own speed-mode ramp and the bus latency (NanotecJog).
    double jogStopDistance(Axis axis, double speed) const override;
    // Safety contract (NanotecStop): 'S' to every drive that may move, answering or not
    // (6.2: in speed mode the only way to end it), then '#*S' to all as the last resort.
    void sendSafetyStop(std::function<void(bool)> done) override;
    void abortHostSide(ErrorKind kind, const QString& message) override;
    bool motionMayBeRunning() const override;
    int safetyStopTimeoutMs() const override;

private:
    struct PendingScan
    {
        RequestId id = 0;
        int first = 1, last = 254, timeoutMs = 40;
    };

    void onTransportOpened();
    void finishWith(RequestId id, const Failure& failure, const QVariant& value = {});
    // The axis' name in messages: the operator's ("feeder", issue 32) or the default.
    QString nameOf(Axis axis) const;
    QString driveName(Axis axis) const;
    qint64 nowMs() const { return m_clock.elapsed(); } // for m_held
    // The drive named by args["axis"] (default X), or null after failing the request.
    HostDrive* driveFor(const QVariantMap& args, RequestId id);

    NanotecBus* m_bus = nullptr;
    NanotecClosedLoop* m_closedLoop = nullptr; // child
    StatusPoller m_poller{this};
    QMap<Axis, HostDrive> m_drives;
    RequestId m_pendingOpen = 0;
    std::optional<PendingScan> m_pendingScan; // scan asked for while the port was closed
    QString m_configError; // invalid axis map: every request is refused with this
    bool m_panic = false;
    bool m_initialising = false;
    int m_userPollMs = 50;
    NanotecHeldSettings m_held; // what read-backs showed and nothing changed since
    QElapsedTimer m_clock;

    NanotecExchange m_exchange{*this};
    NanotecStatus m_sweep{*this};
    NanotecMotion m_motion{*this};
    NanotecJog m_jog{*this};
    NanotecStop m_stop{*this};
    NanotecParameters m_parameters{*this};
    NanotecRecords m_records{*this};
    NanotecOperations m_operations{*this};
};

} // namespace stepdeck::nanotec
