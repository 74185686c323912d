#include "ElabSimulator.h"
#include "Logging.h"

// The machine around the simulated board (buttons, switches, temperature) and the accessors
// tests and stepdeck-sim use to observe it. Every setter first brings the motion up to now, so
// a switch actuated mid-move acts at this moment, not at the next tick.

namespace stepdeck::elab {

void ElabSimulator::setTemperature(int celsius)
{
    m_temperature = qBound(0, celsius, 255); // <ETB>TT#: one unsigned byte
}

void ElabSimulator::setPanicButton(bool pressed)
{
    advanceToNow();
    m_panicButton = pressed;
    if (pressed) {
        qCInfo(lcSimulator) << "elab sim: panic button pressed, all axes stopped";
        stopAll(false);
    }
    sendFlowControl();
    updateTimer();
}

void ElabSimulator::setLimitSwitchActuated(Axis a, bool actuated)
{
    advanceToNow();
    axis(a).setLimitForced(actuated);
    checkLimits();
    updateTimer();
}

void ElabSimulator::setReferenceSwitchActuated(Axis a, bool actuated)
{
    advanceToNow();
    axis(a).setReferenceForced(actuated);
    // A reference move waiting for this switch stops as if it had driven onto it.
    if (axis(a).mode() == ElabSimAxis::Mode::Reference && axis(a).referenceActive())
        axis(a).hardStop();
    updateTimer();
}

void ElabSimulator::setLimitPositions(Axis a, qint64 minimum, qint64 maximum)
{
    advanceToNow();
    axis(a).switches().limitMin = minimum;
    axis(a).switches().limitMax = maximum;
    checkLimits();
    updateTimer();
}

void ElabSimulator::setReferencePosition(Axis a, qint64 position, qint64 window)
{
    advanceToNow();
    axis(a).switches().referencePosition = position;
    axis(a).switches().referenceWindow = qMax<qint64>(0, window);
}

void ElabSimulator::setSwitchWiring(Axis a, bool limitActiveHigh, bool referenceActiveHigh)
{
    advanceToNow();
    axis(a).switches().limitWiredActiveHigh = limitActiveHigh;
    axis(a).switches().referenceWiredActiveHigh = referenceActiveHigh;
    checkLimits();
    updateTimer();
}

ElabSimSwitchConfig ElabSimulator::switchConfig(Axis a) const
{
    return axis(a).switches();
}

void ElabSimulator::setPosition(Axis a, qint64 steps)
{
    advanceToNow();
    axis(a).setPosition(steps);
}

void ElabSimulator::setStreamBuffer(int capacity, int highWater, int lowWater)
{
    m_stream.configure(capacity, highWater, lowWater);
}

qint64 ElabSimulator::position(Axis a)
{
    advanceToNow();
    return axis(a).position();
}

bool ElabSimulator::isMoving(Axis a)
{
    advanceToNow();
    return axis(a).isMoving() || m_stream.running();
}

bool ElabSimulator::isBusy()
{
    advanceToNow();
    return busyNow();
}

qint64 ElabSimulator::remainingSteps(Axis a)
{
    advanceToNow();
    return axis(a).remaining();
}

bool ElabSimulator::limitSwitchActive(Axis a) const
{
    return axis(a).limitActive();
}
bool ElabSimulator::referenceSwitchActive(Axis a) const
{
    return axis(a).referenceActive();
}
bool ElabSimulator::limitSwitchLevelHigh(Axis a) const
{
    return axis(a).limitLevelHigh();
}
ElabSimRamp ElabSimulator::rampParameters(Axis a) const
{
    return axis(a).ramp();
}
qint64 ElabSimulator::executedSteps(Axis a) const
{
    return axis(a).executedSingleSteps();
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
