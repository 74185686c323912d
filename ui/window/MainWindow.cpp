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
#include "window/JobLayout.h"
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
#include <QHBoxLayout>
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

MainWindow::MainWindow(GamepadDevice* gamepad, QWidget* parent)
    : QMainWindow(parent), m_context(new MachineContext(this)),
      m_jog(new JogController(m_context, this)), m_keyboard(new KeyboardJog(this, this)),
      m_connection(new ConnectionBar(m_context, this)), m_linkLabel(new QLabel(this)),
      m_messages(new StatusMessages(this)), m_messageLine(new MessageLine(m_messages, this))
{
    setObjectName(QStringLiteral("mainWindow"));
    // A click that closes a menu never reaches the window (a mis-click once fired PANIC).
    qApp->installEventFilter(new PopupClickGuard(this));
    m_jog->addSource(m_keyboard);
    if (!gamepad)
        gamepad = createSystemGamepadDevice(this);
    else if (!gamepad->parent())
        gamepad->setParent(this);
    m_gamepadSource = new GamepadJogSource(gamepad, this);
    m_gamepadSource->loadSettings();
    m_jog->addSource(m_gamepadSource);
    m_machineBar = new MachineBar(m_context, this);
    m_machineControl = new MachineControl(m_context, m_messages, this);
    buildActions();

    auto* toolbar = addToolBar(tr("Connection"));
    toolbar->setObjectName(QStringLiteral("connectionToolbar"));
    // One tool bar item holding both bars: the hidden one takes no room.
    auto* bars = new QWidget(toolbar);
    auto* barsLayout = new QHBoxLayout(bars);
    barsLayout->setContentsMargins(0, 0, 0, 0);
    barsLayout->addWidget(m_connection);
    barsLayout->addWidget(m_machineBar);
    toolbar->addWidget(bars);
    m_machineBar->setSingleControllerBar(m_connection);
    toolbar->setMovable(false);

    auto* central = new QWidget(this);
    auto* v = new QVBoxLayout(central);
    v->setContentsMargins(4, 4, 4, 4);
    m_safety = new SafetyBar(m_context, m_stopAction, m_panicAction, m_referenceAction, central);
    m_jogPanel = new JogPanel(m_context, m_jog, m_keyboard, central);
    // STOP works with one click even while a menu is open; PANIC does not: the click that
    // closes a menu must not throw the positions away (issue 31: a mis-click fired PANIC).
    // F1 panics whatever is open.
    m_safetyKeys->addButton(m_safety->stopButton(), m_stopAction);
    v->addWidget(m_safety);
    // The jog panel as high as it needs, unless the operator drags the Program dock's
    // separator up: then it scrolls below STOP, PANIC and the banner (issue 47 item 13).
    // During a job the pad's room is the program's; this brings it back by hand (JobLayout).
    m_jobPadToggle = new QPushButton(central);
    m_safety->addRowButton(m_jobPadToggle);
    m_jogArea = new JogArea(m_jogPanel, central);
    v->addWidget(m_jogArea, 1);
    setCentralWidget(central);

    buildDocks();
    buildMenus();

    m_linkLabel->setObjectName(QStringLiteral("linkState"));
    // One line whatever the message (elided, the full text in its tooltip and the log).
    statusBar()->addWidget(m_messageLine, 1);
    statusBar()->addPermanentWidget(m_linkLabel);
    connect(m_messageLine, &MessageLine::logRequested, this, [this] { raisePage(m_log); });

    ControllerSession* session = m_context->session();
    using Owner = StatusMessages::Owner;
    connect(session, &ControllerSession::linkStateChanged, this, &MainWindow::onLinkState);
    connect(session, &ControllerSession::errorOccurred, this,
            [this](const QString& text) { m_messages->show(Owner::Controller, text); });
    connect(session, &ControllerSession::requestFinished, this, &MainWindow::onResult);
    connect(session, &ControllerSession::jogRefused, this,
            [this](const QString& text) { m_messages->show(Owner::Jog, text); });
    connect(m_jog, &JogController::targetsChanged, this, [this](const SlotVelocities& t) {
        if (!t.isEmpty())
            m_messages->clear(Owner::Jog); // jogging works again
    });
    // A refusal whose cause has ended (the emergency stop was released) is no longer true.
    connect(m_jog, &JogController::refusalEnded, this, [this] { m_messages->clear(Owner::Jog); });
    connect(session, &ControllerSession::statusChanged, this, [this](const MachineStatus& s) {
        if (!s.panic)
            m_messages->clear(Owner::Safety);
    });
    connect(m_connection, &ConnectionBar::connectionFailed, this,
            [this](const QString& text) { m_messages->show(Owner::Link, text); });
    // Shown after the new link cleared the old link messages; it stays until it expires.
    connect(m_connection, &ConnectionBar::reconnected, this,
            [this](const QString& text) { m_messages->show(Owner::General, text); });
    connect(m_connection, &ConnectionBar::linkTextChanged, this,
            [this](const QString& text, bool warning) {
                m_linkLabel->setText(text);
                m_linkLabel->setStyleSheet(warning ? QStringLiteral("QLabel { color: #b26a00; "
                                                                    "font-weight: bold; }")
                                                   : QString());
            });
    connect(m_setup, &SetupPage::message, this, [this](const QString& text) {
        m_messages->show(Owner::Setup, text, StatusMessages::Severity::Info, 8000);
    });
    connect(m_context, &MachineContext::modelChanged, this, &MainWindow::updateTitle);
    connect(m_context, &MachineContext::machineChanged, this, &MainWindow::updateTitle);
    // One controller of the machine failed and the machine stopped the others: a held jog
    // input must not start them again (it counts as released until let go).
    connect(m_context, &MachineContext::machineControllerFailed, m_jogPanel, &JogPanel::releaseAll);
    connect(m_context, &MachineContext::modelChanged, this, &MainWindow::updateModelDocks);
    connect(m_jogPanel->keyboardCheck(), &QCheckBox::toggled, m_keyboardAction,
            &QAction::setChecked);

    // Fit the screen (issue 11): at most 1600x1000, never more than the screen offers.
    const QSize largest(1600, 1000);
    QSize size = largest;
    const QScreen* screen = QGuiApplication::primaryScreen();
    if (screen)
        size = size.boundedTo(screen->availableGeometry().size());
    resize(size);
    // Never grows past it by itself (issue 16), and once a window manager framed it, the frame
    // is on the screen too (ScreenBound).
    new ScreenBound(this);
    const QSettings settings;
    const QByteArray savedGeometry =
        settings.value(QStringLiteral("window/geometry")).toByteArray();
    const bool restored = !savedGeometry.isEmpty() && restoreGeometry(savedGeometry);
    // The first start (issue 47 item 13: the first --demo start opened a 1366x768 window whose
    // status bar was below a 768-px screen, the title bar on top of the screen's height): on a
    // screen no larger than that size, maximised, the window manager fitting the frame to the
    // screen's available geometry. Platforms without a window manager (offscreen, minimal:
    // the tests, screenshots) keep the size, which ScreenBound fits.
    if (!restored && screen && hasWindowManager() &&
        (screen->availableGeometry().width() <= largest.width() ||
         screen->availableGeometry().height() <= largest.height()))
        setWindowState(windowState() | Qt::WindowMaximized);
    onLinkState(LinkState::Disconnected, {});
    m_linkLabel->setText(m_connection->linkText());
    updateTitle();
    updateModelDocks();
    buildWorkspaces();
}

