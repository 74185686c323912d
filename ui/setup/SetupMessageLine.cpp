#include "SetupMessageLine.h"
#include <QResizeEvent>

namespace stepdeck::ui {

SetupMessageLine::SetupMessageLine(QWidget* parent) : QLabel(parent)
{
    setWordWrap(false);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    setTextFormat(Qt::PlainText);
}

void SetupMessageLine::setMessage(const QString& text, const QStringList& details)
{
    m_full = text;
    m_full.replace(QLatin1Char('\n'), QStringLiteral("; "));
    m_details = details;
    QStringList tip{m_full};
    tip += details;
    setToolTip(m_full.isEmpty() ? QString() : tip.join(QLatin1Char('\n')));
    elide();
}

QSize SetupMessageLine::sizeHint() const
{
    return {fontMetrics().averageCharWidth() * 20, minimumSizeHint().height()};
}

QSize SetupMessageLine::minimumSizeHint() const
{
    const QMargins m = contentsMargins();
    return {0, fontMetrics().height() + 2 * margin() + m.top() + m.bottom()};
}

void SetupMessageLine::resizeEvent(QResizeEvent* event)
{
    QLabel::resizeEvent(event);
    elide();
}

void SetupMessageLine::elide()
{
    const int width = contentsRect().width() - 2 * margin();
    setText(fontMetrics().elidedText(m_full, Qt::ElideRight, qMax(0, width)));
}

} // namespace stepdeck::ui
