#include "ProgramPathView.h"
#include "ProgramPathViewLayout.h"
#include <QComboBox>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardItemModel>
#include <QToolButton>
#include <QWheelEvent>
#include <cmath>

namespace stepdeck::ui {

using namespace pathviewlayout;

namespace {
constexpr int kControlsHeight = 24; // the view selector and Fit over the top of the drawing
constexpr double kKeyZoom = 1.25;
constexpr double kKeyPanFraction = 0.1;
// A fit area smaller than this either way is no place for the path: the legend then goes
// elsewhere or not at all.
constexpr int kLeastDrawing = 40;
} // namespace

ProgramPathView::ProgramPathView(QWidget* parent)
    : QWidget(parent), m_viewSelector(new QComboBox(this)), m_fit(new QToolButton(this))
{
    setObjectName(QStringLiteral("programPathView"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    // Keys zoom, pan and fit once the drawing has the focus (a click or Tab gives it).
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(tr("Drag: turn (X, Y and Z) \u00b7 Shift+drag or the middle button: pan \u00b7 "
                  "wheel: zoom about the pointer \u00b7 F or a double click: fit \u00b7 + and -: "
                  "zoom \u00b7 arrow keys: pan \u00b7 Ctrl+arrow keys: turn"));
    // Over the drawing, not above it: the page must not grow taller (1366x768).
    m_viewSelector->setObjectName(QStringLiteral("programPreviewViewSelector"));
    m_viewSelector->setFocusPolicy(Qt::StrongFocus);
    for (PreviewViewKind kind : PreviewProjection::kAll)
        m_viewSelector->addItem(PreviewProjection::title(kind), int(kind));
    // Shown while the path is turned, never chosen (disabled): choosing a standard view turns
    // the path back. Chosen over keeping the last view's name, which would claim a view the
    // drawing no longer is.
    m_viewSelector->addItem(tr("Orbit"), kOrbitItem);
    m_fit->setObjectName(QStringLiteral("programPreviewFit"));
    m_fit->setText(tr("Fit"));
    m_fit->setToolTip(tr("Fit the path to the view (F)"));
    m_fit->setFocusPolicy(Qt::StrongFocus);
    m_chosen = PreviewProjection::fromSettingsName(
        QSettings().value(QLatin1String(kSettingsKey)).toString(), PreviewViewKind::Top);
    m_kind = m_chosen;
    m_orientation = PreviewOrientation::of(m_kind);
    connect(m_viewSelector, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        const int item = m_viewSelector->itemData(index).toInt();
        if (item == kOrbitItem)
            updateSelector(); // not a view to choose
        else
            chooseView(PreviewViewKind(item));
    });
    connect(m_fit, &QToolButton::clicked, this, &ProgramPathView::fitToView);
    updateSelector();
}

void ProgramPathView::setPreview(const program::ProgramPreview& preview,
                                 const machine::MachineDescription& machine)
{
    const bool turned = isTurned();
    m_scene.setPreview(preview, machine);
    m_empty.clear();
    // The operator's choice where this machine allows it, else the first view it allows.
    PreviewViewKind kind = m_chosen;
    if (!isAvailable(kind))
        for (PreviewViewKind k : PreviewProjection::kAll)
            if (isAvailable(k)) {
                kind = k;
                break;
            }
    m_kind = kind;
    // A turned view stays turned (as a zoomed one stays zoomed) where the machine allows it.
    if (!turned || !canTurn())
        m_orientation = PreviewOrientation::of(kind);
    updateSelector();
    reproject();
    if (!m_userView)
        fitToView();
}

void ProgramPathView::clearPath(const QString& reason)
{
    m_scene.clear();
    m_empty = reason;
    updateSelector();
    reproject();
}

QString ProgramPathView::emptyText() const
{
    if (!m_empty.isEmpty() || !m_projected.points.isEmpty())
        return m_empty;
    QStringList axes;
    for (int axis : PreviewProjection::axesOf(axesKind()))
        axes << QStringLiteral("XYZ").mid(axis, 1);
    return tr("The program reaches no known position of the axes %1.")
        .arg(axes.join(QStringLiteral(", ")));
}

bool ProgramPathView::isAvailable(PreviewViewKind kind) const
{
    return PreviewProjection::available(kind, m_scene.axes());
}

bool ProgramPathView::chooseView(PreviewViewKind kind)
{
    if (!isAvailable(kind)) {
        updateSelector();
        return false;
    }
    m_chosen = kind;
    QSettings().setValue(QLatin1String(kSettingsKey), PreviewProjection::settingsName(kind));
    setViewKind(kind);
    return true;
}

void ProgramPathView::setViewKind(PreviewViewKind kind)
{
    m_kind = kind;
    m_orientation = PreviewOrientation::of(kind); // a turned view turned back
    updateSelector();
    reproject();
    fitToView(); // another plane: the old zoom means nothing there
}

void ProgramPathView::updateSelector()
{
    auto* model = qobject_cast<QStandardItemModel*>(m_viewSelector->model());
    QStringList reasons;
    const bool turned = isTurned();
    for (int i = 0; i < m_viewSelector->count(); ++i) {
        if (m_viewSelector->itemData(i).toInt() == kOrbitItem) {
            if (model)
                model->item(i)->setEnabled(false);
            m_viewSelector->setItemData(
                i,
                canTurn() ? tr("Turned with the mouse: drag the drawing to turn it, choose a view "
                               "above to turn it back")
                          : tr("Turning the path needs the axes X, Y and Z."),
                Qt::ToolTipRole);
            if (turned)
                m_viewSelector->setCurrentIndex(i);
            continue;
        }
        const auto kind = PreviewViewKind(m_viewSelector->itemData(i).toInt());
        const QString reason = PreviewProjection::unavailableReason(kind, m_scene.axes());
        // Without a machine (no preview yet) every view stays choosable.
        const bool enabled = m_scene.axes().isEmpty() || reason.isEmpty();
        if (model)
            model->item(i)->setEnabled(enabled);
        m_viewSelector->setItemData(i, enabled ? QVariant() : QVariant(reason), Qt::ToolTipRole);
        if (!enabled)
            reasons << QStringLiteral("%1: %2").arg(PreviewProjection::title(kind), reason);
        if (kind == m_kind && !turned)
            m_viewSelector->setCurrentIndex(i);
    }
    m_viewSelector->setToolTip(reasons.isEmpty()
                                   ? tr("How the path is looked at")
                                   : tr("How the path is looked at. Not on this machine:\n%1")
                                         .arg(reasons.join(QLatin1Char('\n'))));
}

void ProgramPathView::reproject()
{
    // Into the same lists and paths: a turn projects again on every mouse move.
    const QList<int> axes = PreviewProjection::axesOf(axesKind());
    if (m_scene.isEmpty())
        m_projected = PreviewScene::Projected{};
    else
        m_scene.project(m_orientation, axes, m_projected);
    m_runningSegments = m_runningLine > 0 ? PreviewScene::segmentsOfLine(m_projected, m_runningLine)
                                          : QPainterPath();
    m_current = PreviewScene::projectPosition(m_orientation, axes, m_currentPosition);
    m_cacheValid = false;
    update();
}

void ProgramPathView::setCurrent(const QMap<QString, double>& position)
{
    if (position == m_currentPosition)
        return;
    m_currentPosition = position;
    m_current = PreviewScene::projectPosition(m_orientation, PreviewProjection::axesOf(axesKind()),
                                              m_currentPosition);
    update();
}

void ProgramPathView::setRunningLine(int line)
{
    if (line == m_runningLine)
        return;
    m_runningLine = line;
    m_runningSegments = line > 0 ? PreviewScene::segmentsOfLine(m_projected, line) : QPainterPath();
    update();
}

QRectF ProgramPathView::fitArea() const
{
    return fitAreaIn(drawingRect());
}

QRectF ProgramPathView::fitAreaIn(const QRect& drawing) const
{
    return QRectF(drawing).adjusted(kMargin, kMargin + kControlsHeight, -kMargin, -kMargin);
}

QStringList ProgramPathView::legendTexts()
{
    return {tr("Feed (G1, arcs)"), tr("Rapid (G0)"),
            tr("Soft limits (machine travel, in work coordinates)"), tr("Running line"),
            tr("Tool")};
}

void ProgramPathView::placeLegend() const
{
    m_placedSize = size();
    const QRect all = rect();
    m_legendRect = QRect();
    m_drawingRect = all;
    m_legendBeside = false;
    // Room for every entry the legend can show, one a row.
    const QFontMetrics metrics(font());
    const QStringList texts = legendTexts();
    int textWidth = 0;
    for (const QString& text : texts)
        textWidth = qMax(textWidth, metrics.horizontalAdvance(text));
    const int entriesHeight = int(texts.size()) * metrics.height() + 2 * kLegendPadding;
    const int entriesWidth = kLegendSample + kLegendGap + textWidth + 2 * kLegendPadding;
    // Beside: a column at the right, at most a third of the width (longer texts elided), its
    // entries below the row of the selector (the view's notes sit top right).
    const int columnWidth = qMin(entriesWidth, all.width() / 3);
    const QRect column(all.right() - columnWidth + 1, all.top(), columnWidth, all.height());
    const QRect besideColumn = all.adjusted(0, 0, -columnWidth, 0);
    const bool columnFits = kControlsHeight + entriesHeight <= all.height();
    // Below: a strip along the bottom.
    const QRect strip(all.left(), all.bottom() - entriesHeight + 1, all.width(), entriesHeight);
    const QRect aboveStrip = all.adjusted(0, 0, 0, -entriesHeight);
    // Whichever lets the fit draw the path larger (what Fit shows, drawn to scale).
    const QRectF bounds = fitBounds();
    const auto scaleIn = [&](const QRect& drawing) {
        const QRectF area = fitAreaIn(drawing);
        if (area.width() < kLeastDrawing || area.height() < kLeastDrawing)
            return 0.0;
        return qMin(area.width() / qMax(bounds.width(), 1e-9),
                    area.height() / qMax(bounds.height(), 1e-9));
    };
    const double beside = columnFits ? scaleIn(besideColumn) : 0.0;
    const double below = scaleIn(aboveStrip);
    if (beside <= 0.0 && below <= 0.0)
        return; // too small for a legend: the path keeps the whole view
    m_legendBeside = beside >= below;
    m_legendRect = m_legendBeside ? column : strip;
    m_drawingRect = m_legendBeside ? besideColumn : aboveStrip;
}

void ProgramPathView::placeLegendIfResized() const
{
    if (m_placedSize != size())
        placeLegend();
}

QRect ProgramPathView::legendRect() const
{
    viewport(); // fitted (and the legend placed) for this size first
    placeLegendIfResized();
    return m_legendRect;
}

QRect ProgramPathView::drawingRect() const
{
    placeLegendIfResized();
    return m_drawingRect;
}

bool ProgramPathView::legendBeside() const
{
    legendRect();
    return m_legendBeside;
}

const PreviewViewport& ProgramPathView::viewport() const
{
    if (!m_userView && m_fittedSize != size()) {
        placeLegend(); // for what this fit shows
        m_viewport.fit(fitBounds(), fitArea());
        m_fittedSize = size();
    }
    return m_viewport;
}

QRectF ProgramPathView::fitBounds() const
{
    // The path when there is one (the work), else the soft limits' box.
    if (!m_projected.points.isEmpty())
        return QPolygonF(m_projected.points).boundingRect();
    if (!m_projected.softLimits.isEmpty())
        return m_projected.softLimits.boundingRect();
    return QRectF(0, 0, 1, 1);
}

void ProgramPathView::fitToView()
{
    m_userView = false;
    m_fittedSize = QSize(); // fitted on the next use, to the size then
    update();
}

void ProgramPathView::zoomBy(const QPointF& at, double factor)
{
    viewport(); // fitted to the size first
    m_viewport.zoomAt(at, factor);
    m_userView = true;
    update();
}

void ProgramPathView::panBy(const QPointF& delta)
{
    viewport(); // fitted to the size first
    m_viewport.panBy(delta);
    m_userView = true;
    update();
}

void ProgramPathView::turnBy(double azimuth, double elevation)
{
    if (!canTurn())
        return;
    const PreviewOrientation next = m_orientation.turned(azimuth, elevation);
    if (next == m_orientation)
        return; // the elevation at its end
    viewport(); // fitted to the size first
    // The path turns about its middle, which stays where it is on the screen: one point
    // projected twice, the scale kept.
    const PreviewPosition pivot = m_scene.centre().value_or(PreviewPosition{});
    const QPointF at = m_viewport.map(m_orientation.project(pivot));
    const bool wasTurned = isTurned();
    m_orientation = next;
    m_viewport.placeAt(m_orientation.project(pivot), at);
    m_userView = true;
    if (isTurned() != wasTurned)
        updateSelector(); // "Orbit", or the standard view the turn came back to
    reproject();
}

void ProgramPathView::resizeEvent(QResizeEvent*)
{
    m_viewSelector->adjustSize();
    m_fit->adjustSize();
    m_viewSelector->move(2, 2);
    m_fit->move(m_viewSelector->geometry().right() + 4, 2);
    m_fit->resize(m_fit->width(), m_viewSelector->height());
    // The viewport fits itself to the new size on its next use (viewport()).
}

void ProgramPathView::wheelEvent(QWheelEvent* event)
{
    // 120 per notch: 1.2 times per notch, smooth for touchpads' smaller steps.
    const double factor = std::pow(1.2, event->angleDelta().y() / 120.0);
    if (factor != 1.0)
        zoomBy(event->position(), factor);
    event->accept();
}

void ProgramPathView::mousePressEvent(QMouseEvent* event)
{
    const bool left = event->button() == Qt::LeftButton;
    // A second button pressed during a drag leaves that drag alone.
    const bool dragging =
        m_drag && m_drag->button != event->button() && (event->buttons() & m_drag->button);
    if (!dragging && (left || event->button() == Qt::MiddleButton)) {
        // The left button turns (where there is X, Y and Z to turn); Shift+left and the middle
        // button pan.
        const bool turn = left && !(event->modifiers() & Qt::ShiftModifier) && canTurn();
        m_drag = Drag{event->position(), event->button(), turn};
        setCursor(turn ? Qt::SizeAllCursor : Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void ProgramPathView::mouseMoveEvent(QMouseEvent* event)
{
    if (!m_drag || !(event->buttons() & m_drag->button))
        return;
    const QPointF delta = event->position() - m_drag->from;
    m_drag->from = event->position();
    if (m_drag->turn)
        // Across: about Z, the way the pointer goes; down: looked at from higher up.
        turnBy(delta.x() * kDegreesPerDragPixel, delta.y() * kDegreesPerDragPixel);
    else
        panBy(delta);
}

void ProgramPathView::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_drag && event->button() == m_drag->button) {
        m_drag.reset();
        unsetCursor();
    }
}

void ProgramPathView::mouseDoubleClickEvent(QMouseEvent*)
{
    fitToView();
}

void ProgramPathView::keyPressEvent(QKeyEvent* event)
{
    const QPointF centre = fitArea().center();
    const double step = width() * kKeyPanFraction;
    const bool turnKey = (event->modifiers() & Qt::ControlModifier) && canTurn();
    switch (event->key()) {
    case Qt::Key_F:
    case Qt::Key_Home:
        fitToView();
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoomBy(centre, kKeyZoom);
        break;
    case Qt::Key_Minus:
        zoomBy(centre, 1.0 / kKeyZoom);
        break;
    // Ctrl+arrows turn the path as a drag the same way would.
    case Qt::Key_Left:
        if (turnKey)
            turnBy(-kKeyTurnDegrees, 0);
        else
            panBy({step, 0});
        break;
    case Qt::Key_Right:
        if (turnKey)
            turnBy(kKeyTurnDegrees, 0);
        else
            panBy({-step, 0});
        break;
    case Qt::Key_Up:
        if (turnKey)
            turnBy(0, -kKeyTurnDegrees);
        else
            panBy({0, step});
        break;
    case Qt::Key_Down:
        if (turnKey)
            turnBy(0, kKeyTurnDegrees);
        else
            panBy({0, -step});
        break;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

} // namespace stepdeck::ui
