#pragma once
#include <QPointF>
#include <QRectF>
#include <QTransform>

namespace stepdeck::ui {

// Where the view's plane (PreviewProjection: right and up) lands in a widget: one scale for
// both directions (a square is drawn square), the plane's up drawn up. Fitting, zooming about a
// point and panning only change the scale and the offset, so the projected path is drawn
// through transform() and never built again for a zoom or a pan. Pure arithmetic.
class PreviewViewport
{
public:
    // The widget point of a plane point, and back.
    QPointF map(const QPointF& plane) const;
    QPointF unmap(const QPointF& widget) const;
    QTransform transform() const;            // plane -> widget, for QPainter::setTransform
    double scale() const { return m_scale; } // pixels per unit

    // The whole of bounds in area, centred, at the largest scale that fits. A bounds of no
    // width or height (a straight line, a point) gets a little room around it.
    void fit(const QRectF& bounds, const QRectF& area);
    // Scales by factor about a widget point: the plane point under it stays under it.
    void zoomAt(const QPointF& widget, double factor);
    void panBy(const QPointF& widgetDelta);
    // Pans so that the plane point lands on the widget point (the scale kept): a turned view
    // keeps the point it turns about where it was on the screen.
    void placeAt(const QPointF& plane, const QPointF& widget);

    bool operator==(const PreviewViewport& o) const
    {
        return m_scale == o.m_scale && m_offset == o.m_offset;
    }
    bool operator!=(const PreviewViewport& o) const { return !(*this == o); }

    // Zoom stays within these many pixels per unit: far enough to see a 0.01 mm step and to
    // see a 100 m path whole, never a scale of zero or infinity.
    static constexpr double kMinScale = 1e-4;
    static constexpr double kMaxScale = 1e5;

private:
    double m_scale = 1;
    QPointF m_offset; // the widget point of the plane's origin
};

} // namespace stepdeck::ui
