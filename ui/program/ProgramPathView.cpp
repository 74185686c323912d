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
    update();
}

void ProgramPathView::clearPath(const QString& reason)
{
    m_points.clear();
    m_limits.reset();
    m_empty = reason;
    update();
}

void ProgramPathView::setCurrent(const std::optional<QPointF>& position)
{
    if (position == m_current)
        return;
    m_current = position;
    update();
}

QRectF ProgramPathView::bounds() const
{
    QRectF r;
    bool any = false;
    auto add = [&](const QPointF& p) {
        if (!any)
            r = QRectF(p, QSizeF(0, 0));
        else
            r = r.united(QRectF(p, QSizeF(0, 0)));
        any = true;
    };
    for (const QPointF& p : m_points)
        add(p);
    if (m_limits) {
        add(m_limits->topLeft());
        add(m_limits->bottomRight());
    }
    if (m_current)
        add(*m_current);
    // A path along one line (or a single point) still gets an area to be drawn in.
    const double span = qMax(qMax(r.width(), r.height()), 1.0);
    if (r.width() < span * 0.05)
        r.adjust(-span * 0.05, 0, span * 0.05, 0);
    if (r.height() < span * 0.05)
        r.adjust(0, -span * 0.05, 0, span * 0.05);
    return r;
}

QPointF ProgramPathView::toWidget(const QPointF& position) const
{
    const QRectF b = bounds();
    const QRectF area = QRectF(rect()).adjusted(kMargin, kMargin, -kMargin, -kMargin);
    // One scale for both axes: a square is drawn square.
    const double scale = qMin(area.width() / b.width(), area.height() / b.height());
    const double x0 = area.center().x() - b.center().x() * scale;
    const double y0 = area.center().y() + b.center().y() * scale; // Y up
    return {x0 + position.x() * scale, y0 - position.y() * scale};
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
    if (m_limits) {
        QPen dashed(QColor(200, 120, 0), 1, Qt::DashLine);
        painter.setPen(dashed);
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(
            QRectF(toWidget(m_limits->topLeft()), toWidget(m_limits->bottomRight())).normalized());
    }
    if (!m_points.isEmpty()) {
        QPainterPath path(toWidget(m_points.first()));
        for (qsizetype i = 1; i < m_points.size(); ++i)
            path.lineTo(toWidget(m_points.at(i)));
        painter.setPen(QPen(QColor(30, 90, 200), 1.5));
        painter.drawPath(path);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(30, 150, 60));
        painter.drawEllipse(toWidget(m_points.first()), 4, 4);
    }
    if (m_current) {
        const QPointF c = toWidget(*m_current);
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

} // namespace stepdeck::ui
