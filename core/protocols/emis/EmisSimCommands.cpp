// The SMC-IC4 simulator's command execution (chapter 9).
#include "EmisSimulator.h"
#include "Logging.h"

namespace stepdeck::emis {

namespace {
using K = Command::Kind;

QByteArray ack(const QByteArray& text = {})
{
    return text + kAck;
}

QByteArray bel()
{
    return QByteArray(1, kBel);
}

QList<Axis> axesOf(const Command& c)
{
    if (c.axis)
        return {*c.axis};
    return emisAxes();
}
} // namespace

QByteArray EmisSimulator::run(const Command& c)
{
    if (c.kind == K::Invalid || !rangeError(c).isEmpty()) {
        qCDebug(lcSimulator) << "emis: refused" << c.text << c.error << rangeError(c);
        return bel();
    }
    switch (c.kind) {
    case K::Version:
        return ack("@V " + QByteArray(kFirmware));
    case K::Input:
        return ack(c.text + ' ' + (inputLevels().value(c.number - 1) ? '1' : '0'));
    case K::AllInputs: {
        if (m_bellOnPollWhileMoving && anyMoving())
            return bel();
        QByteArray bits;
        for (bool level : inputLevels())
            bits += level ? '1' : '0';
        return ack("@IG " + bits);
    }
    case K::Output:
        m_outputs[size_t(c.number - 1)] = c.on;
        return ack();
    case K::Home:
        return runHome(c);
    case K::Vector:
        return runVector(c);
    case K::SystemWrite:
        return runSystemWrite(c);
    case K::ReadSystem:
        return ack(formatSystemParameters(m_stored));
    case K::ClearSystem:
        // 9.16: only the SMCflex entry is erased; the others can simply be overwritten.
        m_stored.erase(
            std::remove_if(m_stored.begin(), m_stored.end(),
                           [](const SystemEntry& e) { return e.key == SystemEntry::Key::SmcFlex; }),
            m_stored.end());
        return ack("*PESYS ");
    case K::ProgramOpen:
        m_programming = c.number;
        m_programHeader = false;
        m_draft = InputProgram{};
        return ack();
    case K::ProgramErase:
        m_programs.remove(c.number);
        return ack(c.text + ' ');
    case K::ProgramHeader:
    case K::ProgramEnd:
        return bel(); // only inside *PWIN (9.17)
    case K::Wait:
        return ack(); // outside a program there is nothing to wait for
    default:
        applyWorking(c);
        return ack();
    }
}

void EmisSimulator::applyWorking(const Command& c)
{
    Working& w = m_working;
    for (Axis axis : axesOf(c)) {
        switch (c.kind) {
        case K::StartSpeed:
            w.startSpeed[axis] = c.value;
            break;
        case K::WorkSpeed:
            w.workSpeed[axis] = c.value;
            break;
        case K::StepResolution:
            w.resolution[axis] = c.value;
            break;
        case K::Current:
            w.runCurrent[axis] = c.value;
            w.idleCurrent[axis] = c.idle;
            break;
        case K::ReferenceOffset:
            w.offset[axis] = c.value;
            break;
        default:
            break;
        }
    }
    if (c.kind == K::ReferenceSpeed)
        w.referenceSpeed = c.value;
    else if (c.kind == K::Ramp)
        w.ramp = c.value;
    else if (c.kind == K::Interpolation)
        w.interpolation = c.on;
}

QByteArray EmisSimulator::runHome(const Command& c)
{
    for (Axis axis : c.axes) {
        if (isMoving(axis)) {
            ++m_busyRefusals;
            return bel(); // the motor is still moving
        }
    }
    if (c.simultaneous) {
        for (Axis axis : c.axes) {
            m_referenceQueue = {axis};
            startNextReference();
        }
    } else {
        m_referenceQueue = c.axes;
        startNextReference();
    }
    // "$Hx<NAK>" (9.9): the echo without the ",a", then <NAK>.
    return c.text.split(',').first() + kNak;
}

QByteArray EmisSimulator::runVector(const Command& c)
{
    for (const VectorTarget& t : c.targets) {
        if (isMoving(t.axis)) {
            ++m_busyRefusals;
            return bel();
        }
    }
    // Physical targets and, with interpolation (9.12: "kommen beide Motoren gleichzeitig ins
    // Ziel"), profiles that make the axes arrive together. The manual does not say how; read
    // here as the board running every other axis as a scaled copy of the slowest one's profile
    // (its start speed, work speed and ramp), so they start, ramp and arrive on the same ticks.
    QMap<Axis, qint64> targets;
    const qint64 nowUs = m_clock.nsecsElapsed() / 1000;
    const qsizetype firstAccepted = m_accepted.size();
    std::optional<Axis> slowest;
    double slowestSeconds = -1;
    for (const VectorTarget& t : c.targets) {
        const qint64 relative = t.absolute ? t.value - position(t.axis) : t.value;
        targets.insert(t.axis, axisRef(t.axis).physical() + relative);
        if (relative != 0)
            m_accepted.append({t.axis, relative, m_working.workSpeed.value(t.axis), 0, nowUs});
        const double seconds =
            double(qAbs(relative)) / qMax<double>(1, m_working.workSpeed.value(t.axis));
        if (seconds > slowestSeconds) {
            slowestSeconds = seconds;
            slowest = t.axis;
        }
    }
    const bool together = m_working.interpolation && targets.size() > 1 && slowestSeconds > 0;
    const EmisSimAxis::Profile lead = together ? profile(*slowest) : EmisSimAxis::Profile{};
    const double leadDistance =
        together ? double(qAbs(targets.value(*slowest) - axisRef(*slowest).physical())) : 0.0;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        EmisSimAxis::Profile p = profile(it.key());
        if (together) {
            const double k = double(qAbs(it.value() - axisRef(it.key()).physical())) / leadDistance;
            p.workSpeed = qMax(1.0, lead.workSpeed * k);
            p.startSpeed = qMin(lead.startSpeed, lead.workSpeed) * k;
            p.rampMs = lead.rampMs;
        }
        for (qsizetype i = firstAccepted; i < m_accepted.size(); ++i)
            if (m_accepted[i].axis == it.key())
                m_accepted[i].runSpeed = p.workSpeed;
        axisRef(it.key()).startMove(it.value(), p);
    }
    ensureTicking();                  // a zero-length target arrives on the first tick
    return QByteArray(1, kNak) + ' '; // "<NAK> <DC1>" (9.11)
}

