#pragma once
#include "ElabCodec.h"
#include "model/MachineStatus.h"
#include <QCoreApplication>

namespace stepdeck::elab {

// Maps the E-LAB status words onto the normalised MachineStatus and decides, from them, which
// commands the manual forbids right now. Pure: no I/O.
class ElabCtlStatusMapper
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::elab::ElabCtlStatusMapper)
public:
    static const QList<Axis>& axes(); // X, Y, Z (boardAxes())
    static int index(Axis axis) { return wireIndex(axis); }

    // RequestMachineState (tm* bits). hostPanic: the host sent ForcePanicStop and nothing has
    // re-initialised the machine since; status.panic stays true meanwhile.
    static void applyMachineState(MachineStatus& status, quint16 word, bool hostPanic);
    // RequestAxeState (ta* bits).
    static void applyAxeState(MachineStatus& status, quint8 byte);
    static void applyTemperature(MachineStatus& status, quint8 celsius);

    static bool axisMoving(quint8 axeState, Axis axis);  // taXMove / taYMove / taZMove
    static bool axisJogging(quint8 axeState, Axis axis); // taXJog / ...
    static bool anyMoveBit(quint8 axeState);
    static bool anyJogBit(quint8 axeState);
    static bool limitSwitch(quint16 machineState, Axis axis); // tmLimSwX...
    static bool referenceSwitch(quint16 machineState, Axis axis);

    enum class Rule {
        Move, // FastMove, feed, reference, first velocity move, DC2 stream
        FirstJog,
        VelocityUpdate, // a running velocity move may be changed without waiting for idle
        Standstill,     // setup, polarity, power, spindle, coolant: only while nothing moves
    };
    // Non-empty: why the manual forbids the command now (the rule is named).
    static QString refusal(Rule rule, quint16 machineState, quint8 axeState);
};

} // namespace stepdeck::elab
