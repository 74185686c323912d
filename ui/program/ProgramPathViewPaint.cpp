// ProgramPathView's drawing: the cached path, then what changes while a program runs.
#include "PreviewStyle.h"
#include "ProgramPathView.h"
#include <QPainter>

namespace stepdeck::ui {

using namespace PreviewStyle;

namespace {
constexpr int kMargin = 12;
constexpr int kLegendMinHeight = 140; // smaller drawings keep the room for the path
} // namespace

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
        painter.setBrush(startColor());
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
        PreviewStyle::paintLegend(painter, legendItems(), rect(), palette(), font());
    PreviewStyle::paintScaleBar(painter, rect(), m_viewport.scale(), scaleText(), palette(),
                                font());
}

QList<PreviewStyle::LegendEntry> ProgramPathView::legendItems() const
{
    QList<PreviewStyle::LegendEntry> items;
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
        entries << item.text;
    return entries;
}

QString ProgramPathView::scaleText() const
{
    return QStringLiteral("%1 %2")
        .arg(QLocale().toString(PreviewStyle::scaleBarLength(viewport().scale()), 'g', 6),
             m_scene.unitOf(axesKind()))
        .trimmed();
}

} // namespace stepdeck::ui
