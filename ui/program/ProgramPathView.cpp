#include "ProgramPathView.h"
#include <QPainter>
#include <QPainterPath>

namespace stepdeck::ui {

namespace {
constexpr int kMargin = 12;
} // namespace

ProgramPathView::ProgramPathView(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("programPathView"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void ProgramPathView::setPath(const QList<QPointF>& points, const std::optional<QRectF>& limits,
                              const QString& unit)
{
    m_points = points;
    m_limits = limits;
    m_unit = unit;
    m_empty.clear();
    updatePathBounds();
    update();
}

void ProgramPathView::clearPath(const QString& reason)
{
    m_points.clear();
    m_limits.reset();
    m_empty = reason;
    updatePathBounds();
    update();
}

void ProgramPathView::setCurrent(const std::optional<QPointF>& position)
{
    if (position == m_current)
        return;
    m_current = position;
    update();
}

namespace {
// The smallest rectangle holding both (QRectF::united ignores a rectangle of no size, which a
// single point is).
QRectF spanned(const std::optional<QRectF>& r, const QPointF& p)
{
    if (!r)
        return QRectF(p, QSizeF(0, 0));
    return QRectF(QPointF(qMin(r->left(), p.x()), qMin(r->top(), p.y())),
                  QPointF(qMax(r->right(), p.x()), qMax(r->bottom(), p.y())));
}
} // namespace

void ProgramPathView::updatePathBounds()
{
    m_pathBounds.reset();
    m_cacheScale.reset();
    for (const QPointF& p : std::as_const(m_points))
        m_pathBounds = spanned(m_pathBounds, p);
    if (m_limits) {
        m_pathBounds = spanned(m_pathBounds, m_limits->topLeft());
        m_pathBounds = spanned(m_pathBounds, m_limits->bottomRight());
    }
}

QRectF ProgramPathView::bounds() const
{
    QRectF r = m_current ? spanned(m_pathBounds, *m_current) : m_pathBounds.value_or(QRectF());
    // A path along one line (or a single point) still gets an area to be drawn in.
    const double span = qMax(qMax(r.width(), r.height()), 1.0);
    if (r.width() < span * 0.05)
        r.adjust(-span * 0.05, 0, span * 0.05, 0);
    if (r.height() < span * 0.05)
        r.adjust(0, -span * 0.05, 0, span * 0.05);
    return r;
}

ProgramPathView::Scale ProgramPathView::currentScale() const
{
    const QRectF b = bounds();
    const QRectF area = QRectF(rect()).adjusted(kMargin, kMargin, -kMargin, -kMargin);
    // One scale for both axes: a square is drawn square.
    Scale s;
    s.scale = qMin(area.width() / b.width(), area.height() / b.height());
    s.x0 = area.center().x() - b.center().x() * s.scale;
    s.y0 = area.center().y() + b.center().y() * s.scale; // Y up
    return s;
}

QPointF ProgramPathView::toWidget(const QPointF& position) const
{
    return currentScale().map(position);
}

void ProgramPathView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().color(QPalette::Base));
    painter.setPen(palette().color(QPalette::Mid));
    painter.drawRect(rect().adjusted(0, 0, -1, -1));
    if (m_points.isEmpty() && !m_current) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect().adjusted(kMargin, kMargin, -kMargin, -kMargin),
                         Qt::AlignCenter | Qt::TextWordWrap, m_empty);
        return;
    }
    const Scale scale = currentScale();
    if (!m_cacheScale || !(*m_cacheScale == scale) ||
        m_cache.size() != size() * devicePixelRatio()) {
        m_cache = QPixmap(size() * devicePixelRatio());
        m_cache.setDevicePixelRatio(devicePixelRatio());
        m_cache.fill(Qt::transparent);
        QPainter cached(&m_cache);
        cached.setRenderHint(QPainter::Antialiasing);
        paintPath(cached, scale);
        m_cacheScale = scale;
        ++m_pathRenders;
    }
    painter.drawPixmap(0, 0, m_cache);
    if (m_current) {
        const QPointF c = scale.map(*m_current);
        painter.setPen(QPen(QColor(220, 0, 0), 2));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(c, 6, 6);
        painter.drawLine(c - QPointF(9, 0), c + QPointF(9, 0));
        painter.drawLine(c - QPointF(0, 9), c + QPointF(0, 9));
    }
    painter.setPen(palette().color(QPalette::Text));
    painter.drawText(rect().adjusted(4, 2, -4, -2), Qt::AlignLeft | Qt::AlignTop,
                     tr("X / Y (%1)").arg(m_unit));
}

void ProgramPathView::paintPath(QPainter& painter, const Scale& scale) const
{
    if (m_limits) {
        QPen dashed(QColor(200, 120, 0), 1, Qt::DashLine);
        painter.setPen(dashed);
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(QRectF(scale.map(m_limits->topLeft()), scale.map(m_limits->bottomRight()))
                             .normalized());
    }
    if (!m_points.isEmpty()) {
        QPainterPath path(scale.map(m_points.first()));
        for (qsizetype i = 1; i < m_points.size(); ++i)
            path.lineTo(scale.map(m_points.at(i)));
        painter.setPen(QPen(QColor(30, 90, 200), 1.5));
        painter.drawPath(path);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(30, 150, 60));
        painter.drawEllipse(scale.map(m_points.first()), 4, 4);
    }
}

} // namespace stepdeck::ui
