// The window's Simulator menu (issue 28, item 2): on the in-process EMIS simulator it offers the
// inputs the machine drives (5..8, the part sensor of docs/examples/emis.ngc), sets them at the
// simulated board, and shows each checked as the controller then reports it.
#include "../EmisUiFixture.h"
#include "TestMain.h"
#include "window/SimulatorMenu.h"
#include <QAction>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::test;

class TestSimulatorMenu : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void input5_triggered_boardHighAndShownAsReported();
    void elab_noInputsToSet_saysSo();
};

void TestSimulatorMenu::input5_triggered_boardHighAndShownAsReported()
{
    EmisUiFixture f;
    QVERIFY(f.connectEmis());
    auto* menu = f.window->findChild<ui::SimulatorMenu*>();
    QVERIFY(menu);
    menu->rebuild(); // as when it opens: the simulator is asked, its answer rebuilds the menu
    QTRY_COMPARE(menu->inputActions().size(), 4);
    QAction* five = menu->inputActions().at(0);
    QCOMPARE(five->text(), QStringLiteral("Input 5 high"));
    QVERIFY(!five->isChecked());
    five->trigger();
    // At the simulated board, then as the controller reads it back.
    bool high = false;
    QTRY_VERIFY(
        f.withEmis([&high](emis::EmisSimulator* sim) { high = sim->inputLevels().at(4); }) && high);
    QTRY_VERIFY(f.session->status().inputs && f.session->status().inputs->at(4));
    menu->rebuild();
    QVERIFY(menu->inputActions().at(0)->isChecked());
    menu->inputActions().at(0)->trigger(); // unchecked: low again
    QTRY_VERIFY(f.session->status().inputs && !f.session->status().inputs->at(4));
}

void TestSimulatorMenu::elab_noInputsToSet_saysSo()
{
    UiFixture f;
    QVERIFY(f.connectSim());
    auto* menu = f.window->findChild<ui::SimulatorMenu*>();
    menu->rebuild();
    QTRY_VERIFY(menu->actions().size() == 1 &&
                menu->actions().at(0)->text().contains(QStringLiteral("no inputs")));
    QVERIFY(menu->inputActions().isEmpty());
    QVERIFY(!menu->actions().at(0)->isEnabled());
}

STEPDECK_TEST_MAIN(TestSimulatorMenu)
#include "tst_simulatormenu.moc"
