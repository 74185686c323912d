#pragma once
#include "controller/ControllerSession.h"
#include <QMainWindow>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QPushButton;

namespace stepdeck::ui {

class ChartsPanel;
class ConnectionBar;
class DrivePanel;
class GamepadDevice;
class GamepadJogSource;
class GamepadPanel;
class HelpMenu;
class InputProgramsPage;
class JobLayout;
class JogArea;
class JogController;
class JogPanel;
class KeyboardJog;
class LaserBridgePage;
class MachineBar;
class MachineContext;
class MachineControl;
class MachineFileActions;
class MachineShortcutGuard;
class MessageLine;
class MessageLog;
class PositionPanel;
class ProgramPage;
class RecordsPage;
class ReferencePanel;
class SafetyBar;
class SafetyKeyFilter;
class StatusMessages;
class SetupPage;
class StatusPanel;
class TrafficConsole;
class WorkspaceFit;
class Workspaces;

// The main window: connection bar, STOP/PANIC and the jog panel in the centre (always
// visible), and docks for position, referencing, status, setup, traffic and charts.
// Esc (STOP) and F1 (PANIC) are application-wide shortcuts: they work whatever has focus.
// The keys of actions that move the machine or change its link (Reference all, Connect /
// Disconnect, Quit) do nothing while a text field has the focus (MachineShortcutGuard).
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // gamepad: the physical jog device; nullptr = the system's (SDL2). Tests pass a fake.
    explicit MainWindow(GamepadDevice* gamepad = nullptr, QWidget* parent = nullptr);
    ~MainWindow() override;

    MachineContext* context() const { return m_context; }
    ConnectionBar* connectionBar() const { return m_connection; }
    // A machine of several controllers (issue 19), in the tool bar while one is open.
    MachineBar* machineBar() const { return m_machineBar; }
    MachineControl* machineControl() const { return m_machineControl; }
    SafetyBar* safetyBar() const { return m_safety; }
    JogPanel* jogPanel() const { return m_jogPanel; }
    // The jog panel's room in the centre: scrolls when the operator gave its height to the
    // Program dock (issue 47 item 13).
    JogArea* jogArea() const { return m_jogArea; }
    // While a job runs the Program dock has the jog pad's room (issue 47 item 15).
    JobLayout* jobLayout() const { return m_jobLayout; }
    HelpMenu* helpMenu() const { return m_helpMenu; }
    JogController* jogController() const { return m_jog; }
    KeyboardJog* keyboardJog() const { return m_keyboard; }
    PositionPanel* positionPanel() const { return m_position; }
    ReferencePanel* referencePanel() const { return m_reference; }
    StatusPanel* statusPanel() const { return m_status; }
    SetupPage* setupPage() const { return m_setup; }
    TrafficConsole* trafficConsole() const { return m_console; }
    ChartsPanel* chartsPanel() const { return m_charts; }
    GamepadPanel* gamepadPanel() const { return m_gamepad; }
    DrivePanel* drivePanel() const { return m_drivePanel; }
    RecordsPage* recordsPage() const { return m_records; }
    InputProgramsPage* inputProgramsPage() const { return m_programs; }
    ProgramPage* programPage() const { return m_programPage; } // motion programs (issue 20)
    LaserBridgePage* laserBridgePage() const { return m_laserBridge; }
    GamepadJogSource* gamepadSource() const { return m_gamepadSource; }
    QAction* stopAction() const { return m_stopAction; }
    QAction* panicAction() const { return m_panicAction; }
    QAction* referenceAction() const { return m_referenceAction; }
    QAction* connectAction() const { return m_connectAction; }
    // Holds the machine's keys back while a text field has the focus (issue 47, item 6).
    MachineShortcutGuard* machineShortcuts() const { return m_machineKeys; }
    // The status bar's current message (empty when its cause has ended or it expired).
    QString lastError() const;
    StatusMessages* messages() const { return m_messages; }
    MessageLine* messageLine() const { return m_messageLine; }
    MessageLog* messageLog() const { return m_log; }
    Workspaces* workspaces() const { return m_workspaces; } // Run and Setup (issue 31)
    WorkspaceFit* workspaceFit() const { return m_fit; }    // says when a page scrolls

