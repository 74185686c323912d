// ProgramPathView's drawing: the cached path, then what changes while a program runs.
#include "ProgramPathView.h"
#include <QPainter>
#include <cmath>

namespace stepdeck::ui {

namespace {
constexpr int kMargin = 12;
constexpr double kScaleBarPixels = 80; // about this long, at a round length
constexpr int kLegendMinHeight = 140;  // smaller drawings keep the room for the path

QPen cosmeticPen(const QColor& color, double width, Qt::PenStyle style = Qt::SolidLine)
{
    // Cosmetic: the width and dashes stay in pixels whatever the zoom (the path is drawn
    // through the viewport's transform).
    QPen pen(color, width, style);
    pen.setCosmetic(true);
    return pen;
}

QPen feedPen()
{
    // One pixel: Qt's raster engine draws cosmetic pens up to 1 px wide with its fast stroker
    // (QCosmeticStroker); 1.5 px went through the general stroker, about 7 us a segment.
    return cosmeticPen(ProgramPathView::feedColor(), 1);
}
QPen rapidPen()
{
    return cosmeticPen(ProgramPathView::rapidColor(), 1, Qt::DashLine);
}
QPen limitsPen()
{
    return cosmeticPen(ProgramPathView::limitsColor(), 1, Qt::DashDotLine);
}
QPen markerPen()
{
    return QPen(QColor(220, 0, 0), 2);
}
QPen runningPen()
{
    return cosmeticPen(QColor(230, 40, 140), 3.5);
}
} // namespace

QColor ProgramPathView::feedColor()
{
    return QColor(30, 90, 200);
}
QColor ProgramPathView::rapidColor()
{
    return QColor(0, 170, 120);
}
QColor ProgramPathView::limitsColor()
{
    return QColor(200, 120, 0);
}

void ProgramPathView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().color(QPalette::Base));
    painter.setPen(palette().color(QPalette::Mid));
    painter.drawRect(rect().adjusted(0, 0, -1, -1));
    if (m_projected.points.isEmpty() && m_projected.softLimits.isEmpty()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect().adjusted(kMargin, kMargin + 24, -kMargin, -kMargin),
                         Qt::AlignCenter | Qt::TextWordWrap, emptyText());
        return;
    }
    viewport(); // fitted to this size first, unless the operator zoomed or panned
    const QSize pixels = size() * devicePixelRatio();
    if (!m_cacheValid || m_cacheViewport != m_viewport || m_cache.size() != pixels) {
        m_cache = QPixmap(pixels);
        m_cache.setDevicePixelRatio(devicePixelRatio());
        m_cache.fill(Qt::transparent);
        QPainter cached(&m_cache);
        cached.setRenderHint(QPainter::Antialiasing);
        renderPath(cached);
        m_cacheViewport = m_viewport;
        m_cacheValid = true;
        ++m_pathRenders;
    }
    painter.drawPixmap(0, 0, m_cache);
    paintOverlay(painter);
}

void ProgramPathView::renderPath(QPainter& painter) const
{
    painter.save();
    painter.setTransform(m_viewport.transform());
    painter.setBrush(Qt::NoBrush);
    if (!m_projected.softLimits.isEmpty()) {
        painter.setPen(limitsPen());
        painter.drawPath(m_projected.softLimits);
    }
    painter.setPen(rapidPen());
    painter.drawPath(m_projected.rapids);
    painter.setPen(feedPen());
    painter.drawPath(m_projected.feeds);
    painter.restore();
    if (m_projected.start) {
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(30, 150, 60));
        painter.drawEllipse(m_viewport.map(*m_projected.start), 4, 4);
    }
}

// What changes while a program runs (the running line, the tool), the legend and the scale:
// drawn over the cached path on every repaint.
void ProgramPathView::paintOverlay(QPainter& painter) const
{
    if (!m_runningSegments.isEmpty()) {
        painter.save();
        painter.setTransform(m_viewport.transform());
        painter.setPen(runningPen());
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(m_runningSegments);
        painter.restore();
    }
    if (m_current) {
        const QPointF c = m_viewport.map(*m_current);
        painter.setPen(markerPen());
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(c, 6, 6);
        painter.drawLine(c - QPointF(9, 0), c + QPointF(9, 0));
        painter.drawLine(c - QPointF(0, 9), c + QPointF(0, 9));
    }
    if (height() >= kLegendMinHeight)
        paintLegend(painter);
    paintScaleBar(painter);
}

