#include "ElabSimulator.h"
#include "Logging.h"

// Protocol dispatch, requests and the time base of the E-LAB simulator. The command handlers
// are in ElabSimCommands.cpp, the motion model in ElabSimAxis, the DC2 buffer in ElabSimStream.

namespace stepdeck::elab {

namespace {
constexpr int kTickMs = 5;              // motion update interval while something moves
constexpr double kSliceSeconds = 0.002; // axes and stream advance together in slices this long

QByteArray hex(quint64 value, int digits)
{
    return QByteArray::number(value, 16).toUpper().rightJustified(digits, '0').right(digits);
}
} // namespace

ElabSimulator::ElabSimulator(const SimulatorOptions& options, QObject* parent)
    : Simulator(options, parent)
{
    // Output pacing at the line's character rate is done by the base class (send() and
    // sendUnsolicited()) whenever options().paceOutput is set.
    m_tick.setInterval(kTickMs);
    m_tick.setTimerType(Qt::PreciseTimer);
    connect(&m_tick, &QTimer::timeout, this, [this] { advanceToNow(); });
    m_clock.start();
    powerOnReset();
}

ElabSimulator::~ElabSimulator() = default;

void ElabSimulator::powerOnReset()
{
    for (ElabSimAxis& a : m_axes)
        a.reset();
    m_stream.reset();
    m_decoder.reset();
    m_setupDone = 0;
    m_drivePower = 0;
    m_spindleRpm = 0;
    m_coolant = false;
    m_lastNakReason.clear();
    m_lastNs = m_clock.nsecsElapsed();
    m_tick.stop();
}

void ElabSimulator::receive(const QByteArray& bytes)
{
    const QList<Command> commands = m_decoder.feed(bytes);
    for (const Command& cmd : commands) {
        if (cmd.code != 0)
            noteReceived(cmd.raw); // line noise outside any command is not a frame
        handle(cmd);
    }
}

void ElabSimulator::handle(const Command& cmd)
{
    ++m_commands;
    advanceToNow();
    if (cmd.code == 0) {
        // Bytes outside any command (line noise): nothing to answer.
        qCDebug(lcSimulator) << "elab sim: ignored" << cmd.raw.toHex() << cmd.error;
        return;
    }
    if (handleRequest(cmd))
        return;
    if (cmd.code == ctrl::DC2) {
        doStreamStep(cmd); // "Der Controller gibt grundsätzlich keine Antwort auf diese Befehle"
        return;
    }
    QString why;
    bool ok = false;
    if (!cmd.valid) {
        // "Im Fehlerfall antwortet das Controllerboard mit einem <NAK>. Kommt ein NAK zurück so
        // wurde hier (meistens) ein falscher Hexstring übertragen."
        why = cmd.error;
    } else if (faults().forceNak > 0) {
        --faults().forceNak;
        why = QStringLiteral("fault injection: forced NAK");
    } else if (!refusedByNotes(cmd, &why)) {
        ok = execute(cmd, &why);
    }
    if (ok) {
        ack();
    } else {
        m_lastNakReason = why;
        qCInfo(lcSimulator) << "elab sim: NAK" << toMnemonics(cmd.raw) << why;
        nak();
    }
    sendFlowControl();
    updateTimer();
}

// Requests answer with data (or nothing) and never take part in forced NAKs.
bool ElabSimulator::handleRequest(const Command& cmd)
{
    switch (cmd.code) {
    case ctrl::ENQ: // RequestMachineState: <ENQ>BBBB#
        send(QByteArray(1, ctrl::ENQ) + hex(machineState(), 4) + '#');
        return true;
    case ctrl::HT: // RequestAxeState: <HT>BB#
        send(QByteArray(1, ctrl::HT) + hex(axeState(), 2) + '#');
        return true;
    case ctrl::ETB: // RequestTemperature: <ETB>TT#
        send(QByteArray(1, ctrl::ETB) + hex(quint8(m_temperature), 2) + '#');
        return true;
    case ctrl::ETX: { // RequestRelPosition: <ETX>XXXXXXXX,YYYYYYYY;ZZZZZZZZ.
        // Interpretation: ForceStopMove says "ist diesem die noch verbleibenden Schritte des
        // vorausgegangenen FastMove Kommandos bekannt ... kann er mit RequestRelPosition die
        // jeweils noch verbleibenden Schritte abfragen". So the reply is, per axis, the signed
        // steps of the last FastMove (or FeedSteps) not executed: 0 after a completed move,
        // target minus reached after a stop, limit or panic; cleared by SetClearPosition and
        // by a new move of the axis. The absolute position stays internal (no reply has it).
        QByteArray reply(1, ctrl::ETX);
        const char separators[3] = {',', ';', '.'};
        for (int i = 0; i < 3; ++i)
            reply += hex(quint32(qint32(m_axes[size_t(i)].remaining())), 8) + separators[i];
        send(reply);
        return true;
    }
    case ctrl::LF: { // RequestStart: <ACK> pressed, <NAK> not (and notes 1, 2 of the table)
        const bool pressed = m_startButton && !anyLimitActive() && !m_panicButton;
        send(QByteArray(1, pressed ? ctrl::ACK : ctrl::NAK));
        return true;
    }
    case ctrl::SYN:  // RequestSync: "Der Controller akzeptiert den Befehl, schickt aber keine
        return true; // Antwort."
    default:
        return false;
    }
}

// Notes of the control-character table: 1 = NAK while a limit switch is active, 2 = NAK while
// the panic (Not-Aus) button is active.
bool ElabSimulator::refusedByNotes(const Command& cmd, QString* why) const
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
    if (note2 && m_panicButton) {
        *why = QStringLiteral("panic button active (tmPanicStop)");
        return true;
    }
    if (note1 && anyLimitActive()) {
        *why = QStringLiteral("limit switch active (taLimSw)");
        return true;
    }
    return false;
}

