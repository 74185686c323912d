#include "EmisSimulator.h"
#include "Logging.h"

namespace stepdeck::emis {

namespace {
constexpr qint64 kPowerOnDistance = 200; // steps between carriage and switch at power-on
} // namespace

EmisSimulator::EmisSimulator(const SimulatorOptions& options, QObject* parent)
    : Simulator(options, parent)
{
    for (Axis axis : emisAxes()) {
        m_switchAt[slot(axis)] = 0;
        axisRef(axis).setPhysical(kPowerOnDistance);
    }
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(5);
    connect(&m_timer, &QTimer::timeout, this, &EmisSimulator::tick);
    connect(&m_flashTimer, &QTimer::timeout, this, &EmisSimulator::flashWritten);
    m_clock.start();
    powerCycle();
}

EmisSimulator::~EmisSimulator() = default;

// ---------------------------------------------------------------- observation

qint64 EmisSimulator::position(Axis axis) const
{
    return axisRef(axis).physical() - m_origin[slot(axis)];
}

bool EmisSimulator::isMoving(Axis axis) const
{
    return axisRef(axis).isMoving() || m_referenceQueue.contains(axis);
}

bool EmisSimulator::anyMoving() const
{
    for (Axis axis : emisAxes()) {
        if (isMoving(axis))
            return true;
    }
    return false;
}

QList<bool> EmisSimulator::inputLevels() const
{
    QList<bool> levels;
    for (Axis axis : emisAxes())
        levels << switchLevel(axis, axisRef(axis).physical());
    for (bool level : m_freeInputs)
        levels << level;
    return levels;
}

bool EmisSimulator::output(int number) const
{
    return number >= 1 && number <= kOutputCount && m_outputs[size_t(number - 1)];
}

std::optional<EmisSimulator::InputProgram> EmisSimulator::program(int input) const
{
    if (!m_programs.contains(input))
        return std::nullopt;
    return m_programs.value(input);
}

// ---------------------------------------------------------------- scenario and faults

void EmisSimulator::setPhysicalPosition(Axis axis, qint64 steps)
{
    const qint64 counter = position(axis);
    axisRef(axis).setPhysical(steps);
    m_origin[slot(axis)] = steps - counter;
}

void EmisSimulator::setSwitchPosition(Axis axis, std::optional<qint64> steps)
{
    m_switchAt[slot(axis)] = steps;
}

void EmisSimulator::setSwitchWiring(Axis axis, bool normallyClosed)
{
    m_wiredNc[slot(axis)] = normallyClosed;
}

void EmisSimulator::setInput(int number, bool level)
{
    if (number >= 5 && number <= kInputCount)
        m_freeInputs[size_t(number - 5)] = level;
}

bool EmisSimulator::setSettableInput(int number, bool level)
{
    if (!settableInputs().contains(number))
        return false;
    setInput(number, level);
    return true;
}

void EmisSimulator::dropArrivals(int count)
{
    m_dropArrivals = count;
}

void EmisSimulator::emergencyStop()
{
    m_referenceQueue.clear();
    for (Axis axis : emisAxes()) {
        EmisSimAxis& a = axisRef(axis);
        a.setPhysical(a.physical()); // idle where it stands
        m_referencing[slot(axis)] = false;
    }
}

void EmisSimulator::externalReset(int bootMs)
{
    emergencyStop();
    powerCycle();
    m_bootMs = bootMs;
    m_booting.start();
}

void EmisSimulator::powerCycle()
{
    for (Axis axis : emisAxes()) {
        axisRef(axis).setPhysical(axisRef(axis).physical()); // stands still
        m_origin[slot(axis)] = axisRef(axis).physical();
        m_referenced[slot(axis)] = false;
        m_referencing[slot(axis)] = false;
    }
    m_referenceQueue.clear();
    m_outputs.fill(false);
    m_programming = 0;
    m_decoder.reset();
    m_flashTimer.stop();
    m_flashParts.clear();
    m_waitingInput.clear();
    loadWorkingFromStored();
}

void EmisSimulator::loadWorkingFromStored()
{
    Working w;
    for (Axis axis : emisAxes()) {
        w.startSpeed[axis] = 200;
        w.workSpeed[axis] = 1000;
        w.offset[axis] = 10;
        w.resolution[axis] = 16;
        w.runCurrent[axis] = 100;
        w.idleCurrent[axis] = 20;
    }
    for (const SystemEntry& e : m_stored) {
        switch (e.key) {
        case SystemEntry::Key::StepResolution:
            w.resolution.insert(e.values);
            break;
        case SystemEntry::Key::Currents:
            w.runCurrent.insert(e.values);
            w.idleCurrent.insert(e.idle);
            break;
        case SystemEntry::Key::StartSpeed:
            w.startSpeed.insert(e.values);
            break;
        case SystemEntry::Key::WorkSpeed:
            w.workSpeed.insert(e.values);
            break;
        case SystemEntry::Key::ReferenceSpeed:
            // One working reference speed for all motors (9.5): X's stored value.
            if (!e.values.isEmpty())
                w.referenceSpeed = e.values.first();
            break;
        case SystemEntry::Key::Ramp:
            w.ramp = e.ramp;
            break;
        case SystemEntry::Key::SmcFlex:
        case SystemEntry::Key::ReferenceSwitch:
            break;
        }
    }
    m_working = w;
}

// ---------------------------------------------------------------- motion

bool EmisSimulator::switchLevel(Axis axis, qint64 physical) const
{
    const auto at = m_switchAt[slot(axis)];
    const bool actuated = at && physical <= *at;
    return m_wiredNc[slot(axis)] ? !actuated : actuated;
}

bool EmisSimulator::switchActive(Axis axis, qint64 physical) const
{
    // The board reads the level through its ##REFSW type (5.2.1): a wrong type makes the
    // reference run end at once, as it would on the machine.
    bool nc = false;
    for (const SystemEntry& e : m_stored) {
        if (e.key == SystemEntry::Key::ReferenceSwitch && e.normallyClosed.contains(axis))
            nc = e.normallyClosed.value(axis);
    }
    const bool level = switchLevel(axis, physical);
    return nc ? !level : level;
}

EmisSimAxis::Profile EmisSimulator::profile(Axis axis) const
{
    EmisSimAxis::Profile p;
    p.startSpeed = double(m_working.startSpeed.value(axis));
    p.workSpeed = double(m_working.workSpeed.value(axis));
    p.rampMs = double(m_working.ramp);
    return p;
}

void EmisSimulator::arrived(Axis axis)
{
    for (qsizetype i = m_accepted.size() - 1; i >= 0; --i) {
        if (m_accepted[i].axis == axis) {
            if (m_accepted[i].arrivedUs < 0)
                m_accepted[i].arrivedUs = m_lastTickUs; // the tick it arrived in
            break;
        }
    }
    if (m_referencing[slot(axis)]) {
        m_referencing[slot(axis)] = false;
        m_referenced[slot(axis)] = true;
        m_origin[slot(axis)] = axisRef(axis).physical(); // counter 0 after the offset
    }
    if (m_dropArrivals > 0) {
        --m_dropArrivals;
        ++m_arrivalsDropped;
        qCInfo(lcSimulator) << "emis fault: arrival of" << axisName(axis) << "not reported";
        return;
    }
    send(QByteArray(1, arrivalCode(axis)));
}

void EmisSimulator::startNextReference()
{
    if (m_referenceQueue.isEmpty())
        return;
    const Axis axis = m_referenceQueue.takeFirst();
    EmisSimAxis::Profile p = profile(axis);
    p.workSpeed = double(m_working.referenceSpeed);
    m_referencing[slot(axis)] = true;
    axisRef(axis).startReference(p, m_working.offset.value(axis));
    ensureTicking();
}

void EmisSimulator::tick()
{
    const qint64 nowUs = m_clock.nsecsElapsed() / 1000;
    const double dt = qMax<qint64>(1, nowUs - m_lastTickUs) / 1e6;
    m_lastTickUs = nowUs;
    bool sequentialDone = false;
    for (Axis axis : emisAxes()) {
        EmisSimAxis& a = axisRef(axis);
        const bool wasReferencing = m_referencing[slot(axis)];
        if (a.advance(dt, [this, axis](qint64 p) { return switchActive(axis, p); })) {
            arrived(axis);
            sequentialDone = sequentialDone || wasReferencing;
        }
    }
    if (sequentialDone) {
        bool anyReferencing = false;
        for (bool r : m_referencing)
            anyReferencing = anyReferencing || r;
        if (!anyReferencing)
            startNextReference(); // $Hxyzu: one after the other (9.9)
    }
    bool moving = false;
    for (const EmisSimAxis& a : m_axes)
        moving = moving || a.isMoving();
    if (!moving && m_referenceQueue.isEmpty())
        m_timer.stop();
}

void EmisSimulator::ensureTicking()
{
    if (m_timer.isActive())
        return;
    m_lastTickUs = m_clock.nsecsElapsed() / 1000;
    m_timer.start();
}

// ---------------------------------------------------------------- receiving

void EmisSimulator::receive(const QByteArray& bytes)
{
    if (m_booting.isValid() && !m_booting.hasExpired(m_bootMs))
        return; // restarting after a reset: the bytes are lost
    if (m_flashTimer.isActive()) {
        m_waitingInput += bytes;
        return;
    }
    const QList<CommandDecoder::Frame> frames = m_decoder.feed(bytes);
    for (int i = 0; i < frames.size(); ++i) {
        execute(frames[i]);
        if (m_flashTimer.isActive()) { // a "##" write: the rest waits until it is done
            for (const CommandDecoder::Frame& later : frames.mid(i + 1))
                m_waitingInput += later.text + later.terminator;
            return;
        }
    }
}

void EmisSimulator::flashWritten()
{
    if (!m_flashParts.isEmpty())
        send(m_flashParts.takeFirst());
    if (!m_flashParts.isEmpty())
        return;
    m_flashTimer.stop();
    receive(std::exchange(m_waitingInput, QByteArray()));
}

void EmisSimulator::execute(const CommandDecoder::Frame& frame)
{
    if (frame.overlong) {
        qCDebug(lcSimulator) << "emis: overlong command dropped";
        send(QByteArray(1, kBel));
        return;
    }
    m_commands << (frame.terminator == kEtx ? QByteArray("<ETX>") : frame.text);
    noteReceived(frame.text + frame.terminator); // the base's log, terminator included
    if (faults().forceNak > 0 || (!m_bellOn.isEmpty() && frame.text == m_bellOn)) {
        if (frame.text == m_bellOn)
            m_bellOn.clear();
        else
            --faults().forceNak;
        send(QByteArray(1, kBel));
        return;
    }
    const Command c = parseCommand(frame.text, frame.terminator);
    const QByteArray reply = m_programming ? runProgramming(c, frame.terminator) : run(c);
    if (!reply.isEmpty())
        send(reply);
}

QList<SimulatedMove> EmisSimulator::acceptedMoves() const
{
    QList<SimulatedMove> out;
    out.reserve(m_accepted.size());
    for (const AcceptedMove& m : m_accepted)
        out.append({m.axis, m.steps});
    return out;
}

} // namespace stepdeck::emis
