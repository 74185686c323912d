#include "ScreenBound.h"
#include <QEvent>
#include <QLayout>
#include <QScreen>
#include <QWidget>

namespace stepdeck::ui {

ScreenBound::ScreenBound(QWidget* window) : QObject(window), m_window(window)
{
    window->installEventFilter(this);
    boundMinimum();
}

QSize ScreenBound::room(const QWidget* window)
{
    const QScreen* screen = window->screen();
    if (!screen)
        return QSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
    const QSize frame = window->frameGeometry().size() - window->geometry().size();
    return screen->availableGeometry().size() - frame;
}

void ScreenBound::boundMinimum()
{
    // Never 0: a zero minimum is not explicit, and the layout would set its own again.
    QSize minimum = m_window->layout() ? m_window->layout()->totalMinimumSize() : QSize(1, 1);
    minimum = minimum.boundedTo(room(m_window)).expandedTo(QSize(1, 1));
    if (m_window->minimumSize() != minimum)
        m_window->setMinimumSize(minimum);
}

void ScreenBound::fitOnScreen()
{
    const QScreen* screen = m_window->screen();
    if (!screen)
        return;
    const QSize size = m_window->size().boundedTo(room(m_window));
    if (size != m_window->size())
        m_window->resize(size);
    const QRect available = screen->availableGeometry();
    QRect frame = m_window->frameGeometry();
    frame.moveRight(qMin(frame.right(), available.right()));
    frame.moveBottom(qMin(frame.bottom(), available.bottom()));
    frame.moveLeft(qMax(frame.left(), available.left()));
    frame.moveTop(qMax(frame.top(), available.top()));
    if (frame.topLeft() != m_window->frameGeometry().topLeft())
        m_window->move(frame.topLeft());
}

bool ScreenBound::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_window) {
        switch (event->type()) {
        case QEvent::LayoutRequest: // the layout has just set its sizes: bound them again
        case QEvent::ScreenChangeInternal:
            boundMinimum();
            break;
        case QEvent::Show:
            boundMinimum();
            fitOnScreen();
            break;
        default:
            break;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace stepdeck::ui
