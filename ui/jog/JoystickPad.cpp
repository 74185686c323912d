#include "JoystickPad.h"
#include <QEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QVariantAnimation>

namespace stepdeck::ui {

namespace {
constexpr double kKnobRadius = 20;
constexpr double kMargin = 26; // room for the edge labels and limit bars
} // namespace

JoystickPad::JoystickPad(Mode mode, QWidget* parent)
    : QWidget(parent), m_mode(mode), m_spring(new QVariantAnimation(this))
{
    if (mode == Mode::Vertical)
        m_vLabel = QStringLiteral("Z");
    setMouseTracking(false);
    setFocusPolicy(Qt::NoFocus);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    m_spring->setDuration(140);
    m_spring->setEasingCurve(QEasingCurve::OutCubic);
    connect(m_spring, &QVariantAnimation::valueChanged, this, [this](const QVariant& v) {
        m_shown = v.toPointF();
        update();
    });
}

void JoystickPad::setAxisLabels(const QString& horizontal, const QString& vertical)
{
    m_hLabel = horizontal;
    m_vLabel = vertical;
    update();
}

void JoystickPad::setDeadZone(double fraction)
{
    m_deadZone = qBound(0.0, fraction, 0.9);
    update();
}

void JoystickPad::setLimitActive(int axisIndex, bool active)
{
    if (axisIndex < 0 || axisIndex > 1 || m_limit[axisIndex] == active)
        return;
    m_limit[axisIndex] = active;
    update();
}

bool JoystickPad::isLimitActive(int axisIndex) const
{
    return axisIndex >= 0 && axisIndex <= 1 && m_limit[axisIndex];
}

void JoystickPad::setVelocityHint(const QPointF& fractions)
{
    if (fractions == m_velocityHint)
        return;
    m_velocityHint = fractions;
    update();
}

QSize JoystickPad::sizeHint() const
{
    return m_mode == Mode::TwoAxis ? QSize(300, 300) : QSize(90, 300);
}

QSize JoystickPad::minimumSizeHint() const
{
    // Small enough that the pads and the jog controls in three columns share the centre
    // beside the German read-out at 1366x768 (issue 31); the pad's travel stays over 120 px.
    return m_mode == Mode::TwoAxis ? QSize(168, 168) : QSize(68, 168);
}

QRectF JoystickPad::travelIn(const QRectF& frame) const
{
    const QRectF area = frame.adjusted(kMargin, kMargin, -kMargin, -kMargin);
    if (m_mode == Mode::Vertical)
        return QRectF(area.center().x(), area.top() + kKnobRadius, 0,
                      area.height() - 2 * kKnobRadius);
    const double side = qMin(area.width(), area.height()) - 2 * kKnobRadius;
    QRectF square(0, 0, side, side);
    square.moveCenter(area.center());
    return square;
}

QPointF JoystickPad::centre() const
{
    return travel().center();
}

QPointF JoystickPad::pointFor(const QPointF& deflection) const
{
    const QRectF t = travel();
    return QPointF(t.center().x() + deflection.x() * t.width() / 2,
                   t.center().y() - deflection.y() * t.height() / 2);
}

QRect JoystickPad::frameOnScreen() const
{
    return QRect(mapToGlobal(QPoint(0, 0)), size());
}

void JoystickPad::dragTo(const QPointF& globalPos)
{
    // Measured against the frame the press began in (see the class comment): a pad that
    // moved since cannot turn the same pointer position into another direction.
    const QRectF t = travelIn(QRectF(m_pressFrame));
    const double dx = t.width() > 0 ? (globalPos.x() - t.center().x()) / (t.width() / 2) : 0.0;
    const double dy = t.height() > 0 ? (t.center().y() - globalPos.y()) / (t.height() / 2) : 0.0;
    const QPointF d(m_mode == Mode::Vertical ? 0.0 : qBound(-1.0, dx, 1.0), qBound(-1.0, dy, 1.0));
    m_shown = d;
    update();
    if (d != m_deflection) {
        m_deflection = d;
        Q_EMIT deflectionChanged(d);
    }
}

void JoystickPad::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton)
        return;
    m_spring->stop();
    m_dragging = true;
    m_pressFrame = frameOnScreen();
    watchAncestors(true);
    dragTo(event->globalPosition());
}

