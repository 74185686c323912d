#pragma once
#include <QList>
#include <QObject>
#include <QPointer>
#include <QSet>

class QAbstractButton;
class QAction;
class QKeyEvent;
class QMouseEvent;

namespace stepdeck::ui {

// Esc (STOP) and F1 (PANIC), application-wide, in every state of the window (issue 7,
// rule 5). Qt's own shortcuts are not enough: a cell editor of an item view accepts
// QEvent::ShortcutOverride for Esc (to cancel the edit), so the window's shortcut never
// fires there, and a modal dialog or a popup blocks the window's shortcuts. This filter sees
// every key event first: on the first ShortcutOverride or KeyPress of Esc/F1 it triggers the
// action, accepts the override (so the action's own shortcut does not fire a second time and
// the key goes on to the focus widget), and lets Esc continue to close the dialog, popup or
// editor as usual. F1 is consumed.
// While a popup (menu, combo box list) has the mouse, a press on a registered button (the
// window registers STOP only) triggers its action too: the popup would otherwise swallow it.
// Dialogs never block the buttons: they are non-modal (see common/Dialogs.h).
class SafetyKeyFilter : public QObject
{
    Q_OBJECT
public:
    SafetyKeyFilter(QAction* stop, QAction* panic, QObject* parent = nullptr);
    ~SafetyKeyFilter() override;

    void addButton(QAbstractButton* button, QAction* action);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool onKey(QEvent* event);
    void onPopupPress(QMouseEvent* event);
    // Triggers at most once per key press (the same press arrives as ShortcutOverride and
    // KeyPress, and once per receiver while it propagates).
    void triggerOnce(int key, QAction* action);

    QPointer<QAction> m_stop;
    QPointer<QAction> m_panic;
    QList<QPair<QPointer<QAbstractButton>, QPointer<QAction>>> m_buttons;
    QSet<int> m_handled;
    bool m_clickHandled = false;
};

} // namespace stepdeck::ui