void MainWindow::buildWorkspaces()
{
    const QStringList run{QStringLiteral("positionDock"), QStringLiteral("referenceDock"),
                          QStringLiteral("programDock")};
    QStringList setup;
    for (QDockWidget* dock : std::as_const(m_docks))
        if (dock != dockOf(m_programPage))
            setup << dock->objectName();
    m_workspaces = new Workspaces(this, run, setup);
    m_workspaces->setJogArea(m_jogArea); // each workspace keeps the operator's room for it
    menuBar()->setCornerWidget(m_workspaces->tabBar(), Qt::TopRightCorner);
    QAction* first = m_viewMenu->actions().value(0);
    m_viewMenu->insertAction(first, m_workspaces->action(Workspaces::Workspace::Run));
    m_viewMenu->insertAction(first, m_workspaces->action(Workspaces::Workspace::Setup));
    m_viewMenu->insertSeparator(first);
    connect(m_workspaces, &Workspaces::switched, this, &MainWindow::updateModelDocks);
    // Once the panels have their rows for the machine's axes.
    connect(m_context, &MachineContext::machineChanged, m_workspaces, &Workspaces::fitContent,
            Qt::QueuedConnection);
    m_workspaces->initialise();
    m_jobLayout = new JobLayout(this, m_jogArea, dockOf(m_programPage), m_workspaces,
                                m_jobPadToggle, m_safety);
    connect(m_programPage, &ProgramPage::jobChanged, m_jobLayout,
            [this](program::RunState state) { m_jobLayout->setJob(state); });
    // A page that cannot have its room says so in the message line (issue 31), and the
    // message ends when everything fits again.
    m_fit = new WorkspaceFit(this);
    // The Setup workspace's forms and lists scroll up and down by nature (issue 47 item 13).
    m_fit->setSidewaysOnly(m_workspaces->current() == Workspaces::Workspace::Setup);
    connect(m_workspaces, &Workspaces::switched, m_fit, [this](Workspaces::Workspace workspace) {
        m_fit->setSidewaysOnly(workspace == Workspaces::Workspace::Setup);
    });
    connect(m_workspaces, &Workspaces::switched, m_fit, &WorkspaceFit::schedule);
    connect(m_context, &MachineContext::machineChanged, m_fit, &WorkspaceFit::schedule);
    connect(m_fit, &WorkspaceFit::fitRequested, m_workspaces, &Workspaces::fitContent);
    connect(m_fit, &WorkspaceFit::fitChanged, this, [this](const QString& text) {
        if (text.isEmpty())
            m_messages->clear(StatusMessages::Owner::Layout);
        else
            m_messages->show(StatusMessages::Owner::Layout, text, StatusMessages::Severity::Info);
    });
    // Run comes up when a program is opened, unless the operator chose a workspace by hand
    // (issue 31). Not when a reference run ends: that happens seconds after the click, while
    // the operator may reach for the jog pad, and nothing moves under the operator's hand.
    connect(m_programPage->files(), &ProgramFiles::loaded, this,
            [this] { m_workspaces->suggest(Workspaces::Workspace::Run); });
}

