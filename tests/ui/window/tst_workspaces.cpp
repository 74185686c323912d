// The Run and Setup workspaces (issue 31) on a 1366x768 laptop screen less a panel and a title
// bar (tst_workspaces_fullhd: the fit on a 1920x1080 screen), with a machine of two controllers
// and four axes (MachineWindowRig) and a program open: one click or key switches, each shows its
// docks, each remembers its layout (also across sessions), a program opened brings up Run
// unless the operator chose by hand, and the Run workspace fits: no scroll bar in its docks or
// the jog column and no text cut, in English and German. Issue 47 item 13: the first start's
// window and its frame are on the screen; the separator above the Program dock moves, and the
// toolpath can be made half the workspace's height, its legend beside or below it; the Setup
// workspace of a maximised Full HD window names no page as scrolling.
#include "../LaptopScreen.h"
#include "../LayoutChecks.h"
#include "../machine/MachineWindowRig.h"
#include "TestMain.h"
#include "connection/ConnectionBar.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "machine/MachineContext.h"
#include "messages/StatusMessages.h"
#include "program/ProgramControls.h"
#include "program/ProgramEditor.h"
#include "program/ProgramFiles.h"
#include "program/ProgramPage.h"
#include "program/ProgramPathView.h"
#include "program/ProgramPreviewView.h"
#include "safety/SafetyBar.h"
#include "window/JobLayout.h"
#include "window/MainWindowJogArea.h"
#include "window/Translations.h"
#include "window/WorkspaceFit.h"
#include "window/Workspaces.h"
#include <QComboBox>
#include <QDockWidget>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QStatusBar>
#include <QStyleOptionComboBox>
#include <QTabBar>

using namespace stepdeck;
using namespace stepdeck::test;
using Workspace = ui::Workspaces::Workspace;

// What a maximised window gets of the screen (issue 31): the height less a 24 px panel and a
// window manager's title bar (36 px, as GNOME's; Xfce's and KDE's are lower).
constexpr int kPanelAndTitleBar = 24 + 36;

class TestWorkspaces : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }
    void firstStart_setup_thenKeysAndTabsSwitch();
    void layout_rememberedPerWorkspaceAndAcrossSessions();
    void programOpened_bringsUpRun_unlessChosenByHand();
    void run_onTheScreen_noScrollBarNoTextCut_data();
    void run_onTheScreen_noScrollBarNoTextCut();
    void run_windowTooSmall_saysWhichPagesScroll();
    void run_separatorDragged_toolpathHalfTheWorkspace();
    void setup_fullHdMaximised_noPageSaidToScroll();
    void setup_sidePages_noSidewaysScroll_data();
    void setup_sidePages_noSidewaysScroll();
    void connectionBar_modelNamesInFull_data();
    void connectionBar_modelNamesInFull();

