#pragma once
#include "model/Axis.h"
#include <QtMath>

namespace stepdeck {

// Host-side jog ramp. The E-LAB manual (Befehle im Jogbetrieb) makes the host responsible
// for ramping jog rates: a rate change larger than the motor can follow loses synchronisation.
// Pure: no timers, no I/O. The owner calls advance() on every tick.
class JogRamp
{
public:
    explicit JogRamp(double accelerationStepsPerS2 = 2000, double maxSpeedStepsPerS = 1000);

    void setAcceleration(double stepsPerS2); // > 0
    double acceleration() const { return m_acceleration; }
    void setMaxSpeed(double stepsPerS); // targets are clamped to +-maxSpeed
    double maxSpeed() const { return m_maxSpeed; }

    void setTarget(Axis axis, double stepsPerS);
    void setTargets(const AxisVelocities& targets); // axes not named keep their target
    void releaseAll();                              // every target to zero (ramps down)
    void reset();                                   // targets and rates to zero at once
    void stopAxis(Axis axis);                       // one axis: target and rate to zero at once

    double target(Axis axis) const { return m_targets.value(axis, 0.0); }
    double current(Axis axis) const { return m_current.value(axis, 0.0); }
    AxisVelocities currentVelocities() const { return m_current; }

    // Moves each axis towards its target by at most acceleration * dtSeconds; returns the
    // new rates. A rate crossing zero stops at zero for one tick before reversing.
    AxisVelocities advance(double dtSeconds);
    // The rates to hold until the next tick, tickSeconds from now (issue 28 item 6). An axis
    // that brakes (its rate falls towards its target, or towards zero before a reversal)
    // holds the rate the ramp reaches at the end of that tick; the others hold current().
    // Why: a rate held for a tick of a falling ramp runs ahead of the ramp by half a tick's
    // travel per tick (v * tick / 2 over a whole stop), and a release waits up to one tick
    // for the next advance(). Holding the lower rate keeps what the device travels after a
    // release within stopDistance(), with some of a tick's travel to spare for the link.
    // No rate is more than acceleration * sinceSentSeconds below `sent` (the rates last sent,
    // sinceSentSeconds ago): each change stays one the motor can follow, as the ramp's own
    // steps are. So the look ahead is all there only for an axis that ran at its rate for a
    // tick or more before the release; released in the first tick after reaching it, an axis
    // may travel up to v * tick / 2 further.
    AxisVelocities heldRates(double tickSeconds, const AxisVelocities& sent = {},
                             double sinceSentSeconds = qInf()) const;
    // How far an axis at `speed` travels after a release, driven as above (having run at
    // `speed` for a tick or more): the rate held until the next tick (at most one tick of
    // travel), then heldRates() tick by tick. It is v^2 / (2a) once braking spans two ticks
    // or more (v >= 2 a tick), else that one tick.
    static double stopDistance(double speed, double acceleration, double tickSeconds);
    bool isIdle() const; // all rates and targets are zero

private:
    double m_acceleration;
    double m_maxSpeed;
    AxisVelocities m_targets;
    AxisVelocities m_current;
};

} // namespace stepdeck
