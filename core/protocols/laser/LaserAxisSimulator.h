#pragma once
#include "LaserCodec.h"
#include "LaserSimAxis.h"
#include "sim/Simulator.h"
#include <QElapsedTimer>
#include <QTimer>
#include <array>

namespace stepdeck::laser {

// The axis side of the laser marker's motor-axis protocol: three motor axes X, Y, Z on one
// RS232 line (manual: laser-motoraxis-rs232.en.txt). It decodes the laser's 8-byte commands
// (malformed ones are ignored and counted), moves each axis by elapsed time (LaserSimAxis) and
// sends a status frame "after having reached its last commanded target position or after it
// has stopped" -- at the target, the end switch, the home switch of a home command, and when
// the door opens or closes. Faults: silence and dropped/corrupted frames (Simulator::faults()),
// garbage before every status frame, an end switch within reach (config(axis).endSwitch).
class LaserAxisSimulator : public Simulator
{
    Q_OBJECT
public:
    explicit LaserAxisSimulator(const SimulatorOptions& options, QObject* parent = nullptr);
    ~LaserAxisSimulator() override;

    void receive(const QByteArray& bytes) override;
    bool standingStill() override; // no axis moves (after advancing to now)

    // ---- the machine ----
    LaserSimAxisConfig& config(Axis axis) { return axis_(axis).config(); }
    void setSpeed(double unitsPerS); // every axis
    void powerOn(Axis axis, qint64 physical);
    // The door switch. Opening stops every axis ("usually stops the motor") and keeps its
    // target ("it should not prevent the motor from trying to reach its commanded target");
    // closing lets them go on. Reading of the manual: every axis that stops sends '3' and
    // every axis that goes on sends '4'; with no axis moving, axis X reports for the machine.
    void setDoorOpen(bool open);
    bool doorOpen() const { return m_doorOpen; }
    // Garbage fault: every status frame is preceded by a malformed line.
    void setGarbageBeforeStatus(bool on) { m_garbage = on; }
    // Sends a status frame on its own (tests: unsolicited frames).
    void reportStatus(Axis axis, Status status);
    // The machine's emergency stop (the protocol has no stop command): every axis stands
    // where it is and forgets its target; no status frame follows.
    void emergencyStop() override;

    // ---- observation ----
    QList<CommandFrame> receivedCommands() const { return m_commands; }
    void clearReceivedCommands() { m_commands.clear(); }
    int rejectedFrames() const { return m_rejected; }
    // Move commands the axes accepted, with their length in laser units from where the axis
    // stood (its own count) to the target, in order; zero-length ones are left out.
    using AcceptedMove = SimulatedMove;
    QList<SimulatedMove> acceptedMoves() const override { return m_accepted; }
    void clearAcceptedMoves() { m_accepted.clear(); }
    QList<QByteArray> sentStatusFrames() const { return m_sent; }
    qint64 position(Axis axis) override;
    bool isMoving(Axis axis) override;
    bool isHomed(Axis axis) const { return axis_(axis).homed(); }
    bool isTicking() const { return m_tick.isActive(); }

private:
    static size_t index(Axis axis);
    LaserSimAxis& axis_(Axis axis) { return m_axes[index(axis)]; }
    const LaserSimAxis& axis_(Axis axis) const { return m_axes[index(axis)]; }
    void execute(const CommandFrame& command);
    void sendStatus(Axis axis, Status status);
    void advanceToNow();
    void updateTimer();

    CommandDecoder m_decoder;
    std::array<LaserSimAxis, kAxisCount> m_axes;
    QList<CommandFrame> m_commands;
    QList<AcceptedMove> m_accepted;
    QList<QByteArray> m_sent;
    int m_rejected = 0;
    bool m_doorOpen = false;
    bool m_garbage = false;
    QTimer m_tick{this};
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
};

} // namespace stepdeck::laser
