#include "SafetyKeyFilter.h"
#include <QAction>
#include <QApplication>
#include <QKeyEvent>
#include <QWidget>

namespace stepdeck::ui {

SafetyKeyFilter::SafetyKeyFilter(QAction* stop, QAction* panic, QObject* parent)
    : QObject(parent), m_stop(stop), m_panic(panic)
{
    qApp->installEventFilter(this);
}

SafetyKeyFilter::~SafetyKeyFilter()
{
    qApp->removeEventFilter(this);
}

bool SafetyKeyFilter::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() != QEvent::KeyPress)
        return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() != Qt::Key_Escape && key->key() != Qt::Key_F1)
        return false;
    QWidget* popup = QApplication::activePopupWidget();
    QWidget* modal = QApplication::activeModalWidget();
    if (!popup && !modal)
        return false; // the main window's shortcuts handle it
    // A key event travels from the focus widget up to its parents, and this filter sees every
    // step: act on the first receiver only.
    QWidget* first = popup ? (popup->focusWidget() ? popup->focusWidget() : popup)
                           : (QApplication::focusWidget() ? QApplication::focusWidget() : modal);
    if (watched != first)
        return false;
    if (key->key() == Qt::Key_Escape) {
        if (m_stop)
            m_stop->trigger();
        return false; // and let Esc close the dialog or popup
    }
    if (m_panic && !key->isAutoRepeat())
        m_panic->trigger();
    return true;
}

} // namespace stepdeck::ui