MainWindow::~MainWindow() = default;

void MainWindow::buildActions()
{
    m_stopAction = new QAction(tr("&Stop"), this);
    m_stopAction->setShortcut(QKeySequence(Qt::Key_Escape));
    m_stopAction->setShortcutContext(Qt::ApplicationShortcut);
    m_stopAction->setToolTip(tr("Ramped stop of all motion (Esc)"));
    connect(m_stopAction, &QAction::triggered, this, &MainWindow::stopAll);
    addAction(m_stopAction);

    m_panicAction = new QAction(tr("&Panic stop"), this);
    m_panicAction->setShortcut(QKeySequence(Qt::Key_F1));
    m_panicAction->setShortcutContext(Qt::ApplicationShortcut);
    m_panicAction->setToolTip(tr("Immediate stop without ramp (F1); positions are lost"));
    connect(m_panicAction, &QAction::triggered, this, &MainWindow::panicAll);
    addAction(m_panicAction);
    m_safetyKeys = new SafetyKeyFilter(m_stopAction, m_panicAction, this);

    m_referenceAction = new QAction(tr("&Reference all"), this);
    m_referenceAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_H));
    m_connectAction = new QAction(tr("&Connect / Disconnect"), this);
    m_connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    // Keys that start motion or drop the link are for the machine, not for a text field: typed
    // into the program editor or the MDI line they once started referencing or disconnected
    // (issue 47, item 6). STOP and PANIC above are not held back; the keyboard jog (Ctrl+J)
    // moves nothing itself and pauses in text fields on its own (KeyboardJog).
    m_machineKeys = new MachineShortcutGuard(this);
    m_machineKeys->add(m_referenceAction);
    m_machineKeys->add(m_connectAction);
    connect(m_connectAction, &QAction::triggered, this, [this] {
        if (m_context->hasMachineFile())
            m_machineBar->toggleConnection();
        else
            m_connection->toggleConnection();
    });
    m_resetAction = new QAction(tr("Reset &controller"), this);
    connect(m_resetAction, &QAction::triggered, this, [this] {
        m_jogPanel->releaseAll();
        m_context->reset();
    });
    m_keyboardAction = new QAction(tr("&Keyboard jog"), this);
    m_keyboardAction->setCheckable(true);
    m_keyboardAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_J));
    addAction(m_keyboardAction);
}

