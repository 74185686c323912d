#pragma once
#include "model/Axis.h"

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
    bool isIdle() const; // all rates and targets are zero

private:
    double m_acceleration;
    double m_maxSpeed;
    AxisVelocities m_targets;
    AxisVelocities m_current;
};

} // namespace stepdeck
