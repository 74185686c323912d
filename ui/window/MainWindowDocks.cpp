// MainWindow, its docks and pages: making them, a page's dock, raising a page, and the docks
// a model cannot use.
#include "MainWindow.h"
#include "PopupClickGuard.h"
#include "bridge/LaserBridgePage.h"
#include "charts/ChartsPanel.h"
#include "common/ConnectionGate.h"
#include "common/Dialogs.h"
#include "connection/ConnectionBar.h"
#include "console/TrafficConsole.h"
#include "drives/DrivePanel.h"
#include "gamepad/GamepadDevice.h"
#include "gamepad/GamepadJogSource.h"
#include "gamepad/GamepadPanel.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/KeyboardJog.h"
#include "machine/MachineBar.h"
#include "machine/MachineContext.h"
#include "machine/MachineControl.h"
#include "machine/MachineFileActions.h"
#include "machine/MachineMdi.h"
#include "machine/SpindleCoolantBar.h"
#include "messages/MessageLine.h"
#include "messages/MessageLog.h"
#include "messages/StatusMessages.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "program/ProgramFiles.h"
#include "program/ProgramPage.h"
#include "programs/InputProgramsPage.h"
#include "records/RecordsPage.h"
#include "safety/SafetyBar.h"
#include "safety/SafetyKeyFilter.h"
#include "setup/SetupPage.h"
#include "status/StatusPanel.h"
#include "window/HelpMenu.h"
#include "window/MachineShortcutGuard.h"
#include "window/MainWindowJogArea.h"
#include "window/ScreenBound.h"
#include "window/SimulatorMenu.h"
#include "window/Translations.h"
#include "window/WorkspaceFit.h"
#include "window/Workspaces.h"
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QDateTime>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

namespace stepdeck::ui {

QDockWidget* MainWindow::addDock(QWidget* widget, const QString& title, const QString& name,
                                 Qt::DockWidgetArea area)
{
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    // A page scrolls instead of forcing its size on the window (issue 11: the window must
    // fit 1024x768; docks add up their minimum sizes otherwise).
    auto* scroll = new QScrollArea(dock);
    scroll->setObjectName(name + QStringLiteral("Scroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(widget);
    dock->setWidget(scroll);
    addDockWidget(area, dock);
    m_docks << dock;
    return dock;
}

QWidget* MainWindow::pageOf(QDockWidget* dock)
{
    auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
    return scroll ? scroll->widget() : dock->widget();
}

QDockWidget* MainWindow::dockOf(QWidget* page) const
{
    for (QDockWidget* dock : m_docks) {
        if (pageOf(dock) == page)
            return dock;
    }
    return nullptr;
}

QList<QPair<QString, QWidget*>> MainWindow::pages() const
{
    QList<QPair<QString, QWidget*>> out{{QStringLiteral("jog"), m_jogPanel}};
    for (QDockWidget* dock : m_docks) {
        if (!dock->toggleViewAction()->isVisible())
            continue; // a page this model does not have
        QString stem = dock->objectName();
        stem.chop(4); // "Dock"
        out.append({stem, pageOf(dock)});
    }
    return out;
}

void MainWindow::raisePage(QWidget* page)
{
    QDockWidget* dock = dockOf(page);
    if (!dock)
        return;
    // A page of the other workspace: that workspace comes up, with the page on top.
    if (m_workspaces && dock->isHidden() && !m_workspaces->belongsToCurrent(dock))
        m_workspaces->switchTo(m_workspaces->current() == Workspaces::Workspace::Run
                                   ? Workspaces::Workspace::Setup
                                   : Workspaces::Workspace::Run);
    dock->show();
    dock->raise();
}

QDockWidget* MainWindow::addPage(QWidget* page, const QString& title, const QString& name,
                                 Qt::DockWidgetArea area, QWidget* tabWith)
{
    QDockWidget* dock = addDock(page, title, name, area);
    if (QDockWidget* other = tabWith ? dockOf(tabWith) : nullptr)
        tabifyDockWidget(other, dock);
    m_viewMenu->insertAction(m_viewSeparator, dock->toggleViewAction());
    return dock;
}

void MainWindow::updateModelDocks()
{
    // A dock the model cannot use is hidden and leaves the View menu too.
    const Capabilities caps = m_context->capabilities();
    const QList<QPair<QDockWidget*, bool>> docks{{m_drivesDock, caps.multiDrive},
                                                 {m_recordsDock, caps.records},
                                                 {m_programsDock, caps.inputPrograms}};
    for (const auto& [dock, available] : docks) {
        const bool wasAvailable = dock->toggleViewAction()->isVisible();
        dock->toggleViewAction()->setVisible(available);
        if (!available)
            dock->hide();
        // A page the model brings shows where it belongs (the Setup workspace), once.
        else if (!wasAvailable && dock->isHidden() &&
                 (!m_workspaces || m_workspaces->belongsToCurrent(dock)))
            dock->show();
    }
}

} // namespace stepdeck::ui