QList<QPair<QString, QPen>> ProgramPathView::legendItems() const
{
    QList<QPair<QString, QPen>> items;
    if (!m_projected.feeds.isEmpty())
        items.append({tr("Feed (G1, arcs)"), feedPen()});
    if (!m_projected.rapids.isEmpty())
        items.append({tr("Rapid (G0)"), rapidPen()});
    if (!m_projected.softLimits.isEmpty())
        items.append({tr("Soft limits (machine travel, in work coordinates)"), limitsPen()});
    if (!m_runningSegments.isEmpty())
        items.append({tr("Running line"), runningPen()});
    if (m_current)
        items.append({tr("Tool"), markerPen()});
    return items;
}

QStringList ProgramPathView::legendEntries() const
{
    QStringList entries;
    for (const auto& item : legendItems())
        entries << item.first;
    return entries;
}

void ProgramPathView::paintLegend(QPainter& painter) const
{
    const QList<QPair<QString, QPen>> items = legendItems();
    if (items.isEmpty())
        return;
    const QFontMetrics metrics(font());
    const int rowHeight = metrics.height();
    constexpr int kSample = 22; // the pen's sample line
    constexpr int kTextLeft = 10 + kSample;
    // Left of the scale bar; a long text is elided, not drawn over the bar.
    const int textRoom = qMax(40, width() - kTextLeft - 110);
    int textWidth = 0;
    for (const auto& item : items)
        textWidth = qMax(textWidth, qMin(textRoom, metrics.horizontalAdvance(item.first)));
    int y = height() - 6 - rowHeight * int(items.size());
    painter.save();
    // Over the path, readable: the background shows through a little.
    QColor background = palette().color(QPalette::Base);
    background.setAlpha(210);
    painter.fillRect(QRect(3, y - 2, kTextLeft + textWidth + 4, rowHeight * int(items.size()) + 4),
                     background);
    for (const auto& [text, pen] : items) {
        const double mid = y + rowHeight / 2.0;
        painter.setPen(pen);
        painter.drawLine(QPointF(6, mid), QPointF(6 + kSample, mid));
        painter.setPen(palette().color(QPalette::Text));
        painter.drawText(QRect(kTextLeft, y, textRoom, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                         metrics.elidedText(text, Qt::ElideRight, textRoom));
        y += rowHeight;
    }
    painter.restore();
}

double ProgramPathView::scaleBarLength() const
{
    // A round length (1, 2 or 5 times a power of ten) about kScaleBarPixels long.
    const double raw = kScaleBarPixels / m_viewport.scale();
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double step : {5.0, 2.0, 1.0})
        if (step * decade <= raw)
            return step * decade;
    return decade;
}

QString ProgramPathView::scaleText() const
{
    return QStringLiteral("%1 %2")
        .arg(QLocale().toString(scaleBarLength(), 'g', 6), m_scene.unitOf(m_kind))
        .trimmed();
}

void ProgramPathView::paintScaleBar(QPainter& painter) const
{
    const double pixels = scaleBarLength() * m_viewport.scale();
    const QPointF right(width() - 8, height() - 8);
    const QPointF left = right - QPointF(pixels, 0);
    painter.setPen(QPen(palette().color(QPalette::Text), 1));
    painter.drawLine(left, right);
    painter.drawLine(left, left - QPointF(0, 4));
    painter.drawLine(right, right - QPointF(0, 4));
    const QFontMetrics metrics(font());
    painter.drawText(
        QRectF(left.x() - 40, left.y() - 4 - metrics.height(), pixels + 40, metrics.height()),
        Qt::AlignRight | Qt::AlignBottom, scaleText());
}

} // namespace stepdeck::ui
