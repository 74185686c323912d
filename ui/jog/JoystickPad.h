#pragma once
#include <QPointF>
#include <QWidget>

class QVariantAnimation;

namespace stepdeck::ui {

// A virtual joystick. Two-axis (square pad, X right, Y up) or one-axis (vertical stick).
// Dragging the knob reports the deflection (-1..1 per axis); releasing it springs back to the
// centre and reports released(). The velocity ramp is the core's job: the spring-back is only
// what the operator sees. Limit switches light up the edges of the affected axis.
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

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void changeEvent(QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    QRectF travel() const; // the area the knob centre can reach
    void dragTo(const QPointF& pos);
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
    QVariantAnimation* m_spring;
};

} // namespace stepdeck::ui
