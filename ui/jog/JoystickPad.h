#pragma once
#include <QPointF>
#include <QPointer>
#include <QWidget>

class QVariantAnimation;

namespace stepdeck::ui {

// A virtual joystick. Two-axis (square pad, X right, Y up) or one-axis (vertical stick).
// Dragging the knob reports the deflection (-1..1 per axis); releasing it springs back to the
// centre and reports released(). The velocity ramp is the core's job: the spring-back is only
// what the operator sees. Limit switches light up the edges of the affected axis.
//
// A held pad holds still (safety contract, rule 6; issue 16): the press freezes the pad's
// frame in screen coordinates and every deflection of that drag is measured against the
// frozen frame, never against a widget that moved or resized since. Any change of the frame
// while the button is held -- a layout that re-flowed, a resized dock, a moved window -- ends
// the drag at once (deflection zero, released(), dragInterrupted()) and the pad ignores the
// still-held pointer until the button is released and pressed again.
class JoystickPad : public QWidget
{
    Q_OBJECT
public:
    enum class Mode { TwoAxis, Vertical };

    explicit JoystickPad(Mode mode, QWidget* parent = nullptr);

    void setAxisLabels(const QString& horizontal, const QString& vertical);
    void setDeadZone(double fraction);
    void setLimitActive(int axisIndex, bool active); // 0: horizontal, 1: vertical
    bool isLimitActive(int axisIndex) const;
    void setVelocityHint(const QPointF& fractions); // live commanded rates, drawn as a marker
    QPointF deflection() const { return m_deflection; }
    bool isDragging() const { return m_dragging; }
    // While dragging: ends the drag (as described above) if the pad's frame on screen is no
    // longer the one the press began in. True if the drag goes on.
    bool confirmFrameHeld();
    Mode mode() const { return m_mode; }

    // Centre of the pad and the point of full positive deflection, in widget coordinates
    // (tests and keyboard focus helpers use these).
    QPointF centre() const;
    QPointF pointFor(const QPointF& deflection) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

public Q_SLOTS:
    void recenter(); // ends a drag at once (focus loss, STOP)

Q_SIGNALS:
    void deflectionChanged(const QPointF& deflection);
    void released();
    // The drag ended because the pad moved or resized under the held pointer.
    void dragInterrupted();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void changeEvent(QEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void moveEvent(QMoveEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QRectF travel() const { return travelIn(rect()); } // the area the knob centre can reach
    QRectF travelIn(const QRectF& frame) const;
    QRect frameOnScreen() const;
    void dragTo(const QPointF& globalPos);
    void watchAncestors(bool on);
    void paintBase(QPainter& p);
    void paintLimits(QPainter& p);
    void paintKnob(QPainter& p);

    Mode m_mode;
    QString m_hLabel = QStringLiteral("X");
    QString m_vLabel = QStringLiteral("Y");
    double m_deadZone = 0.08;
    bool m_limit[2] = {false, false};
    QPointF m_deflection;
    QPointF m_shown; // knob position drawn (animates back to centre)
    QPointF m_velocityHint;
    bool m_dragging = false;
    QRect m_pressFrame; // the pad on screen when the press began (global coordinates)
    QList<QPointer<QWidget>> m_watched; // the pad's ancestors, watched while dragging
    QVariantAnimation* m_spring;
};

} // namespace stepdeck::ui
