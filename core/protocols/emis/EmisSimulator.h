#pragma once
#include "EmisGrammar.h"
#include "EmisSimAxis.h"
#include "sim/Simulator.h"
#include <QElapsedTimer>
#include <QTimer>
#include <array>
#include <utility>

namespace stepdeck::emis {

// The device side of an SMC-IC4 (chapter 9): four motors with ramps, reference switches on
// inputs 1-4, inputs 5-8 set by tests, seven outputs, the "##" system parameters (loaded into
// the working values at power-on), input programs, and faults.
//
// Replies follow the manual's examples literally: "@V SMC-IC4 v1.07<ACK>", "$Hx<NAK>" then
// "<DC1>", "<NAK> " then "<DC1>" for vector moves, "<ACK> Ready! <ACK> <ACK> <ACK> <ACK>" for
// system parameters, "*PESYS <ACK>", "*PEIN1 <ACK>". Invalid commands or values and moves of a
// motor that is still moving are answered with <BEL> and not executed.
//
// Readings where the manual is silent:
// - "##" writes are stored for the next power-on (powerCycle()); only ##REFSW, which has no
//   working command, takes effect at once.
// - After a reference run the board's position counter is 0 (after leaving the switch by the
//   offset); at power-on it starts at 0 wherever the carriage stands.
// - Programming an input (*PWIN..<ETX>) stores the program; running it on an input edge is
//   not simulated.
// - *PRSYS lists the stored entries as "##<entry>" separated by CR LF, closed by <ACK>.
// - A "##" write answers its <ACK> at once, then "Ready!" and the further <ACK>s one flash
//   write time apart (setFlashWriteMs); kStoredAcks of them, or one per motor the entry
//   names (setStoredAcksPerMotor), the two readings of 9.14. Commands that come meanwhile
//   wait until the flash is written (one controller, busy writing).
class EmisSimulator : public Simulator
{
    Q_OBJECT
public:
    static constexpr const char* kFirmware = "SMC-IC4 v1.07";
    struct Working
    {
        QMap<Axis, qint64> startSpeed, workSpeed, offset, resolution, runCurrent, idleCurrent;
        qint64 referenceSpeed = 400;
        qint64 ramp = 100;
        bool interpolation = true;
    };
    struct InputProgram
    {
        QByteArray title;
        QList<QByteArray> commands;
    };

    explicit EmisSimulator(const SimulatorOptions& options, QObject* parent = nullptr);
    ~EmisSimulator() override;

    bool standingStill() override { return !anyMoving(); }
    void receive(const QByteArray& bytes) override;

    // ---- what the device saw and does ----
    QList<QByteArray> receivedCommands() const { return m_commands; } // framed texts, in order
    void clearReceivedCommands() { m_commands.clear(); }
    qint64 position(Axis axis) const; // the board's counter
    qint64 position(Axis axis) override { return std::as_const(*this).position(axis); }
    qint64 physicalPosition(Axis axis) const { return axisRef(axis).physical(); }
    bool isMoving(Axis axis) const;
    bool isMoving(Axis axis) override { return std::as_const(*this).isMoving(axis); }
    bool anyMoving() const;
    bool isReferenced(Axis axis) const { return m_referenced[slot(axis)]; }
    QList<bool> inputLevels() const;
    bool output(int number) const; // 1..7
    const Working& working() const { return m_working; }
    QList<SystemEntry> storedEntries() const { return m_stored; }
    std::optional<InputProgram> program(int input) const;
    int arrivalsDropped() const { return m_arrivalsDropped; }
    // Vector moves (9.11) the board accepted, per axis with their relative length in steps
    // (absolute targets converted at acceptance), in order; zero-length targets are left out.
    struct AcceptedMove
    {
        Axis axis;
        qint64 steps;
        qint64 workSpeed = 0; // the axis' work speed (#E1, 9.5) when it was accepted
        // What the bench and the coordination tests measure at the device (issue 30): the
        // speed the axis ran at (with interpolation, 9.12, the share that brings it in with the
        // others), when the move was accepted and when its <DCn> went out (-1: not yet), in µs
        // of the simulator's clock.
        double runSpeed = 0;
        qint64 acceptedUs = 0;
        qint64 arrivedUs = -1;
    };
    // The probe the soak and the fault matrix ask (Simulator::acceptedMoves) ...
    QList<SimulatedMove> acceptedMoves() const override;
    // ... and the same moves with the work speed each ran at.
    QList<AcceptedMove> acceptedMovesWithSpeed() const { return m_accepted; }
    // Moves and reference runs refused with <BEL> because a named motor was still moving.
    int busyRefusals() const { return m_busyRefusals; }

