#include "ElabSimulator.h"
#include "Logging.h"

// Protocol dispatch, requests, the <DC2> stream and the time base of the E-LAB simulator. The
// command interpreter is ElabSimCommands, the board's state ElabSimBoard, the motion model
// ElabSimAxis, the DC2 buffer ElabSimStream.

namespace stepdeck::elab {

namespace {
constexpr int kTickMs = 5;              // motion update interval while something moves
constexpr double kSliceSeconds = 0.002; // axes and stream advance together in slices this long
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
    m_board.powerOn();
    m_decoder.reset();
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
    ++m_commandCount;
    advanceToNow();
    if (m_dropReplyTo != 0 && cmd.code == m_dropReplyTo) {
        m_dropReplyTo = 0;
        ++faults().dropReplies; // executed, but its reply is lost on the line
    }
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
    } else if (!m_board.refusedByNotes(cmd, &why)) {
        ok = m_commands.execute(cmd, &why);
    }
    if (ok) {
        journal(cmd);
        ack();
    } else {
        m_lastNakReason = why;
        qCInfo(lcSimulator) << "elab sim: NAK" << toMnemonics(cmd.raw) << why;
        nak();
    }
    sendFlowControl();
    updateTimer();
}

void ElabSimulator::journal(const Command& cmd)
{
    // FastMove XYZ <EOT>, XY <FF> (X, Y) and Z <BS> (Z only): the values in axis order.
    QList<Axis> axes;
    if (cmd.code == ctrl::EOT)
        axes = {Axis::X, Axis::Y, Axis::Z};
    else if (cmd.code == ctrl::FF)
        axes = {Axis::X, Axis::Y};
    else if (cmd.code == ctrl::BS)
        axes = {Axis::Z};
    for (int i = 0; i < axes.size(); ++i) {
        if (cmd.values[size_t(i)] != 0)
            m_acceptedMoves.append({axes[i], cmd.values[size_t(i)]});
    }
}

// Requests answer with data (or nothing) and never take part in forced NAKs.
bool ElabSimulator::handleRequest(const Command& cmd)
{
    switch (cmd.code) {
    case ctrl::ENQ: // RequestMachineState: <ENQ>BBBB#
        send(encodeReply::machineState(machineState()));
        return true;
    case ctrl::HT: // RequestAxeState: <HT>BB#
        send(encodeReply::axeState(axeState()));
        return true;
    case ctrl::ETB: // RequestTemperature: <ETB>TT#
        send(encodeReply::temperature(quint8(m_board.temperature)));
        return true;
    case ctrl::ETX: { // RequestRelPosition: <ETX>XXXXXXXX,YYYYYYYY;ZZZZZZZZ.
        // Interpretation: ForceStopMove says "ist diesem die noch verbleibenden Schritte des
        // vorausgegangenen FastMove Kommandos bekannt ... kann er mit RequestRelPosition die
        // jeweils noch verbleibenden Schritte abfragen". So the reply is, per axis, the signed
        // steps of the last FastMove (or FeedSteps) not executed: 0 after a completed move,
        // target minus reached after a stop, limit or panic; cleared by SetClearPosition and
        // by a new move of the axis. The absolute position stays internal (no reply has it).
        Triple<qint32> remaining{};
        for (size_t i = 0; i < 3; ++i)
            remaining[i] = qint32(m_board.axes[i].remaining());
        send(encodeReply::relPosition(remaining));
        return true;
    }
    case ctrl::LF: { // RequestStart: <ACK> pressed, <NAK> not (and notes 1, 2 of the table)
        const bool pressed =
            m_board.startButton && !m_board.anyLimitActive() && !m_board.panicButton;
        send(QByteArray(1, pressed ? ctrl::ACK : ctrl::NAK));
        return true;
    }
    case ctrl::SYN:  // RequestSync: "Der Controller akzeptiert den Befehl, schickt aber keine
        return true; // Antwort."
    default:
        return false;
    }
}

quint16 ElabSimulator::machineState()
{
    advanceToNow();
    return m_board.machineState();
}

quint8 ElabSimulator::axeState()
{
    advanceToNow();
    return m_board.axeState();
}

// ------------------------------------------------------------------ time

void ElabSimulator::advanceToNow()
{
    const qint64 now = m_clock.nsecsElapsed();
    const double seconds = double(now - m_lastNs) / 1e9;
    m_lastNs = now;
    m_board.advance(seconds, kSliceSeconds);
    sendFlowControl();
    updateTimer();
}

