// The simulated E-LAB board's state and what follows from it alone (ElabSimBoard.h).
#include "ElabSimBoard.h"
#include "Logging.h"

namespace stepdeck::elab {

void ElabSimBoard::powerOn()
{
    for (ElabSimAxis& a : axes)
        a.reset();
    stream.reset();
    setupDone = 0;
    drivePower = 0;
    spindleRpm = 0;
    coolant = false;
}

void ElabSimBoard::clearCounters()
{
    for (ElabSimAxis& a : axes) {
        a.clearRemaining();
        a.clearSingleSteps();
    }
    stream.clearCounters();
}

void ElabSimBoard::advance(double seconds, double slice)
{
    while (seconds > 0 && (anyAxisMoving() || stream.running())) {
        if (!anyAxisMoving() && stream.isEmpty()) {
            advanceStream(seconds); // waiting for the host's next step: nothing to integrate
            break;
        }
        const double step = qMin(seconds, slice);
        seconds -= step;
        const bool wasMoving = anyAxisMoving();
        for (ElabSimAxis& a : axes) {
            if (a.advance(step) == ElabSimAxis::Event::ReferenceHit)
                qCDebug(lcSimulator) << "elab sim: reference switch reached at" << a.position();
        }
        advanceStream(step);
        checkLimits();
        if (wasMoving && !anyAxisMoving())
            noteTrace(); // a move came to rest
    }
}

// Notes of the control-character table: 1 = NAK while a limit switch is active, 2 = NAK while
// the panic (Not-Aus) button is active.
bool ElabSimBoard::refusedByNotes(const Command& cmd, QString* why) const
{
    bool note1 = false;
    bool note2 = false;
    switch (cmd.code) {
    case ctrl::EOT:
    case ctrl::BS:
    case ctrl::VT:
    case ctrl::FF:
    case ctrl::CR:
    case ctrl::DC2:
    case ctrl::CAN:
    case ctrl::EM:
    case ctrl::SUB:
    case ctrl::RS:
    case ctrl::US:
        note1 = note2 = true;
        break;
    case ctrl::SOH:
    case ctrl::STX:
    case ctrl::SI:
    case ctrl::DC4:
        note2 = true;
        break;
    default:
        break;
    }
    if (note2 && panicButton) {
        *why = QStringLiteral("panic button active (tmPanicStop)");
        return true;
    }
    if (note1 && anyLimitActive()) {
        *why = QStringLiteral("limit switch active (taLimSw)");
        return true;
    }
    return false;
}

quint16 ElabSimBoard::machineState() const
{
    quint16 word = 0;
    if (drivePower >= 25) // SetDrivePower: "<25 = off"
        word |= machine::DriveOn;
    if (spindleRpm > 0)
        word |= machine::SpindleOn;
    if (busy())
        word |= machine::Busy;
    if (temperature > 50)
        word |= machine::OverTemp;
    if (!setupComplete())
        word |= machine::InvSetup;
    for (int i = 0; i < 3; ++i) {
        if (axes[size_t(i)].limitActive())
            word |= quint16(machine::LimSwX << i);
        if (axes[size_t(i)].referenceActive())
            word |= quint16(machine::RefSwX << i);
    }
    if (panicButton)
        word |= machine::PanicStop;
    return word;
}

quint8 ElabSimBoard::axeState() const
{
    quint8 byte = 0;
    for (int i = 0; i < 3; ++i) {
        const ElabSimAxis& a = axes[size_t(i)];
        // The DC2 stream is feed mode for all three axes until it has drained after EndOfFeed.
        if (a.mode() == ElabSimAxis::Mode::Jog)
            byte |= quint8(axe::XJog << (2 * i));
        else if (a.isMoving() || stream.running())
            byte |= quint8(axe::XMove << (2 * i));
        if (a.limitActive())
            byte |= axe::LimSw;
        if (a.referenceActive())
            byte |= axe::RefSw;
    }
    return byte;
}

// "Alle Positionier Befehle ... bedingen als erstes ein korrektes Setup ... Dann muss ... der
// Stillstand der Maschine sichergestellt sein."
bool ElabSimBoard::canStartMove(QString* why) const
{
    if (!setupComplete()) {
        *why = QStringLiteral("setup incomplete (tmInvSetup)");
        return false;
    }
    if (anyAxisMoving() || stream.running()) {
        *why = QStringLiteral("axes still moving");
        return false;
    }
    return true;
}

double ElabSimBoard::streamRate() const
{
    // One buffer, three feed rates: the slowest one paces the stream so that no axis runs
    // above its feed rate and the figure keeps its shape.
    quint16 rate = 0xFFFF;
    for (const ElabSimAxis& a : axes)
        rate = qMin(rate, a.ramp().feedSpeed);
    return rate;
}

void ElabSimBoard::stopAll(bool ramped)
{
    for (ElabSimAxis& a : axes) {
        if (!ramped)
            a.hardStop();
        else if (a.mode() != Mode::Jog)
            a.rampStop();
        // Reading of the manual: the jog mode lists only SetJogSpeed and ForcePanicStop
        // ("Parameter und Kommandos" of "Der Jog-Modus"), and zero rates are the documented
        // way to stop a jog. So ForceStopMove is answered but leaves a jogging axis running;
        // a host that relies on it to end a jog is caught by the tests.
    }
    if (ramped) {
        if (stream.running())
            stream.halt(); // "enthält der Controller Buffer mit grosser Wahrscheinlichkeit
                           // noch Einzelschritte" -- kept until ForceFlushBuffer
    } else {
        stream.flush();
    }
}

bool ElabSimBoard::anyLimitActive() const
{
    for (const ElabSimAxis& a : axes) {
        if (a.limitActive())
            return true;
    }
    return false;
}

bool ElabSimBoard::anyAxisMoving() const
{
    for (const ElabSimAxis& a : axes) {
        if (a.isMoving())
            return true;
    }
    return false;
}

bool ElabSimBoard::onlyModeMoving(Mode mode) const
{
    for (const ElabSimAxis& a : axes) {
        if (a.isMoving() && a.mode() != mode)
            return false;
    }
    return true;
}

// "Wenn eine Fahrt einen Endschalter erreicht hat, dann wird diese auch immer sofort
// abgebrochen, ausgenommen wiederum die Jog Bewegungen." Covers switches reached by motion,
// switches actuated by hand and a polarity change that makes a switch read active.
void ElabSimBoard::checkLimits()
{
    if (!anyLimitActive())
        return;
    bool stopped = false;
    for (ElabSimAxis& a : axes) {
        if (a.isMoving() && a.mode() != ElabSimAxis::Mode::Jog) {
            a.hardStop();
            stopped = true;
        }
    }
    if (stream.running()) {
        stream.halt();
        stopped = true;
    }
    if (stopped)
        qCInfo(lcSimulator) << "elab sim: limit switch active, move aborted";
}

void ElabSimBoard::advanceStream(double seconds)
{
    if (!stream.running())
        return;
    const int count = stream.due(seconds, streamRate());
    for (int n = 0; n < count; ++n) {
        const Triple<int> steps = decodeStepByte(stream.pop());
        bool free = true;
        for (int i = 0; i < 3; ++i)
            free = axes[size_t(i)].singleStep(steps[size_t(i)]) && free;
        noteTrace();
        if (!free)
            break; // checkLimits() halts the stream
    }
    if (stream.endPending() && stream.isEmpty())
        stream.finish();
}

void ElabSimBoard::noteTrace()
{
    if (trace.size() < kMaxTrace)
        trace.push_back({axes[0].position(), axes[1].position(), axes[2].position()});
}

} // namespace stepdeck::elab
