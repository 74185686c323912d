#pragma once
#include "NanotecBus.h"
#include "NanotecSchema.h"
#include "controller/Controller.h"
#include "controller/StatusPoller.h"

namespace stepdeck::nanotec {

class NanotecClosedLoop;

// Adapter for a bus of Nanotec SMCI33 / SMCI47-S drives: one drive per axis, each at its
// RS485 address (ControllerOptions::axisAddresses; default X=1, Y=2, Z=3), all behind one
// half-duplex link run by NanotecBus.
//
// Writes are verified by default: the drives echo even invalid values and silently ignore
// them (every "Antwort der Firmware" paragraph), so only a read-back with 'Z' confirms a write.
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
    // Drives calibration and closed-loop reference runs through the exchange steps below.
    friend class NanotecClosedLoop;

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
    int sweepBudgetMs() const;

protected:
    void applyJogVelocity(const AxisVelocities& stepsPerS) override;
    QString jogRefusal() const override;
    QString jogAxisRefusal(Axis axis, double target) const override;
    // The drive's own speed-mode ramp and the bus latency (NanotecMotion.cpp).
    double jogStopDistance(Axis axis, double speed) const override;
    // Safety contract (NanotecStop.cpp): 'S' to every drive that may move, answering or not
    // (6.2: in speed mode the only way to end it), then '#*S' to all as the last resort.
    void sendSafetyStop(std::function<void(bool)> done) override;
    void abortHostSide(ErrorKind kind, const QString& message) override;
    bool motionMayBeRunning() const override;
    int safetyStopTimeoutMs() const override;

private:
    static constexpr int kMaxRampWaitMs = 3000; // a longer ramp-down is cut short by 'S'
    enum class Jog { Idle, Starting, Running, Stopping };
    struct Drive
    {
        Axis axis = Axis::X;
        int address = 1;
        bool responding = true;
        int misses = 0;
        QString firmware;
        std::optional<qint64> status; // last '$' / 'j' word (5.21)
        qint64 position = 0;          // last 'C'
        std::optional<qint64> inputs; // last 'ZY' (5.30)
        qint64 limitSwitchType = 0;   // 'e' (5.7)
        qint64 minFrequency = 400;    // 'u', 'o', 'b' caches for speed-mode ramps
        qint64 maxFrequency = 1000;
        qint64 ramp = 2364;
        bool motionPending = false; // 'A' sent, waiting for ready
        bool referencing = false;
        bool positionErrorReported = false;
        Jog jog = Jog::Idle;
        bool jogBusy = false;       // a jog sequence is on the bus
        bool stopScheduled = false; // a zero rate waits out the ramp's zero crossing
        bool velocityMove = false;  // speed mode started by velocityMove (no lease)
        double jogDesired = 0;
        double jogApplied = 0;
        qint64 savedMaxFrequency = 0; // 'o' before speed mode, restored afterwards
    };

    struct Failure
    {
        ErrorKind kind = ErrorKind::None;
        QString message;
        bool ok() const { return kind == ErrorKind::None; }
    };
    using Done = std::function<void(const Failure&)>;
    using Step = std::function<void(const Done&)>;
    using Check = std::function<Failure(const Reply&)>;

    // --- step helpers (NanotecOperations.cpp) ---
    void runSteps(QList<Step> steps, Done done);
    static void runFrom(std::shared_ptr<QList<Step>> steps, int index, Done done);
    Step tolerant(Step step); // failures are logged, the sequence goes on
    static Check sink(std::function<void(qint64)> store);
    Step exchange(Axis axis, const QByteArray& body, Check check = {},
                  NanotecBus::Priority priority = NanotecBus::Priority::Command, int retries = 0,
                  int timeoutMs = 0);
    // Reads 'Z<cmd>' and fails VerifyFailed unless it equals expected (the drive echoes
    // invalid values and silently ignores them, so only a read-back proves a setting).
    Step expectValue(Axis axis, const QByteArray& cmd, qint64 expected);
    bool mayMove(const Drive& d) const; // as far as the host can tell
    Step wait(int ms);
    Failure outcomeFailure(Axis axis, const QByteArray& body, NanotecBus::Outcome outcome,
                           const Reply& reply);
    void finishWith(RequestId id, const Failure& failure, const QVariant& value = {});
    QString driveName(Axis axis) const;
    Drive* driveFor(const QVariantMap& args, RequestId id);