void ElabSimulator::sendFlowControl()
{
    switch (m_board.stream.flow()) {
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
    const bool needed =
        m_board.anyAxisMoving() || (m_board.stream.running() && !m_board.stream.isEmpty());
    if (needed && !m_tick.isActive())
        m_tick.start();
    else if (!needed && m_tick.isActive())
        m_tick.stop();
}

// SetFeedStepXYZ. No reply in any case ("Der Controller gibt grundsätzlich keine Antwort auf
// diese Befehle"), so where notes 1/2 or the preconditions would NAK, the step is dropped and
// counted as rejected; a ForceStopMove or a limit switch halts the stream until GS/RS.
void ElabSimulator::doStreamStep(const Command& cmd)
{
    // The board up to now first: time before the first <DC2> is not the stream's ("dass der
    // Controller sofort mit dem ersten <DC2> mit der Fahrt anfängt"), and a running stream
    // whose buffer ran dry while this pair was on its way counts that underrun now.
    advanceToNow();
    m_board.stream.noteArrival();
    if (!m_board.stream.running()) {
        QString why;
        if (!cmd.valid || m_board.refusedByNotes(cmd, &why) || !m_board.canStartMove(&why) ||
            m_board.stream.halted() || m_board.streamRate() <= 0) {
            m_board.stream.countRejected();
            return;
        }
        m_board.stream.start();
    } else if (!cmd.valid) {
        m_board.stream.countRejected();
        return;
    }
    m_board.stream.push(cmd.stepByte);
    sendFlowControl();
    updateTimer();
}

// ------------------------------------------------------------------ the machine around it
// The machine around the simulated board (buttons, switches, temperature) and the accessors
// tests and stepdeck-sim use to observe it. Every setter first brings the motion up to now, so
// a switch actuated mid-move acts at this moment, not at the next tick.

void ElabSimulator::setTemperature(int celsius)
{
    m_board.temperature = qBound(0, celsius, 255); // <ETB>TT#: one unsigned byte
}

void ElabSimulator::setPanicButton(bool pressed)
{
    advanceToNow();
    m_board.panicButton = pressed;
    if (pressed) {
        qCInfo(lcSimulator) << "elab sim: panic button pressed, all axes stopped";
        m_board.stopAll(false);
    }
    sendFlowControl();
    updateTimer();
}

void ElabSimulator::setLimitSwitchActuated(Axis a, bool actuated)
{
    advanceToNow();
    m_board.axis(a).setLimitForced(actuated);
    m_board.checkLimits();
    updateTimer();
}

void ElabSimulator::setReferenceSwitchActuated(Axis a, bool actuated)
{
    advanceToNow();
    m_board.axis(a).setReferenceForced(actuated);
    // A reference move waiting for this switch stops as if it had driven onto it.
    if (m_board.axis(a).mode() == ElabSimAxis::Mode::Reference && m_board.axis(a).referenceActive())
        m_board.axis(a).hardStop();
    updateTimer();
}

void ElabSimulator::setLimitPositions(Axis a, qint64 minimum, qint64 maximum)
{
    advanceToNow();
    m_board.axis(a).switches().limitMin = minimum;
    m_board.axis(a).switches().limitMax = maximum;
    m_board.checkLimits();
    updateTimer();
}

void ElabSimulator::setReferencePosition(Axis a, qint64 position, qint64 window)
{
    advanceToNow();
    m_board.axis(a).switches().referencePosition = position;
    m_board.axis(a).switches().referenceWindow = qMax<qint64>(0, window);
}

void ElabSimulator::setSwitchWiring(Axis a, bool limitActiveHigh, bool referenceActiveHigh)
{
    advanceToNow();
    m_board.axis(a).switches().limitWiredActiveHigh = limitActiveHigh;
    m_board.axis(a).switches().referenceWiredActiveHigh = referenceActiveHigh;
    m_board.checkLimits();
    updateTimer();
}

ElabSimSwitchConfig ElabSimulator::switchConfig(Axis a) const
{
    return m_board.axis(a).switches();
}

void ElabSimulator::setPosition(Axis a, qint64 steps)
{
    advanceToNow();
    m_board.axis(a).setPosition(steps);
}

void ElabSimulator::setStreamBuffer(int capacity, int highWater, int lowWater)
{
    m_board.stream.configure(capacity, highWater, lowWater);
}

qint64 ElabSimulator::position(Axis a)
{
    advanceToNow();
    return m_board.axis(a).position();
}

bool ElabSimulator::isMoving(Axis a)
{
    advanceToNow();
    return m_board.axis(a).isMoving() || m_board.stream.running();
}

bool ElabSimulator::isBusy()
{
    advanceToNow();
    return m_board.busy();
}

qint64 ElabSimulator::remainingSteps(Axis a)
{
    advanceToNow();
    return m_board.axis(a).remaining();
}

bool ElabSimulator::limitSwitchActive(Axis a) const
{
    return m_board.axis(a).limitActive();
}
bool ElabSimulator::referenceSwitchActive(Axis a) const
{
    return m_board.axis(a).referenceActive();
}
bool ElabSimulator::limitSwitchLevelHigh(Axis a) const
{
    return m_board.axis(a).limitLevelHigh();
}
ElabSimRamp ElabSimulator::rampParameters(Axis a) const
{
    return m_board.axis(a).ramp();
}
qint64 ElabSimulator::executedSteps(Axis a) const
{
    return m_board.axis(a).executedSingleSteps();
}

void ElabSimulator::emergencyStop()
{
    const bool silent = faults().silent;
    faults().silent = true; // nobody asked: the ACK stays at the device
    receive(encode::stopMove());
    faults().silent = silent;
}

bool ElabSimulator::isStopFrame(const QByteArray& frame) const
{
    return frame == encode::stopMove() || frame == encode::panicStop() ||
           frame == encode::panicStop() + encode::panicStop() ||
           frame == encode::jogSpeed({0, 0, 0});
}

} // namespace stepdeck::elab
