#pragma once
#include "PreviewScene.h"
#include "PreviewStyle.h"
#include "PreviewViewport.h"
#include <QPixmap>
#include <QWidget>
#include <optional>

class QComboBox;
class QToolButton;

namespace stepdeck::ui {

// The path of a checked program (issues 20, 29) in work coordinates, to scale: from the top
// (X/Y), the front (X/Z), the side (Y/Z) or isometric, as far as the machine has those axes
// (PreviewProjection; the choice is remembered). Feeds solid, rapids (G0) dashed in another
// colour, the soft limits' box (machine limits converted to work coordinates) dash-dotted, the
// start, a legend and a scale bar; while a program runs the tool where the machine stands and
// the running line's segments highlighted. Fitted to the path when a preview arrives (until
// the operator zooms, pans or turns) and by "Fit" (F, Home, a double click) in the orientation
// it has; the wheel zooms about the pointer.
// Turning (issue 47 item 14), where the machine has X, Y and Z: a drag with the left button
// turns the path about its middle (PreviewOrientation: kDegreesPerDragPixel of azimuth per
// pixel across, of elevation per pixel down, the elevation within +-90), a drag with the
// middle button or Shift+left pans (on a machine without X, Y and Z the left button pans too);
// Ctrl+arrow keys turn by kKeyTurnDegrees, + - and the arrow keys zoom and pan. The standard
// views are presets of the orientation: choosing one in the selector turns the path back to it
// and fits; a turned view shows "Orbit" in the selector (an entry that is not chosen, only
// shown: the angles are not remembered) until a standard view is chosen.
// The projected path is built once per preview, view and step of a turn (PreviewScene, into
// the same memory); zoom and pan draw it through a transform, and a moving marker does not draw
// the path again (a cached picture).
// The legend has a room of its own beside or below the drawing (issue 47 item 13: it covered
// the path): a column at the right or a strip along the bottom, whichever lets the fit draw the
// path larger, placed when the view fits the path or changes size (never during a turn), with
// room for every entry it can show (a run adds two: nothing moves when a run starts). The path
// is drawn only in the rest (drawingRect()), however it is zoomed, panned or turned.
class ProgramPathView : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramPathView(QWidget* parent = nullptr);

    void setPreview(const program::ProgramPreview& preview,
                    const machine::MachineDescription& machine);
    void clearPath(const QString& reason); // nothing to draw, and why
    // Where the axes stand now, work coordinates (empty: unknown or not running).
    void setCurrent(const QMap<QString, double>& position);
    // The block that runs now (0: none): its segments are highlighted.
    void setRunningLine(int line);

    // The standard view last chosen (or the first the machine has); turned, the orientation
    // differs from its preset.
    PreviewViewKind viewKind() const { return m_kind; }
    PreviewOrientation orientation() const { return m_orientation; }
    bool isTurned() const { return m_orientation != PreviewOrientation::of(m_kind); }
    bool canTurn() const { return isAvailable(PreviewViewKind::Isometric); } // X, Y and Z
    // Turns the path further about its middle, which stays where it is on the screen.
    void turnBy(double azimuth, double elevation);
    // Chosen by the operator (remembered in QSettings kSettingsKey); an unavailable view is
    // refused (false).
    bool chooseView(PreviewViewKind kind);
    bool isAvailable(PreviewViewKind kind) const;
    void fitToView();

    // The drawn path's points in the view's plane (top view: X/Y), in path order.
    const QList<QPointF>& points() const { return m_projected.points; }
    std::optional<QPointF> current() const { return m_current; } // in the plane
    int runningLine() const { return m_runningLine; }
    QString emptyText() const;
    QPointF toWidget(const QPointF& plane) const { return viewport().map(plane); }
    QPointF toPlane(const QPointF& widget) const { return viewport().unmap(widget); }
    const PreviewScene::Projected& projected() const { return m_projected; }
    QString scaleText() const; // the scale bar's length and unit ("10 mm")
    QStringList legendEntries() const;
    // The legend's room; empty when the view is too small for one (the path keeps the room).
    QRect legendRect() const;
    // Where the path is drawn: the view less the legend's room.
    QRect drawingRect() const;
    bool legendBeside() const; // a column at the right (else a strip along the bottom)
    QComboBox* viewSelector() const { return m_viewSelector; }
    QToolButton* fitButton() const { return m_fit; }
    // How often the path itself was drawn (tests: a moving marker does not redraw it).
    int pathRenders() const { return m_pathRenders; }

    static constexpr const char* kSettingsKey = "program/previewView";
    static constexpr double kDegreesPerDragPixel = 0.5;
    static constexpr double kKeyTurnDegrees = 15;
    static constexpr int kOrbitItem = -1; // the selector's data of the "Orbit" entry

    QSize sizeHint() const override { return {320, 240}; }
    QSize minimumSizeHint() const override { return {120, 60}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    // The viewport, fitted again first when the size changed since the last fit and the
    // operator has not zoomed or panned (a hidden widget gets its resize events late).
    const PreviewViewport& viewport() const;
    void setViewKind(PreviewViewKind kind);
    // The axes a drawn point needs: the view's, all three when turned.
    PreviewViewKind axesKind() const { return isTurned() ? PreviewViewKind::Isometric : m_kind; }
    void reproject();
    void updateSelector();
    void zoomBy(const QPointF& at, double factor);
    void panBy(const QPointF& delta);
    QRectF fitArea() const;                       // in drawingRect()
    QRectF fitAreaIn(const QRect& drawing) const; // the drawing less margins and controls
    QRectF fitBounds() const;                     // what Fit shows, in the plane
    // The legend's room and the drawing's for this size and what Fit shows.
    void placeLegend() const;
    void placeLegendIfResized() const;
    // Every text the legend can show, in its order.
    static QStringList legendTexts();
    // ProgramPathViewPaint.cpp
    void renderPath(QPainter& painter) const;
    void paintOverlay(QPainter& painter) const;
    void paintLegend(QPainter& painter) const;
    QList<PreviewStyle::LegendEntry> legendItems() const;

    PreviewScene m_scene;
    PreviewScene::Projected m_projected;
    PreviewViewKind m_kind = PreviewViewKind::Top;
    PreviewViewKind m_chosen = PreviewViewKind::Top; // the operator's choice (remembered)
    mutable PreviewViewport m_viewport;
    mutable QSize m_fittedSize; // the size the viewport was last fitted to
    mutable QSize m_placedSize; // the size the legend was last placed for
    mutable QRect m_legendRect;
    mutable QRect m_drawingRect;
    mutable bool m_legendBeside = false;
    bool m_userView = false; // zoomed or panned: a new preview keeps the view
    PreviewOrientation m_orientation;
    struct Drag
    {
        QPointF from;
        Qt::MouseButton button = Qt::LeftButton;
        bool turn = false; // else pan
    };
    std::optional<Drag> m_drag;
    QMap<QString, double> m_currentPosition;
    std::optional<QPointF> m_current;
    int m_runningLine = 0;
    QPainterPath m_runningSegments;
    // The path drawn once per preview, view, size and viewport; the marker over it.
    QPixmap m_cache;
    std::optional<PreviewViewport> m_cacheViewport;
    QRect m_cacheDrawing; // the drawing's room the cache was clipped to
    bool m_cacheValid = false;
    int m_pathRenders = 0;
    QString m_empty;
    QComboBox* m_viewSelector;
    QToolButton* m_fit;
};

} // namespace stepdeck::ui
