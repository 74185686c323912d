#include "DroValueLabel.h"
#include <QPainter>
#include <QStyle>

namespace stepdeck::ui {

namespace {
constexpr int kGap = 6; // between the digits and the unit
}

DroValueLabel::DroValueLabel(QWidget* parent) : QLabel(parent), m_digits(font())
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void DroValueLabel::setDigitFont(const QFont& font)
{
    if (font == m_digits)
        return;
    m_digits = font;
    updateGeometry();
    update();
}

void DroValueLabel::setUnit(const QString& unit)
{
    if (unit == m_unit)
        return;
    m_unit = unit;
    update(); // the box keeps its size: the digits make room
}

void DroValueLabel::setReservedText(const QString& text)
{
    if (text == m_reserved)
        return; // set on every status poll: the same text must not relayout and repaint
    m_reserved = text;
    updateGeometry();
    update();
}

QRect DroValueLabel::textArea() const
{
    return contentsRect().adjusted(margin(), margin(), -margin(), -margin());
}

int DroValueLabel::unitWidth() const
{
    return m_unit.isEmpty() ? 0 : fontMetrics().horizontalAdvance(m_unit) + kGap;
}

QFont DroValueLabel::fitted(const QString& text, int width) const
{
    QFont font = m_digits;
    const double full = m_digits.pointSizeF();
    for (double size = full; size >= full * kMinimumScale; size -= 0.5) {
        font.setPointSizeF(size);
        if (QFontMetrics(font).horizontalAdvance(text) <= width)
            return font;
    }
    font.setPointSizeF(full * kMinimumScale);
    return font;
}

QFont DroValueLabel::shownDigitFont() const
{
    const int width = textArea().width() - unitWidth();
    QFont font = fitted(m_reserved, width);
    if (QFontMetrics(font).horizontalAdvance(text()) > width)
        font = fitted(text(), width);
    return font;
}

bool DroValueLabel::textFits() const
{
    return QFontMetrics(shownDigitFont()).horizontalAdvance(text()) <=
           textArea().width() - unitWidth();
}

QSize DroValueLabel::chrome() const
{
    // Frame, style-sheet padding and margin around the text.
    return QSize(width() - contentsRect().width(), height() - contentsRect().height()) +
           QSize(2 * margin(), 2 * margin());
}

QSize DroValueLabel::sizeHint() const
{
    ensurePolished();
    const QFontMetrics digits(m_digits);
    return QSize(digits.horizontalAdvance(m_reserved) + unitWidth(), digits.height()) + chrome();
}

QSize DroValueLabel::minimumSizeHint() const
{
    // The reserved text in the smallest type: the column never forces the dock wider.
    QFont smallest = m_digits;
    smallest.setPointSizeF(m_digits.pointSizeF() * kMinimumScale);
    return QSize(QFontMetrics(smallest).horizontalAdvance(m_reserved) + unitWidth() +
                     chrome().width(),
                 sizeHint().height());
}

void DroValueLabel::paintEvent(QPaintEvent* event)
{
    QFrame::paintEvent(event); // frame and style-sheet border; the background is drawn already
    QPainter painter(this);
    const QRect area = textArea();
    const int unitW = unitWidth();
    if (unitW > 0) {
        // The unit on the digits' baseline.
        const QFont digits = shownDigitFont();
        const int baseline =
            area.top() +
            (area.height() + QFontMetrics(digits).ascent() - QFontMetrics(digits).descent()) / 2;
        const QFontMetrics fm = fontMetrics();
        const QRect unitRect(area.right() - unitW + kGap + 1, baseline - fm.ascent(), unitW - kGap,
                             fm.height());
        style()->drawItemText(&painter, unitRect, Qt::AlignLeft | Qt::AlignTop, palette(),
                              isEnabled(), m_unit, foregroundRole());
    }
    painter.setFont(shownDigitFont());
    const QRect digitsRect = area.adjusted(0, 0, -unitW, 0);
    style()->drawItemText(&painter, digitsRect, Qt::AlignRight | Qt::AlignVCenter, palette(),
                          isEnabled(), text(), foregroundRole());
}

} // namespace stepdeck::ui
