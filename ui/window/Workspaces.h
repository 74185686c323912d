#pragma once
#include <QByteArray>
#include <QList>
#include <QObject>
#include <QStringList>

class QAction;
class QDockWidget;
class QMainWindow;
class QTabBar;

namespace stepdeck::ui {

class JogArea;

// The window's two workspaces (issue 31), as Candle's and UGS's tabs or AXIS's notebook:
// - Run: what a running job needs (the program with its preview, the position, the jog pad
//   and STOP/PANIC in the centre), the setup pages out of the way;
// - Setup: parameters, drives, records, input programs, the laser bridge, traffic, charts,
//   status and messages, each with room for its content.
// Each workspace is a layout of the window's docks (QMainWindow::saveState): its own default,
// and the operator's changes to it remembered while switching and across sessions
// (QSettings "window/workspace/run|setup"). The centre (STOP, PANIC, the banner, the jog
// pad) and the message line stay in both; the room the operator left the jog pad by dragging
// the separator below the centre (JogArea) is each workspace's too ("window/jogRoom/run|setup").
// Switching: the tab bar in the menu bar's corner, Ctrl+1 and Ctrl+2, or View > Run / Setup.
class Workspaces : public QObject
{
    Q_OBJECT
public:
    enum class Workspace { Run, Setup };

    // runDocks / setupDocks: the docks shown in each workspace's default layout (a dock may
    // be in both), by object name.
    Workspaces(QMainWindow* window, const QStringList& runDocks, const QStringList& setupDocks);

    Workspace current() const { return m_current; }
    bool chosenByHand() const { return m_byHand; }
    QTabBar* tabBar() const { return m_tabs; }
    QAction* action(Workspace workspace) const;
    // The centre's jog area, whose room each workspace keeps (before initialise()).
    void setJogArea(JogArea* area) { m_jogArea = area; }
    // Whether the dock shows in the current workspace's default layout.
    bool belongsToCurrent(QDockWidget* dock) const;

    // The default layouts, made once every dock exists and the window has its size; then the
    // remembered ones (settings), and the workspace the last session ended in.
    void initialise();
    void switchTo(Workspace workspace);
    // As switchTo, unless the operator chose a workspace by hand in this session (a program
    // opened brings up Run, issue 31).
    void suggest(Workspace workspace);
    void resetCurrent(); // the current workspace's default layout
    // Run: the read-out's and the program's docks grown where their page would scroll (a
    // machine of more axes was opened, longer German texts), referencing below the read-out
    // where the operator put it there (by default it is behind the read-out's tab).
    void fitContent();
    void save() const; // into the settings (at close)
    // Shown and not behind another dock's tab.
    static bool isOnScreen(const QDockWidget* dock);

Q_SIGNALS:
    void switched(stepdeck::ui::Workspaces::Workspace workspace);

private:
    void apply(Workspace workspace, const QByteArray& state, int jogRoom);
    void announce(); // the tabs, the actions and switched() for the current workspace
    QByteArray defaultLayout(Workspace workspace);
    // The default layout's dock sizes, as shares of the window's size now.
    void arrange(Workspace workspace);
    void setCorners(Workspace workspace);
    QDockWidget* dock(const QString& name) const;
    static int index(Workspace workspace) { return workspace == Workspace::Run ? 0 : 1; }

    QMainWindow* m_window;
    QStringList m_docks[2];
    QByteArray m_default[2];
    QByteArray m_state[2];
    int m_jogRoom[2] = {-1, -1}; // JogArea::room() of each workspace (-1: the whole pad)
    JogArea* m_jogArea = nullptr;
    Workspace m_current = Workspace::Setup;
    bool m_byHand = false;
    QTabBar* m_tabs;
    QAction* m_actions[2];
};

} // namespace stepdeck::ui
