#include "PreviewViewport.h"
#include <QtGlobal>

namespace stepdeck::ui {

QPointF PreviewViewport::map(const QPointF& plane) const
{
    return {m_offset.x() + plane.x() * m_scale, m_offset.y() - plane.y() * m_scale};
}

QPointF PreviewViewport::unmap(const QPointF& widget) const
{
    return {(widget.x() - m_offset.x()) / m_scale, (m_offset.y() - widget.y()) / m_scale};
}

QTransform PreviewViewport::transform() const
{
    return QTransform(m_scale, 0, 0, -m_scale, m_offset.x(), m_offset.y());
}

void PreviewViewport::fit(const QRectF& bounds, const QRectF& area)
{
    QRectF b = bounds.normalized();
    // A path along one line (or a single point) still gets an area to be drawn in.
    const double span = qMax(qMax(b.width(), b.height()), 1.0);
    if (b.width() < span * 0.05)
        b.adjust(-span * 0.05, 0, span * 0.05, 0);
    if (b.height() < span * 0.05)
        b.adjust(0, -span * 0.05, 0, span * 0.05);
    const double scale = qMin(area.width() / b.width(), area.height() / b.height());
    m_scale = qBound(kMinScale, scale, kMaxScale);
    m_offset = QPointF(area.center().x() - b.center().x() * m_scale,
                       area.center().y() + b.center().y() * m_scale);
}

void PreviewViewport::zoomAt(const QPointF& widget, double factor)
{
    const QPointF under = unmap(widget);
    m_scale = qBound(kMinScale, m_scale * factor, kMaxScale);
    m_offset = QPointF(widget.x() - under.x() * m_scale, widget.y() + under.y() * m_scale);
}

void PreviewViewport::panBy(const QPointF& widgetDelta)
{
    m_offset += widgetDelta;
}

void PreviewViewport::placeAt(const QPointF& plane, const QPointF& widget)
{
    m_offset += widget - map(plane);
}

} // namespace stepdeck::ui