quint16 ElabSimulator::machineState()
{
    advanceToNow();
    quint16 word = 0;
    if (m_drivePower >= 25) // SetDrivePower: "<25 = off"
        word |= machine::DriveOn;
    if (m_spindleRpm > 0)
        word |= machine::SpindleOn;
    if (busyNow())
        word |= machine::Busy;
    if (m_temperature > 50)
        word |= machine::OverTemp;
    if (!setupComplete())
        word |= machine::InvSetup;
    for (int i = 0; i < 3; ++i) {
        if (m_axes[size_t(i)].limitActive())
            word |= quint16(machine::LimSwX << i);
        if (m_axes[size_t(i)].referenceActive())
            word |= quint16(machine::RefSwX << i);
    }
    if (m_panicButton)
        word |= machine::PanicStop;
    return word;
}

quint8 ElabSimulator::axeState()
{
    advanceToNow();
    quint8 byte = 0;
    for (int i = 0; i < 3; ++i) {
        const ElabSimAxis& a = m_axes[size_t(i)];
        // The DC2 stream is feed mode for all three axes until it has drained after EndOfFeed.
        if (a.mode() == ElabSimAxis::Mode::Jog)
            byte |= quint8(axe::XJog << (2 * i));
        else if (a.isMoving() || m_stream.running())
            byte |= quint8(axe::XMove << (2 * i));
        if (a.limitActive())
            byte |= axe::LimSw;
        if (a.referenceActive())
            byte |= axe::RefSw;
    }
    return byte;
}

// ------------------------------------------------------------------ time

void ElabSimulator::advanceToNow()
{
    const qint64 now = m_clock.nsecsElapsed();
    double seconds = double(now - m_lastNs) / 1e9;
    m_lastNs = now;
    while (seconds > 0 && (anyAxisMoving() || m_stream.running())) {
        if (!anyAxisMoving() && m_stream.isEmpty()) {
            advanceStream(seconds); // waiting for the host's next step: nothing to integrate
            break;
        }
        const double slice = qMin(seconds, kSliceSeconds);
        seconds -= slice;
        for (ElabSimAxis& a : m_axes) {
            if (a.advance(slice) == ElabSimAxis::Event::ReferenceHit)
                qCDebug(lcSimulator) << "elab sim: reference switch reached at" << a.position();
        }
        advanceStream(slice);
        checkLimits();
    }
    sendFlowControl();
    updateTimer();
}

void ElabSimulator::advanceStream(double seconds)
{
    if (!m_stream.running())
        return;
    const int count = m_stream.due(seconds, streamRate());
    for (int n = 0; n < count; ++n) {
        const Triple<int> steps = decodeStepByte(m_stream.pop());
        bool free = true;
        for (int i = 0; i < 3; ++i)
            free = m_axes[size_t(i)].singleStep(steps[size_t(i)]) && free;
        if (!free)
            break; // checkLimits() halts the stream
    }
    if (m_stream.endPending() && m_stream.isEmpty())
        m_stream.finish();
}

// "Wenn eine Fahrt einen Endschalter erreicht hat, dann wird diese auch immer sofort
// abgebrochen, ausgenommen wiederum die Jog Bewegungen." Covers switches reached by motion,
// switches actuated by hand and a polarity change that makes a switch read active.
void ElabSimulator::checkLimits()
{
    if (!anyLimitActive())
        return;
    bool stopped = false;
    for (ElabSimAxis& a : m_axes) {
        if (a.isMoving() && a.mode() != ElabSimAxis::Mode::Jog) {
            a.hardStop();
            stopped = true;
        }
    }
    if (m_stream.running()) {
        m_stream.halt();
        stopped = true;
    }
    if (stopped)
        qCInfo(lcSimulator) << "elab sim: limit switch active, move aborted";
}

void ElabSimulator::sendFlowControl()
{
    switch (m_stream.flow()) {
    case ElabSimStream::Flow::SendXOff:
        sendUnsolicited(QByteArray(1, ctrl::XOFF));
        break;
    case ElabSimStream::Flow::SendXOn:
        sendUnsolicited(QByteArray(1, ctrl::XON));
        break;
    case ElabSimStream::Flow::None:
        break;
    }
}

void ElabSimulator::updateTimer()
{
    // Tick only while something can change by itself; idle costs no CPU.
    const bool needed = anyAxisMoving() || (m_stream.running() && !m_stream.isEmpty());
    if (needed && !m_tick.isActive())
        m_tick.start();
    else if (!needed && m_tick.isActive())
        m_tick.stop();
}

} // namespace stepdeck::elab
