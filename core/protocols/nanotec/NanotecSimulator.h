#pragma once
#include "NanotecDrive.h"
#include "sim/Simulator.h"
#include <QElapsedTimer>
#include <QTimer>
#include <memory>

namespace stepdeck::nanotec {

// A bus of simulated Nanotec drives behind one link (SimulatorOptions::addresses; default
// 1, 2, 3). It frames host commands, hands each to the drive at its address (or to all for
// '*'), and sends the replies: three-digit address for short replies, unpadded for long ones
// (the manual's examples "001s1000" and "1:CL_motor_pp+50"). With several drives on the bus
// a broadcast makes them all answer at once, which on RS485 is a collision: garbage.
// Motion advances by elapsed time; the timer runs only while a drive is active.
class NanotecSimulator : public Simulator
{
    Q_OBJECT
public:
    explicit NanotecSimulator(const SimulatorOptions& options, QObject* parent = nullptr);
    ~NanotecSimulator() override;

    void receive(const QByteArray& bytes) override;

    // The drive that currently answers at `address` (after 'm' it moves), or nullptr.
    NanotecDrive* drive(int address) const;
    NanotecDrive* addDrive(int address); // nullptr if taken or invalid
    QList<NanotecDrive*> drives() const;
    bool standingStill() override; // no drive turns its motor (after advancing to now)

    // The probes of the base class name the drive at address n axis n-1: X=1, Y=2, Z=3 as the
    // default machine (defaultAxisAddresses()), then U=4, axis5=5, ... axis254=254, as a bus
    // of drives numbered 1..N is mapped by --axes (issue 32). An axis without a drive at its
    // address neither moves nor has a position.
    static int probeAddress(Axis axis) { return axis.index() + 1; }
    bool isMoving(Axis axis) override; // the drive is active (moving, settling, pausing)
    qint64 position(Axis axis) override;
    QList<SimulatedMove> acceptedMoves() const override;      // startedMoves() by axis
    void emergencyStop() override;                            // '#*S' (6.2), replies go nowhere
    bool isStopFrame(const QByteArray& frame) const override; // 'S' to one drive or to all

    // Positioning runs ('A' in mode 1, positioning p1/p2) the drives started, in order, with
    // the steps each was to travel: soak runs compare them with the host's successful moves.
    struct StartedMove
    {
        int address;
        qint64 steps;
        // What the bench and the coordination tests measure at the device (issue 30): the top
        // speed 'o' it ran at (6.9), when 'A' started it and when its run ended (at the target,
        // or stopped; -1: not yet), in µs of the simulator's clock.
        qint64 maxFrequency = 0;
        qint64 startedUs = 0;
        qint64 arrivedUs = -1;
    };
    const QList<StartedMove>& startedMoves() const { return m_startedMoves; }
    // ---- fault injection per drive (bus-wide faults: Simulator::faults()) ----
    void setDriveSilent(int address, bool silent);
    void garbleReplies(int address, int count);
    void replyFromWrongAddress(int address, int count, int wrongAddress = 0);
    void flipSwitchInputInReplies(int address, int count); // Faults::switchInputNoise
    // Closed loop (manual 8.1, NanotecDriveClosedLoop.h): an unplugged encoder makes the
    // calibration and closed-loop reference runs fail; how long a calibration run takes.
    void setEncoderConnected(int address, bool connected);
    void setCalibrationMs(int ms); // every drive on the bus
    // The drive echoes writes of this setting (e.g. 'i') and keeps its old value.
    void ignoreSetting(int address, char command);
    // The drive loses power and comes back: its motor stops, its RAM settings and position
    // are those of power-on (NanotecDrive's defaults: relative positioning, p1) and it answers
    // nothing for bootMs while the bootloader waits for '@A' (5.32: half a second).
    void powerCycle(int address, int bootMs = 500);

private:
    void execute(const Command& command);
    void reply(NanotecDrive* drive, int address, const NanotecDrive::Answer& answer);
    QByteArray frame(int address, const NanotecDrive::Answer& answer) const;
    void tick();
    void ensureTicking();
    void noteArrival(int address, qint64 us); // the last started move of that drive

    std::vector<std::unique_ptr<NanotecDrive>> m_drives;
    CommandDecoder m_decoder;
    QList<StartedMove> m_startedMoves;
    QTimer m_timer{this};
    QElapsedTimer m_clock;
    qint64 m_lastTickUs = 0;
};

} // namespace stepdeck::nanotec
