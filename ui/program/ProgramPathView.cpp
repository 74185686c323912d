#include "ProgramPathView.h"
#include <QComboBox>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardItemModel>
#include <QToolButton>
#include <QWheelEvent>
#include <cmath>

namespace stepdeck::ui {

namespace {
constexpr int kMargin = 12;
constexpr int kControlsHeight = 24; // the view selector and Fit over the top of the drawing
constexpr double kKeyZoom = 1.25;
constexpr double kKeyPanFraction = 0.1;
} // namespace

ProgramPathView::ProgramPathView(QWidget* parent)
    : QWidget(parent), m_viewSelector(new QComboBox(this)), m_fit(new QToolButton(this))
{
    setObjectName(QStringLiteral("programPathView"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    // Keys zoom, pan and fit once the drawing has the focus (a click or Tab gives it).
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(tr("Wheel: zoom about the pointer \u00b7 drag: pan \u00b7 F or a double click: "
                  "fit \u00b7 + and -: zoom \u00b7 arrow keys: pan"));
    // Over the drawing, not above it: the page must not grow taller (1366x768).
    m_viewSelector->setObjectName(QStringLiteral("programPreviewViewSelector"));
    m_viewSelector->setFocusPolicy(Qt::StrongFocus);
    for (PreviewViewKind kind : PreviewProjection::kAll)
        m_viewSelector->addItem(PreviewProjection::title(kind), int(kind));
    m_fit->setObjectName(QStringLiteral("programPreviewFit"));
    m_fit->setText(tr("Fit"));
    m_fit->setToolTip(tr("Fit the path to the view (F)"));
    m_fit->setFocusPolicy(Qt::StrongFocus);
    m_chosen = PreviewProjection::fromSettingsName(
        QSettings().value(QLatin1String(kSettingsKey)).toString(), PreviewViewKind::Top);
    m_kind = m_chosen;
    connect(m_viewSelector, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        chooseView(PreviewViewKind(m_viewSelector->itemData(index).toInt()));
    });
    connect(m_fit, &QToolButton::clicked, this, &ProgramPathView::fitToView);
    updateSelector();
}

void ProgramPathView::setPreview(const program::ProgramPreview& preview,
                                 const machine::MachineDescription& machine)
{
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
    for (int axis : PreviewProjection::axesOf(m_kind))
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
    updateSelector();
    reproject();
    fitToView(); // another plane: the old zoom means nothing there
}

void ProgramPathView::updateSelector()
{
    auto* model = qobject_cast<QStandardItemModel*>(m_viewSelector->model());
    QStringList reasons;
    for (int i = 0; i < m_viewSelector->count(); ++i) {
        const auto kind = PreviewViewKind(m_viewSelector->itemData(i).toInt());
        const QString reason = PreviewProjection::unavailableReason(kind, m_scene.axes());
        // Without a machine (no preview yet) every view stays choosable.
        const bool enabled = m_scene.axes().isEmpty() || reason.isEmpty();
        if (model)
            model->item(i)->setEnabled(enabled);
        m_viewSelector->setItemData(i, enabled ? QVariant() : QVariant(reason), Qt::ToolTipRole);
        if (!enabled)
            reasons << QStringLiteral("%1: %2").arg(PreviewProjection::title(kind), reason);
        if (kind == m_kind)
            m_viewSelector->setCurrentIndex(i);
    }
    m_viewSelector->setToolTip(reasons.isEmpty()
                                   ? tr("How the path is looked at")
                                   : tr("How the path is looked at. Not on this machine:\n%1")
                                         .arg(reasons.join(QLatin1Char('\n'))));
}

void ProgramPathView::reproject()
{
    m_projected = m_scene.isEmpty() ? PreviewScene::Projected{} : m_scene.project(m_kind);
    m_runningSegments = PreviewScene::segmentsOfLine(m_projected, m_runningLine);
    m_current = PreviewScene::projectPosition(m_kind, m_currentPosition);
    m_cacheValid = false;
    update();
}

void ProgramPathView::setCurrent(const QMap<QString, double>& position)
{
    if (position == m_currentPosition)
        return;
    m_currentPosition = position;
    m_current = PreviewScene::projectPosition(m_kind, m_currentPosition);
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
    return QRectF(rect()).adjusted(kMargin, kMargin + kControlsHeight, -kMargin, -kMargin);
}

const PreviewViewport& ProgramPathView::viewport() const
{
    if (!m_userView && m_fittedSize != size()) {
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
    if (event->button() == Qt::LeftButton) {
        m_dragFrom = event->position();
        setCursor(Qt::ClosedHandCursor);
    }
    QWidget::mousePressEvent(event);
}

void ProgramPathView::mouseMoveEvent(QMouseEvent* event)
{
    if (m_dragFrom && (event->buttons() & Qt::LeftButton)) {
        panBy(event->position() - *m_dragFrom);
        m_dragFrom = event->position();
    }
}

void ProgramPathView::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton) {
        m_dragFrom.reset();
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
    case Qt::Key_Left:
        panBy({step, 0});
        break;
    case Qt::Key_Right:
        panBy({-step, 0});
        break;
    case Qt::Key_Up:
        panBy({0, step});
        break;
    case Qt::Key_Down:
        panBy({0, -step});
        break;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

} // namespace stepdeck::ui
