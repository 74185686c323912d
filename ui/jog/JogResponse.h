#pragma once
#include <QtGlobal>
#include <cmath>

namespace stepdeck::ui {

// Maps a stick deflection (-1..1) to a speed fraction (-1..1): nothing inside the dead zone,
// then a power curve so small deflections give fine control. Pure.
struct JogResponse
{
    double deadZone = 0.08; // fraction of full deflection that gives no motion
    double exponent = 2.0;  // 1 = linear, 2 = quadratic, 3 = cubic

    double apply(double deflection) const
    {
        const double magnitude = qMin(1.0, std::fabs(deflection));
        if (magnitude <= deadZone || deadZone >= 1.0)
            return 0.0;
        const double scaled = (magnitude - deadZone) / (1.0 - deadZone);
        const double shaped = std::pow(scaled, qMax(0.1, exponent));
        return deflection < 0 ? -shaped : shaped;
    }
};

} // namespace stepdeck::ui