void JoystickPad::mouseMoveEvent(QMouseEvent* event)
{
    if (m_dragging && confirmFrameHeld())
        dragTo(event->globalPosition());
}

void JoystickPad::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        recenter();
}

bool JoystickPad::confirmFrameHeld()
{
    if (!m_dragging)
        return false;
    if (frameOnScreen() == m_pressFrame)
        return true;
    recenter();
    Q_EMIT dragInterrupted();
    return false;
}

void JoystickPad::moveEvent(QMoveEvent* event)
{
    QWidget::moveEvent(event);
    confirmFrameHeld();
}

void JoystickPad::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    confirmFrameHeld();
}

bool JoystickPad::eventFilter(QObject* watched, QEvent* event)
{
    // An ancestor that moves or resizes can carry the pad along without the pad itself
    // getting a move event (its position inside the parent did not change).
    if (event->type() == QEvent::Move || event->type() == QEvent::Resize)
        confirmFrameHeld();
    return QWidget::eventFilter(watched, event);
}

void JoystickPad::watchAncestors(bool on)
{
    for (const QPointer<QWidget>& w : std::as_const(m_watched)) {
        if (w)
            w->removeEventFilter(this);
    }
    m_watched.clear();
    if (!on)
        return;
    for (QWidget* w = parentWidget(); w; w = w->parentWidget()) {
        w->installEventFilter(this);
        m_watched.append(w);
    }
}

void JoystickPad::recenter()
{
    const bool was = m_dragging || !m_deflection.isNull();
    m_dragging = false;
    watchAncestors(false);
    m_deflection = QPointF();
    if (!m_shown.isNull()) {
        m_spring->stop();
        m_spring->setStartValue(m_shown);
        m_spring->setEndValue(QPointF());
        m_spring->start();
    }
    if (was) {
        Q_EMIT deflectionChanged(m_deflection);
        Q_EMIT released();
    }
}

void JoystickPad::changeEvent(QEvent* event)
{
    // A window that is no longer active gets no mouse release: end the drag now.
    if (event->type() == QEvent::ActivationChange && !isActiveWindow())
        recenter();
    QWidget::changeEvent(event);
}

void JoystickPad::hideEvent(QHideEvent* event)
{
    recenter();
    QWidget::hideEvent(event);
}

void JoystickPad::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    paintBase(p);
    paintLimits(p);
    paintKnob(p);
}

