#pragma once
#include "bridge/LaserAnswerPolicy.h"
#include "bridge/LaserBridgeConfig.h"
#include "bridge/LaserBridgeLog.h"
#include "bridge/LaserBridgeMotion.h"
#include "controller/ControllerSession.h"
#include "protocols/laser/LaserCodec.h"
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace stepdeck {
class Transport;
}

namespace stepdeck::bridge {

// StepDeck as the motor axes of a laser marker (manual: laser-motoraxis-rs232.en.txt), with
// any controller behind it. This class is the laser side (the port, its frames, the answers,
// the door, the log); the controller side is LaserBridgeMotion. The bridge answers the laser's
// frames on the laser port (9600 8N1) and drives the controller only through its ControllerSession,
// respecting its capabilities and refusals -- so the CLI command `laser-bridge` and the GUI's Laser
// bridge page share it.
//
// Per laser axis (what is answered, and when nothing is: LaserAnswerPolicy):
// - home: the controller's reference run (its direction as Capabilities::referenceDirection
//   allows); answers '2' with the position after it (0).
// - move: goes to target x scale steps from the reference; answers '0' with the position in
//   laser units once the axis stands at the target. An axis not referenced since the bridge
//   started (or unreferenced by the controller since) is referenced first.
// - A target that arrives while the axis moves replaces the old one: controllers with a
//   ramped stop are stopped, and once they stand every axis goes on to its newest target;
//   others (no stop, or a stop that loses the position) first arrive, then go to the newest.
// - A move the controller refuses because another axis moves waits until it is idle; one it
//   refuses at an active limit switch is answered '1'; other refusals are logged and not
//   answered (the laser raises its timeout alarm).
// - An axis that stops at a limit switch is answered '1', at its reference switch '2'; one that
//   stops short for another reason (the operator's STOP or PANIC) is not answered: the
//   operator keeps priority. Targets that arrive while the operator jogs are dropped.
// - A target not answered (stopped short, position unknown, the controller failed or its link
//   went down) is logged as an error and shown in AxisView::failure at once; the laser raises
//   its own timeout alarm. No answer ever carries a position the controller does not know.
// - Malformed frames are logged and ignored; they never move anything.
// - Door (setDoorOpen, e.g. from a controller input): open stops motion where the controller
//   can and answers '3'; closed answers '4' and the axes go on to their targets.
class LaserBridge : public QObject
{
    Q_OBJECT
public:
    enum class Phase { Idle, Referencing, Moving, Waiting, Stopping, Failed };
    struct AxisView
    {
        Axis laserAxis = Axis::X;
        Axis controllerAxis = Axis::X;
        Phase phase = Phase::Idle;
        std::optional<laser::CommandFrame> target; // the laser's newest unanswered command
        bool referenced = false;                   // referenced by the bridge since it started
        std::optional<laser::StatusFrame> lastAnswer;
        QString failure; // the last target not answered and why; cleared by the next command
    };
    using LogEntry = LaserBridgeLogEntry;

    LaserBridge(ControllerSession* session, Transport* laserPort, const LaserBridgeConfig& config,
                QObject* parent = nullptr);
    ~LaserBridge() override;

    const LaserBridgeConfig& config() const { return m_config; }
    // Opens the laser port (9600 8N1): started() or failed() follows.
    void start();
    // Stops the motion the bridge started (where the controller has a stop), closes the laser
    // port; finished() follows (at once when nothing moves).
    void shutdown();
    bool isRunning() const { return m_running; }
    QList<AxisView> axes() const;
    static QString phaseName(Phase phase);
    // The door switch on a controller input: models that publish their digital inputs as the
    // bitmask MachineStatus::raw["inputs"] (bit 0 = input 1). Set means the door is open.
    // std::nullopt where the model publishes no inputs.
    static std::optional<bool> doorInputState(const MachineStatus& status, int input);
    static QString formatLogEntry(const LogEntry& entry)
    {
        return formatLaserBridgeLogEntry(entry);
    }

public Q_SLOTS:
    void setDoorOpen(bool open);

Q_SIGNALS:
    void started();
    void failed(const QString& reason);
    void finished();
    void logged(const stepdeck::bridge::LaserBridge::LogEntry& entry);
    void axisChanged(const stepdeck::bridge::LaserBridge::AxisView& view);

private:
    using Slot = LaserBridgeSlot;
    using Job = LaserBridgeSlot::Job;

    void onLaserOpened();
    void onLaserFailed(const QString& reason);
    void onLaserData(const QByteArray& bytes);
    void onCommand(const laser::CommandFrame& frame);
    void onStatus(const MachineStatus& status);        // the door input, then the motion
    void reply(Slot& slot, const LaserAnswer& answer); // the frame, else drop()
    void send(Slot& slot, const laser::StatusFrame& frame);
    // A target the bridge does not answer: logged, shown as the axis' failure.
    void drop(Slot& slot, const QString& why);
    void reportDoor(bool open);
    void log(LogEntry::Kind kind, const QString& text, const QByteArray& frame = {});
    void publish(const Slot& slot);
    void finishShutdown();
    LaserBridgeMotion::Hooks motionHooks();

    QPointer<ControllerSession> m_session;
    QPointer<Transport> m_laser;
    LaserBridgeConfig m_config;
    LaserAnswerPolicy m_answers;
    Capabilities m_caps;
    laser::CommandDecoder m_decoder;
    QMap<Axis, Slot> m_slots; // by laser axis
    LaserBridgeMotion m_motion;
    bool m_running = false;
    bool m_shuttingDown = false;
    bool m_doorOpen = false;
    bool m_doorReportPending = false; // '3' goes out when the stop for the door has settled
    QTimer m_shutdownTimeout{this};
};

} // namespace stepdeck::bridge

Q_DECLARE_METATYPE(stepdeck::bridge::LaserBridge::LogEntry)
Q_DECLARE_METATYPE(stepdeck::bridge::LaserBridge::AxisView)
