#pragma once
#include "PreviewProjection.h"
#include "machine/MachineDescription.h"
#include "program/ProgramCheck.h"
#include <QPainterPath>
#include <optional>

namespace stepdeck::ui {

// The preview's path prepared for drawing (issue 29): the checked path's X, Y and Z (work
// coordinates) with how each point is reached, and the soft limits converted to work
// coordinates; project() turns them into one view's plane geometry (PreviewProjection), built
// once per preview and view: the feeds and the rapids as one QPainterPath each, the soft-limit
// box, the start and the bounds. Zoom and pan draw these through a transform
// (PreviewViewport), so drawing costs only the path's (bounded) point count.
class PreviewScene
{
public:
    void setPreview(const program::ProgramPreview& preview,
                    const machine::MachineDescription& machine);
    void clear();
    // The machine's axes among X, Y, Z (what the views may use).
    QStringList axes() const { return m_axes; }
    bool isEmpty() const { return m_points.isEmpty(); }

    // The plane geometry of one view.
    struct Projected
    {
        QPainterPath feeds;      // G1, arcs' chords, reference runs: solid
        QPainterPath rapids;     // G0: dashed
        QPainterPath softLimits; // the box (edges) of the view's axes' soft limits; empty: none
        QList<QPointF> points;   // every point drawn, in path order
        QList<int> lines;        // the block that ends at each of points
        QList<bool> rapid;       // whether a G0 reaches each of points
        QList<bool> joined;      // whether each of points is joined to the one before it
        std::optional<QPointF> start;
        std::optional<QRectF> bounds; // of the path and the soft-limit box
    };
    Projected project(PreviewViewKind kind) const;
    // The segments that end at points of line (a block's chords), in the plane.
    static QPainterPath segmentsOfLine(const Projected& projected, int line);
    // Where a position (axis name -> work coordinate) lands on the view's plane; nullopt when
    // it lacks one of the view's axes.
    static std::optional<QPointF> projectPosition(PreviewViewKind kind,
                                                  const QMap<QString, double>& position);
    // The unit of the view's axes ("mm"; "mm/in" when they differ).
    QString unitOf(PreviewViewKind kind) const;

private:
    struct Point
    {
        PreviewPosition position{};
        unsigned known = 0; // bit i: axis i of position is known
        bool rapid = false;
        int line = 0;
    };
    QPainterPath softLimitBox(PreviewViewKind kind) const;

    QList<Point> m_points;
    QStringList m_axes;
    QStringList m_units{QString(), QString(), QString()};
    // Per axis (X, Y, Z) its soft limits in work coordinates, if it has them.
    std::array<std::optional<std::pair<double, double>>, 3> m_limits;
};

} // namespace stepdeck::ui
