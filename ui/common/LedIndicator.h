#pragma once
#include <QColor>
#include <QWidget>

namespace stepdeck::ui {

// A round status lamp with an optional text beside it.
class LedIndicator : public QWidget
{
    Q_OBJECT
public:
    enum class State { Off, On, Warning, Fault, Unknown };

    explicit LedIndicator(const QString& text = {}, QWidget* parent = nullptr);

    void setState(State state);
    State state() const { return m_state; }
    // Convenience: on -> onState, off -> Off.
    void setOn(bool on, State onState = State::On) { setState(on ? onState : State::Off); }
    void setText(const QString& text);
    QString text() const { return m_text; }
    void setDiameter(int pixels);

    static QColor colorFor(State state);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QString m_text;
    State m_state = State::Unknown;
    int m_diameter = 14;
};

} // namespace stepdeck::ui