    // Pages for --screenshot: a file stem and the page widget (the dock's content, or the
    // central jog panel).
    QList<QPair<QString, QWidget*>> pages() const;
    void raisePage(QWidget* page);
    QDockWidget* dockOf(QWidget* page) const;
    // For model pages added by other parts (e.g. a model's own page): a dock with the page in
    // a scroll area, tabbed with the dock of tabWith (if given), listed in the View menu.
    QDockWidget* addPage(QWidget* page, const QString& title, const QString& name,
                         Qt::DockWidgetArea area, QWidget* tabWith = nullptr);

public Q_SLOTS:
    // Opens the machine file (links not opened yet: Connect all); an invalid file is reported
    // in the message line naming the field, and nothing is opened. For File > Open machine
    // and `stepdeck --machine FILE`.
    bool openMachine(const QString& path);
    // Every controller of the machine stops and closes; the single-controller bar returns.
    void closeMachine();
    // The machine editor's Re-open machine (issue 31): the machine open now is closed and
    // opened again from path (its saved file), reconnected if it was connected, its positions
    // unknown until referenced as after any reconnect. Refused while anything moves or runs:
    // then the reason (also in the message line); empty when it was re-opened.
    QString reopenMachine(const QString& path);
    void stopAll();
    void panicAll();
    void showError(const QString& message);
    void resetLayout();

protected:
    bool event(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    // Whether the platform has a window manager that maximises (not offscreen or minimal).
    static bool hasWindowManager();
    void buildActions();
    void buildMenus();
    void connectMachineFiles(MachineFileActions* files);
    // Why the machine may not be replaced now (something moves, a program or run is under
    // way), or empty.
    QString machineBusyText() const;
    void buildDocks();
    QDockWidget* addDock(QWidget* widget, const QString& title, const QString& name,
                         Qt::DockWidgetArea area);
    static QWidget* pageOf(QDockWidget* dock);
    void buildWorkspaces();
    void updateTitle();
    void updateModelDocks(); // docks only some models have (drives, records)
    void onLinkState(LinkState state, const QString& reason);
    void onResult(const CommandResult& result);

    MachineContext* m_context;
    JogController* m_jog;
    KeyboardJog* m_keyboard;
    ConnectionBar* m_connection;
    MachineBar* m_machineBar = nullptr;
    MachineControl* m_machineControl = nullptr;
    MachineFileActions* m_machineFiles = nullptr;
    SafetyBar* m_safety = nullptr;
    SafetyKeyFilter* m_safetyKeys = nullptr;
    MachineShortcutGuard* m_machineKeys = nullptr;
    JogPanel* m_jogPanel = nullptr;
    JogArea* m_jogArea = nullptr;
    JobLayout* m_jobLayout = nullptr;
    QPushButton* m_jobPadToggle = nullptr;
    HelpMenu* m_helpMenu = nullptr;
    PositionPanel* m_position = nullptr;
    ReferencePanel* m_reference = nullptr;
    StatusPanel* m_status = nullptr;
    SetupPage* m_setup = nullptr;
    TrafficConsole* m_console = nullptr;
    ChartsPanel* m_charts = nullptr;
    GamepadPanel* m_gamepad = nullptr;
    DrivePanel* m_drivePanel = nullptr;
    RecordsPage* m_records = nullptr;
    LaserBridgePage* m_laserBridge = nullptr;
    QDockWidget* m_drivesDock = nullptr;
    QDockWidget* m_recordsDock = nullptr;
    InputProgramsPage* m_programs = nullptr;
    ProgramPage* m_programPage = nullptr;
    QDockWidget* m_programsDock = nullptr;
    GamepadJogSource* m_gamepadSource = nullptr;
    QList<QDockWidget*> m_docks;
    QMenu* m_viewMenu = nullptr;
    QAction* m_viewSeparator = nullptr;
    QAction* m_connectAction = nullptr;
    QAction* m_stopAction = nullptr;
    QAction* m_panicAction = nullptr;
    QAction* m_referenceAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_keyboardAction = nullptr;
    QLabel* m_linkLabel;
    StatusMessages* m_messages;
    MessageLine* m_messageLine;
    MessageLog* m_log = nullptr;
    WorkspaceFit* m_fit = nullptr;
    Workspaces* m_workspaces = nullptr;
};

} // namespace stepdeck::ui
