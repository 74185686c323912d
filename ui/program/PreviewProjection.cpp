#include "PreviewProjection.h"
#include <QtMath>
#include <cmath>

namespace stepdeck::ui {

namespace {
const char* const kAxisNames[3] = {"X", "Y", "Z"};
// Isometric: the X and Y axes 30 degrees below the horizontal, Z vertical, all three at the
// same scale (cos 30 = sqrt(3)/2, sin 30 = 1/2).
const double kCos30 = std::sqrt(3.0) / 2.0;
constexpr double kSin30 = 0.5;

// Sine and cosine of degrees, exact at the quarter turns: the top, front and side presets put
// a point exactly where PreviewProjection::project does (a Z of no influence on the top view,
// not cos(pi/2) = 6e-17 of it).
void sinCos(double degrees, double& s, double& c)
{
    double d = std::fmod(degrees, 360.0);
    if (d < 0)
        d += 360.0;
    if (d == 0) {
        s = 0;
        c = 1;
    } else if (d == 90) {
        s = 1;
        c = 0;
    } else if (d == 180) {
        s = 0;
        c = -1;
    } else if (d == 270) {
        s = -1;
        c = 0;
    } else {
        const double r = qDegreesToRadians(d);
        s = std::sin(r);
        c = std::cos(r);
    }
}

double wrapAzimuth(double degrees)
{
    if (!std::isfinite(degrees))
        return 0;
    double d = std::fmod(degrees, 360.0); // (-360, 360)
    if (d <= -180)
        d += 360;
    else if (d > 180)
        d -= 360;
    return d;
}
} // namespace

QList<int> PreviewProjection::axesOf(PreviewViewKind kind)
{
    switch (kind) {
    case PreviewViewKind::Top:
        return {0, 1};
    case PreviewViewKind::Front:
        return {0, 2};
    case PreviewViewKind::Side:
        return {1, 2};
    case PreviewViewKind::Isometric:
        return {0, 1, 2};
    }
    return {};
}

bool PreviewProjection::available(PreviewViewKind kind, const QStringList& axes)
{
    for (int axis : axesOf(kind))
        if (!axes.contains(QLatin1String(kAxisNames[axis])))
            return false;
    return true;
}

QString PreviewProjection::unavailableReason(PreviewViewKind kind, const QStringList& axes)
{
    QStringList needed, missing;
    for (int axis : axesOf(kind)) {
        needed << QLatin1String(kAxisNames[axis]);
        if (!axes.contains(QLatin1String(kAxisNames[axis])))
            missing << QLatin1String(kAxisNames[axis]);
    }
    if (missing.isEmpty())
        return {};
    return tr("This view needs the axes %1; the machine lacks %2.")
        .arg(needed.join(QStringLiteral(", ")), missing.join(QStringLiteral(", ")));
}

QString PreviewProjection::title(PreviewViewKind kind)
{
    switch (kind) {
    case PreviewViewKind::Top:
        return tr("Top (X/Y)");
    case PreviewViewKind::Front:
        return tr("Front (X/Z)");
    case PreviewViewKind::Side:
        return tr("Side (Y/Z)");
    case PreviewViewKind::Isometric:
        return tr("Isometric");
    }
    return {};
}

QString PreviewProjection::settingsName(PreviewViewKind kind)
{
    switch (kind) {
    case PreviewViewKind::Top:
        return QStringLiteral("top");
    case PreviewViewKind::Front:
        return QStringLiteral("front");
    case PreviewViewKind::Side:
        return QStringLiteral("side");
    case PreviewViewKind::Isometric:
        return QStringLiteral("isometric");
    }
    return {};
}

PreviewViewKind PreviewProjection::fromSettingsName(const QString& name, PreviewViewKind fallback)
{
    for (PreviewViewKind kind : kAll)
        if (settingsName(kind) == name)
            return kind;
    return fallback;
}

QPointF PreviewProjection::project(PreviewViewKind kind, const PreviewPosition& p)
{
    switch (kind) {
    case PreviewViewKind::Top:
        return {p[0], p[1]};
    case PreviewViewKind::Front:
        return {p[0], p[2]};
    case PreviewViewKind::Side:
        return {p[1], p[2]};
    case PreviewViewKind::Isometric:
        return {(p[0] - p[1]) * kCos30, (p[0] + p[1]) * kSin30 + p[2]};
    }
    return {};
}

PreviewOrientation::PreviewOrientation(double azimuth, double elevation)
    : m_azimuth(wrapAzimuth(azimuth)),
      m_elevation(std::isfinite(elevation) ? qBound(-90.0, elevation, 90.0) : 0.0)
{
    // The work turned by the azimuth about Z, then tilted towards the viewer by the elevation:
    // right = (cos a, -sin a, 0), up = sin e * (sin a, cos a, 0) + cos e * (0, 0, 1).
    double sa, ca, se, ce;
    sinCos(m_azimuth, sa, ca);
    sinCos(m_elevation, se, ce);
    m_xRight = ca;
    m_yRight = -sa;
    m_xUp = se * sa;
    m_yUp = se * ca;
    m_zUp = ce;
}

double PreviewOrientation::isometricElevation()
{
    // tan(elevation) = 1 / sqrt(2): the X, Y and Z axes equally foreshortened.
    static const double elevation = qRadiansToDegrees(std::atan(1.0 / std::sqrt(2.0)));
    return elevation;
}

PreviewOrientation PreviewOrientation::of(PreviewViewKind kind)
{
    switch (kind) {
    case PreviewViewKind::Top:
        return {0, 90};
    case PreviewViewKind::Front:
        return {0, 0};
    case PreviewViewKind::Side:
        return {-90, 0};
    case PreviewViewKind::Isometric:
        return {45, isometricElevation()};
    }
    return {};
}

PreviewOrientation PreviewOrientation::turned(double azimuth, double elevation) const
{
    return {m_azimuth + azimuth, m_elevation + elevation};
}

std::optional<PreviewViewKind> PreviewOrientation::preset() const
{
    for (PreviewViewKind kind : PreviewProjection::kAll)
        if (of(kind) == *this)
            return kind;
    return std::nullopt;
}

} // namespace stepdeck::ui
