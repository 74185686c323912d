#pragma once
#include "program/ProgramCheck.h"
#include <QPixmap>
#include <QWidget>
#include <optional>

namespace stepdeck::ui {

// The XY path of a checked program (issue 20), drawn to scale with Y up: the soft limits of X
// and Y as a dashed rectangle, the path through the block end points, the start point, and
// the machine's current position while a program runs. The axes move each at its own rate
// (ProgramPreview::motionNote), so the straight lines are where each block ends, not the
// exact way between.
class ProgramPathView : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramPathView(QWidget* parent = nullptr);

    // points: X/Y of the path (axes the path does not know yet are left out); limits: the
    // rectangle of X's and Y's soft limits, if both have them.
    void setPath(const QList<QPointF>& points, const std::optional<QRectF>& limits,
                 const QString& unit);
    void clearPath(const QString& reason); // nothing to draw, and why
    // Where X and Y stand now (nullopt: unknown or not running).
    void setCurrent(const std::optional<QPointF>& position);

    const QList<QPointF>& points() const { return m_points; }
    std::optional<QPointF> current() const { return m_current; }
    QString emptyText() const { return m_empty; }
    // Where a machine position is drawn in the widget (for tests of the marker).
    QPointF toWidget(const QPointF& position) const;
    // How often the path itself was drawn (tests: a moving marker does not redraw it).
    int pathRenders() const { return m_pathRenders; }

    QSize sizeHint() const override { return {320, 240}; }
    QSize minimumSizeHint() const override { return {120, 60}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QRectF bounds() const; // machine coordinates shown
    struct Scale
    {
        double scale = 1, x0 = 0, y0 = 0;
        QPointF map(const QPointF& p) const { return {x0 + p.x() * scale, y0 - p.y() * scale}; }
        bool operator==(const Scale& o) const
        {
            return scale == o.scale && x0 == o.x0 && y0 == o.y0;
        }
    };
    Scale currentScale() const;
    void updatePathBounds();
    void paintPath(QPainter& painter, const Scale& scale) const;

    QList<QPointF> m_points;
    // The path and the soft limits' rectangle, worked out once per path (issue 28: a 20 000-point
    // path was measured again for every point of every repaint, 2.5 s per block at 100 % CPU).
    std::optional<QRectF> m_pathBounds;
    // The path drawn once at this size and scale; only the marker is drawn on every repaint.
    QPixmap m_cache;
    std::optional<Scale> m_cacheScale;
    int m_pathRenders = 0;
    std::optional<QRectF> m_limits;
    std::optional<QPointF> m_current;
    QString m_unit;
    QString m_empty;
};

} // namespace stepdeck::ui
