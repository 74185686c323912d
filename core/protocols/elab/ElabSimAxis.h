#pragma once
#include <QtGlobal>

namespace stepdeck::elab {

// Ramp and feed parameters of one axis as the host set them ("Setup Befehle").
struct ElabSimRamp
{
    quint16 startSpeed = 0;   // <ESC>S, steps/s
    quint16 maxSpeed = 0;     // <ESC>M, steps/s
    quint16 acceleration = 0; // <ESC>A, taken as steps/s^2 (manual: "sensible 500..2000")
    quint16 feedSpeed = 0;    // <FS>, steps/s
};

// Where the switches of one axis sit on the simulated machine and how they are wired. The
// wiring is the machine's truth; the polarity the host configures with <SO>/<DLE> only says how
// the firmware reads the level, so a wrong setting makes a switch read active when it is free.
struct ElabSimSwitchConfig
{
    // Defaults: a machine powered on 20000 steps above its home switch, with limit switches
    // well outside. Power-on position is 0, so no switch is active at power-on.
    qint64 limitMin = -200000;         // limit switch actuated at or below this position
    qint64 limitMax = 200000;          // ... and at or above this one
    qint64 referencePosition = -20000; // reference switch centre
    qint64 referenceWindow = 10;       // actuated within +- this many steps of the centre
    bool limitWiredActiveHigh = false; // actuated switch drives the line high (else low)
    bool referenceWiredActiveHigh = false;
};

// The motion model of one axis: position in steps, trapezoidal ramps for FastMove, reference
// and velocity moves, constant rate for feed and jog, advanced by elapsed time. Pure (no Qt
// objects, no timers): the simulator feeds it time slices.
class ElabSimAxis
{
public:
    enum class Mode { Idle, FastMove, Feed, Reference, Velocity, Jog };
    enum class Event { None, Finished, LimitHit, ReferenceHit };

    ElabSimRamp& ramp() { return m_ramp; }
    const ElabSimRamp& ramp() const { return m_ramp; }
    ElabSimSwitchConfig& switches() { return m_switches; }
    const ElabSimSwitchConfig& switches() const { return m_switches; }

    // ---- switches ----
    void setLimitPolarity(bool activeHigh) { m_limitPolarityHigh = activeHigh; }
    void setReferencePolarity(bool activeHigh) { m_referencePolarityHigh = activeHigh; }
    void setLimitForced(bool actuated) { m_limitForced = actuated; }
    void setReferenceForced(bool actuated) { m_referenceForced = actuated; }
    bool limitActuated() const; // mechanically pressed
    bool referenceActuated() const;
    bool limitLevelHigh() const; // electrical level at the controller input
    bool referenceLevelHigh() const;
    bool limitActive() const; // what the firmware reports (level vs configured polarity)
    bool referenceActive() const;

    // ---- motion commands (the simulator checks the manual's preconditions first) ----
    void startFastMove(qint64 steps);
    void startFeed(qint64 steps);
    void startReference(int direction);
    // First VelocityMove starts with the sign; while the axis still runs in velocity mode the
    // sign is ignored and only the rate changes (manual: SetVelocityMoveXYZ).
    void setVelocity(int rate);
    void setJogRate(int rate);
    void rampStop(); // ForceStopMove: brake ramp, no step lost; feed stops at once (no ramp)
    void hardStop(); // PanicStop, limit switch: immediately
    // One single step of the DC2 stream. Returns false when a limit switch is active after it.
    bool singleStep(int direction);

    // Advances by `seconds`; returns the event that ended the motion, if any.
    Event advance(double seconds);

    Mode mode() const { return m_mode; }
    bool isMoving() const { return m_mode != Mode::Idle; }
    bool isStopping() const { return m_stopping; }
    int direction() const { return m_direction; }
    double speed() const { return m_speed; }
    qint64 position() const { return m_position; }
    void setPosition(qint64 position) { m_position = position; }
    // Signed steps of the last FastMove/feed not yet executed (RequestRelPosition).
    qint64 remaining() const { return m_direction * m_stepsLeft; }
    void clearRemaining();
    qint64 executedSingleSteps() const { return m_singleSteps; }
    void clearSingleSteps() { m_singleSteps = 0; }

    void reset(); // power-on: parameters, configured polarity, motion; the machine stays

private:
    Event advanceSlice(double seconds);
    void updateRampSpeed(double seconds);
    double startSpeed() const { return qMax<double>(1.0, m_ramp.startSpeed); }
    double brakingDistance() const;
    void finish();

    ElabSimRamp m_ramp;
    ElabSimSwitchConfig m_switches;
    bool m_limitPolarityHigh = false; // power-on: low-active, like the default wiring
    bool m_referencePolarityHigh = false;
    bool m_limitForced = false;
    bool m_referenceForced = false;

    Mode m_mode = Mode::Idle;
    qint64 m_position = 0;
    int m_direction = 1;
    double m_speed = 0;       // current step rate, steps/s
    double m_targetSpeed = 0; // velocity/jog: commanded rate
    double m_fraction = 0;    // part of a step already travelled
    qint64 m_stepsLeft = 0;   // FastMove/feed: unsigned count, kept after a ramped stop
    bool m_stopping = false;
    qint64 m_singleSteps = 0;
};

} // namespace stepdeck::elab
