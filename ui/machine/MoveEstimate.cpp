#include "MoveEstimate.h"
#include <cmath>

namespace stepdeck::ui {

namespace {
struct Phases
{
    double v0, vPeak, a;
    double tAccel, dAccel, tCruise, dCruise;
};

Phases phases(double distance, const MoveProfile& p)
{
    Phases f{};
    f.a = p.acceleration;
    f.v0 = qBound(1.0, p.startSpeed, qMax(1.0, p.maxSpeed));
    f.vPeak = qMax(f.v0, p.maxSpeed);
    f.tAccel = (f.vPeak - f.v0) / f.a;
    f.dAccel = (f.v0 + f.vPeak) / 2 * f.tAccel;
    if (2 * f.dAccel > distance) { // no cruise: the peak speed is never reached
        f.vPeak = std::sqrt(f.v0 * f.v0 + f.a * distance);
        f.tAccel = (f.vPeak - f.v0) / f.a;
        f.dAccel = distance / 2;
    }
    f.dCruise = qMax(0.0, distance - 2 * f.dAccel);
    f.tCruise = f.dCruise / f.vPeak;
    return f;
}
} // namespace

double MoveEstimate::duration(double distance, const MoveProfile& profile)
{
    if (distance <= 0 || !profile.isValid())
        return 0;
    const Phases f = phases(distance, profile);
    return 2 * f.tAccel + f.tCruise;
}

double MoveEstimate::travelled(double distance, const MoveProfile& profile, double seconds)
{
    if (distance <= 0 || seconds <= 0 || !profile.isValid())
        return 0;
    const Phases f = phases(distance, profile);
    double s = 0;
    if (seconds < f.tAccel) {
        s = f.v0 * seconds + f.a * seconds * seconds / 2;
    } else if (seconds < f.tAccel + f.tCruise) {
        s = f.dAccel + f.vPeak * (seconds - f.tAccel);
    } else {
        const double t = qMin(seconds - f.tAccel - f.tCruise, f.tAccel);
        s = f.dAccel + f.dCruise + f.vPeak * t - f.a * t * t / 2;
    }
    return qBound(0.0, s, distance);
}

} // namespace stepdeck::ui