    // ---- scenario and faults ----
    void setPhysicalPosition(Axis axis, qint64 steps); // the board's counter does not change
    void setSwitchPosition(Axis axis,
                           std::optional<qint64> steps);  // active at/below; nullopt: none
    void setSwitchWiring(Axis axis, bool normallyClosed); // the switch as wired
    void setInput(int number, bool level);                // inputs 5..8
    // Inputs 5..8: what the machine wires to them (inputs 1..4 are the reference switches,
    // manual 5.2, driven by the simulated carriages).
    QList<int> settableInputs() const override { return {5, 6, 7, 8}; }
    bool setSettableInput(int number, bool level) override;
    void dropArrivals(int count); // the next `count` <DCn> are not sent (the motor still stops)
    void bellOn(const QByteArray& command) { m_bellOn = command; } // <BEL> the next time it comes
    // A board that refuses the input query while a motor moves (<BEL>: "busy", a reading the
    // manual allows, chapter 9 introduction).
    void setBellOnPollWhileMoving(bool on) { m_bellOnPollWhileMoving = on; }
    void setFlashWriteMs(int ms) { m_flashWriteMs = qMax(0, ms); } // 0: the whole reply at once
    void setStoredAcksPerMotor(bool on) { m_storedAcksPerMotor = on; }
    void withholdStoredAcks(int count) { m_withheldAcks = count; } // the next "##" sends fewer
    void powerCycle(); // working values from the stored ones, counters 0, outputs off
    // The machine's emergency-stop circuit (the board has no stop command): every motor
    // stands where it is at once, reference runs are abandoned, no <DCn> follows.
    void emergencyStop() override;
    // A button on the reset input (5.8): every motor stops where it is, no <DCn> follows, then
    // the board starts like after a power cycle; while it starts (bootMs; the manual gives no
    // time) it takes no command and answers nothing.
    void externalReset(int bootMs);

private:
    // An axis' place in the per-axis arrays: its number 1..4 less one (the codec's table).
    static std::size_t slot(Axis axis) { return std::size_t(axisNumber(axis) - 1); }
    EmisSimAxis& axisRef(Axis axis) { return m_axes[slot(axis)]; }
    const EmisSimAxis& axisRef(Axis axis) const { return m_axes[slot(axis)]; }
    void execute(const CommandDecoder::Frame& frame);
    QByteArray run(const Command& c); // the reply; empty: none
    QByteArray runProgramming(const Command& c, char terminator);
    QByteArray runVector(const Command& c);
    QByteArray runHome(const Command& c);
    QByteArray runSystemWrite(const Command& c);
    void applyWorking(const Command& c);
    void storeEntry(const SystemEntry& entry);
    void loadWorkingFromStored();
    bool switchActive(Axis axis, qint64 physical) const;
    bool switchLevel(Axis axis, qint64 physical) const;
    EmisSimAxis::Profile profile(Axis axis) const;
    void startNextReference();
    void arrived(Axis axis);
    void tick();
    void ensureTicking();
    void flashWritten(); // the next part of a "##" reply; input that waited is taken then

    std::array<EmisSimAxis, 4> m_axes;
    std::array<qint64, 4> m_origin{}; // physical step that the board's counter calls 0
    std::array<bool, 4> m_referenced{};
    std::array<std::optional<qint64>, 4> m_switchAt;
    std::array<bool, 4> m_wiredNc{};
    std::array<bool, 4> m_referencing{};
    QList<Axis> m_referenceQueue;       // sequential reference runs still to do ($Hxyzu)
    std::array<bool, 4> m_freeInputs{}; // inputs 5..8
    std::array<bool, 7> m_outputs{};
    Working m_working;
    QList<SystemEntry> m_stored;
    QMap<int, InputProgram> m_programs;
    int m_programming = 0; // input being programmed (9.17), 0: none
    bool m_programHeader = false;
    InputProgram m_draft;
    QList<AcceptedMove> m_accepted;
    int m_dropArrivals = 0;
    int m_arrivalsDropped = 0;
    int m_busyRefusals = 0;
    QByteArray m_bellOn;
    bool m_bellOnPollWhileMoving = false;
    int m_flashWriteMs = 10;
    bool m_storedAcksPerMotor = false;
    int m_withheldAcks = 0;
    QList<QByteArray> m_flashParts; // the rest of a "##" reply, one part per flash write
    QTimer m_flashTimer{this};
    QByteArray m_waitingInput; // received while the flash is written
    QElapsedTimer m_booting;   // valid: restarting after a reset until m_bootMs
    int m_bootMs = 0;
    CommandDecoder m_decoder;
    QList<QByteArray> m_commands;
    QTimer m_timer{this};
    QElapsedTimer m_clock;
    qint64 m_lastTickUs = 0;
};

} // namespace stepdeck::emis
