// LaserBridge end to end: a scripted laser on a real pty (QSerialPort on the bridge's side),
// the E-LAB and Nanotec simulators behind a ControllerSession.
#include "LaserBridgeRig.h"
#include "TestMain.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/nanotec/NanotecSimulator.h"

using namespace stepdeck;
using namespace stepdeck::laser;
using stepdeck::test::LaserBridgeRig;
using Kind = stepdeck::bridge::LaserBridge::LogEntry::Kind;

namespace {
constexpr qint64 kElabReference = -300; // reference switch of every E-LAB axis in these tests

qint64 elabPosition(LaserBridgeRig& rig, Axis axis)
{
    qint64 p = 0;
    rig.onSim<elab::ElabSimulator>([&](elab::ElabSimulator* s) { p = s->position(axis); });
    return p;
}

bool elabMoving(LaserBridgeRig& rig, Axis axis)
{
    bool moving = false;
    rig.onSim<elab::ElabSimulator>([&](elab::ElabSimulator* s) { moving = s->isMoving(axis); });
    return moving;
}

qint64 nanotecPosition(LaserBridgeRig& rig, int address)
{
    qint64 p = 0;
    rig.onSim<nanotec::NanotecSimulator>(
        [&](nanotec::NanotecSimulator* s) { p = s->drive(address)->position(); });
    return p;
}

bool elabRig(LaserBridgeRig& rig, int maxSpeed = 4000, const bridge::LaserBridgeConfig& cfg = {})
{
    if (!rig.connectController(QStringLiteral("elab"), maxSpeed))
        return false;
    rig.onSim<elab::ElabSimulator>([](elab::ElabSimulator* s) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            s->setReferencePosition(a, kElabReference, 5);
    });
    return rig.startBridge(cfg);
}

bool nanotecRig(LaserBridgeRig& rig, const bridge::LaserBridgeConfig& cfg = {})
{
    if (!rig.connectController(QStringLiteral("nanotec")))
        return false;
    rig.onSim<nanotec::NanotecSimulator>([](nanotec::NanotecSimulator* s) {
        for (nanotec::NanotecDrive* d : s->drives())
            d->setSwitches(-150, 50000);
    });
    return rig.startBridge(cfg);
}
} // namespace

class TestLaserBridgeEndToEnd : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void elab_home_answersHomeSwitch_deviceAtReference();
    void elab_firstMove_referencesFirst_thenScaledTarget();
    void elab_retargetWhileMoving_stopsThenNewestTarget();
    void elab_endSwitch_positionLost_noAnswerErrorSaysWhy();
    void elab_door_stopsAnswersThree_closedAnswersFourAndArrives();
    void elab_operatorStop_keepsPriority_noAnswer();
    void elab_shutdown_stopsMotionItStarted();
    void malformedFrames_ignoredAndNothingMoves_data();
    void malformedFrames_ignoredAndNothingMoves();
    void unmappedLaserAxis_ignored();
    void nanotec_homeBeforeFirstMove_andHome();
    void nanotec_retargetWhileMoving_arrivesThenNewest();
};

void TestLaserBridgeEndToEnd::elab_home_answersHomeSwitch_deviceAtReference()
{
    LaserBridgeRig rig;
    QVERIFY(elabRig(rig));
    rig.laserSends("1100000\r");
    QVERIFY(rig.waitAnswers(1));
    QCOMPARE(rig.answers(), (QList<StatusFrame>{{Axis::X, 0, Status::HomeSwitch}}));
    QCOMPARE(rig.fromBridge, QByteArray("1000002\r"));
    QVERIFY(qAbs(elabPosition(rig, Axis::X) - kElabReference) <= 5);
    QVERIFY(!elabMoving(rig, Axis::X));
    QVERIFY(rig.session->status().axes.value(Axis::X).referenced);
    QCOMPARE(elabPosition(rig, Axis::Y), qint64(0)); // the other axes never moved
}

