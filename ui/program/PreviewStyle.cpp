#include "PreviewStyle.h"
#include <QFontMetrics>
#include <QPainter>
#include <QPalette>
#include <cmath>

namespace stepdeck::ui::PreviewStyle {

namespace {
constexpr double kScaleBarPixels = 80;
constexpr int kScaleBarRoom = 110; // the legend's texts end left of it

QPen cosmeticPen(const QColor& color, double width, Qt::PenStyle style = Qt::SolidLine)
{
    QPen pen(color, width, style);
    pen.setCosmetic(true);
    return pen;
}
} // namespace

QColor feedColor()
{
    return QColor(30, 90, 200);
}
QColor rapidColor()
{
    return QColor(0, 170, 120);
}
QColor limitsColor()
{
    return QColor(200, 120, 0);
}
QColor runningColor()
{
    return QColor(230, 40, 140);
}
QColor startColor()
{
    return QColor(30, 150, 60);
}
QPen feedPen()
{
    return cosmeticPen(feedColor(), 1);
}
QPen rapidPen()
{
    return cosmeticPen(rapidColor(), 1, Qt::DashLine);
}
QPen limitsPen()
{
    return cosmeticPen(limitsColor(), 1, Qt::DashDotLine);
}
QPen runningPen()
{
    // Wider than 1 px (the general stroker) is affordable: one block's segments.
    return cosmeticPen(runningColor(), 3.5);
}
QPen markerPen()
{
    return QPen(QColor(220, 0, 0), 2);
}

void paintLegend(QPainter& painter, const QList<LegendEntry>& entries, const QRect& area,
                 const QPalette& palette, const QFont& font)
{
    if (entries.isEmpty())
        return;
    const QFontMetrics metrics(font);
    const int rowHeight = metrics.height();
    constexpr int kSample = 22; // the pen's sample line
    const int sampleLeft = area.left() + 6;
    const int textLeft = sampleLeft + kSample + 4;
    const int textRoom = qMax(40, area.right() - textLeft - kScaleBarRoom);
    int textWidth = 0;
    for (const LegendEntry& entry : entries)
        textWidth = qMax(textWidth, qMin(textRoom, metrics.horizontalAdvance(entry.text)));
    int y = area.bottom() - 6 - rowHeight * int(entries.size());
    painter.save();
    // Over the path, readable: the path shows through a little.
    QColor background = palette.color(QPalette::Base);
    background.setAlpha(210);
    painter.fillRect(QRect(area.left() + 3, y - 2, textLeft - area.left() + textWidth + 1,
                           rowHeight * int(entries.size()) + 4),
                     background);
    for (const LegendEntry& entry : entries) {
        const double mid = y + rowHeight / 2.0;
        painter.setPen(entry.pen);
        painter.drawLine(QPointF(sampleLeft, mid), QPointF(sampleLeft + kSample, mid));
        painter.setPen(palette.color(QPalette::Text));
        painter.drawText(QRect(textLeft, y, textRoom, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                         metrics.elidedText(entry.text, Qt::ElideRight, textRoom));
        y += rowHeight;
    }
    painter.restore();
}

double scaleBarLength(double pixelsPerUnit)
{
    const double raw = kScaleBarPixels / pixelsPerUnit;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double step : {5.0, 2.0, 1.0})
        if (step * decade <= raw)
            return step * decade;
    return decade;
}

void paintScaleBar(QPainter& painter, const QRect& area, double pixelsPerUnit, const QString& label,
                   const QPalette& palette, const QFont& font)
{
    const double pixels = scaleBarLength(pixelsPerUnit) * pixelsPerUnit;
    const QPointF right(area.right() - 7, area.bottom() - 7);
    const QPointF left = right - QPointF(pixels, 0);
    painter.save();
    painter.setPen(QPen(palette.color(QPalette::Text), 1));
    painter.drawLine(left, right);
    painter.drawLine(left, left - QPointF(0, 4));
    painter.drawLine(right, right - QPointF(0, 4));
    const QFontMetrics metrics(font);
    painter.drawText(
        QRectF(left.x() - 40, left.y() - 4 - metrics.height(), pixels + 40, metrics.height()),
        Qt::AlignRight | Qt::AlignBottom, label);
    painter.restore();
}

} // namespace stepdeck::ui::PreviewStyle
