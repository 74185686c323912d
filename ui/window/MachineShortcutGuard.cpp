#include "MachineShortcutGuard.h"
#include "common/TextFieldFocus.h"
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QKeySequence>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

namespace stepdeck::ui {

MachineShortcutGuard::MachineShortcutGuard(QObject* parent) : QObject(parent)
{
    qApp->installEventFilter(this);
}

MachineShortcutGuard::~MachineShortcutGuard()
{
    qApp->removeEventFilter(this);
}

void MachineShortcutGuard::add(QAction* action)
{
    if (action && !guards(action))
        m_actions.append(action);
}

bool MachineShortcutGuard::guards(const QAction* action) const
{
    for (const QPointer<QAction>& a : m_actions) {
        if (a && a.data() == action)
            return true;
    }
    return false;
}

bool MachineShortcutGuard::textFieldHasFocus()
{
    return ui::textFieldHasFocus();
}

bool MachineShortcutGuard::isGuardedKey(const QKeyEvent* key) const
{
    // A key on the number pad carries KeypadModifier; the shortcut map ignores it for the
    // match, so must this.
    Qt::KeyboardModifiers modifiers = key->modifiers();
    modifiers.setFlag(Qt::KeypadModifier, false);
    const QKeySequence pressed(QKeyCombination(modifiers, Qt::Key(key->key())));
    for (const QPointer<QAction>& a : m_actions) {
        if (!a)
            continue;
        for (const QKeySequence& shortcut : a->shortcuts()) {
            // A partial match is the first key of a longer shortcut: held back too, so the
            // shortcut map never starts on a sequence whose end would move the machine.
            if (!shortcut.isEmpty() && pressed.matches(shortcut) != QKeySequence::NoMatch)
                return true;
        }
    }
    return false;
}

bool MachineShortcutGuard::eventFilter(QObject*, QEvent* event)
{
    if (event->type() != QEvent::ShortcutOverride)
        return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (!isGuardedKey(key) || !textFieldHasFocus())
        return false;
    // Accepted: Qt fires no shortcut for this press and delivers it to the focus widget as a
    // key press, as for any key a text field claims for itself.
    event->accept();
    return true;
}

} // namespace stepdeck::ui
