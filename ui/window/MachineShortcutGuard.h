#pragma once
#include <QList>
#include <QObject>
#include <QPointer>

class QAction;
class QKeyEvent;

namespace stepdeck::ui {

// Shortcuts that move the machine or change its link do not fire while a text field has the
// focus (issue 47, item 6: Ctrl+H typed into the program editor started Reference all, Ctrl+K
// disconnected). An operator typing G-code, an MDI line or a value has the hands on the keys
// for text, not for the machine: a slip of a modifier must not start motion or drop the link.
// The one place that decides it: installed on the application, this sees the ShortcutOverride
// Qt sends to the focus widget before any shortcut fires; for a registered action's key with a
// text field focused it accepts the override, which is Qt's own way of saying "this key is
// for the widget": no shortcut fires and the key goes on to the text field as a key press
// (Ctrl+K deletes to the end of the line there, Ctrl+H does nothing).
// STOP (Esc) and PANIC (F1) are never registered here: they work wherever the focus is
// (SafetyKeyFilter, rule 5), as does the feed hold (F2), which only stops. The actions stay
// usable from their menus and buttons; only their keys wait until the focus leaves the field.
class MachineShortcutGuard : public QObject
{
    Q_OBJECT
public:
    explicit MachineShortcutGuard(QObject* parent = nullptr);
    ~MachineShortcutGuard() override;

    // The action's shortcuts (read when a key arrives, so a later setShortcut counts too) no
    // longer fire from a text field.
    void add(QAction* action);
    bool guards(const QAction* action) const;

    // A widget that takes typed text has the focus: a line edit (a form's field, the MDI
    // line, an item view's cell editor), a spin box, a plain or rich text edit (the program
    // editor), an editable combo box. Read-only ones count too: the hands are on the text
    // either way. The same widgets pause the keyboard jog (KeyboardJog::textFieldHasFocus).
    static bool textFieldHasFocus();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool isGuardedKey(const QKeyEvent* key) const;

    QList<QPointer<QAction>> m_actions;
};

} // namespace stepdeck::ui
