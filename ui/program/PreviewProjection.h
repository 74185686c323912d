#pragma once
#include <QCoreApplication>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <array>
#include <optional>

namespace stepdeck::ui {

// How the preview looks at the path (issue 29): from above (X right, Y up), from the front
// (X right, Z up), from the side (Y right, Z up) or isometric (seen from the front left
// corner above the table: X to the upper right, Y to the upper left, Z up, all at one scale).
// Pure arithmetic, no widgets.
enum class PreviewViewKind { Top, Front, Side, Isometric };

// A position in work coordinates: X, Y, Z in their units; an axis the machine lacks is 0.
using PreviewPosition = std::array<double, 3>;

class PreviewProjection
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::PreviewProjection)
public:
    static constexpr std::array<PreviewViewKind, 4> kAll{
        PreviewViewKind::Top, PreviewViewKind::Front, PreviewViewKind::Side,
        PreviewViewKind::Isometric};

    // The axes a view needs, as indices into PreviewPosition (0 X, 1 Y, 2 Z).
    static QList<int> axesOf(PreviewViewKind kind);
    // A view is possible when the machine has every axis it needs (axes: its axis names).
    static bool available(PreviewViewKind kind, const QStringList& axes);
    // Why a view is not possible on a machine (empty when it is).
    static QString unavailableReason(PreviewViewKind kind, const QStringList& axes);
    static QString title(PreviewViewKind kind); // "Top (X/Y)"
    static QString settingsName(PreviewViewKind kind);
    static PreviewViewKind fromSettingsName(const QString& name, PreviewViewKind fallback);

    // The point on the view's plane: right and up (the widget flips up to its own down). The
    // isometric view here is the isometric drawing (every axis at full length); the path view
    // draws through PreviewOrientation, whose isometric preset is the same picture at
    // sqrt(2/3) of this size (the true projection: lengths across the screen keep their scale).
    static QPointF project(PreviewViewKind kind, const PreviewPosition& p);
};

// How the path is turned for the view (issue 47 item 14): an orthographic view, the work turned
// about Z by azimuth (counterclockwise seen from above) and seen from elevation above the table
// (90: from straight above, 0: from the front, -90: from below). The standard views are its
// presets: top (0, 90) and front (0, 0) as PreviewProjection draws them, side (-90, 0) and
// isometric (45, 35.26: from the front left above). Angles in degrees; the azimuth is kept
// within (-180, 180], the elevation within [-90, 90]. Projecting a point costs five
// multiplications (the sines and cosines are computed once per orientation). Pure arithmetic.
class PreviewOrientation
{
public:
    PreviewOrientation() : PreviewOrientation(0, 90) {} // the top view
    PreviewOrientation(double azimuth, double elevation);
    static PreviewOrientation of(PreviewViewKind kind);
    // The elevation of the isometric preset: every axis at the same angle to the screen.
    static double isometricElevation();

    double azimuth() const { return m_azimuth; }
    double elevation() const { return m_elevation; }
    // Turned further by the given degrees (the elevation clamped, the azimuth wrapped).
    PreviewOrientation turned(double azimuth, double elevation) const;
    // The standard view these exact angles are, if any.
    std::optional<PreviewViewKind> preset() const;

    // The point on the view's plane: right and up, as PreviewProjection::project.
    QPointF project(const PreviewPosition& p) const
    {
        return {p[0] * m_xRight + p[1] * m_yRight, p[0] * m_xUp + p[1] * m_yUp + p[2] * m_zUp};
    }

    bool operator==(const PreviewOrientation& o) const
    {
        return m_azimuth == o.m_azimuth && m_elevation == o.m_elevation;
    }
    bool operator!=(const PreviewOrientation& o) const { return !(*this == o); }

private:
    double m_azimuth = 0, m_elevation = 90;
    // The screen's right and up in work coordinates (right has no Z).
    double m_xRight = 1, m_yRight = 0, m_xUp = 0, m_yUp = 1, m_zUp = 0;
};

} // namespace stepdeck::ui