QByteArray EmisSimulator::runSystemWrite(const Command& c)
{
    storeEntry(c.system);
    // 9.14: "<ACK> Ready! <ACK> <ACK> <ACK> <ACK>", each <ACK> after "Ready!" once its part of
    // the flash is written.
    const int acks = (m_storedAcksPerMotor ? c.system.motorCount() : kStoredAcks) -
                     std::exchange(m_withheldAcks, 0);
    QList<QByteArray> parts{ack()};
    for (int i = 0; i < acks; ++i)
        parts << (i ? QByteArray(" ") : QByteArray(" Ready! ")) + ack();
    if (m_flashWriteMs == 0)
        return parts.join();
    m_flashParts = parts.mid(1);
    m_flashTimer.start(m_flashWriteMs);
    return parts.first();
}

void EmisSimulator::storeEntry(const SystemEntry& entry)
{
    for (SystemEntry& e : m_stored) {
        if (e.key != entry.key)
            continue;
        // Per-axis entries keep the axes the new entry does not name.
        e.values.insert(entry.values);
        e.idle.insert(entry.idle);
        e.normallyClosed.insert(entry.normallyClosed);
        e.ramp = entry.ramp;
        e.flexStart = entry.flexStart;
        e.flexWork = entry.flexWork;
        e.flexRamp = entry.flexRamp;
        return;
    }
    m_stored << entry;
}

QByteArray EmisSimulator::runProgramming(const Command& c, char terminator)
{
    // 9.17: *PWINn, then the header closed by <STX>, then commands, then <ETX>; every step
    // is acknowledged; the commands are stored, not executed.
    if (c.kind == K::ProgramEnd) {
        if (!m_programHeader)
            return bel();
        m_programs.insert(m_programming, m_draft);
        m_programming = 0;
        return ack();
    }
    if (!m_programHeader) {
        if (terminator != kStx || c.kind != K::ProgramHeader || c.number != m_programming ||
            !rangeError(c).isEmpty())
            return bel();
        m_draft.title = c.title;
        m_programHeader = true;
        return ack();
    }
    if (!programRefusal(c).isEmpty() || !rangeError(c).isEmpty())
        return bel();
    m_draft.commands << c.text;
    return ack();
}

} // namespace stepdeck::emis
