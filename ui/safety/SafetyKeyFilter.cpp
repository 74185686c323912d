#include "SafetyKeyFilter.h"
#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QTimer>
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

void SafetyKeyFilter::addButton(QAbstractButton* button, QAction* action)
{
    m_buttons.append({button, action});
}

bool SafetyKeyFilter::eventFilter(QObject*, QEvent* event)
{
    switch (event->type()) {
    case QEvent::ShortcutOverride:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
        return onKey(event);
    case QEvent::MouseButtonPress:
        if (QApplication::activePopupWidget())
            onPopupPress(static_cast<QMouseEvent*>(event));
        return false;
    default:
        return false;
    }
}

void SafetyKeyFilter::triggerOnce(int key, QAction* action)
{
    if (!action || m_handled.contains(key))
        return;
    m_handled.insert(key);
    // The release ends the press; should it never come, the next event-loop turn does.
    QTimer::singleShot(0, this, [this, key] { m_handled.remove(key); });
    action->trigger();
}

bool SafetyKeyFilter::onKey(QEvent* event)
{
    auto* key = static_cast<QKeyEvent*>(event);
    const bool escape = key->key() == Qt::Key_Escape;
    if (!escape && key->key() != Qt::Key_F1)
        return false;
    if (event->type() == QEvent::KeyRelease) {
        if (!key->isAutoRepeat())
            m_handled.remove(key->key());
        return !escape;
    }
    if (!key->isAutoRepeat())
        triggerOnce(key->key(), escape ? m_stop.data() : m_panic.data());
    if (event->type() == QEvent::ShortcutOverride) {
        // Accepted: no shortcut fires for this press, and the key goes on to the focus widget.
        event->accept();
        return true;
    }
    return !escape; // Esc still closes the dialog, popup or cell editor; F1 is ours
}

void SafetyKeyFilter::onPopupPress(QMouseEvent* event)
{
    if (m_clickHandled)
        return;
    const QPoint global = event->globalPosition().toPoint();
    QWidget* popup = QApplication::activePopupWidget();
    if (popup && popup->rect().contains(popup->mapFromGlobal(global)))
        return; // a click inside the popup itself
    for (const auto& [button, action] : std::as_const(m_buttons)) {
        if (!button || !action || !button->isVisible() || !button->isEnabled())
            continue;
        if (!button->rect().contains(button->mapFromGlobal(global)))
            continue;
        m_clickHandled = true; // once per press, whichever receiver sees it first
        QTimer::singleShot(0, this, [this] { m_clickHandled = false; });
        action->trigger();
        return;
    }
}

} // namespace stepdeck::ui
