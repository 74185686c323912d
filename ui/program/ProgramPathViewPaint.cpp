// ProgramPathView's drawing: the cached path, then what changes while a program runs.
#include "PreviewStyle.h"
#include "ProgramPathView.h"
#include "ProgramPathViewLayout.h"
#include <QPainter>

namespace stepdeck::ui {

using namespace PreviewStyle;
using namespace pathviewlayout; // the legend's rows, as ProgramPathView::placeLegend reserves them

namespace {
constexpr int kScaleBarRoom = 110; // the scale bar beside the entries of a strip
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
    // The path only in the drawing's room: never under the legend.
    const QRect drawing = drawingRect();
    const QSize pixels = size() * devicePixelRatio();
    if (!m_cacheValid || m_cacheViewport != m_viewport || m_cache.size() != pixels ||
        m_cacheDrawing != drawing) {
        m_cache = QPixmap(pixels);
        m_cache.setDevicePixelRatio(devicePixelRatio());
        m_cache.fill(Qt::transparent);
        QPainter cached(&m_cache);
        cached.setRenderHint(QPainter::Antialiasing);
        cached.setClipRect(drawing);
        renderPath(cached);
        m_cacheViewport = m_viewport;
        m_cacheDrawing = drawing;
        m_cacheValid = true;
        ++m_pathRenders;
    }
    painter.drawPixmap(0, 0, m_cache);
    painter.save();
    painter.setClipRect(drawing);
    paintOverlay(painter);
    painter.restore();
    paintLegend(painter);
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

// What changes while a program runs (the running line, the tool): drawn over the cached path
// on every repaint.
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
}

// The legend in its own room beside or below the drawing (placeLegend), and the scale bar: in a
// strip beside the entries where they leave it the room, else in the drawing's lower right.
void ProgramPathView::paintLegend(QPainter& painter) const
{
    const QRect room = legendRect();
    const QRect drawing = drawingRect();
    QRect scaleArea = drawing;
    if (!room.isEmpty()) {
        painter.save();
        // The line between the drawing and the legend.
        painter.setPen(palette().color(QPalette::Mid));
        if (m_legendBeside)
            painter.drawLine(room.topLeft(), room.bottomLeft());
        else
            painter.drawLine(room.topLeft(), room.topRight());
        const QFontMetrics metrics(font());
        const int rowHeight = metrics.height();
        // The entries from the top of the rows reserved for all of them: an entry that comes
        // with a run is added below, nothing above it moves.
        const int rows = int(legendTexts().size());
        int y = room.bottom() + 1 - kLegendPadding - rows * rowHeight;
        const int sampleLeft = room.left() + kLegendPadding;
        const int textLeft = sampleLeft + kLegendSample + kLegendGap;
        int textRight = room.right() - kLegendPadding;
        const QList<PreviewStyle::LegendEntry> entries = legendItems();
        if (!m_legendBeside) {
            int widest = 0;
            for (const auto& entry : entries)
                widest = qMax(widest, metrics.horizontalAdvance(entry.text));
            // The scale bar at the strip's right end, where the texts leave it the room.
            if (textLeft + widest + kScaleBarRoom <= room.right()) {
                textRight = textLeft + widest;
                scaleArea = room.adjusted(textRight + 1 - room.left(), 0, 0, 0);
            } else {
                textRight = qMin(qMax(textLeft + 40, room.right() - kScaleBarRoom),
                                 room.right() - kLegendPadding);
                if (textRight + kScaleBarRoom <= room.right())
                    scaleArea = room.adjusted(textRight + 1 - room.left(), 0, 0, 0);
            }
        }
        const int textRoom = qMax(0, textRight - textLeft + 1);
        for (const auto& entry : entries) {
            const double mid = y + rowHeight / 2.0;
            painter.setPen(entry.pen);
            painter.drawLine(QPointF(sampleLeft, mid), QPointF(sampleLeft + kLegendSample, mid));
            painter.setPen(palette().color(QPalette::Text));
            painter.drawText(QRect(textLeft, y, textRoom, rowHeight),
                             Qt::AlignLeft | Qt::AlignVCenter,
                             metrics.elidedText(entry.text, Qt::ElideRight, textRoom));
            y += rowHeight;
        }
        painter.restore();
    }
    PreviewStyle::paintScaleBar(painter, scaleArea, m_viewport.scale(), scaleText(), palette(),
                                font());
}

QList<PreviewStyle::LegendEntry> ProgramPathView::legendItems() const
{
    // In the order of legendTexts(): feed, rapid, soft limits, running line, tool.
    const QStringList texts = legendTexts();
    QList<PreviewStyle::LegendEntry> items;
    if (!m_projected.feeds.isEmpty())
        items.append({texts.at(0), feedPen()});
    if (!m_projected.rapids.isEmpty())
        items.append({texts.at(1), rapidPen()});
    if (!m_projected.softLimits.isEmpty())
        items.append({texts.at(2), limitsPen()});
    if (!m_runningSegments.isEmpty())
        items.append({texts.at(3), runningPen()});
    if (m_current)
        items.append({texts.at(4), markerPen()});
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
