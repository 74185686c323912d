// The Run workspace's spindle and coolant bar (issue 47 item 1) on a machine whose spindle
// output drives a laser (issue 50 item 5): it names the laser, its switch turns the beam on at
// the board (the in-process E-LAB simulator) and off again, as the board reports it.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineDescription.h"
#include "machine/SpindleCoolantBar.h"
#include "protocols/elab/ElabSimulator.h"
#include <QPushButton>
#include <QtTest>
#include <atomic>
#include <memory>

using namespace stepdeck;

namespace {
// The board's spindle output, read in the controller thread (the in-process simulator).
std::optional<quint32> boardRpm(ControllerSession* session)
{
    auto rpm = std::make_shared<std::atomic<quint32>>(0);
    auto done = std::make_shared<std::atomic_bool>(false);
    session->withSimulator([rpm, done](Simulator* sim) {
        *rpm = static_cast<elab::ElabSimulator*>(sim)->spindleRpm();
        *done = true;
    });
    QElapsedTimer t;
    t.start();
    while (!*done && t.elapsed() < 5000)
        QTest::qWait(5);
    return *done ? std::optional<quint32>(*rpm) : std::nullopt;
}
} // namespace

class TestSpindleCoolantBar : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { test::isolateSettings(); }
    void laser_namedAndSwitchedAtTheBoard_data();
    void laser_namedAndSwitchedAtTheBoard();
};

void TestSpindleCoolantBar::laser_namedAndSwitchedAtTheBoard_data()
{
    QTest::addColumn<bool>("laser");
    QTest::addColumn<QString>("name"); // "Spindle" or "Laser"
    QTest::newRow("a spindle") << false << "Spindle";
    QTest::newRow("a laser") << true << "Laser";
}

void TestSpindleCoolantBar::laser_namedAndSwitchedAtTheBoard()
{
    QFETCH(bool, laser);
    QFETCH(QString, name);
    machine::MachineDescription d = machine::MachineDescription::singleController(
        *findModel(QStringLiteral("elab")), QStringLiteral("sim"));
    d.spindle.laser = laser;
    ui::MachineContext context;
    QString error;
    QVERIFY2(context.openMachine(d, &error), qPrintable(error));
    ui::SpindleCoolantBar bar(&context);
    QCOMPARE(bar.spindleText(), name + QStringLiteral(": unknown")); // not connected
    context.connectMachine();
    QTRY_VERIFY_WITH_TIMEOUT(bar.spindleButton()->isEnabled(), 10000);
    QCOMPARE(bar.spindleText(), name + QStringLiteral(": off"));
    QCOMPARE(bar.spindleButton()->text(), name + QStringLiteral(" on"));
    ControllerSession* session = context.machine()->session(d.controllers.first().id);
    bar.spindleButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(boardRpm(session).value_or(0) > 0, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(bar.spindleText(), name + QStringLiteral(": on"), 10000);
    QCOMPARE(bar.spindleButton()->text(), name + QStringLiteral(" off"));
    bar.spindleButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(boardRpm(session), std::optional<quint32>(0), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(bar.spindleText(), name + QStringLiteral(": off"), 10000);
    context.closeMachine();
}

STEPDECK_TEST_MAIN(TestSpindleCoolantBar)
#include "tst_spindlecoolantbar.moc"
