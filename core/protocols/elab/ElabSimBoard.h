#pragma once
#include "ElabCodec.h"
#include "ElabSimAxis.h"
#include "ElabSimStream.h"
#include "model/Axis.h"
#include <array>
#include <vector>

namespace stepdeck::elab {

// The state of the simulated E-LAB board and the machine around it (axes, <DC2> buffer,
// setup, outputs, temperature, buttons), with what follows from it alone: the rules of the
// control-character table, the status words, stops, limit switches and the motion of a time
// slice. No I/O and no clock: ElabSimulator brings it up to now and answers on the line;
// ElabSimCommands changes it by command.
class ElabSimBoard
{
public:
    using Mode = ElabSimAxis::Mode;

    std::array<ElabSimAxis, 3> axes;
    ElabSimStream stream;
    int setupDone = 0; // bit 0 start speed, bit 1 max speed, bit 2 acceleration
    int drivePower = 0;
    quint32 spindleRpm = 0;
    bool coolant = false;
    int temperature = 25;
    bool startButton = false;
    bool panicButton = false;
    // The path the board took, for tests to compare with a program's: the axes' positions
    // after each executed stream vector and where every move came to rest, in order, at most
    // kMaxTrace of them (later ones are dropped).
    static constexpr size_t kMaxTrace = 1000000;
    std::vector<Triple<qint64>> trace;

    ElabSimAxis& axis(Axis a) { return axes[wireIndex(a)]; }
    const ElabSimAxis& axis(Axis a) const { return axes[wireIndex(a)]; }
    // Power-on: setup incomplete, parameters cleared, relays off, buffer empty. The machine
    // (switch positions, wiring, buttons, temperature) stays.
    void powerOn();

    bool setupComplete() const { return setupDone == 0x7; }
    bool anyLimitActive() const;
    bool anyAxisMoving() const;
    bool busy() const { return anyAxisMoving() || stream.running(); }
    bool onlyModeMoving(Mode mode) const;
    // Notes of the control-character table: 1 = NAK while a limit switch is active, 2 = NAK
    // while the panic (Not-Aus) button is active.
    bool refusedByNotes(const Command& cmd, QString* why) const;
    // "Alle Positionier Befehle ... bedingen als erstes ein korrektes Setup ... Dann muss ...
    // der Stillstand der Maschine sichergestellt sein."
    bool canStartMove(QString* why) const;
    double streamRate() const;
    quint16 machineState() const;
    quint8 axeState() const;

    // SetClearPosition: the steps remaining, the single steps and the stream counters.
    void clearCounters();
    // ForceStopMove (ramped) or ForcePanicStop.
    void stopAll(bool ramped);
    // A limit switch that reads active stops every move but jog.
    void checkLimits();
    // Axes and stream over `seconds`, in slices of at most `slice` seconds.
    void advance(double seconds, double slice);

private:
    void advanceStream(double seconds);
    void noteTrace();
};

} // namespace stepdeck::elab
