#include "ElabSimulator.h"
#include "Logging.h"

// Command handlers of the E-LAB simulator (manual sections "Setup Befehle", "Hilfs
// Funktionen", "Stop Befehle", "Befehle zur Positionierung", "Befehle im Arbeitsmodus",
// "Befehle im Jogbetrieb", "Befehle zur einfachen Achsen Bewegung"). Each returns false with a
// reason when the board answers NAK; the notes of the control-character table (limit switch,
// panic button) are checked before, in ElabSimulator::refusedByNotes().

namespace stepdeck::elab {

using Mode = ElabSimAxis::Mode;

namespace {
// Boolean parameters: "eine Logische 1 ist gleichwertig mit einem $FF, eine Logische 0 wird
// durch $00 dargestellt". Anything else is a malformed parameter.
bool isBoolByte(qint64 v)
{
    return v == 0x00 || v == 0xFF;
}
} // namespace

bool ElabSimulator::execute(const Command& cmd, QString* why)
{
    switch (cmd.code) {
    case ctrl::ACK:
        // 0x06 is listed as "Request Absolute Position", but the manual documents neither a
        // reply nor a use for it (no absolute position reply exists anywhere in it). The
        // simulator refuses it like an unknown command instead of inventing a reply format.
        *why = QStringLiteral("RequestAbsolutePosition is undocumented");
        return false;
    case ctrl::BEL: // ForcePanicStop: no ramp, the buffer is lost as well
        stopAll(false);
        return true;
    case ctrl::XOFF: // ForceStopMove: brake ramps, no step lost
        stopAll(true);
        return true;
    case ctrl::GS: // ForceFlushBuffer
        m_stream.flush();
        return true;
    case ctrl::RS: // SetClearPosition: "setzt die internen Zähler zurück"
        for (ElabSimAxis& a : m_axes) {
            a.clearRemaining();
            a.clearSingleSteps();
        }
        m_stream.clearCounters();
        return true;
    case ctrl::CR: // EndOfFeed: the stream ends once its buffer has drained
        if (m_stream.running()) {
            m_stream.endOfFeed();
            if (m_stream.isEmpty())
                m_stream.finish();
        }
        return true;
    case ctrl::ESC:
        return doRamp(cmd, why);
    case ctrl::FS: // SetFeedSpeed
        for (int i = 0; i < 3; ++i)
            m_axes[size_t(i)].ramp().feedSpeed = quint16(cmd.values[size_t(i)]);
        return true;
    case ctrl::SO:
    case ctrl::DLE:
        return doPolarity(cmd, why);
    case ctrl::STX: // SetDrivePower: "einen Wert zwischen 0 und 100"
        if (cmd.values[0] > 100) {
            *why = QStringLiteral("drive power above 100");
            return false;
        }
        m_drivePower = int(cmd.values[0]);
        return true;
    case ctrl::SOH: // SetSpindleRPM: "einen Wert zwischen 0 und 1000"
        if (cmd.values[0] > 1000) {
            *why = QStringLiteral("spindle rpm above 1000");
            return false;
        }
        m_spindleRpm = quint32(cmd.values[0]);
        return true;
    case ctrl::SI: // SetCoolOnOff
        if (!isBoolByte(cmd.values[0])) {
            *why = QStringLiteral("coolant value is neither $00 nor $FF");
            return false;
        }
        m_coolant = cmd.values[0] != 0;
        return true;
    case ctrl::EOT:
    case ctrl::BS:
    case ctrl::FF:
        return doFastMove(cmd, why);
    case ctrl::EM:
    case ctrl::SUB:
    case ctrl::VT:
        return doFeed(cmd, why);
    case ctrl::US:
        return doReference(cmd, why);
    case ctrl::CAN:
        return doVelocity(cmd, why);
    case ctrl::DC4:
        return doJog(cmd, why);
    default:
        *why = QStringLiteral("unknown command");
        return false;
    }
}

bool ElabSimulator::doRamp(const Command& cmd, QString* why)
{
    for (int i = 0; i < 3; ++i) {
        ElabSimRamp& r = m_axes[size_t(i)].ramp();
        const quint16 v = quint16(cmd.values[size_t(i)]);
        switch (cmd.ramp) {
        case RampKind::StartSpeed:
            r.startSpeed = v;
            break;
        case RampKind::MaxSpeed:
            r.maxSpeed = v;
            break;
        case RampKind::Acceleration:
            r.acceleration = v;
            break;
        default:
            *why = QStringLiteral("unknown ramp selector");
            return false;
        }
    }
    // tmInvSetup: "das Setup (StartSpeed, MaxSpeed, Acceleration) ist noch nicht komplett"
    m_setupDone |= cmd.ramp == RampKind::StartSpeed ? 1 : cmd.ramp == RampKind::MaxSpeed ? 2 : 4;
    return true;
}

bool ElabSimulator::doPolarity(const Command& cmd, QString* why)
{
    for (int i = 0; i < 3; ++i) {
        if (!isBoolByte(cmd.values[size_t(i)])) {
            *why = QStringLiteral("polarity is neither $00 nor $FF");
            return false;
        }
    }
    for (int i = 0; i < 3; ++i) {
        const bool high = cmd.values[size_t(i)] != 0;
        if (cmd.code == ctrl::SO)
            m_axes[size_t(i)].setLimitPolarity(high);
        else
            m_axes[size_t(i)].setReferencePolarity(high);
    }
    checkLimits(); // a polarity that makes a switch read active stops a running move
    return true;
}

// "Alle Positionier Befehle ... bedingen als erstes ein korrektes Setup ... Dann muss ... der
// Stillstand der Maschine sichergestellt sein."
bool ElabSimulator::canStartMove(QString* why) const
{
    if (!setupComplete()) {
        *why = QStringLiteral("setup incomplete (tmInvSetup)");
        return false;
    }
    if (anyAxisMoving() || m_stream.running()) {
        *why = QStringLiteral("axes still moving");
        return false;
    }
    return true;
}

bool ElabSimulator::doFastMove(const Command& cmd, QString* why)
{
    if (!canStartMove(why))
        return false;
    std::array<qint64, 3> steps{};
    if (cmd.code == ctrl::EOT)
        steps = cmd.values;
    else if (cmd.code == ctrl::FF)
        steps = {cmd.values[0], cmd.values[1], 0};
    else
        steps = {0, 0, cmd.values[0]};
    // RequestRelPosition reports the steps of *this* move not yet executed (see remaining()).
    for (int i = 0; i < 3; ++i) {
        m_axes[size_t(i)].clearRemaining();
        m_axes[size_t(i)].startFastMove(steps[size_t(i)]);
    }
    return true;
}

bool ElabSimulator::doFeed(const Command& cmd, QString* why)
{
    if (!canStartMove(why))
        return false;
    const int index = cmd.code == ctrl::EM ? 0 : cmd.code == ctrl::SUB ? 1 : 2;
    ElabSimAxis& a = m_axes[size_t(index)];
    if (a.ramp().feedSpeed == 0 && cmd.values[0] != 0) {
        // Undocumented: a feed at rate 0 would never end. Refuse it rather than hang.
        *why = QStringLiteral("feed speed not set");
        return false;
    }
    for (ElabSimAxis& other : m_axes)
        other.clearRemaining();
    a.startFeed(cmd.values[0]);
    return true;
}

bool ElabSimulator::doReference(const Command& cmd, QString* why)
{
    for (qint64 v : cmd.values) {
        if (v < -1 || v > 1) { // "Die Werte sind 16bit Integer (-1/0/+1)"
            *why = QStringLiteral("reference direction is not -1, 0 or +1");
            return false;
        }
    }
    if (!canStartMove(why))
        return false;
    for (int i = 0; i < 3; ++i)
        m_axes[size_t(i)].startReference(int(cmd.values[size_t(i)]));
    return true;
}

bool ElabSimulator::doVelocity(const Command& cmd, QString* why)
{
    // "Der Stop Befehl und der VelocityMove Befehl selbst bilden die Ausnahme": a repeated
    // VelocityMove while only velocity moves run changes the rates (sign ignored per axis).
    if (!setupComplete()) {
        *why = QStringLiteral("setup incomplete (tmInvSetup)");
        return false;
    }
    if (m_stream.running() || !onlyModeMoving(Mode::Velocity)) {
        *why = QStringLiteral("axes still moving");
        return false;
    }
    for (int i = 0; i < 3; ++i)
        m_axes[size_t(i)].setVelocity(int(cmd.values[size_t(i)]));
    return true;
}

bool ElabSimulator::doJog(const Command& cmd, QString* why)
{
    // Jog needs the setup and standstill before the first jog command; later ones only change
    // the rates ("Nach dem Absetzen des ersten Jog-Kommandos ..."). No note 1: jogging off an
    // active limit switch is how the machine gets free again.
    if (!setupComplete()) {
        *why = QStringLiteral("setup incomplete (tmInvSetup)");
        return false;
    }
    if (m_stream.running() || !onlyModeMoving(Mode::Jog)) {
        *why = QStringLiteral("axes still moving");
        return false;
    }
    for (int i = 0; i < 3; ++i)
        m_axes[size_t(i)].setJogRate(int(cmd.values[size_t(i)]));
    return true;
}

// SetFeedStepXYZ. No reply in any case ("Der Controller gibt grundsätzlich keine Antwort auf
// diese Befehle"), so where notes 1/2 or the preconditions would NAK, the step is dropped and
// counted as rejected; a ForceStopMove or a limit switch halts the stream until GS/RS.
void ElabSimulator::doStreamStep(const Command& cmd)
{
    m_stream.noteArrival();
    if (!m_stream.running()) {
        QString why;
        if (!cmd.valid || refusedByNotes(cmd, &why) || !canStartMove(&why) || m_stream.halted() ||
            streamRate() <= 0) {
            m_stream.countRejected();
            return;
        }
        m_stream.start();
    } else if (!cmd.valid) {
        m_stream.countRejected();
        return;
    }
    m_stream.push(cmd.stepByte);
    sendFlowControl();
    updateTimer();
}

double ElabSimulator::streamRate() const
{
    // One buffer, three feed rates: the slowest one paces the stream so that no axis runs
    // above its feed rate and the figure keeps its shape.
    quint16 rate = 0xFFFF;
    for (const ElabSimAxis& a : m_axes)
        rate = qMin(rate, a.ramp().feedSpeed);
    return rate;
}

void ElabSimulator::stopAll(bool ramped)
{
    for (ElabSimAxis& a : m_axes) {
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
        if (m_stream.running())
            m_stream.halt(); // "enthält der Controller Buffer mit grosser Wahrscheinlichkeit
                             // noch Einzelschritte" -- kept until ForceFlushBuffer
    } else {
        m_stream.flush();
    }
}

bool ElabSimulator::anyLimitActive() const
{
    for (const ElabSimAxis& a : m_axes) {
        if (a.limitActive())
            return true;
    }
    return false;
}

bool ElabSimulator::anyAxisMoving() const
{
    for (const ElabSimAxis& a : m_axes) {
        if (a.isMoving())
            return true;
    }
    return false;
}

bool ElabSimulator::onlyModeMoving(Mode mode) const
{
    for (const ElabSimAxis& a : m_axes) {
        if (a.isMoving() && a.mode() != mode)
            return false;
    }
    return true;
}

} // namespace stepdeck::elab
