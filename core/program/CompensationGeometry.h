#pragma once
// The plane geometry of cutter compensation (CutterCompensation): points, a move's programmed
// path, and the lines and circles the tool's path runs on. Pure; machine coordinates of X and Y.
#include <vector>

namespace stepdeck::program::compensation {

struct Point
{
    double x = 0, y = 0;
};

inline Point operator-(Point a, Point b)
{
    return {a.x - b.x, a.y - b.y};
}
inline Point operator+(Point a, Point b)
{
    return {a.x + b.x, a.y + b.y};
}
inline Point operator*(double k, Point a)
{
    return {k * a.x, k * a.y};
}
inline double dot(Point a, Point b)
{
    return a.x * b.x + a.y * b.y;
}
inline double cross(Point a, Point b)
{
    return a.x * b.y - a.y * b.x;
}
double length(Point a);
Point unit(Point a); // length 1, or 0 for no length
inline Point left(Point a)
{
    return {-a.y, a.x};
} // turned 90 degrees counter-clockwise

// A move in the XY plane: a line, or an arc about `centre`.
struct Path
{
    bool arc = false;
    Point start, end, centre;
    double sweep = 0; // radians, + counter-clockwise (arcs)
    int line = 0;     // the block's line
};

// The direction of travel at the start or end of a path.
Point tangentAt(const Path& p, bool atEnd);
// The angle from `from` to `to` turning the way of `sweep`, in [0, 2 pi).
double turned(double from, double to, double sweep);

// A line through two points or a circle: the tool's path of a move, for inside corners.
struct Geometry
{
    bool circle = false;
    Point a, b;   // line: through a and b
    Point centre; // circle
    double radius = 0;
};

// Where two of them cross (none, one or two points).
std::vector<Point> intersections(const Geometry& g, const Geometry& h);
// How far along a move's tool path a point lies: (0, 1] from its start to its nominal end
// (lines), or the angle turned from the start (arcs, compared with the sweep).
double along(const Geometry& g, const Path& path, Point start, Point point);

} // namespace stepdeck::program::compensation