private:
    ui::MainWindow* window() const { return m_rig.window(); }
    ui::Workspaces* workspaces() const { return window()->workspaces(); }
    QDockWidget* dock(const char* name) const
    {
        return window()->findChild<QDockWidget*>(QLatin1String(name));
    }
    bool shown(const char* name) const { return dock(name) && dock(name)->isVisible(); }
    bool onScreen(const char* name) const { return ui::Workspaces::isOnScreen(dock(name)); }
    QString programFile(const QString& text) const
    {
        return m_rig.writeFile(text.toUtf8(), QStringLiteral("job.ngc"));
    }
    // A pocket's outline (relative: the rotary axis is not referenced) and a turn of A.
    static QString pocketProgram()
    {
        return QStringLiteral(
            "(Pocket outline, in the style of a CAM post)\nG21 G91 G17\nM3 S500\nG0 Z2\n"
            "G0 X5 Y5\nG1 Z-3 F6\nG1 X3\nG2 X3 Y3 I0 J3\nG1 X-6\nG1 Y-3\nG0 Z3\nG0 A90\n"
            "M2\n");
    }
    static QString rectText(const QRect& r)
    {
        return QStringLiteral("%1,%2 %3x%4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height());
    }
    // Docks of the window whose page scrolls, "name: w x h in w x h".
    QStringList scrollingDocks() const
    {
        QStringList out;
        for (QDockWidget* d : window()->findChildren<QDockWidget*>()) {
            auto* area = qobject_cast<QScrollArea*>(d->widget());
            if (!ui::Workspaces::isOnScreen(d) || !area)
                continue;
            if (area->verticalScrollBar()->isVisible() || area->horizontalScrollBar()->isVisible())
                out << QStringLiteral("%1: %2x%3 in %4x%5")
                           .arg(d->objectName())
                           .arg(area->widget()->minimumSizeHint().width())
                           .arg(area->widget()->minimumSizeHint().height())
                           .arg(area->viewport()->width())
                           .arg(area->viewport()->height());
        }
        return out;
    }
    // The rows "en" and "de" of a test that runs in both languages.
    static void addLanguageRows()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("de") << QStringLiteral("de");
    }
    // The window built again in that language (its texts are set when it is made), shown.
    bool showIn(const QString& language)
    {
        ui::translations::install(qApp, language);
        m_rig.f = std::make_unique<UiFixture>();
        window()->show();
        return QTest::qWaitForWindowActive(window());
    }
    void saveShot(const QString& name) const
    {
        const QByteArray dir = qgetenv("STEPDECK_SHOT_DIR");
        if (!dir.isEmpty())
            window()->grab().save(QString::fromLocal8Bit(dir) + QLatin1Char('/') + name);
    }

    MachineWindowRig m_rig;
};

