#include "ElidedLabel.h"
#include <QHelpEvent>
#include <QPainter>
#include <QStyle>
#include <QTextLayout>
#include <QToolTip>

namespace stepdeck::ui {

namespace {
// QTextLayout breaks lines at U+2028, not at '\n'.
QString forLayout(const QString& text)
{
    QString out = text;
    out.replace(QLatin1Char('\n'), QChar::LineSeparator);
    return out;
}
} // namespace

ElidedLabel::ElidedLabel(QWidget* parent, int lines) : QLabel(parent), m_lines(qMax(1, lines))
{
    setWordWrap(false); // the wrapping is ours: QLabel's would make the height follow the text
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void ElidedLabel::setLines(int lines)
{
    m_lines = qMax(1, lines);
    updateGeometry();
    update();
}

void ElidedLabel::setReservedTexts(const QStringList& texts)
{
    if (texts == m_reserved)
        return;
    m_reserved = texts;
    QSizePolicy policy = sizePolicy();
    policy.setVerticalPolicy(texts.isEmpty() ? QSizePolicy::Fixed : QSizePolicy::Preferred);
    policy.setHeightForWidth(!texts.isEmpty());
    setSizePolicy(policy);
    updateGeometry();
    update();
}

void ElidedLabel::setMinimumTextWidth(int pixels)
{
    m_minimumTextWidth = qMax(0, pixels);
    updateGeometry();
}

QMargins ElidedLabel::textMargins() const
{
    // contentsRect() holds the frame and the style sheet's border and padding.
    const QRect contents = contentsRect();
    const int m = margin();
    return QMargins(contents.left() + m, contents.top() + m, width() - contents.right() - 1 + m,
                    height() - contents.bottom() - 1 + m);
}

int ElidedLabel::textHeight(int lineCount) const
{
    const QFontMetrics fm = fontMetrics();
    return fm.height() + (qMax(1, lineCount) - 1) * fm.lineSpacing();
}

int ElidedLabel::lineCount(const QString& text, int textWidth) const
{
    QTextLayout layout(forLayout(text), font());
    QTextOption option;
    option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    layout.setTextOption(option);
    int count = 0;
    layout.beginLayout();
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(qMax(1, textWidth));
        ++count;
    }
    layout.endLayout();
    return qMax(1, count);
}

QStringList ElidedLabel::layoutLines(int textWidth, int maxLines, bool* elided) const
{
    const QString text = forLayout(QLabel::text());
    const QFontMetrics fm = fontMetrics();
    *elided = false;
    QStringList out;
    if (text.isEmpty())
        return out;
    textWidth = qMax(1, textWidth);
    if (maxLines <= 1) {
        QString flat = text;
        flat.replace(QChar::LineSeparator, QLatin1Char(' '));
        const QString shown = fm.elidedText(flat, Qt::ElideRight, textWidth);
        *elided = shown != flat;
        return {shown};
    }
    QTextLayout layout(text, font());
    QTextOption option;
    option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    layout.setTextOption(option);
    layout.beginLayout();
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(textWidth);
        if (out.size() == maxLines - 1) {
            // The last line we have room for takes the rest of the text, elided.
            QString rest = text.mid(line.textStart());
            rest.replace(QChar::LineSeparator, QLatin1Char(' '));
            const QString shown = fm.elidedText(rest.trimmed(), Qt::ElideRight, textWidth);
            *elided = shown != rest.trimmed();
            out << shown;
            break;
        }
        out << text.mid(line.textStart(), line.textLength()).remove(QChar::LineSeparator).trimmed();
    }
    layout.endLayout();
    return out;
}

QStringList ElidedLabel::currentLines(bool* elided) const
{
    // As many lines as the label's height holds now (at least one).
    const QMargins m = textMargins();
    const int available = height() - m.top() - m.bottom();
    const QFontMetrics fm = fontMetrics();
    const int fit = available < fm.height() ? 1 : 1 + (available - fm.height()) / fm.lineSpacing();
    return layoutLines(width() - m.left() - m.right(), fit, elided);
}

QStringList ElidedLabel::shownLines() const
{
    bool elided = false;
    return currentLines(&elided);
}

bool ElidedLabel::isElided() const
{
    bool elided = false;
    currentLines(&elided);
    return elided;
}

QString ElidedLabel::toolTipText() const
{
    if (!isElided())
        return toolTip();
    return toolTip().isEmpty() ? text() : text() + QStringLiteral("\n\n") + toolTip();
}

QSize ElidedLabel::sizeHint() const
{
    ensurePolished();
    const QMargins m = textMargins();
    const int w =
        qMax(m_minimumTextWidth, fontMetrics().averageCharWidth() * 4) + m.left() + m.right();
    if (!hasHeightForWidth())
        return QSize(w, textHeight(m_lines) + m.top() + m.bottom());
    // With reserved texts the layout asks heightForWidth() at the real width; the hint's own
    // height is for a line of about 60 characters.
    return QSize(w, heightForWidth(fontMetrics().averageCharWidth() * 60 + m.left() + m.right()));
}

QSize ElidedLabel::minimumSizeHint() const
{
    ensurePolished();
    const QMargins m = textMargins();
    return QSize(sizeHint().width(), textHeight(m_lines) + m.top() + m.bottom());
}

bool ElidedLabel::hasHeightForWidth() const
{
    return !m_reserved.isEmpty();
}

int ElidedLabel::heightForWidth(int width) const
{
    ensurePolished();
    const QMargins m = textMargins();
    int count = m_lines;
    const int textWidth = width - m.left() - m.right();
    for (const QString& text : m_reserved)
        count = qMax(count, lineCount(text, textWidth));
    return textHeight(count) + m.top() + m.bottom();
}

bool ElidedLabel::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const QString tip = toolTipText();
        if (tip.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(static_cast<QHelpEvent*>(event)->globalPos(), tip, this);
        return true;
    }
    return QLabel::event(event);
}

void ElidedLabel::paintEvent(QPaintEvent* event)
{
    QFrame::paintEvent(event); // frame and style-sheet border; the background is drawn already
    const QStringList lines = shownLines();
    if (lines.isEmpty())
        return;
    QPainter painter(this);
    const QMargins m = textMargins();
    const QRect area = rect().marginsRemoved(m);
    const QFontMetrics fm = fontMetrics();
    const int blockHeight = textHeight(int(lines.size()));
    int top = area.top();
    if (alignment() & Qt::AlignVCenter)
        top += (area.height() - blockHeight) / 2;
    else if (alignment() & Qt::AlignBottom)
        top += area.height() - blockHeight;
    const int horizontal = int(alignment() & Qt::AlignHorizontal_Mask);
    for (const QString& line : lines) {
        const QRect lineRect(area.left(), top, area.width(), fm.height());
        style()->drawItemText(&painter, lineRect, horizontal | Qt::AlignVCenter, palette(),
                              isEnabled(), line, foregroundRole());
        top += fm.lineSpacing();
    }
}

} // namespace stepdeck::ui
