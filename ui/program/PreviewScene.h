#pragma once
#include "PreviewProjection.h"
#include "machine/MachineDescription.h"
#include "program/ProgramCheck.h"
#include <QPainterPath>
#include <optional>

namespace stepdeck::ui {

// The preview's path prepared for drawing (issue 29): the checked path's X, Y and Z (work
// coordinates) with how each point is reached, and the soft limits converted to work
// coordinates; project() turns them into one view's plane geometry (PreviewProjection, or a
// PreviewOrientation when the operator turns the path, issue 47), built once per preview and
// view (and per step of a turn): the feeds and the rapids as one QPainterPath each, the
// soft-limit box, the start and the bounds. Zoom and pan draw these through a transform
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
    // The plane geometry of the path turned by orientation (issue 47 item 14), of the points
    // known on every one of axes (indices into PreviewPosition; a turned view needs X, Y and Z,
    // a preset its view's axes). Into out, whose memory is reused: turning the view projects
    // again on every mouse move without allocating per point.
    void project(const PreviewOrientation& orientation, const QList<int>& axes,
                 Projected& out) const;
    // The segments that end at points of line (a block's chords), in the plane.
    static QPainterPath segmentsOfLine(const Projected& projected, int line);
    // Where a position (axis name -> work coordinate) lands on the view's plane; nullopt when
    // it lacks one of the view's axes.
    static std::optional<QPointF> projectPosition(PreviewViewKind kind,
                                                  const QMap<QString, double>& position);
    static std::optional<QPointF> projectPosition(const PreviewOrientation& orientation,
                                                  const QList<int>& axes,
                                                  const QMap<QString, double>& position);
    // The middle of what a turned view shows, in work coordinates: of the box of the points
    // known on X, Y and Z, else of the soft limits' box (an axis without limits at 0); the view
    // turns about it. nullopt: neither.
    std::optional<PreviewPosition> centre() const { return m_centre; }
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
    std::optional<PreviewPosition> computeCentre() const;
    // ToPlane: PreviewPosition -> QPointF (a view's or an orientation's projection).
    template <typename ToPlane>
    void projectWith(const ToPlane& toPlane, const QList<int>& axes, Projected& out) const;
    template <typename ToPlane>
    void softLimitBox(const ToPlane& toPlane, const QList<int>& axes, QPainterPath& box) const;

    QList<Point> m_points;
    QStringList m_axes;
    QStringList m_units{QString(), QString(), QString()};
    // Per axis (X, Y, Z) its soft limits in work coordinates, if it has them.
    std::array<std::optional<std::pair<double, double>>, 3> m_limits;
    std::optional<PreviewPosition> m_centre;
};

} // namespace stepdeck::ui
