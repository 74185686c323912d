#pragma once
#include "NanotecCodec.h"
#include "NanotecDriveClosedLoop.h"
#include <QByteArray>
#include <QList>
#include <QMap>
#include <array>

namespace stepdeck::nanotec {

// One simulated SMCI33/SMCI47-S drive: its settings in RAM, 32 records in a simulated
// EEPROM, the error memory and time-based motion in the modes of the manual. No I/O: the
// bus (NanotecSimulator) feeds it command bodies and sends what it answers.
class NanotecDrive
{
public:
    explicit NanotecDrive(int address);

    int address() const { return m_address; }

    struct Answer
    {
        QByteArray body;       // reply without address and CR; empty: no reply
        bool longForm = false; // long replies carry the address unpadded ("1:...", 1.2)
    };
    // Executes one command body (what follows "#<addr>"). Echoes even invalid values and
    // ignores them, answers '?' to unknown commands, exactly as the manual describes.
    Answer handle(const QByteArray& body);
    // Advances motion by dt seconds; returns unsolicited reply bodies (auto status 'j').
    QList<QByteArray> advance(double dt);
    bool isActive() const; // moving, settling or pausing between records

    // --- inspection and scenario set-up (tests, stepdeck-sim) ---
    qint64 value(char cmd) const { return m_params.value(cmd); }
    qint64 longValue(const QByteArray& keyword) const { return m_long.value(keyword); }
    qint64 position() const { return qRound64(m_count); }
    qint64 encoderPosition() const
    {
        return m_closedLoop.encoderConnected() ? qRound64(m_physical - m_encoderOffset)
                                               : m_closedLoop.frozenEncoder();
    }
    double physicalPosition() const { return m_physical; }
    double speed() const { return m_speed * m_dir; } // signed steps/s
    quint8 statusWord() const;
    bool ready() const { return m_run == Run::Idle && m_holdMs <= 0; }
    bool running() const { return m_run != Run::Idle; } // a run under way (before settling)
    // The external limit switch (input 6) is actuated at or beyond these physical positions.
    void setSwitches(double negative, double positive);
    bool externalSwitchActuated() const;
    void pushError(int code); // error memory (5.15)
    // Test fault: the encoder found the motor off its demand position (5.9/5.13: status bit
    // "Positionsfehler", error memory 'Position'); 'D' (5.14) clears it.
    void injectPositionError();
    int lastErrorSlot() const { return m_lastSlot; }
    bool answersDisabled() const { return m_silentMode; } // after '|0' (6.4)
    // Encoder, calibration (!101) and closed-loop reference run (!8) of manual 8.1.
    const DriveClosedLoop& closedLoop() const { return m_closedLoop; }
    void setEncoderConnected(bool connected)
    {
        m_closedLoop.setEncoderConnected(connected, encoderPosition());
    }
    void setCalibrationMs(int ms) { m_closedLoop.setCalibrationMs(ms); }

    struct Faults
    {
        bool silent = false;       // no answer and no action: a drive that went off the bus
        int garble = 0;            // the next N replies get a byte destroyed
        int wrongAddress = 0;      // the next N replies carry another address
        int wrongAddressValue = 0; // 0: address + 1
        // The next N 'ZY' replies report input 6 (the external switch, bit 0x20) inverted, as a
        // digit of line noise inside the value can: the protocol has no checksum to catch it.
        int switchInputNoise = 0;
        // Keeps '!101' / '!8' but does not run them on 'A' (a firmware without closed loop).
        bool closedLoopRunsIgnored = false;
        // Settings (command characters) echoed but not kept, as an invalid value would be:
        // a drive whose firmware ignores them.
        QByteArray ignoredSettings;
    };
    Faults faults;

private:
    enum class Run { Idle, Position, Speed, Flag, RefSeek, RefFree, FreeTravel, ClosedLoop };

    Answer handleLong(const QByteArray& body);
    Answer handleRead(const QByteArray& body);
    QByteArray handleValue(char c, const QByteArray& body); // commands with a number
    QByteArray handlePlain(char c, const QByteArray& body); // commands without one
    bool validSetting(char cmd, qint64 v) const;
    void applySetting(char cmd, qint64 v);
    void start();
    void stopNow();
    void finishRun(bool chain = true); // chain: repetitions and next record may follow
    void startRun();                   // A, or the next repetition / next record (6.13-6.16)
    void loadRecord(int n);
    QByteArray inputsWord() const; // 'ZY' (5.30)
    void checkSwitches(QList<QByteArray>* out);
    void stepPositioning(double dt);
    void stepSpeed(double dt);
    void stepFreeTravel(double dt); // free travel after a switch or to the index mark
    void beginFreeTravel(int dir, bool toReference);
    double acceleration() const; // steps/s^2 from 'b' (6.11)
    qint64 stepsPerRevolution() const;
    bool atIndexMark() const;
    int switchBehaviour(bool external, bool reference) const; // bit index in 'l', -1 invalid
    void moveBy(double steps);
    void startClosedLoopRun(qint64 mode); // !101 / !8 (NanotecDriveClosedLoop.h)
    void stepClosedLoop(double dt);
    int freeDirection(int behaviour) const; // 0 forward, 1 backward -> +1/-1

    int m_address;
    QMap<char, qint64> m_params;
    QMap<QByteArray, qint64> m_long;
    std::array<RecordData, kRecordCount + 1> m_eeprom; // 1..32
    std::array<int, kErrorSlots + 1> m_errors{};       // 1..32
    int m_lastSlot = 0;
    bool m_silentMode = false;
    bool m_positionError = false;
    DriveClosedLoop m_closedLoop;

    // motion
    Run m_run = Run::Idle;
    double m_physical = 0;      // steps, absolute (switches and index marks live here)
    double m_encoderOffset = 0; // I = physical - offset
    double m_count = 0;         // C, with the sub-step part of a run in progress
    double m_speed = 0;         // magnitude, steps/s
    int m_dir = 1;
    double m_target = 0;   // counter target of a positioning run
    double m_topSpeed = 0; // o, or n after the trigger (flag mode)
    bool m_flagTriggered = false;
    bool m_reference = false; // the run is a reference run (p3/p4)
    bool m_internalRef = false;
    int m_runsDone = 0;
    double m_holdMs = 0; // settle time / record pause: busy, not moving
    bool m_restartAfterHold = false;
    bool m_notifyWhenReady = false; // auto status 'j' (5.31) once the run is over
    double m_freeLeft = 0;          // steps left of a fixed free travel (index mark)
    bool m_wasSwitch = false;
    double m_lastPhysical = 0;
    double m_negSwitch = -3000, m_posSwitch = 3000;
};

} // namespace stepdeck::nanotec
