// LaserBridge end to end when a target cannot be reached or a position is not known: the laser
// gets a frame only with a position the controller knows, nothing otherwise, and the bridge
// says why at once (log error, AxisView::failure). The controllers behind run on a second
// pseudo-terminal or in the session (port "sim"), the laser on a real pty.
#include "LaserBridgeRig.h"
#include "TestMain.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/emis/EmisSimulator.h"
#include "protocols/laser/LaserAxisSimulator.h"

using namespace stepdeck;
using namespace stepdeck::laser;
using stepdeck::test::LaserBridgeRig;
using Kind = stepdeck::bridge::LaserBridge::LogEntry::Kind;
using Phase = stepdeck::bridge::LaserBridge::Phase;

namespace {
bridge::LaserBridge::AxisView viewOf(LaserBridgeRig& rig, Axis laserAxis)
{
    for (const bridge::LaserBridge::AxisView& v : rig.bridge->axes()) {
        if (v.laserAxis == laserAxis)
            return v;
    }
    return {};
}
} // namespace

class TestLaserBridgeFailures : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void laserAxes_endSwitch_answersOneAtReportedPosition();
    void emis_overdueArrivalOnSwitch_noMadeUpPosition();
    void door_noPositionKnown_notReported_thenByAReferencedAxis();
    void controllerFailsMidMove_noAnswer_failureAtOnce_data();
    void controllerFailsMidMove_noAnswer_failureAtOnce();
};

// The laser axes behind report where their end switch stopped them: that position is known,
// so the laser gets '1' with it.
void TestLaserBridgeFailures::laserAxes_endSwitch_answersOneAtReportedPosition()
{
    LaserBridgeRig rig;
    QVERIFY(rig.connectControllerOnPty(QStringLiteral("laser-axis")));
    auto* sim = rig.simOnPty<LaserAxisSimulator>();
    sim->setSpeed(20000);
    sim->config(Axis::Y).endSwitch = 500; // units from the home switch
    QVERIFY(rig.startBridge());
    rig.laserSends("2200900\r");
    QVERIFY(rig.waitAnswers(1));
    QCOMPARE(rig.answers(), (QList<StatusFrame>{{Axis::Y, 500, Status::EndSwitch}}));
    QCOMPARE(sim->position(Axis::Y), qint64(500));
    QVERIFY(!sim->isMoving(Axis::Y));
}

// The SMC-IC4's arrival <DC1> is lost (the move ran; "<DC1>" never came) while its reference
// input 1 reads high. The host no longer knows where X is: the bridge used to answer
// "1000002" (home switch at 00000); now the laser gets nothing and the error says why.
void TestLaserBridgeFailures::emis_overdueArrivalOnSwitch_noMadeUpPosition()
{
    LaserBridgeRig rig;
    ControllerOptions options;
    options.commandTimeoutMs = 200; // the arrival deadline: about a second for this move
    QVERIFY(rig.connectControllerOnPty(QStringLiteral("emis"), options));
    auto* sim = rig.simOnPty<emis::EmisSimulator>();
    sim->setSwitchPosition(Axis::X, -20);
    QVERIFY(rig.startBridge());
    rig.laserSends("1100000\r");
    QVERIFY(rig.waitAnswers(1));
    QCOMPARE(rig.answers().first(), (StatusFrame{Axis::X, 0, Status::HomeSwitch}));
    sim->setSwitchPosition(Axis::X, 100000); // input 1 high wherever X stands
    sim->dropArrivals(1);
    rig.laserSends("2100020\r");
    QTRY_COMPARE_WITH_TIMEOUT(rig.logCount(Kind::Error, "did not confirm reaching its target"), 1,
                              10000);
    QCOMPARE(sim->arrivalsDropped(), 1);
    QCOMPARE(sim->position(Axis::X), qint64(20)); // the board did arrive
    QVERIFY(rig.session->status().axes.value(Axis::X).referenceSwitch);
    QVERIFY(!rig.session->status().axes.value(Axis::X).positionKnown);
    QVERIFY(rig.laserQuiet(200));
    QCOMPARE(rig.answers().size(), 1);
    QCOMPARE(viewOf(rig, Axis::X).phase, Phase::Failed);
}