void TestWorkspaces::firstStart_setup_thenKeysAndTabsSwitch()
{
    // The first start (no geometry saved): the window, its frame and its status bar on the
    // screen's available geometry (issue 47 item 13: the status bar was below the screen).
    const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
    QVERIFY2(available.contains(window()->frameGeometry()),
             qPrintable(rectText(window()->frameGeometry()) + QStringLiteral(" on ") +
                        rectText(available)));
    QStatusBar* statusBar = window()->statusBar();
    QVERIFY2(available.contains(QRect(statusBar->mapToGlobal(QPoint()), statusBar->size())),
             qPrintable(rectText(QRect(statusBar->mapToGlobal(QPoint()), statusBar->size()))));
    // Nothing referenced, no program: the setup pages (where a new machine starts).
    QCOMPARE(workspaces()->current(), Workspace::Setup);
    QVERIFY(shown("setupDock"));
    QVERIFY(!shown("programDock"));
    QTest::keyClick(window(), Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(workspaces()->current(), Workspace::Run);
    QCOMPARE(workspaces()->tabBar()->currentIndex(), 0);
    for (const char* name : {"programDock", "positionDock", "referenceDock"})
        QVERIFY2(shown(name), name);
    // Referencing below the position on a Full HD screen; lower, behind the position's tab,
    // one click away.
    QVERIFY(onScreen("positionDock"));
    if (window()->height() >= 900) {
        QVERIFY(onScreen("referenceDock"));
        QVERIFY(window()->tabifiedDockWidgets(dock("positionDock")).isEmpty());
    } else {
        QVERIFY(!onScreen("referenceDock"));
        QCOMPARE(window()->tabifiedDockWidgets(dock("positionDock")),
                 QList<QDockWidget*>{dock("referenceDock")});
        dock("referenceDock")->raise();
        QTRY_VERIFY(onScreen("referenceDock"));
        QVERIFY(!onScreen("positionDock"));
        dock("positionDock")->raise();
    }
    for (const char* name : {"setupDock", "trafficDock", "chartsDock", "statusDock"})
        QVERIFY2(!shown(name), name);
    // The tab bar in the menu bar's corner: one click.
    QTabBar* tabs = workspaces()->tabBar();
    QVERIFY(tabs->isVisible());
    QTest::mouseClick(tabs, Qt::LeftButton, {}, tabs->tabRect(1).center());
    QCOMPARE(workspaces()->current(), Workspace::Setup);
    QVERIFY(shown("setupDock"));
    QVERIFY(!shown("programDock"));
    QTest::keyClick(window(), Qt::Key_1, Qt::ControlModifier);
    QTest::keyClick(window(), Qt::Key_2, Qt::ControlModifier);
    QCOMPARE(workspaces()->current(), Workspace::Setup);
}

void TestWorkspaces::layout_rememberedPerWorkspaceAndAcrossSessions()
{
    workspaces()->switchTo(Workspace::Run);
    // The operator's changes to Run: the program's dock made higher, referencing closed.
    const int programHeight = dock("programDock")->height() + 40;
    window()->resizeDocks({dock("programDock")}, {programHeight}, Qt::Vertical);
    QCoreApplication::processEvents();
    QCOMPARE(dock("programDock")->height(), programHeight);
    dock("referenceDock")->hide();
    workspaces()->switchTo(Workspace::Setup);
    QVERIFY(shown("referenceDock")); // Setup's own layout
    dock("chartsDock")->raise();
    workspaces()->switchTo(Workspace::Run);
    QVERIFY(!shown("referenceDock"));
    QVERIFY(shown("programDock"));
    QCoreApplication::processEvents(); // the fit after a switch (queued) grows, never shrinks
    QCOMPARE(dock("programDock")->height(), programHeight);
    // Another session: the window opens in the workspace it closed in, each as it was left.
    window()->close();
    m_rig.f = std::make_unique<UiFixture>();
    window()->show();
    QVERIFY(QTest::qWaitForWindowActive(window()));
    QCOMPARE(workspaces()->current(), Workspace::Run);
    QVERIFY(!shown("referenceDock"));
    QVERIFY(shown("programDock"));
    workspaces()->switchTo(Workspace::Setup);
    QVERIFY(shown("referenceDock"));
    QVERIFY(!shown("programDock"));
    // View > Reset layout: the current workspace's default.
    window()->resetLayout();
    QVERIFY(shown("setupDock"));
    workspaces()->switchTo(Workspace::Run);
    window()->resetLayout();
    QVERIFY(shown("referenceDock"));
}

void TestWorkspaces::programOpened_bringsUpRun_unlessChosenByHand()
{
    QVERIFY(window()->programPage()->files()->load(programFile(QStringLiteral("G0 X1\nM2\n"))));
    QCOMPARE(workspaces()->current(), Workspace::Run);
    QVERIFY(shown("programDock"));
    // Chosen by hand: the next program does not take the workspace away.
    QTest::keyClick(window(), Qt::Key_2, Qt::ControlModifier);
    QVERIFY(window()->programPage()->files()->load(programFile(QStringLiteral("G0 X2\nM2\n"))));
    QCOMPARE(workspaces()->current(), Workspace::Setup);
}

void TestWorkspaces::run_onTheScreen_noScrollBarNoTextCut_data()
{
    addLanguageRows();
}

void TestWorkspaces::run_onTheScreen_noScrollBarNoTextCut()
{
    QFETCH(QString, language);
    QVERIFY(showIn(language));
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable()); // an arc needs its plane's positions known
    QVERIFY(window()->programPage()->files()->load(programFile(pocketProgram())));
    QCOMPARE(workspaces()->current(), Workspace::Run);
    QTRY_VERIFY(!window()->programPage()->isChecking());
    // The layout settles (the read-out's height follows the machine's axes, queued).
    QTRY_VERIFY2(scrollingDocks().isEmpty(),
                 qPrintable(scrollingDocks().join(QStringLiteral("; "))));
    // The centre too: the jog controls beside the pads (in two columns where one does not fit).
    auto* side =
        window()->centralWidget()->findChild<QScrollArea*>(QStringLiteral("jogSideScroll"));
    QVERIFY(side);
    QTRY_VERIFY2(!side->verticalScrollBar()->isVisible(),
                 qPrintable(QStringLiteral("jog side %1 high (%2 at its width) in %3")
                                .arg(side->widget()->minimumSizeHint().height())
                                .arg(side->widget()->heightForWidth(side->viewport()->width()))
                                .arg(side->viewport()->height())));
    // The jog pad whole below STOP, PANIC and the banner (it scrolls only where the operator
    // gives its height to the Program dock, issue 47 item 13).
    ui::JogArea* jog = window()->jogArea();
    QVERIFY(!jog->isShortByChoice());
    QTRY_VERIFY2(!jog->verticalScrollBar()->isVisible() && !jog->horizontalScrollBar()->isVisible(),
                 qPrintable(QStringLiteral("jog pad %1 high in %2")
                                .arg(jog->neededHeight())
                                .arg(jog->viewport()->height())));
    // The toolpath's legend has a room of its own (issue 47 item 13: it covered the drawing).
    ui::ProgramPathView* path = window()->programPage()->preview()->pathView();
    const QRect legendIdle = path->legendRect();
    const QRect drawingIdle = path->drawingRect();
    QVERIFY2(!legendIdle.intersects(drawingIdle),
             qPrintable(rectText(legendIdle) + QStringLiteral(" over ") + rectText(drawingIdle)));
    // Named by the screen the window is on (less its panel and title bar).
    const QSize screen = QGuiApplication::primaryScreen()->size();
    saveShot(QStringLiteral("run-%1x%2%3.png")
                 .arg(screen.width())
                 .arg(screen.height() + kPanelAndTitleBar)
                 .arg(language == QLatin1String("en") ? QString() : QLatin1Char('-') + language));
    QStringList cut;
    for (const char* name : {"positionDock", "referenceDock", "programDock"})
        cut += clippedTexts(dock(name));
    cut += clippedTexts(window()->centralWidget());
    QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QStringLiteral("; "))));
    // Issue 47: the same workspace while the job runs (the banner names the run and its line,
    // the spindle is on), then STOP.
    ui::ProgramPage* page = window()->programPage();
    const int programIdle = dock("programDock")->height();
    const int workspaceHeight = window()->centralWidget()->height() + programIdle;
    QTRY_VERIFY(page->controls()->runButton()->isEnabled());
    page->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(page->runner() &&
                                 page->runner()->state() == program::RunState::Running &&
                                 page->runner()->currentLine() >= 5 && m_rig.elab->moving(Axis::Z),
                             20000);
    QTRY_VERIFY(window()->safetyBar()->bannerSeverity() == QLatin1String("job"));
    // Issue 47 item 15: the job has the jog pad's room. The toolpath is at least half the Run
    // workspace's height (the centre and the Program dock below it), its legend still beside it.
    QVERIFY(window()->jobLayout()->isJobLayout());
    QVERIFY(!window()->jobLayout()->isPadShown());
    QTRY_VERIFY2(
        path->height() * 2 >= workspaceHeight,
        qPrintable(
            QStringLiteral("toolpath %1 high of %2").arg(path->height()).arg(workspaceHeight)));
    QVERIFY(!path->legendRect().intersects(path->drawingRect()));
    saveShot(QStringLiteral("run-%1x%2-running%3.png")
                 .arg(screen.width())
                 .arg(screen.height() + kPanelAndTitleBar)
                 .arg(language == QLatin1String("en") ? QString() : QLatin1Char('-') + language));
    // The pad comes back only by the operator's hand (a touch-off during a hold), and goes again.
    auto* toggle = window()->findChild<QPushButton*>(QStringLiteral("jobJogPadToggle"));
    QVERIFY(toggle && toggle->isVisible());
    auto place = [this](QWidget* w) { return QRect(w->mapTo(window(), QPoint()), w->size()); };
    const QRect stopPlace = place(window()->safetyBar()->stopButton());
    const QRect togglePlace = place(toggle);
    toggle->click();
    QVERIFY(window()->jobLayout()->isPadShown());
    QTRY_VERIFY(!jog->isShortByChoice() && !jog->verticalScrollBar()->isVisible());
    // STOP and the button stay where the operator's hand is.
    QCOMPARE(place(window()->safetyBar()->stopButton()), stopPlace);
    QCOMPARE(place(toggle).topLeft(), togglePlace.topLeft());
    toggle->click();
    QTRY_VERIFY(path->height() * 2 >= workspaceHeight);
    window()->safetyBar()->stopButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(!page->isRunning(), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
    // The job over, the layout is the operator's again: the whole pad, the dock as it was.
    QTRY_VERIFY(!window()->jobLayout()->isJobLayout());
    QVERIFY(!toggle->isVisible());
    QTRY_COMPARE(dock("programDock")->height(), programIdle);
    QVERIFY(!jog->isShortByChoice());
    ui::translations::install(qApp, QStringLiteral("en"));
}

