#include "LedIndicator.h"
#include <QPainter>
#include <QRadialGradient>

namespace stepdeck::ui {

LedIndicator::LedIndicator(const QString& text, QWidget* parent) : QWidget(parent), m_text(text)
{
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void LedIndicator::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    update();
}

void LedIndicator::setText(const QString& text)
{
    if (text == m_text)
        return; // the lamps are set on every status poll
    m_text = text;
    updateGeometry();
    update();
}

void LedIndicator::setDiameter(int pixels)
{
    m_diameter = pixels;
    updateGeometry();
    update();
}

QColor LedIndicator::colorFor(State state)
{
    switch (state) {
    case State::Off:
        return QColor(0x55, 0x5b, 0x61);
    case State::On:
        return QColor(0x2e, 0xcc, 0x40);
    case State::Warning:
        return QColor(0xff, 0xb3, 0x00);
    case State::Fault:
        return QColor(0xe5, 0x39, 0x35);
    case State::Unknown:
        return QColor(0x9e, 0x9e, 0x9e);
    }
    return Qt::gray;
}

QSize LedIndicator::sizeHint() const
{
    const int textWidth = m_text.isEmpty() ? 0 : fontMetrics().horizontalAdvance(m_text) + 6;
    return QSize(m_diameter + 4 + textWidth, qMax(m_diameter + 4, fontMetrics().height() + 2));
}

void LedIndicator::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF led(2, (height() - m_diameter) / 2.0, m_diameter, m_diameter);
    const QColor base = colorFor(m_state);
    QRadialGradient g(led.center() - QPointF(m_diameter / 5.0, m_diameter / 5.0), m_diameter);
    g.setColorAt(0, m_state == State::Off ? base.lighter(130) : base.lighter(160));
    g.setColorAt(1, base.darker(m_state == State::Off ? 110 : 130));
    p.setBrush(g);
    p.setPen(QPen(base.darker(180), 1));
    p.drawEllipse(led);
    if (!m_text.isEmpty()) {
        p.setPen(palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled,
                                 QPalette::WindowText));
        const QRect textRect(m_diameter + 8, 0, width() - m_diameter - 8, height());
        p.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft, m_text);
    }
}

} // namespace stepdeck::ui
