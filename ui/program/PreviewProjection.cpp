#include "PreviewProjection.h"
#include <cmath>

namespace stepdeck::ui {

namespace {
const char* const kAxisNames[3] = {"X", "Y", "Z"};
// Isometric: the X and Y axes 30 degrees below the horizontal, Z vertical, all three at the
// same scale (cos 30 = sqrt(3)/2, sin 30 = 1/2).
const double kCos30 = std::sqrt(3.0) / 2.0;
constexpr double kSin30 = 0.5;
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

} // namespace stepdeck::ui
