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

public Q_SLOTS:
    // The machine the window runs now: Edit machine… edits it. Empty: none.
    void setCurrentMachine(const QString& path);
    void newMachine();
    void chooseMachineToOpen();
    void editMachine();
    // Remembers path as the most recent machine and asks the window to open it.
    void open(const QString& path);

Q_SIGNALS:
    void openRequested(const QString& path);

private:
    MachineEditor* showEditor(MachineEditor* editor);
    void rebuildRecentMenu();

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
};

} // namespace stepdeck::ui