// "A layout that cannot fit says so instead of clipping" (issue 31): made smaller than its
// pages need, the window names the pages that scroll in the message line; given the room
// again, the docks take it back and the message ends.
void TestWorkspaces::run_windowTooSmall_saysWhichPagesScroll()
{
    window()->show();
    QVERIFY(QTest::qWaitForWindowActive(window()));
    QVERIFY(m_rig.openAndConnect());
    workspaces()->switchTo(Workspace::Run);
    QTRY_VERIFY2(scrollingDocks().isEmpty(), qPrintable(scrollingDocks().join(u';')));
    ui::WorkspaceFit* fit = window()->workspaceFit();
    QTRY_VERIFY(fit->lastReported().isEmpty());
    QSignalSpy said(fit, &ui::WorkspaceFit::fitChanged);
    // The notice never covers a message about the machine ("Machine opened", a stop); here
    // nothing else is said.
    window()->messages()->clearAll();
    const QSize full = window()->size();
    window()->resize(full.width(), full.height() * 2 / 3);
    // Which pages give way first depends on the docks' minimum sizes: whichever scroll, the
    // message names each of them.
    QTRY_VERIFY(!fit->lastReported().isEmpty());
    for (QDockWidget* d : window()->findChildren<QDockWidget*>()) {
        auto* area = qobject_cast<QScrollArea*>(d->widget());
        if (area && fit->lastReported().contains(d->windowTitle()))
            QVERIFY2(area->verticalScrollBar()->isVisible() ||
                         area->horizontalScrollBar()->isVisible(),
                     qPrintable(d->windowTitle())); // named, and it does scroll
    }
    QVERIFY(!said.isEmpty());
    const QString text = said.constLast().at(0).toString();
    for (const QString& page : fit->lastReported())
        QVERIFY2(text.contains(page), qPrintable(text));
    QCOMPARE(window()->messages()->currentText(), text);
    window()->resize(full);
    QTRY_VERIFY(fit->lastReported().isEmpty());
    QCOMPARE(said.constLast().at(0).toString(), QString());
    QVERIFY2(window()->messages()->currentText() != text,
             qPrintable(window()->messages()->currentText()));
}

