#pragma once
#include "ElabSimBoard.h"
#include "ElabSimCommands.h"
#include "model/Axis.h"
#include "sim/Simulator.h"
#include <QElapsedTimer>
#include <QTimer>

namespace stepdeck::elab {

// The device side of the E-LAB 3-axis protocol (manual: elab-3axis-stepper-controller.de.txt):
// every command of the control-character table with the ACK/NAK rules of its notes
// (ElabSimCommands), time-based motion per axis (ElabSimAxis), switches at configurable
// positions with the configured polarity, temperature, start and panic buttons (ElabSimBoard),
// the <DC2> step buffer with XOFF/XON (ElabSimStream) and fault injection. This class answers
// on the line and keeps the time: positions advance by elapsed time; a timer runs only while
// something moves.
class ElabSimulator : public Simulator
{
    Q_OBJECT
public:
    explicit ElabSimulator(const SimulatorOptions& options, QObject* parent = nullptr);
    ~ElabSimulator() override;

    void receive(const QByteArray& bytes) override;

    // Power-on state: setup incomplete, parameters cleared, positions 0, relays off, buffer
    // empty. The machine itself (switch positions, wiring, buttons, temperature) stays.
    void powerOnReset();

    // ---- fault injection (drop/corrupt/delay/silent: faults() of the base class) ----
    // The next `count` commands that the controller answers with ACK/NAK are refused with NAK
    // and not executed. Requests (ENQ, HT, ETB, ETX, LF) are not affected.
    void forceNak(int count) { faults().forceNak = qMax(0, count); }
    // The reply to the next command with this control byte is lost (e.g. the ACK of a <DC4>).
    void dropNextReplyTo(char code) { m_dropReplyTo = code; }
    int forcedNaksPending() const { return faults().forceNak; }

    // ---- the machine around the board ----
    void setTemperature(int celsius);
    int temperature() const { return m_board.temperature; }
    void setStartButton(bool pressed) { m_board.startButton = pressed; }
    bool startButton() const { return m_board.startButton; }
    void setPanicButton(bool pressed); // Not-Aus: stops everything, sets tmPanicStop
    bool panicButton() const { return m_board.panicButton; }
    // Switches actuated by hand (or stuck), independent of the position.
    void setLimitSwitchActuated(Axis axis, bool actuated);
    void setReferenceSwitchActuated(Axis axis, bool actuated);
    void setLimitPositions(Axis axis, qint64 minimum, qint64 maximum);
    void setReferencePosition(Axis axis, qint64 position, qint64 window);
    void setSwitchWiring(Axis axis, bool limitActiveHigh, bool referenceActiveHigh);
    ElabSimSwitchConfig switchConfig(Axis axis) const;
    void setPosition(Axis axis, qint64 steps); // places the carriage (test setup)
    void setStreamBuffer(int capacity, int highWater, int lowWater);

    // ---- observation (tests, stepdeck-sim) ----
    quint16 machineState();
    quint8 axeState();
    qint64 position(Axis axis) override;
    bool isMoving(Axis axis) override;
    bool isBusy();
    bool standingStill() override { return !isBusy(); }
    // ForceStopMove as the host sends it (the reply goes nowhere).
    void emergencyStop() override;
    // ForceStopMove, ForcePanicStop (single or doubled) and a zero jog rate (<DC4>0,0,0).
    bool isStopFrame(const QByteArray& frame) const override;
    qint64 remainingSteps(Axis axis);
    bool limitSwitchActive(Axis axis) const;
    bool referenceSwitchActive(Axis axis) const;
    bool limitSwitchLevelHigh(Axis axis) const;
    ElabSimRamp rampParameters(Axis axis) const;
    int drivePower() const { return m_board.drivePower; }
    quint32 spindleRpm() const { return m_board.spindleRpm; }
    bool coolant() const { return m_board.coolant; }
    // <DC2> stream: single steps executed per axis (absolute count), step bytes executed,
    // bytes that arrived with the buffer full, bytes refused (panic, limit, no setup, stopped).
    qint64 executedSteps(Axis axis) const;
    qint64 executedStepBytes() const { return m_board.stream.executed(); }
    qint64 streamOverflows() const { return m_board.stream.overflows(); }
    qint64 streamRejected() const { return m_board.stream.rejected(); }
    int streamBuffered() const { return m_board.stream.size(); }
    qint64 streamUnderruns() const { return m_board.stream.underruns(); }
    void clearStreamCounters() { m_board.stream.clearCounters(); }
    // The step bytes the board executed, in order (ElabSimStream::executedRecord).
    const std::vector<quint8>& executedStepRecord() const
    {
        return m_board.stream.executedRecord();
    }
    // Where the axes stood after each executed stream vector and where each move came to rest
    // (ElabSimBoard::trace).
    const std::vector<Triple<qint64>>& positionTrace() const { return m_board.trace; }
    bool streamHostPaused() const { return m_board.stream.hostPaused(); }
    // The most <DC2> pairs that arrived after one of the board's XOFFs, before its XON.
    int streamMostPairsAfterXOff() const { return m_board.stream.mostPairsAfterXOff(); }
    bool isTicking() const { return m_tick.isActive(); }
    qint64 commandsReceived() const { return m_commandCount; }
    // Positioning moves (FastMove XY/XYZ/Z) the board accepted with ACK, per axis, in order:
    // soak runs compare them with the moves the host was told succeeded.
    using AcceptedMove = SimulatedMove;
    QList<SimulatedMove> acceptedMoves() const override { return m_acceptedMoves; }
    QString lastNakReason() const { return m_lastNakReason; } // why the last NAK was sent

private:
    void handle(const Command& cmd);
    bool handleRequest(const Command& cmd);
    void doStreamStep(const Command& cmd);
    void journal(const Command& accepted);
    void ack() { send(QByteArray(1, ctrl::ACK)); }
    void nak() { send(QByteArray(1, ctrl::NAK)); }
    void advanceToNow();
    void sendFlowControl();
    void updateTimer();

    CommandDecoder m_decoder;
    ElabSimBoard m_board;
    ElabSimCommands m_commands{m_board};
    QTimer m_tick{this};
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
    qint64 m_commandCount = 0;
    QList<AcceptedMove> m_acceptedMoves;
    QString m_lastNakReason;
    char m_dropReplyTo = 0;
};

} // namespace stepdeck::elab
