#include "ScreenBound.h"
#include <QEvent>
#include <QLayout>
#include <QScreen>
#include <QWidget>
#include <QWindowStateChangeEvent>

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
    // A maximised window is the window manager's to fit (a resize or move here would end the
    // maximised state).
    if (!screen || (m_window->windowState() & (Qt::WindowMaximized | Qt::WindowFullScreen)))
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
            m_awaitingFrame = !frameKnown();
            break;
        case QEvent::Move:
        case QEvent::Resize:
            // The window manager has framed (or restored) the window: fitted again, frame and
            // all, once it is done with this move (not from inside its event).
            if (m_awaitingFrame && m_window->isVisible() && frameKnown()) {
                m_awaitingFrame = false;
                QMetaObject::invokeMethod(this, &ScreenBound::fitOnScreen, Qt::QueuedConnection);
            }
            break;
        case QEvent::WindowStateChange:
            // Restored from maximised: its normal size, frame and all, on the screen too, now
            // and once the window manager has restored it (its next move or resize).
            if (m_window->isVisible() &&
                !(m_window->windowState() &
                  (Qt::WindowMaximized | Qt::WindowFullScreen | Qt::WindowMinimized)) &&
                static_cast<QWindowStateChangeEvent*>(event)->oldState().testAnyFlags(
                    Qt::WindowMaximized | Qt::WindowFullScreen)) {
                m_awaitingFrame = true;
                QMetaObject::invokeMethod(this, &ScreenBound::fitOnScreen, Qt::QueuedConnection);
            }
            break;
        default:
            break;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace stepdeck::ui
