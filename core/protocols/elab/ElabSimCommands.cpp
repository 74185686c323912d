#include "ElabSimCommands.h"
#include "Logging.h"

// Command handlers of the E-LAB simulator (manual sections "Setup Befehle", "Hilfs
// Funktionen", "Stop Befehle", "Befehle zur Positionierung", "Befehle im Arbeitsmodus",
// "Befehle im Jogbetrieb", "Befehle zur einfachen Achsen Bewegung"). Each returns false with a
// reason when the board answers NAK; the notes of the control-character table (limit switch,
// panic button) are checked before, in ElabSimBoard::refusedByNotes().

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

bool ElabSimCommands::execute(const Command& cmd, QString* why)
{
    switch (cmd.code) {
    case ctrl::ACK:
        // 0x06 is listed as "Request Absolute Position", but the manual documents neither a
        // reply nor a use for it (no absolute position reply exists anywhere in it). The
        // simulator refuses it like an unknown command instead of inventing a reply format.
        *why = QStringLiteral("RequestAbsolutePosition is undocumented");
        return false;
    case ctrl::BEL: // ForcePanicStop: no ramp, the buffer is lost as well
        m_board.stopAll(false);
        return true;
    case ctrl::XOFF: // ForceStopMove: brake ramps, no step lost
        m_board.stopAll(true);
        return true;
    case ctrl::GS: // ForceFlushBuffer
        m_board.stream.flush();
        return true;
    case ctrl::RS: // SetClearPosition: "setzt die internen Zähler zurück"
        m_board.clearCounters();
        return true;
    case ctrl::CR: // EndOfFeed: the stream ends once its buffer has drained
        if (m_board.stream.running()) {
            m_board.stream.endOfFeed();
            if (m_board.stream.isEmpty())
                m_board.stream.finish();
        }
        return true;
    case ctrl::ESC:
        return doRamp(cmd, why);
    case ctrl::FS: // SetFeedSpeed
        for (int i = 0; i < 3; ++i)
            m_board.axes[size_t(i)].ramp().feedSpeed = quint16(cmd.values[size_t(i)]);
        return true;
    case ctrl::SO:
    case ctrl::DLE:
        return doPolarity(cmd, why);
    case ctrl::STX:
    case ctrl::SOH:
    case ctrl::SI:
        return doAuxiliary(cmd, why);
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

bool ElabSimCommands::doAuxiliary(const Command& cmd, QString* why)
{
    switch (cmd.code) {
    case ctrl::STX: // SetDrivePower: "einen Wert zwischen 0 und 100"
        if (cmd.values[0] > 100) {
            *why = QStringLiteral("drive power above 100");
            return false;
        }
        m_board.drivePower = int(cmd.values[0]);
        return true;
    case ctrl::SOH: // SetSpindleRPM: "einen Wert zwischen 0 und 1000"
        if (cmd.values[0] > 1000) {
            *why = QStringLiteral("spindle rpm above 1000");
            return false;
        }
        m_board.spindleRpm = quint32(cmd.values[0]);
        return true;
    case ctrl::SI: // SetCoolOnOff
        if (!isBoolByte(cmd.values[0])) {
            *why = QStringLiteral("coolant value is neither $00 nor $FF");
            return false;
        }
        m_board.coolant = cmd.values[0] != 0;
        return true;
    default:
        *why = QStringLiteral("unknown command");
        return false;
    }
}

bool ElabSimCommands::doRamp(const Command& cmd, QString* why)
{
    for (int i = 0; i < 3; ++i) {
        ElabSimRamp& r = m_board.axes[size_t(i)].ramp();
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
    m_board.setupDone |= cmd.ramp == RampKind::StartSpeed ? 1
                         : cmd.ramp == RampKind::MaxSpeed ? 2
                                                          : 4;
    return true;
}

bool ElabSimCommands::doPolarity(const Command& cmd, QString* why)
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
            m_board.axes[size_t(i)].setLimitPolarity(high);
        else
            m_board.axes[size_t(i)].setReferencePolarity(high);
    }
    m_board.checkLimits(); // a polarity that makes a switch read active stops a running move
    return true;
}

bool ElabSimCommands::doFastMove(const Command& cmd, QString* why)
{
    if (!m_board.canStartMove(why))
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
        m_board.axes[size_t(i)].clearRemaining();
        m_board.axes[size_t(i)].startFastMove(steps[size_t(i)]);
    }
    return true;
}

bool ElabSimCommands::doFeed(const Command& cmd, QString* why)
{
    if (!m_board.canStartMove(why))
        return false;
    const int index = cmd.code == ctrl::EM ? 0 : cmd.code == ctrl::SUB ? 1 : 2;
    ElabSimAxis& a = m_board.axes[size_t(index)];
    if (a.ramp().feedSpeed == 0 && cmd.values[0] != 0) {
        // Undocumented: a feed at rate 0 would never end. Refuse it rather than hang.
        *why = QStringLiteral("feed speed not set");
        return false;
    }
    for (ElabSimAxis& other : m_board.axes)
        other.clearRemaining();
    a.startFeed(cmd.values[0]);
    return true;
}

bool ElabSimCommands::doReference(const Command& cmd, QString* why)
{
    for (qint64 v : cmd.values) {
        if (v < -1 || v > 1) { // "Die Werte sind 16bit Integer (-1/0/+1)"
            *why = QStringLiteral("reference direction is not -1, 0 or +1");
            return false;
        }
    }
    if (!m_board.canStartMove(why))
        return false;
    for (int i = 0; i < 3; ++i)
        m_board.axes[size_t(i)].startReference(int(cmd.values[size_t(i)]));
    return true;
}

bool ElabSimCommands::doVelocity(const Command& cmd, QString* why)
{
    // "Der Stop Befehl und der VelocityMove Befehl selbst bilden die Ausnahme": a repeated
    // VelocityMove while only velocity moves run changes the rates (sign ignored per axis).
    if (!m_board.setupComplete()) {
        *why = QStringLiteral("setup incomplete (tmInvSetup)");
        return false;
    }
    if (m_board.stream.running() || !m_board.onlyModeMoving(Mode::Velocity)) {
        *why = QStringLiteral("axes still moving");
        return false;
    }
    for (int i = 0; i < 3; ++i)
        m_board.axes[size_t(i)].setVelocity(int(cmd.values[size_t(i)]));
    return true;
}

bool ElabSimCommands::doJog(const Command& cmd, QString* why)
{
    // Jog needs the setup and standstill before the first jog command; later ones only change
    // the rates ("Nach dem Absetzen des ersten Jog-Kommandos ..."). No note 1: jogging off an
    // active limit switch is how the machine gets free again.
    if (!m_board.setupComplete()) {
        *why = QStringLiteral("setup incomplete (tmInvSetup)");
        return false;
    }
    if (m_board.stream.running() || !m_board.onlyModeMoving(Mode::Jog)) {
        *why = QStringLiteral("axes still moving");
        return false;
    }
    for (int i = 0; i < 3; ++i)
        m_board.axes[size_t(i)].setJogRate(int(cmd.values[size_t(i)]));
    return true;
}

} // namespace stepdeck::elab
