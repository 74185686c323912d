#pragma once
#include <QCoreApplication>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <array>

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

    // The point on the view's plane: right and up (the widget flips up to its own down).
    static QPointF project(PreviewViewKind kind, const PreviewPosition& p);
};

} // namespace stepdeck::ui
