#pragma once
#include <QtGlobal>

namespace stepdeck::ui {

// Where a positioning move probably is, for a model that does not report positions during a
// move: a trapezoidal profile (start speed, acceleration up to max speed, cruise, and the
// same ramp down), from the ramp parameters the host wrote or read in this session. Shown
// marked as an estimate; never beyond the target. Pure.
struct MoveProfile
{
    double startSpeed = 0;   // steps/s
    double maxSpeed = 0;     // steps/s
    double acceleration = 0; // steps/s^2
    bool isValid() const { return maxSpeed > 0 && acceleration > 0; }
};

class MoveEstimate
{
public:
    // Steps travelled after `seconds` of a move of `distance` steps (>= 0), 0..distance.
    static double travelled(double distance, const MoveProfile& profile, double seconds);
    // Seconds the whole move takes.
    static double duration(double distance, const MoveProfile& profile);
};

} // namespace stepdeck::ui
