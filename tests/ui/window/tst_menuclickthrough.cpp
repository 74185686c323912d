// Issue 31 (a finding, safety): a click that closes an open menu must not reach the window
// under it. It once did: a mis-click beside a menu fired PANIC (SafetyKeyFilter let a press
// on PANIC through an open popup, as it does for STOP). Every menu of the application (the
// menu bar's, context menus made later) takes the closing click for itself; STOP alone still
// acts through a popup (tst_safetyshortcuts::popupOpen_clickOnStop_stops), F1 panics always.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "machine/MachineContext.h"
#include "safety/SafetyBar.h"
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMenuClickThrough : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void closingClick_onPanic_closesTheMenuOnly_data();
    void closingClick_onPanic_closesTheMenuOnly();
};

void TestMenuClickThrough::closingClick_onPanic_closesTheMenuOnly_data()
{
    QTest::addColumn<bool>("menuBarMenu"); // else a context menu made later
    QTest::newRow("menu bar") << true;
    QTest::newRow("context menu") << false;
}

void TestMenuClickThrough::closingClick_onPanic_closesTheMenuOnly()
{
    QFETCH(bool, menuBarMenu);
    UiFixture f;
    QVERIFY(f.connectSim());
    f.window->show();
    QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
    QSignalSpy panics(f.window->context(), &ui::MachineContext::panicTriggered);
    QMenu* menu = nullptr;
    QMenu contextMenu(f.window.get());
    if (menuBarMenu) {
        menu = f.window->menuBar()->actions().first()->menu();
    } else {
        contextMenu.addAction(QStringLiteral("Copy"));
        menu = &contextMenu;
    }
    QVERIFY(menu);
    menu->popup(f.window->mapToGlobal(QPoint(10, 40)));
    QTRY_VERIFY(menu->isVisible());
    QVERIFY(menu->testAttribute(Qt::WA_NoMouseReplay)); // PopupClickGuard
    QPushButton* panic = f.window->safetyBar()->panicButton();
    QWindow* window = f.window->windowHandle();
    const QPoint at = window->mapFromGlobal(panic->mapToGlobal(panic->rect().center()));
    QTest::mouseClick(window, Qt::LeftButton, {}, at);
    QTRY_VERIFY(!menu->isVisible());
    QTest::qWait(50); // let a replayed click, if any, arrive
    QCOMPARE(panics.size(), 0);
    // Pressed again now that no menu is open, PANIC works.
    QTest::mouseClick(window, Qt::LeftButton, {}, at);
    QTRY_COMPARE(panics.size(), 1);
}

STEPDECK_TEST_MAIN(TestMenuClickThrough)
#include "tst_menuclickthrough.moc"
