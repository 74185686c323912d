// CompensationGeometry: lines and circles of cutter compensation (CutterCompensation.cpp).
#include "CompensationGeometry.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::program::compensation {

namespace {
constexpr double kTwoPi = 2 * 3.14159265358979323846;
constexpr double kLengthEpsilon = 1e-9; // mm: no travel
} // namespace

double length(Point a)
{
    return std::hypot(a.x, a.y);
}

Point unit(Point a)
{
    const double l = length(a);
    return l > 0 ? (1 / l) * a : Point{};
}

Point tangentAt(const Path& p, bool atEnd)
{
    if (!p.arc)
        return unit(p.end - p.start);
    const Point radial = unit((atEnd ? p.end : p.start) - p.centre);
    return p.sweep > 0 ? left(radial) : -1.0 * left(radial);
}

double turned(double from, double to, double sweep)
{
    double d = sweep > 0 ? to - from : from - to;
    d = std::fmod(d, kTwoPi);
    return d < 0 ? d + kTwoPi : d;
}

std::vector<Point> intersections(const Geometry& g, const Geometry& h)
{
    if (!g.circle && !h.circle) {
        const Point u = g.b - g.a, v = h.b - h.a;
        const double den = cross(u, v);
        if (std::fabs(den) < 1e-12 * length(u) * length(v))
            return {};
        const double s = cross(h.a - g.a, v) / den;
        return {g.a + s * u};
    }
    if (g.circle != h.circle) {
        const Geometry& line = g.circle ? h : g;
        const Geometry& circle = g.circle ? g : h;
        const Point u = unit(line.b - line.a);
        const Point f = line.a - circle.centre;
        const double b = dot(f, u);
        const double c = dot(f, f) - circle.radius * circle.radius;
        const double disc = b * b - c;
        if (disc < 0)
            return {};
        const double r = std::sqrt(disc);
        return {line.a + (-b - r) * u, line.a + (-b + r) * u};
    }
    const Point d = h.centre - g.centre;
    const double l = length(d);
    if (l < kLengthEpsilon || l > g.radius + h.radius || l < std::fabs(g.radius - h.radius))
        return {};
    const double a = (g.radius * g.radius - h.radius * h.radius + l * l) / (2 * l);
    const double hh = std::sqrt(std::max(0.0, g.radius * g.radius - a * a));
    const Point m = g.centre + (a / l) * d;
    const Point n = (hh / l) * left(d);
    return {m + n, m - n};
}

double along(const Geometry& g, const Path& path, Point start, Point point)
{
    if (!g.circle) {
        const Point u = g.b - g.a;
        return dot(point - start, u) / dot(u, u);
    }
    return turned(std::atan2(start.y - g.centre.y, start.x - g.centre.x),
                  std::atan2(point.y - g.centre.y, point.x - g.centre.x), path.sweep);
}

} // namespace stepdeck::program::compensation