void TestLaserBridgeEndToEnd::elab_firstMove_referencesFirst_thenScaledTarget()
{
    LaserBridgeRig rig;
    bridge::LaserBridgeConfig cfg;
    cfg.axisMap = {{Axis::X, Axis::Z}, {Axis::Y, Axis::Y}}; // laser 1 drives Z
    cfg.scale = 2;
    QVERIFY(elabRig(rig, 4000, cfg));
    rig.laserSends("2100150\r");
    QVERIFY(rig.waitAnswers(1));
    QCOMPARE(rig.answers(), (QList<StatusFrame>{{Axis::X, 150, Status::TargetReached}}));
    QCOMPARE(rig.logCount(Kind::Note, "referencing it first"), 1);
    // Referenced, then 150 x 2 steps from the reference: the device shows both.
    const qint64 z = elabPosition(rig, Axis::Z);
    QVERIFY2(qAbs(z - (kElabReference + 300)) <= 5, qPrintable(QString::number(z)));
    QCOMPARE(rig.session->status().axes.value(Axis::Z).position, qint64(300));
    QCOMPARE(elabPosition(rig, Axis::X), qint64(0));
    // A second move needs no reference run.
    rig.laserSends("2100010\r");
    QVERIFY(rig.waitAnswers(2));
    QCOMPARE(rig.answers().last(), (StatusFrame{Axis::X, 10, Status::TargetReached}));
    QCOMPARE(rig.logCount(Kind::Note, "referencing it first"), 1);
    QVERIFY(qAbs(elabPosition(rig, Axis::Z) - (kElabReference + 20)) <= 5);
}

void TestLaserBridgeEndToEnd::elab_retargetWhileMoving_stopsThenNewestTarget()
{
    LaserBridgeRig rig;
    QVERIFY(elabRig(rig, 1500));
    rig.laserSends("1200000\r");
    QVERIFY(rig.waitAnswers(1));
    const qint64 reference = elabPosition(rig, Axis::Y);
    rig.laserSends("2290000\r"); // a minute away
    QTRY_VERIFY_WITH_TIMEOUT(elabPosition(rig, Axis::Y) > reference + 200, 10000);
    const qsizetype sentBefore = rig.toController.size();
    rig.laserSends("2200050\r");
    QVERIFY(rig.waitAnswers(2));
    QCOMPARE(rig.answers().last(), (StatusFrame{Axis::Y, 50, Status::TargetReached}));
    QVERIFY(rig.laserQuiet(200));
    QCOMPARE(rig.answers().size(), 2); // nothing for the discarded 90000
    QVERIFY(qAbs(elabPosition(rig, Axis::Y) - (reference + 50)) <= 5);
    QVERIFY(!elabMoving(rig, Axis::Y));
    // The board was stopped (ForceStopMove) before the new target went out.
    QVERIFY(rig.toController.mid(sentBefore).contains(elab::encode::stopMove()));
    QCOMPARE(rig.logCount(Kind::Note, "stopping first"), 1);
}

// The E-LAB board stops at a limit switch without a ramp and its position is lost (the adapter
// marks it unknown): every status frame carries the position, so the laser gets no frame with
// a made-up one (it used to get "1000001"); the error says why.
void TestLaserBridgeEndToEnd::elab_endSwitch_positionLost_noAnswerErrorSaysWhy()
{
    LaserBridgeRig rig;
    QVERIFY(elabRig(rig));
    rig.onSim<elab::ElabSimulator>(
        [](elab::ElabSimulator* s) { s->setLimitPositions(Axis::X, -100000, 100); });
    rig.laserSends("2100900\r");
    QTRY_COMPARE_WITH_TIMEOUT(
        rig.logCount(Kind::Error, "limit switch, but its position is unknown"), 1, 10000);
    QVERIFY(!elabMoving(rig, Axis::X));
    QVERIFY(elabPosition(rig, Axis::X) <= 101);
    QVERIFY(!rig.session->status().axes.value(Axis::X).positionKnown);
    QVERIFY(rig.laserQuiet(200));
    QVERIFY(rig.fromBridge.isEmpty());
    const auto views = rig.bridge->axes();
    QCOMPARE(views.first().phase, bridge::LaserBridge::Phase::Failed);
    QVERIFY(views.first().failure.contains("move X to 900"));
}

