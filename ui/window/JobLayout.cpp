#include "JobLayout.h"
#include "MainWindowJogArea.h"
#include "Workspaces.h"
#include <QDockWidget>
#include <QMainWindow>
#include <QPushButton>

namespace stepdeck::ui {

using program::RunState;

JobLayout::JobLayout(QMainWindow* window, JogArea* jogArea, QDockWidget* programDock,
                     Workspaces* workspaces, QPushButton* toggle, QWidget* above)
    : QObject(window), m_window(window), m_jogArea(jogArea), m_programDock(programDock),
      m_workspaces(workspaces), m_toggle(toggle), m_above(above)
{
    m_toggle->setObjectName(QStringLiteral("jobJogPadToggle"));
    m_toggle->setFocusPolicy(Qt::NoFocus); // the arrows keep jogging
    connect(m_toggle, &QPushButton::clicked, this, [this] { showPad(!m_padShown); });
    // As wide as its longer text, so that it does not move when its text changes.
    int wide = 0;
    for (const bool shown : {false, true}) {
        m_padShown = shown;
        updateToggle();
        wide = qMax(wide, m_toggle->sizeHint().width());
    }
    m_padShown = false;
    m_toggle->setMinimumWidth(wide);
    updateToggle();
}

void JobLayout::setJob(RunState state)
{
    const bool job =
        state == RunState::Running || state == RunState::Paused || state == RunState::Stopping;
    if (job == m_active)
        return;
    if (job) {
        // A job started in the Setup workspace, or with the Program dock elsewhere (floating,
        // closed), leaves the layout alone: the operator arranged it so.
        if (m_workspaces->current() != Workspaces::Workspace::Run || !m_programDock ||
            !Workspaces::isOnScreen(m_programDock) || m_programDock->isFloating())
            return;
        m_active = true;
        m_padShown = false;
        m_dockHeightBefore = m_programDock->height();
        // With the pad's room gone the centre stands at its minimum, which would squeeze STOP's
        // row and the banner and move them under the operator's hand: they keep their height.
        m_above->setMinimumHeight(m_above->height());
        give();
    } else {
        m_active = false;
        m_above->setMinimumHeight(0);
        m_jogArea->setJobCollapsed(false);
        if (m_workspaces->current() == Workspaces::Workspace::Run)
            restoreDock();
    }
    updateToggle();
}

void JobLayout::showPad(bool shown)
{
    if (!m_active || shown == m_padShown)
        return;
    m_padShown = shown;
    if (shown) {
        m_jogArea->setJobCollapsed(false);
        restoreDock();
    } else {
        give();
    }
    updateToggle();
}

void JobLayout::give()
{
    m_jogArea->setJobCollapsed(true);
    // As high as the window lets it: resizeDocks stops at the centre's minimum (STOP, PANIC,
    // the banner and this button). Queued, as in restoreDock().
    QMetaObject::invokeMethod(
        this,
        [this] {
            if (m_programDock && m_active && !m_padShown)
                m_window->resizeDocks({m_programDock}, {m_window->height()}, Qt::Vertical);
        },
        Qt::QueuedConnection);
}

void JobLayout::restoreDock()
{
    // Once the centre's layout has the pad's minimum again (a posted layout request): sized at
    // once, the dock would keep the pad's room and the pad would scroll.
    QMetaObject::invokeMethod(
        this,
        [this] {
            if (m_programDock && isPadShown())
                m_window->resizeDocks({m_programDock}, {m_dockHeightBefore}, Qt::Vertical);
        },
        Qt::QueuedConnection);
}

void JobLayout::updateToggle()
{
    m_toggle->setVisible(m_active);
    m_toggle->setText(m_padShown ? tr("Hide jog pad") : tr("Show jog pad"));
    m_toggle->setToolTip(m_padShown
                             ? tr("Give the jog pad's room to the program's lines and toolpath "
                                  "until the job ends.")
                             : tr("The job has the jog pad's room. Show it to jog during a hold "
                                  "(a touch-off at a tool change); the keyboard jog works "
                                  "either way."));
}

} // namespace stepdeck::ui