// Issue 47 item 13: "the splitter above the Program dock does not move" (the centre's minimum,
// the jog pad's, held it) and the toolpath was about 150 px high at 1366x768. Dragged up as far
// as it goes, the separator gives the toolpath at least half the Run workspace's height (from
// the tool bar to the status bar); STOP, PANIC and the banner stay whole, the jog pad scrolls up
// and down below them (no "too small" for a room the operator chose), the legend keeps its own
// room, the room stays the workspace's across a switch, and Reset layout gives the jog pad its
// height back.
void TestWorkspaces::run_separatorDragged_toolpathHalfTheWorkspace()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable());
    QVERIFY(window()->programPage()->files()->load(programFile(pocketProgram())));
    QCOMPARE(workspaces()->current(), Workspace::Run);
    QTRY_VERIFY(!window()->programPage()->isChecking());
    QTRY_VERIFY2(scrollingDocks().isEmpty(), qPrintable(scrollingDocks().join(u';')));
    ui::JogArea* jog = window()->jogArea();
    QTRY_VERIFY(!jog->verticalScrollBar()->isVisible());
    QWidget* centre = window()->centralWidget();
    QDockWidget* program = dock("programDock");
    ui::ProgramPathView* path = window()->programPage()->preview()->pathView();
    const int workspace = window()->statusBar()->geometry().top() - centre->geometry().top();
    const int before = path->height();

    // The separator between the centre and the Program dock, pressed and dragged up to the top
    // of the centre (it stops where STOP, PANIC and the banner need their room).
    const QRect centreRect = centre->geometry();
    const QPoint grip(centreRect.center().x(),
                      (centreRect.bottom() + program->geometry().top()) / 2);
    QTest::mousePress(window(), Qt::LeftButton, Qt::NoModifier, grip);
    QVERIFY2(jog->isDragged(), qPrintable(QStringLiteral("no separator at %1,%2 (centre %3, "
                                                         "program %4)")
                                              .arg(grip.x())
                                              .arg(grip.y())
                                              .arg(rectText(centreRect))
                                              .arg(rectText(program->geometry()))));
    const QPoint top(grip.x(), centreRect.top() + 10);
    QTest::mouseMove(window(), QPoint(grip.x(), (grip.y() + top.y()) / 2));
    QTest::qWait(50); // QMainWindow moves the separator on a timer
    QTest::mouseMove(window(), top);
    QTest::qWait(50);
    QTest::mouseRelease(window(), Qt::LeftButton, Qt::NoModifier, top);
    QVERIFY(!jog->isDragged());
    QTRY_VERIFY2(path->height() >= workspace / 2,
                 qPrintable(QStringLiteral("the toolpath %1 px high (%2 before) in a workspace "
                                           "%3 px high")
                                .arg(path->height())
                                .arg(before)
                                .arg(workspace)));
    QVERIFY(jog->isShortByChoice());
    // STOP, PANIC and the banner whole; the jog pad never scrolls sideways.
    for (QWidget* w : {static_cast<QWidget*>(window()->safetyBar()->stopButton()),
                       static_cast<QWidget*>(window()->safetyBar()->panicButton()),
                       window()->findChild<QWidget*>(QStringLiteral("safetyBanner"))}) {
        QVERIFY(w);
        QVERIFY2(w->visibleRegion().boundingRect() == w->rect(),
                 qPrintable(w->objectName() + QStringLiteral(": ") +
                            rectText(w->visibleRegion().boundingRect())));
    }
    QVERIFY(!jog->horizontalScrollBar()->isVisible());
    // The legend in its room beside or below the drawing, the path in the rest.
    QVERIFY(!path->legendRect().isEmpty());
    QVERIFY2(!path->legendRect().intersects(path->drawingRect()),
             qPrintable(rectText(path->legendRect()) + QStringLiteral(" over ") +
                        rectText(path->drawingRect())));
    for (const QPointF& p : path->points())
        QVERIFY2(path->drawingRect().contains(path->toWidget(p).toPoint()),
                 qPrintable(QStringLiteral("%1, %2 outside %3")
                                .arg(path->toWidget(p).x())
                                .arg(path->toWidget(p).y())
                                .arg(rectText(path->drawingRect()))));
    // The operator chose the jog pad's room: no page is said to scroll.
    ui::WorkspaceFit* fit = window()->workspaceFit();
    fit->schedule();
    QTest::qWait(500); // the fit looks twice, once the layout settled
    QVERIFY2(fit->scrollingPages().isEmpty(), qPrintable(fit->scrollingPages().join(u',')));
    // The room stays Run's across a switch.
    const int dragged = path->height();
    workspaces()->switchTo(Workspace::Setup);
    QVERIFY(!jog->isShortByChoice()); // Setup's own: the whole jog pad
    workspaces()->switchTo(Workspace::Run);
    QVERIFY(jog->isShortByChoice());
    QTRY_COMPARE(path->height(), dragged);
    // Reset layout: the jog pad whole again.
    window()->resetLayout();
    QVERIFY(!jog->isShortByChoice());
    QTRY_VERIFY(!jog->verticalScrollBar()->isVisible());
    QTRY_VERIFY(path->height() < dragged);
}

