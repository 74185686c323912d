#pragma once
#include "program/ProgramRunner.h"
#include <QObject>
#include <QPointer>

class QDockWidget;
class QMainWindow;
class QPushButton;

namespace stepdeck::ui {

class JogArea;
class Workspaces;

// The Run workspace while a program's job runs (issue 47 item 15): from its start to its end,
// holds included, the jog pad gives its room to the Program dock, so the toolpath, the running
// lines and the job's state (line, time left, hold, spindle) have the middle of the window; the
// pad matters when idle. At the job's end the layout is the operator's again (the jog pad's
// room and the Program dock's height as they were).
// Nothing moves under the operator's hand in between: the pad comes back during a job only by
// the operator's click on the centre's "Show jog pad" (a touch-off at M6 jogs Z), and goes again
// by "Hide jog pad". The keyboard jog and STOP/PANIC work either way. The Setup workspace and a
// job started there are left as they are.
class JobLayout : public QObject
{
    Q_OBJECT
public:
    // toggle: the centre's "Show jog pad" / "Hide jog pad" button, shown during a job only.
    // above: what stands above the jog pad in the centre (STOP, PANIC, the banner), kept at its
    // height during the job.
    JobLayout(QMainWindow* window, JogArea* jogArea, QDockWidget* programDock,
              Workspaces* workspaces, QPushButton* toggle, QWidget* above);

    // ProgramPage::jobChanged: Running, Paused and Stopping are a job; anything else ends it.
    void setJob(stepdeck::program::RunState state);
    bool isJobLayout() const { return m_active; }
    bool isPadShown() const { return !m_active || m_padShown; }
    void showPad(bool shown);

private:
    void give();        // the jog pad's room to the Program dock
    void restoreDock(); // the Program dock's height before the job
    void updateToggle();

    QMainWindow* m_window;
    JogArea* m_jogArea;
    QPointer<QDockWidget> m_programDock;
    Workspaces* m_workspaces;
    QPushButton* m_toggle;
    QWidget* m_above;
    bool m_active = false;
    bool m_padShown = false;
    int m_dockHeightBefore = 0; // the Program dock's height at the job's start
};

} // namespace stepdeck::ui
