// MainWindow, its menus.
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

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    auto* machineFiles = new MachineFileActions(m_context, this);
    m_machineFiles = machineFiles;
    machineFiles->addTo(file);
    connectMachineFiles(machineFiles);
    file->addSeparator();
    file->addAction(m_connectAction);
    file->addSeparator();
    file->addAction(tr("&Load parameters\u2026"), m_setup, &SetupPage::load);
    file->addAction(tr("&Save parameters\u2026"), m_setup, &SetupPage::saveAs);
    file->addAction(tr("Save &traffic\u2026"), m_console, &TrafficConsole::saveAs);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    // Quitting closes every link (and ends a running program) like Disconnect does.
    m_machineKeys->add(quit);

    QMenu* machine = menuBar()->addMenu(tr("&Machine"));
    machine->addAction(m_stopAction);
    machine->addAction(m_panicAction);
    machine->addSeparator();
    machine->addAction(m_referenceAction);
    machine->addAction(m_keyboardAction);
    QAction* refresh = machine->addAction(tr("Refresh &status"), this,
                                          [this] { m_context->session()->refreshStatus(); });
    // Not held back in text fields: a status read changes nothing on the machine.
    refresh->setShortcut(QKeySequence::Refresh);
    // These need a connection; STOP and PANIC never are disabled (they say why instead).
    auto* gate = new ConnectionGate(m_context, this);
    for (QAction* a : {refresh, m_referenceAction, m_resetAction})
        gate->add(a);
    machine->addAction(m_resetAction);

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* dock : std::as_const(m_docks))
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewSeparator = m_viewMenu->addSeparator();
    m_viewMenu->addAction(tr("Reset &layout"), this, &MainWindow::resetLayout);
    QMenu* language = m_viewMenu->addMenu(tr("&Language"));
    auto* group = new QActionGroup(language);
    const QString current = translations::configured();
    QStringList codes{QString()};
    codes << translations::available();
    for (const QString& code : codes) {
        QAction* a = language->addAction(code.isEmpty() ? tr("System default")
                                                        : translations::languageName(code));
        a->setCheckable(true);
        a->setChecked(code == current);
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code] {
            translations::setConfigured(code);
            dialogs::message(this, QMessageBox::Information, tr("Language"),
                             tr("The language changes when StepDeck is started again."));
        });
    }

    menuBar()->addMenu(new SimulatorMenu(m_context, this));
    m_helpMenu = new HelpMenu(this, m_jogPanel, this);
    menuBar()->addMenu(m_helpMenu);
}

} // namespace stepdeck::ui