void MainWindow::buildDocks()
{
    m_position = new PositionPanel(m_context, this);
    m_reference = new ReferencePanel(m_context, this);
    m_status = new StatusPanel(m_context, this);
    m_setup = new SetupPage(m_context, this);
    m_console = new TrafficConsole(m_context, this);
    m_charts = new ChartsPanel(m_context, this);
    m_gamepad = new GamepadPanel(m_gamepadSource, m_jog->axisMap(), this);
    m_drivePanel = new DrivePanel(m_context, this);
    m_records = new RecordsPage(m_context, this);
    connect(m_referenceAction, &QAction::triggered, m_reference, &ReferencePanel::referenceAll);
    connect(m_keyboardAction, &QAction::toggled, m_jogPanel->keyboardCheck(),
            &QCheckBox::setChecked);

    addDock(m_position, tr("Position"), QStringLiteral("positionDock"), Qt::LeftDockWidgetArea);
    addDock(m_reference, tr("Referencing"), QStringLiteral("referenceDock"),
            Qt::LeftDockWidgetArea);
    QDockWidget* status =
        addDock(m_status, tr("Status"), QStringLiteral("statusDock"), Qt::RightDockWidgetArea);
    QDockWidget* pad =
        addDock(m_gamepad, tr("Gamepad"), QStringLiteral("gamepadDock"), Qt::RightDockWidgetArea);
    tabifyDockWidget(status, pad);
    m_drivesDock =
        addDock(m_drivePanel, tr("Drives"), QStringLiteral("drivesDock"), Qt::RightDockWidgetArea);
    tabifyDockWidget(pad, m_drivesDock);
    status->raise();
    QDockWidget* setup =
        addDock(m_setup, tr("Setup"), QStringLiteral("setupDock"), Qt::BottomDockWidgetArea);
    QDockWidget* traffic =
        addDock(m_console, tr("Traffic"), QStringLiteral("trafficDock"), Qt::BottomDockWidgetArea);
    QDockWidget* charts =
        addDock(m_charts, tr("Charts"), QStringLiteral("chartsDock"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(setup, traffic);
    tabifyDockWidget(traffic, charts);
    // Charts and the traffic view behind another tab are not redrawn (issues 10 and 21, idle
    // cost); they catch up when their tab comes on top.
    connect(charts, &QDockWidget::visibilityChanged, m_charts, &ChartsPanel::setOnScreen);
    connect(traffic, &QDockWidget::visibilityChanged, m_console, &TrafficConsole::setOnScreen);
    m_recordsDock =
        addDock(m_records, tr("Records"), QStringLiteral("recordsDock"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(charts, m_recordsDock);
    m_programs = new InputProgramsPage(m_context, this);
    m_programsDock = addDock(m_programs, tr("Input programs"), QStringLiteral("inputProgramsDock"),
                             Qt::BottomDockWidgetArea);
    tabifyDockWidget(m_recordsDock, m_programsDock);
    m_laserBridge = new LaserBridgePage(m_context, m_connection->portScanner(), this);
    tabifyDockWidget(m_recordsDock,
                     addDock(m_laserBridge, tr("Laser bridge"), QStringLiteral("laserBridgeDock"),
                             Qt::BottomDockWidgetArea));
    m_log = new MessageLog(m_messages, this);
    QDockWidget* log =
        addDock(m_log, tr("Messages"), QStringLiteral("messagesDock"), Qt::BottomDockWidgetArea);
    tabifyDockWidget(traffic, log);
    m_programPage = new ProgramPage(m_context, this);
    // A program's "(MSG, text)" on the message line, kept in the log (LinuxCNC shows it too).
    connect(m_programPage, &ProgramPage::operatorMessage, this,
            [this](int line, const QString& text) {
                m_messages->show(StatusMessages::Owner::General,
                                 tr("Program line %1: %2").arg(line).arg(text),
                                 StatusMessages::Severity::Info, 30000);
            });
    // A running program owns spindle and coolant: the Position dock's switches wait (issue 47).
    connect(m_programPage, &ProgramPage::programRunning, m_position->spindleCoolant(),
            &SpindleCoolantBar::setProgramRunning);
    connect(m_programPage, &ProgramPage::jobChanged, m_safety, &SafetyBar::setJob);
    connect(m_context->mdi(), &MachineMdi::operatorMessage, this, [this](int, const QString& text) {
        m_messages->show(StatusMessages::Owner::General, tr("MDI: %1").arg(text),
                         StatusMessages::Severity::Info, 30000);
    });
    tabifyDockWidget(setup, addDock(m_programPage, tr("Program"), QStringLiteral("programDock"),
                                    Qt::BottomDockWidgetArea));
    connect(log, &QDockWidget::visibilityChanged, m_messageLine, &MessageLine::setLogOnScreen);
    setup->raise();
    setDockNestingEnabled(true);
}

void MainWindow::stopAll()
{
    m_jogPanel->releaseAll();
    m_reference->stopped(tr("Referencing stopped."));
    // Every controller at once; sent, not confirmed: "stopped" follows only once each
    // reports standstill (MachineControl). The machine then tells whoever holds its motion (a
    // program, an MDI line, Go to; Machine::abortRequested) to end as aborted, not failed by
    // the stop it did not ask for: no list of them here.
    m_machineControl->stop();
}

void MainWindow::panicAll()
{
    m_jogPanel->releaseAll();
    // Every controller at once; the holder of the machine's motion aborts after it
    // (Machine::abortRequested), so that its own stop never goes ahead of the panic.
    m_machineControl->panic();
    m_reference->stopped(tr("Referencing stopped."));
}

void MainWindow::showError(const QString& message)
{
    m_messages->show(StatusMessages::Owner::General, message);
}

QString MainWindow::lastError() const
{
    return m_messages->currentText();
}

void MainWindow::onResult(const CommandResult& result)
{
    if (!result.ok() && result.error != ErrorKind::Cancelled)
        m_messages->show(StatusMessages::Owner::Request, result.message);
}

void MainWindow::onLinkState(LinkState state, const QString& reason)
{
    using Owner = StatusMessages::Owner;
    if (state != LinkState::Connected)
        m_jogPanel->releaseAll();
    if (state == LinkState::Connected) {
        // A new link: what the last one reported is over.
        for (Owner owner : {Owner::Link, Owner::Controller, Owner::Request, Owner::Jog})
            m_messages->clear(owner);
    } else if (!reason.isEmpty()) {
        m_messages->show(Owner::Link, reason);
    }
    updateTitle();
}

bool MainWindow::openMachine(const QString& path)
{
    m_jogPanel->releaseAll();
    return m_machineControl->open(path);
}

void MainWindow::closeMachine()
{
    m_jogPanel->releaseAll();
    m_reference->stopped(tr("Referencing stopped."));
    m_context->closeMachine(); // the machine's close aborts the holder of its motion
}

void MainWindow::updateTitle()
{
    if (m_context->hasMachineFile()) {
        setWindowTitle(m_machineControl->title());
        return;
    }
    const ModelInfo* model = m_context->model();
    QString title = QStringLiteral("StepDeck");
    if (model)
        title += QStringLiteral(" \u2014 ") + modelDisplayName(*model);
    if (m_context->isConnected()) {
        const QString port =
            m_context->portName() == QLatin1String("sim") ? tr("simulator") : m_context->portName();
        title += QStringLiteral(" @ ") + port;
    }
    setWindowTitle(title);
}

void MainWindow::resetLayout()
{
    m_workspaces->resetCurrent(); // its default, sized for the window now
    updateModelDocks();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    m_jogPanel->releaseAll();
    // Unsaved machine edits are not dropped with the window: the editor asks first.
    if (m_machineFiles && !m_machineFiles->closeEditorThen([this] {
            QMetaObject::invokeMethod(this, &QWidget::close, Qt::QueuedConnection);
        })) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    m_workspaces->save(); // each workspace's layout
    QMainWindow::closeEvent(event);
}

bool MainWindow::hasWindowManager()
{
    const QString platform = QGuiApplication::platformName();
    return platform != QLatin1String("offscreen") && platform != QLatin1String("minimal");
}

bool MainWindow::event(QEvent* event)
{
    const QEvent::Type type = event->type();
    const bool handled = QMainWindow::event(event);
    // A press the main window itself accepts is one on a dock separator (QMainWindow starts
    // moving it; elsewhere the press is ignored): while it is dragged the jog panel may give
    // its height to the Program dock, and the height it has at the release is kept (issue 47
    // item 13: the separator above the Program dock did not move, the centre's minimum held it).
    if (!m_jogArea)
        return handled;
    if (type == QEvent::MouseButtonPress && event->isAccepted() &&
        static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton)
        m_jogArea->beginDrag();
    else if (type == QEvent::MouseButtonRelease && m_jogArea->isDragged())
        m_jogArea->endDrag();
    return handled;
}

void MainWindow::changeEvent(QEvent* event)
{
    // Deactivating the window ends every jog at once: the key-up or mouse release would go to
    // another window and the axis would keep running until the lease expires.
    if (event->type() == QEvent::ActivationChange && !isActiveWindow()) {
        m_jogPanel->releaseAll();
        // Nor does a separator's drag see its release: it ends where it is.
        if (m_jogArea && m_jogArea->isDragged())
            m_jogArea->endDrag();
    }
    QMainWindow::changeEvent(event);
}

} // namespace stepdeck::ui