// Issue 47 item 13: the Setup workspace said "The window is too small for these pages, they
// scroll" even maximised at 1920x1080: its forms and lists (every axis' parameters, referencing,
// the status lamps) scroll up and down by nature. There only a page that scrolls sideways is
// named (WorkspaceFit::setSidewaysOnly), and at Full HD none does.
void TestWorkspaces::setup_fullHdMaximised_noPageSaidToScroll()
{
    if (QGuiApplication::primaryScreen()->availableGeometry().width() < 1920)
        QSKIP("on the Full HD screen (tst_workspaces_fullhd)");
    window()->showMaximized();
    QTRY_VERIFY(window()->isMaximized());
    QVERIFY(m_rig.openAndConnect());
    workspaces()->switchTo(Workspace::Setup);
    ui::WorkspaceFit* fit = window()->workspaceFit();
    QVERIFY(fit->sidewaysOnly());
    fit->schedule();
    QTest::qWait(500); // the fit looks twice, once the layout settled
    QVERIFY2(fit->scrollingPages().isEmpty(), qPrintable(fit->scrollingPages().join(u',')));
    QVERIFY2(fit->lastReported().isEmpty(), qPrintable(fit->lastReported().join(u',')));
    QVERIFY2(!window()->messages()->currentText().contains(QStringLiteral("too small")),
             qPrintable(window()->messages()->currentText()));
    // Run counts every page again.
    workspaces()->switchTo(Workspace::Run);
    QVERIFY(!fit->sidewaysOnly());
}