    // --- link and status (NanotecController.cpp) ---
    void onTransportOpened();
    void initialiseDrives();
    void onPollDue();
    void pollDrive(QList<Axis> remaining, bool withInputs, std::shared_ptr<bool> answered);
    void onUnsolicited(const Reply& reply);
    void applyStatusWord(Drive& d, qint64 word);
    void noteAnswer(Drive& d, bool answered);
    void updateStatus();
    int pollTimeoutMs() const;
    void scan(RequestId id, int first, int last, int timeoutMs); // NanotecOperations.cpp
    void runPendingScan();

    // --- motion (NanotecMotion.cpp) ---
    QString motionRefusal(Axis axis, bool needsPosition) const;
    QString unknownAxes(const QList<Axis>& axes) const;
    QString belowStartFrequency(Axis axis, double stepsPerS) const; // non-empty: refused
    // verify: per axis the settings that must read back before 'A' ('!', 'p', 's', 'd', 'o').
    void startPositioning(RequestId id, const QMap<Axis, QList<QByteArray>>& setup,
                          bool referenceRun,
                          const QMap<Axis, QMap<QByteArray, qint64>>& verify = {});
    void pumpJog(Axis axis, bool zeroConfirmed = false);
    Step setting(Axis axis, const QByteArray& body); // an idempotent setting, retried once
    Step startRun(Axis axis); // 'A', its lost echo settled by the status word
    QList<Step> rampDownSteps(Drive& d, NanotecBus::Priority priority);
    int rampTimeMs(const Drive& d, double fromHz) const;
    void referenceWithType(RequestId id, const QMap<Axis, int>& directions, bool internal);
    void confirmStopped(RequestId id, QList<Axis> axes, const QString& context);

    // --- parameters, records, error memory (NanotecParameters.cpp) ---
    Step readStep(Axis axis, const ParamDef& def, std::function<void(qint64)> sink,
                  std::shared_ptr<QMap<QByteArray, qint64>> cache);
    Step writeStep(Axis axis, const ParamDef& def, qint64 wire);
    Step verifyStep(Axis axis, const ParamDef& def, qint64 expected,
                    std::shared_ptr<QMap<QByteArray, qint64>> cache);
    void noteWritten(Drive& d, const ParamDef& def, qint64 wire);
    QList<Step> motorAddressSteps(Axis axis, int address, bool verify);
    // Why a parameter write is refused before anything is sent (empty: it is not).
    QString writeRefusal(const ParameterSet& values) const;
    void readRecord(RequestId id, Axis axis, int record);
    void readAllRecords(RequestId id, Axis axis);
    void writeRecord(RequestId id, Axis axis, int record, const QVariantMap& values);
    void loadOrSaveRecord(RequestId id, Axis axis, int record, bool save);
    void readErrorMemory(RequestId id, Axis axis);
    Step readRecordStep(Axis axis, int record, std::shared_ptr<QVariantMap> out);

    NanotecBus* m_bus = nullptr;
    NanotecClosedLoop* m_closedLoop = nullptr; // child
    StatusPoller m_poller{this};
    QMap<Axis, Drive> m_drives;
    RequestId m_pendingOpen = 0;
    struct PendingScan
    {
        RequestId id = 0;
        int first = 1, last = 254, timeoutMs = 40;
    };
    std::optional<PendingScan> m_pendingScan; // scan asked for while the port was closed
    QString m_configError; // invalid axis map: every request is refused with this
    bool m_panic = false;
    bool m_initialising = false;
    int m_userPollMs = 50;
    quint64 m_sweeps = 0;
};

} // namespace stepdeck::nanotec