void JoystickPad::paintBase(QPainter& p)
{
    const QRectF t = travel();
    const QRectF base =
        t.adjusted(-kKnobRadius - 4, -kKnobRadius - 4, kKnobRadius + 4, kKnobRadius + 4);
    const bool dark = palette().color(QPalette::Window).lightness() < 128;
    p.setPen(QPen(palette().color(QPalette::Mid), 1.5));
    p.setBrush(dark ? QColor(0x26, 0x2b, 0x31) : QColor(0xe9, 0xed, 0xf1));
    p.drawRoundedRect(base, 14, 14);

    // Dead zone and cross hair.
    p.setPen(QPen(palette().color(QPalette::Mid), 1, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    const QPointF c = t.center();
    if (m_mode == Mode::TwoAxis) {
        p.drawLine(QPointF(base.left() + 6, c.y()), QPointF(base.right() - 6, c.y()));
        p.drawLine(QPointF(c.x(), base.top() + 6), QPointF(c.x(), base.bottom() - 6));
        const QSizeF dz(t.width() * m_deadZone, t.height() * m_deadZone);
        p.setPen(QPen(QColor(0x42, 0x8b, 0xca, 120), 1));
        p.setBrush(QColor(0x42, 0x8b, 0xca, 30));
        p.drawRect(QRectF(c - QPointF(dz.width() / 2, dz.height() / 2), dz));
    } else {
        p.drawLine(QPointF(c.x(), base.top() + 6), QPointF(c.x(), base.bottom() - 6));
        const double dz = t.height() * m_deadZone / 2;
        p.setPen(QPen(QColor(0x42, 0x8b, 0xca, 120), 1));
        p.setBrush(QColor(0x42, 0x8b, 0xca, 30));
        p.drawRect(QRectF(c.x() - 14, c.y() - dz, 28, 2 * dz));
    }

    // Edge labels.
    p.setPen(palette().color(QPalette::WindowText));
    QFont f = font();
    f.setBold(true);
    p.setFont(f);
    const QRectF r = rect();
    p.drawText(QRectF(r.left(), r.top(), r.width(), kMargin - 4), Qt::AlignCenter,
               QStringLiteral("+") + m_vLabel);
    p.drawText(QRectF(r.left(), r.bottom() - kMargin + 4, r.width(), kMargin - 4), Qt::AlignCenter,
               QStringLiteral("\u2212") + m_vLabel);
    if (m_mode == Mode::TwoAxis) {
        p.drawText(QRectF(r.right() - kMargin + 2, c.y() - 10, kMargin - 2, 20), Qt::AlignCenter,
                   QStringLiteral("+") + m_hLabel);
        p.drawText(QRectF(r.left(), c.y() - 10, kMargin - 2, 20), Qt::AlignCenter,
                   QStringLiteral("\u2212") + m_hLabel);
    }
}

void JoystickPad::paintLimits(QPainter& p)
{
    // The E-LAB status says which axis hit a limit, not which end: light both ends.
    const QRectF t = travel();
    const QRectF base =
        t.adjusted(-kKnobRadius - 4, -kKnobRadius - 4, kKnobRadius + 4, kKnobRadius + 4);
    const QColor red(0xe5, 0x39, 0x35);
    p.setPen(Qt::NoPen);
    p.setBrush(red);
    if (m_limit[0] && m_mode == Mode::TwoAxis) {
        p.drawRoundedRect(QRectF(base.left() - 7, base.top() + 10, 5, base.height() - 20), 2, 2);
        p.drawRoundedRect(QRectF(base.right() + 2, base.top() + 10, 5, base.height() - 20), 2, 2);
    }
    if (m_limit[1]) {
        p.drawRoundedRect(QRectF(base.left() + 10, base.top() - 7, base.width() - 20, 5), 2, 2);
        p.drawRoundedRect(QRectF(base.left() + 10, base.bottom() + 2, base.width() - 20, 5), 2, 2);
    }
    if (m_limit[0] || m_limit[1]) {
        p.setPen(red);
        QFont f = font();
        f.setBold(true);
        f.setPointSizeF(f.pointSizeF() * 0.85);
        p.setFont(f);
        p.drawText(base.adjusted(4, 4, -4, -4), Qt::AlignLeft | Qt::AlignTop, tr("LIMIT"));
    }
}

void JoystickPad::paintKnob(QPainter& p)
{
    const QPointF knob = pointFor(m_shown);
    const QPointF c = centre();
    if (!m_velocityHint.isNull()) {
        // Where the ramped, commanded velocity is right now.
        p.setPen(QPen(QColor(0x2e, 0xcc, 0x40), 3, Qt::SolidLine, Qt::RoundCap));
        p.drawLine(c, pointFor(m_velocityHint));
    }
    p.setPen(QPen(QColor(0x1b, 0x5e, 0x9a), 2));
    p.drawLine(c, knob);
    QRadialGradient g(knob - QPointF(6, 6), kKnobRadius * 1.6);
    g.setColorAt(0, m_dragging ? QColor(0x64, 0xb5, 0xf6) : QColor(0x90, 0xa4, 0xae));
    g.setColorAt(1, m_dragging ? QColor(0x15, 0x65, 0xc0) : QColor(0x45, 0x5a, 0x64));
    p.setBrush(g);
    p.setPen(QPen(QColor(0x26, 0x32, 0x38), 1.5));
    p.drawEllipse(knob, kKnobRadius, kKnobRadius);
}

} // namespace stepdeck::ui