void TestWorkspaces::setup_sidePages_noSidewaysScroll_data()
{
    addLanguageRows();
}

// Issue 31 finding: the Gamepad page needed a horizontal scroll bar in German. The Setup
// workspace's side pages (gamepad, status) scroll at most vertically.
void TestWorkspaces::setup_sidePages_noSidewaysScroll()
{
    QFETCH(QString, language);
    QVERIFY(showIn(language));
    QVERIFY(m_rig.openAndConnect());
    workspaces()->switchTo(Workspace::Setup);
    for (const char* name : {"gamepadDock", "statusDock"}) {
        QDockWidget* d = dock(name);
        QVERIFY2(d, name);
        d->raise();
        QTRY_VERIFY2(onScreen(name), name);
        auto* area = qobject_cast<QScrollArea*>(d->widget());
        QVERIFY2(area, name);
        QTRY_VERIFY2(!area->horizontalScrollBar()->isVisible(),
                     qPrintable(QStringLiteral("%1: %2 wide in %3")
                                    .arg(QLatin1String(name))
                                    .arg(area->widget()->minimumSizeHint().width())
                                    .arg(area->viewport()->width())));
    }
    ui::translations::install(qApp, QStringLiteral("en"));
}

void TestWorkspaces::connectionBar_modelNamesInFull_data()
{
    addLanguageRows();
}

// Issue 31 finding: the model combo was clipped in German. Every model's name shows in full
// in the tool bar of the window on the laptop screen.
void TestWorkspaces::connectionBar_modelNamesInFull()
{
    QFETCH(QString, language);
    QVERIFY(showIn(language));
    QComboBox* combo = window()->connectionBar()->modelCombo();
    QTRY_VERIFY(combo->isVisible());
    for (int i = 0; i < combo->count(); ++i) {
        combo->setCurrentIndex(i);
        QCoreApplication::processEvents();
        QStyleOptionComboBox option;
        option.initFrom(combo);
        const QRect text = combo->style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                          QStyle::SC_ComboBoxEditField, combo);
        const int needed = combo->fontMetrics().horizontalAdvance(combo->currentText());
        QVERIFY2(text.width() >= needed, qPrintable(QStringLiteral("\"%1\": %2 px of %3")
                                                        .arg(combo->currentText())
                                                        .arg(text.width())
                                                        .arg(needed)));
    }
    ui::translations::install(qApp, QStringLiteral("en"));
}

namespace {
int runWorkspaces(int argc, char** argv)
{
#ifdef STEPDECK_FULL_HD
    // tst_workspaces_fullhd
    return runOnScreen<TestWorkspaces>(argc, argv, 1920, 1080 - kPanelAndTitleBar);
#else
    return runOnScreen<TestWorkspaces>(argc, argv, 1366, 768 - kPanelAndTitleBar);
#endif
}
} // namespace

STEPDECK_TEST_MAIN_WITH(TestWorkspaces, runWorkspaces)
#include "tst_workspaces.moc"
