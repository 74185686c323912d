#pragma once
#include <QList>
#include <QPen>
#include <QString>

class QPainter;
class QPalette;
class QFont;

namespace stepdeck::ui::PreviewStyle {

// How the path view draws each kind of line (issue 29), and its legend and scale bar. The path
// pens are cosmetic (their width and dashes in pixels whatever the zoom, the path being drawn
// through the viewport's transform) and at most 1 px wide: Qt's raster engine strokes those
// with its fast QCosmeticStroker; a 1.5 px pen went through the general stroker, about 7 us a
// segment (docs/benchmark.md, --preview-frame).
QColor feedColor();
QColor rapidColor();
QColor limitsColor();
QColor runningColor();
QPen feedPen();    // solid
QPen rapidPen();   // dashed
QPen limitsPen();  // dash-dotted
QPen runningPen(); // wide, over the path
QPen markerPen();  // the tool
QColor startColor();

struct LegendEntry
{
    QString text;
    QPen pen;
};
// The entries in the lower left of area, a sample line and the text each, on a backdrop; texts
// are elided to leave the lower right to the scale bar.
void paintLegend(QPainter& painter, const QList<LegendEntry>& entries, const QRect& area,
                 const QPalette& palette, const QFont& font);
// A round length (1, 2 or 5 times a power of ten) in the plane's units about 80 pixels long.
double scaleBarLength(double pixelsPerUnit);
// The bar of that length in the lower right of area, with label above it.
void paintScaleBar(QPainter& painter, const QRect& area, double pixelsPerUnit, const QString& label,
                   const QPalette& palette, const QFont& font);

} // namespace stepdeck::ui::PreviewStyle
