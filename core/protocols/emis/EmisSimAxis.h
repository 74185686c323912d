#pragma once
#include <QtGlobal>
#include <functional>

namespace stepdeck::emis {

// One simulated SMC-IC4 motor: time-based motion in physical steps (the carriage's place on
// the machine; the board's own position counter is the simulator's business). Pure: the
// simulator calls advance() from its timer.
//
// Moves ramp from the start speed to the work speed within the ramp time and back down so
// that they arrive at start speed (9.6). A reference run (9.9) drives towards negative
// positions at the reference speed until the switch reports active, then moves `offset` steps
// back out of it (9.10).
class EmisSimAxis
{
public:
    struct Profile
    {
        double startSpeed = 200; // steps/s
        double workSpeed = 1000; // steps/s
        double rampMs = 100;
    };
    enum class Phase { Idle, Moving, Searching, Leaving };

    void setPhysical(qint64 steps);
    qint64 physical() const { return qRound64(m_position); }
    double velocity() const { return m_phase == Phase::Idle ? 0.0 : m_direction * m_speed; }
    Phase phase() const { return m_phase; }
    bool isMoving() const { return m_phase != Phase::Idle; }

    void startMove(qint64 physicalTarget, const Profile& profile);
    void startReference(const Profile& profile, qint64 offset);
    // Advances by dt seconds; `switchActive(physical)` tells whether the board sees its
    // reference switch there. Returns true when the motion ended in this step.
    bool advance(double dt, const std::function<bool(qint64)>& switchActive);

private:
    void beginLeg(double target, const Profile& profile);

    Phase m_phase = Phase::Idle;
    double m_position = 0;
    double m_target = 0;
    double m_speed = 0;
    int m_direction = 1;
    Profile m_profile;
    qint64 m_offset = 0;
};

} // namespace stepdeck::emis
