#pragma once
#include <QObject>
#include <QPointer>
#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace stepdeck::ui {

class MachineContext;
class MachineEditor;
class ToolTableDialog;

// The File menu's machine actions (issue 19): New machine…, Open machine…, Edit machine… and
// the Recent machines submenu (remembered in QSettings like the recent ports). Opening a
// machine is the window's business: this only emits openRequested(path). New and Edit open
// the machine editor, a window of its own (never modal); New starts from the controller that
// is connected now, if any.
class MachineFileActions : public QObject
{
    Q_OBJECT
public:
    MachineFileActions(MachineContext* context, QWidget* window);

    // Adds the actions and the submenu to menu.
    void addTo(QMenu* menu);
    QAction* newAction() const { return m_new; }
    QAction* openAction() const { return m_open; }
    QAction* editAction() const { return m_edit; }
    QAction* toolsAction() const { return m_tools; }
    QMenu* recentMenu() const { return m_recent; }
    // The editor window open now (nullptr: none).
    MachineEditor* editor() const;
    // The main window is closing: true when no editor holds unsaved changes (an open editor is
    // closed). Otherwise false: the editor comes to the front and asks first, and `then` runs
    // once it closed (saved or discarded); after Cancel nothing runs and the window stays.
    bool closeEditorThen(std::function<void()> then);
    // The file Edit machine… edits: the open machine's own file, else the one last opened here.
    QString currentMachine() const;
    // How the window re-opens its machine from the saved file (issue 31): empty when it did,
    // otherwise why not (something moves, a program runs). Unset: Re-open is refused.
    void setReopen(std::function<QString(const QString& path)> reopen)
    {
        m_reopenMachine = std::move(reopen);
    }

public Q_SLOTS:
    // The machine file last opened through these actions: Edit machine… edits it when the
    // window runs no machine file (currentMachine()). Empty: none.
    void setCurrentMachine(const QString& path);
    void newMachine();
    void chooseMachineToOpen();
    void editMachine();
    // Remembers path as the most recent machine and asks the window to open it.
    void open(const QString& path);

Q_SIGNALS:
    void openRequested(const QString& path);
    // The file of the machine the window runs was saved: text says it still runs on the
    // description it was opened with and how to re-open it.
    void openMachineSaved(const QString& text);

private:
    MachineEditor* showEditor(MachineEditor* editor);
    void rebuildRecentMenu();
    void onSaved(MachineEditor* editor, const QString& path);
    void reopen(MachineEditor* editor, const QString& path);

    MachineContext* m_context;
    QWidget* m_window;
    QAction* m_new;
    QAction* m_open;
    QAction* m_edit;
    QAction* m_tools;
    QMenu* m_recent;
    QString m_current;
    QPointer<MachineEditor> m_editor;
    QPointer<ToolTableDialog> m_toolDialog;
    std::function<QString(const QString&)> m_reopenMachine;
};

} // namespace stepdeck::ui