void TestLaserBridgeEndToEnd::elab_door_stopsAnswersThree_closedAnswersFourAndArrives()
{
    LaserBridgeRig rig;
    QVERIFY(elabRig(rig, 1500));
    rig.laserSends("1100000\r");
    QVERIFY(rig.waitAnswers(1));
    const qint64 reference = elabPosition(rig, Axis::X);
    rig.laserSends("2103000\r");
    QTRY_VERIFY_WITH_TIMEOUT(elabPosition(rig, Axis::X) > reference + 100, 10000);
    rig.bridge->setDoorOpen(true);
    QVERIFY(rig.waitAnswers(2));
    QCOMPARE(rig.answers().at(1).status, Status::DoorOpened);
    QVERIFY(!elabMoving(rig, Axis::X)); // stopped before the '3' went out
    const qint64 stoppedAt = elabPosition(rig, Axis::X);
    QVERIFY(stoppedAt < reference + 3000);
    QCOMPARE(qint64(rig.answers().at(1).position), stoppedAt - reference);
    QVERIFY(rig.laserQuiet(200));
    QCOMPARE(elabPosition(rig, Axis::X), stoppedAt); // held while the door is open
    rig.bridge->setDoorOpen(false);
    QVERIFY(rig.waitAnswers(4));
    QCOMPARE(rig.answers().at(2).status, Status::DoorClosed);
    QCOMPARE(rig.answers().at(3), (StatusFrame{Axis::X, 3000, Status::TargetReached}));
    QVERIFY(qAbs(elabPosition(rig, Axis::X) - (reference + 3000)) <= 5);
}

void TestLaserBridgeEndToEnd::elab_operatorStop_keepsPriority_noAnswer()
{
    LaserBridgeRig rig;
    QVERIFY(elabRig(rig, 1500));
    rig.laserSends("1300000\r");
    QVERIFY(rig.waitAnswers(1));
    const qint64 reference = elabPosition(rig, Axis::Z);
    rig.laserSends("2390000\r");
    QTRY_VERIFY_WITH_TIMEOUT(elabPosition(rig, Axis::Z) > reference + 100, 10000);
    QVERIFY(rig.waitOk(rig.session->stop())); // the operator's STOP on another page
    QTRY_VERIFY_WITH_TIMEOUT(rig.logCount(Kind::Error, "short of its target") == 1, 10000);
    QVERIFY(!elabMoving(rig, Axis::Z));
    const qint64 stoppedAt = elabPosition(rig, Axis::Z);
    QVERIFY(rig.laserQuiet(300));
    QCOMPARE(rig.answers().size(), 1); // the laser gets no answer: its timeout alarm tells
    QCOMPARE(elabPosition(rig, Axis::Z), stoppedAt); // and the bridge did not restart it
}

void TestLaserBridgeEndToEnd::elab_shutdown_stopsMotionItStarted()
{
    LaserBridgeRig rig;
    QVERIFY(elabRig(rig, 1500));
    rig.laserSends("1200000\r");
    QVERIFY(rig.waitAnswers(1));
    const qint64 reference = elabPosition(rig, Axis::Y);
    rig.laserSends("2290000\r"); // a minute of travel
    QTRY_VERIFY_WITH_TIMEOUT(elabPosition(rig, Axis::Y) > reference + 200, 10000);
    QSignalSpy finished(rig.bridge.get(), &bridge::LaserBridge::finished);
    rig.bridge->shutdown();
    QVERIFY(finished.count() > 0 || finished.wait(5000));
    QTRY_VERIFY_WITH_TIMEOUT(!elabMoving(rig, Axis::Y), 5000); // the board's ramped stop
    QVERIFY(elabPosition(rig, Axis::Y) < reference + 5000);
    QVERIFY(rig.toController.contains(elab::encode::stopMove()));
    QCOMPARE(rig.answers().size(), 1); // no answer for the abandoned target
    QVERIFY(!rig.laserPort->isOpen());
    QVERIFY(!rig.bridge->isRunning());
}

void TestLaserBridgeEndToEnd::malformedFrames_ignoredAndNothingMoves_data()
{
    QTest::addColumn<QByteArray>("frame");
    QTest::newRow("short") << QByteArray("210015\r");
    QTest::newRow("long") << QByteArray("21001500\r");
    QTest::newRow("letter") << QByteArray("21x0150\r");
    QTest::newRow("axis 4") << QByteArray("2400150\r");
    QTest::newRow("axis 0") << QByteArray("2000150\r");
    QTest::newRow("command 3") << QByteArray("3100150\r");
    QTest::newRow("echoed status") << QByteArray("1001500\r"); // home of axis 0
    QTest::newRow("control bytes") << QByteArray("\x01\x02\x13\r");
}

