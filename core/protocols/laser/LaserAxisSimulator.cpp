#include "LaserAxisSimulator.h"
#include "Logging.h"

namespace stepdeck::laser {

namespace {
constexpr int kTickMs = 5;
const QList<Axis> kAxes{Axis::X, Axis::Y, Axis::Z};
} // namespace

LaserAxisSimulator::LaserAxisSimulator(const SimulatorOptions& options, QObject* parent)
    : Simulator(options, parent)
{
    // Power-up somewhere off the home switch, so the first target homes first.
    for (LaserSimAxis& a : m_axes)
        a.powerOn(1000);
    m_tick.setTimerType(Qt::PreciseTimer);
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, [this] {
        advanceToNow();
        updateTimer();
    });
    m_clock.start();
}

LaserAxisSimulator::~LaserAxisSimulator() = default;

size_t LaserAxisSimulator::index(Axis axis)
{
    const int n = axisNumber(axis);
    return n > 0 ? size_t(n - 1) : 0;
}

void LaserAxisSimulator::setSpeed(double unitsPerS)
{
    advanceToNow();
    for (LaserSimAxis& a : m_axes)
        a.config().speed = qMax(1.0, unitsPerS);
}

void LaserAxisSimulator::powerOn(Axis axis, qint64 physical)
{
    advanceToNow();
    axis_(axis).powerOn(physical);
    axis_(axis).setHalted(m_doorOpen);
    updateTimer();
}

qint64 LaserAxisSimulator::position(Axis axis)
{
    advanceToNow();
    return axis_(axis).position();
}

bool LaserAxisSimulator::standingStill()
{
    advanceToNow();
    for (const LaserSimAxis& a : m_axes) {
        if (a.isMoving())
            return false;
    }
    return true;
}

bool LaserAxisSimulator::isMoving(Axis axis)
{
    advanceToNow();
    return axis_(axis).isMoving();
}

void LaserAxisSimulator::receive(const QByteArray& bytes)
{
    advanceToNow();
    for (const DecodedCommand& d : m_decoder.feed(bytes)) {
        if (!d.ok()) {
            // The laser's frames are all-or-nothing: a malformed one moves nothing.
            ++m_rejected;
            qCDebug(lcSimulator) << "laser-axis sim: ignored" << d.raw << describeError(d.error);
            continue;
        }
        noteReceived(d.raw);
        m_commands << *d.frame;
        execute(*d.frame);
    }
    updateTimer();
}

void LaserAxisSimulator::execute(const CommandFrame& command)
{
    LaserSimAxis& a = axis_(command.axis);
    // A new target replaces the old one; its status follows on the next tick, also for a
    // target the axis already stands on.
    if (command.command == Command::Home) {
        a.home();
        return;
    }
    if (const qint64 steps = command.position - a.position(); steps != 0)
        m_accepted.append({command.axis, steps});
    a.moveTo(command.position);
}

void LaserAxisSimulator::emergencyStop()
{
    advanceToNow();
    for (LaserSimAxis& a : m_axes)
        a.stop();
    updateTimer();
}

void LaserAxisSimulator::setDoorOpen(bool open)
{
    advanceToNow();
    if (open == m_doorOpen)
        return;
    m_doorOpen = open;
    QList<Axis> affected;
    for (Axis axis : kAxes) {
        if (axis_(axis).hasTarget())
            affected << axis;
        axis_(axis).setHalted(open);
    }
    if (affected.isEmpty())
        affected << Axis::X;
    for (Axis axis : affected)
        sendStatus(axis, open ? Status::DoorOpened : Status::DoorClosed);
    updateTimer();
}

void LaserAxisSimulator::reportStatus(Axis axis, Status status)
{
    advanceToNow();
    sendStatus(axis, status);
}

void LaserAxisSimulator::sendStatus(Axis axis, Status status)
{
    const qint64 position = qBound<qint64>(0, axis_(axis).position(), qint64(kMaxPosition));
    const QByteArray frame = encodeStatus({axis, int(position), status});
    m_sent << frame;
    if (m_garbage)
        send("9x\r");
    send(frame);
}

void LaserAxisSimulator::advanceToNow()
{
    const qint64 now = m_clock.nsecsElapsed();
    const double seconds = (now - m_lastNs) / 1e9;
    m_lastNs = now;
    if (seconds <= 0)
        return;
    for (Axis axis : kAxes) {
        switch (axis_(axis).advance(seconds)) {
        case LaserSimAxis::Event::None:
            break;
        case LaserSimAxis::Event::TargetReached:
            sendStatus(axis, Status::TargetReached);
            break;
        case LaserSimAxis::Event::HomeReached:
            sendStatus(axis, Status::HomeSwitch);
            break;
        case LaserSimAxis::Event::EndSwitch:
            sendStatus(axis, Status::EndSwitch);
            break;
        }
    }
}

void LaserAxisSimulator::updateTimer()
{
    bool moving = false;
    for (const LaserSimAxis& a : m_axes)
        moving = moving || a.isMoving();
    if (moving && !m_tick.isActive())
        m_tick.start();
    else if (!moving)
        m_tick.stop();
}

} // namespace stepdeck::laser
