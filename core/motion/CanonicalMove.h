#pragma once
#include <QString>
#include <array>
#include <optional>

// The motion layer (issue 30, docs/architecture.md "Motion"): what programs, MDI lines and Go
// to ask of the machine, as LinuxCNC's canonical machining commands do (STRAIGHT_FEED,
// ARC_FEED): moves in machine coordinates with their feed and path mode, independent of any
// controller. Per-model executors turn runs of them into what a controller can do.
namespace stepdeck::motion {

// The axes of a move by slot (an executor's axis order), at most kMaxAxes.
constexpr int kMaxAxes = 9;
using Position = std::array<double, kMaxAxes>; // each slot in its axis' unit

// How consecutive moves join (LinuxCNC's G61, G61.1, G64).
enum class PathMode : quint8 { ExactPath, ExactStop, Blend };

// An arc in the plane of two slots, turning about `centre` from `startAngle` by `sweep`
// radians (+ counter-clockwise), its radius changing evenly from startRadius to endRadius (an
// end point off the circle within LinuxCNC's tolerance: a spiral, as ArcPath plans it). The
// move's other slots go from start to end evenly along the way (a helix, or rotary axes).
struct ArcGeometry
{
    int plane[2] = {0, 1};
    double centre[2] = {0, 0};
    double startRadius = 0;
    double endRadius = 0;
    double startAngle = 0;
    double sweep = 0;
};

// One move: a straight line from start to end, or an arc. feed: the path speed in the axes'
// unit per second (the program's F); a rapid has none (each axis at its fast speed). The path
// length is measured over the slots that move, in their units, as LinuxCNC measures XYZ.
struct CanonicalMove
{
    enum class Kind : quint8 { Rapid, Line, Arc };

    Kind kind = Kind::Line;
    int line = 0;      // the program line it comes from (0: none)
    int axisCount = 0; // slots 0..axisCount-1 take part
    Position start{};
    Position end{};
    std::optional<ArcGeometry> arc; // kind Arc
    double feed = 0;                // unit/s along the path (Line, Arc)
    PathMode pathMode = PathMode::Blend;

    static CanonicalMove straight(int axisCount, const Position& start, const Position& end,
                                  double feed, int line = 0);

    double length() const;
    // The point at path distance s (0..length()), every slot.
    Position at(double s) const;
    // The largest rate any slot moves at along the path when the path runs at 1 unit/s: |d
    // slot / d s| at its greatest (a line: the slot's share of the length; an arc: the radius
    // over the length, at most). Times feed and steps per unit: that slot's steps/s.
    double slotRatePerFeed(int slot) const;
    // A reason the move cannot be laid (no slots, a slot out of range, values not finite), or
    // empty.
    QString invalidReason() const;
};

} // namespace stepdeck::motion