// The door report carries a position as every frame does: with none known it is not sent
// (it used to go out as "1000003"), once an axis is referenced that axis reports it.
void TestLaserBridgeFailures::door_noPositionKnown_notReported_thenByAReferencedAxis()
{
    LaserBridgeRig rig;
    QVERIFY(rig.connectController(QStringLiteral("elab")));
    rig.onSim<elab::ElabSimulator>([](elab::ElabSimulator* s) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            s->setReferencePosition(a, -300, 5);
    });
    QVERIFY(rig.startBridge());
    rig.bridge->setDoorOpen(true);
    QCOMPARE(rig.logCount(Kind::Error, "not reported to the laser"), 1);
    QVERIFY(rig.laserQuiet(200));
    QVERIFY(rig.fromBridge.isEmpty());
    rig.bridge->setDoorOpen(false);
    rig.laserSends("1200000\r"); // Y home while the door is closed
    QVERIFY(rig.waitAnswers(1));
    rig.bridge->setDoorOpen(true);
    QVERIFY(rig.waitAnswers(2));
    QCOMPARE(rig.answers().last(), (StatusFrame{Axis::Y, 0, Status::DoorOpened}));
}

void TestLaserBridgeFailures::controllerFailsMidMove_noAnswer_failureAtOnce_data()
{
    QTest::addColumn<bool>("vanish"); // the port vanishes; else the controller falls silent
    QTest::newRow("controller silent") << false;
    QTest::newRow("controller port vanished") << true;
}

// The link to the controller fails while the bridge's move runs. The protocol has no error
// status and the position is unknown now, so the laser gets nothing (its timeout alarm follows);
// the bridge says so at once, keeps serving the laser port and drops new targets with the
// reason.
void TestLaserBridgeFailures::controllerFailsMidMove_noAnswer_failureAtOnce()
{
    QFETCH(bool, vanish);
    LaserBridgeRig rig;
    QVERIFY(rig.connectControllerOnPty(QStringLiteral("elab")));
    auto* sim = rig.simOnPty<elab::ElabSimulator>();
    sim->setReferencePosition(Axis::X, -300, 5);
    QVERIFY(rig.waitOk(rig.session->writeParameters(LaserBridgeRig::elabRamps(1500), false)));
    QVERIFY(rig.startBridge());
    rig.laserSends("1100000\r");
    QVERIFY(rig.waitAnswers(1));
    rig.laserSends("2190000\r"); // a minute of travel
    QTRY_VERIFY_WITH_TIMEOUT(sim->isMoving(Axis::X), 5000);
    if (vanish)
        rig.controllerEnd->vanish();
    else
        sim->faults().silent = true;
    QTRY_COMPARE_WITH_TIMEOUT(rig.logCount(Kind::Error, "the controller's link was lost"), 1,
                              10000);
    QVERIFY(rig.session->linkState() != LinkState::Connected);
    const bridge::LaserBridge::AxisView x = viewOf(rig, Axis::X);
    QCOMPARE(x.phase, Phase::Failed);
    QVERIFY2(x.failure.contains("move X to 90000") && x.failure.contains("link was lost"),
             qPrintable(x.failure));
    QVERIFY(!x.target);
    QVERIFY(rig.laserQuiet(300));
    QCOMPARE(rig.answers().size(), 1); // only the home's '2'
    // Still serving the laser port: a new target is dropped at once, with the reason.
    QVERIFY(rig.bridge->isRunning());
    rig.laserSends("2100010\r");
    QTRY_COMPARE(rig.logCount(Kind::Error, "move X to 10: the controller is not connected"), 1);
    QVERIFY(rig.laserQuiet(200));
    QCOMPARE(rig.answers().size(), 1);
    sim->faults().silent = false; // the close at the end gets its stop acknowledged
}

STEPDECK_TEST_MAIN(TestLaserBridgeFailures)
#include "tst_laserbridge_failures.moc"