void TestLaserBridgeEndToEnd::malformedFrames_ignoredAndNothingMoves()
{
    QFETCH(QByteArray, frame);
    LaserBridgeRig rig;
    QVERIFY(elabRig(rig));
    const qsizetype sentBefore = rig.toController.size();
    rig.laserSends(frame);
    QTRY_VERIFY(rig.logCount(Kind::Ignored) >= 1);
    QVERIFY(rig.laserQuiet(200));
    QVERIFY(rig.fromBridge.isEmpty());
    QCOMPARE(rig.logCount(Kind::FromLaser), 0);
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        QVERIFY(!elabMoving(rig, a));
        QCOMPARE(elabPosition(rig, a), qint64(0));
    }
    // Only status polls went to the board: no motion command of any kind.
    elab::CommandDecoder decoder;
    for (const elab::Command& c : decoder.feed(rig.toController.mid(sentBefore)))
        QVERIFY2(c.code == elab::ctrl::ENQ || c.code == elab::ctrl::HT ||
                     c.code == elab::ctrl::ETB || c.code == elab::ctrl::ETX ||
                     c.code == elab::ctrl::LF,
                 qPrintable(QString::number(c.code)));
}

void TestLaserBridgeEndToEnd::unmappedLaserAxis_ignored()
{
    LaserBridgeRig rig;
    bridge::LaserBridgeConfig cfg;
    cfg.axisMap = {{Axis::X, Axis::X}};
    QVERIFY(elabRig(rig, 4000, cfg));
    rig.laserSends("2300100\r");
    QTRY_COMPARE(rig.logCount(Kind::Ignored, "not mapped"), 1);
    QVERIFY(rig.laserQuiet(100));
    QVERIFY(!elabMoving(rig, Axis::Z));
}

void TestLaserBridgeEndToEnd::nanotec_homeBeforeFirstMove_andHome()
{
    LaserBridgeRig rig;
    QVERIFY(nanotecRig(rig));
    rig.laserSends("2200400\r");
    QVERIFY(rig.waitAnswers(1));
    QCOMPARE(rig.answers(), (QList<StatusFrame>{{Axis::Y, 400, Status::TargetReached}}));
    QCOMPARE(rig.logCount(Kind::Note, "referencing it first"), 1);
    QCOMPARE(nanotecPosition(rig, 2), qint64(400));
    QVERIFY(rig.session->status().axes.value(Axis::Y).referenced);
    QVERIFY(rig.toController.contains("#2p4\r")); // the external reference run (6.6 p=4)
    rig.laserSends("1200000\r");
    QVERIFY(rig.waitAnswers(2));
    QCOMPARE(rig.answers().last(), (StatusFrame{Axis::Y, 0, Status::HomeSwitch}));
    QCOMPARE(nanotecPosition(rig, 1), qint64(0)); // X never moved
}

void TestLaserBridgeEndToEnd::nanotec_retargetWhileMoving_arrivesThenNewest()
{
    LaserBridgeRig rig;
    QVERIFY(nanotecRig(rig));
    rig.laserSends("1100000\r");
    QVERIFY(rig.waitAnswers(1));
    rig.laserSends("2101500\r");
    QTRY_VERIFY_WITH_TIMEOUT(nanotecPosition(rig, 1) > 50, 10000);
    rig.laserSends("2100100\r");
    QTRY_COMPARE_WITH_TIMEOUT(rig.logCount(Kind::Note, "arrives first"), 1, 5000);
    QVERIFY(rig.waitAnswers(2));
    QCOMPARE(rig.answers().last(), (StatusFrame{Axis::X, 100, Status::TargetReached}));
    QCOMPARE(rig.answers().size(), 2);
    QCOMPARE(nanotecPosition(rig, 1), qint64(100));
    // No stop went to the drive: 'S' would lose the position (no ramp, 6.2).
    QVERIFY(!rig.toController.contains("#1S\r"));
}

STEPDECK_TEST_MAIN(TestLaserBridgeEndToEnd)
#include "tst_laserbridge_e2e.moc"
