// LaserAxisSimulator: the device side of the laser motor-axis protocol, driven with the
// laser's own frames (LaserCodec) and observed through the frames it transmits.
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::laser;

class TestLaserAxisSimulator : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void move_notHomed_homesFirstThenReportsTargetOnly();
    void home_reportsHomeSwitchAtZero();
    void move_whileMoving_newTargetReplacesOld();
    void move_toCurrentPosition_reportsAtOnce();
    void move_beyondEndSwitch_reportsEndSwitch();
    void door_openHaltsAndReports3_closeResumesAndReports4();
    void door_idleMachine_axisXReports();
    void malformedFrames_ignoredAndCounted();
    void silentFault_movesButSaysNothing();
    void garbageFault_precedesEveryStatus();
    void threeAxes_independent();
    void acceptedMoves_journalAndEmergencyStop();

private:
    // Frames sent since the test began, decoded on the laser side.
    QList<StatusFrame> statuses() const;
    bool waitForStatuses(int count, int timeoutMs = 3000);

    LaserAxisSimulator* m_sim = nullptr;
    QSignalSpy* m_spy = nullptr;
};

void TestLaserAxisSimulator::init()
{
    m_sim = new LaserAxisSimulator(SimulatorOptions{});
    m_sim->setSpeed(20000);
    m_spy = new QSignalSpy(m_sim, &Simulator::transmit);
}

void TestLaserAxisSimulator::cleanup()
{
    delete m_spy;
    delete m_sim;
}

QList<StatusFrame> TestLaserAxisSimulator::statuses() const
{
    StatusDecoder decoder;
    QList<StatusFrame> out;
    for (const DecodedStatus& d : decoder.feed(test::joinedBytes(*m_spy))) {
        if (d.ok())
            out << *d.frame;
    }
    return out;
}

bool TestLaserAxisSimulator::waitForStatuses(int count, int timeoutMs)
{
    QElapsedTimer t;
    t.start();
    while (statuses().size() < count && t.elapsed() < timeoutMs)
        m_spy->wait(20);
    return statuses().size() >= count;
}

void TestLaserAxisSimulator::move_notHomed_homesFirstThenReportsTargetOnly()
{
    QVERIFY(!m_sim->isHomed(Axis::Y));
    m_sim->receive(encodeMove(Axis::Y, 150));
    QVERIFY(m_sim->isMoving(Axis::Y));
    QVERIFY(waitForStatuses(1));
    QCOMPARE(statuses(), (QList<StatusFrame>{{Axis::Y, 150, Status::TargetReached}}));
    QCOMPARE(test::joinedBytes(*m_spy), QByteArray("2001500\r"));
    QVERIFY(m_sim->isHomed(Axis::Y));
    QCOMPARE(m_sim->position(Axis::Y), qint64(150));
    QVERIFY(!m_sim->isMoving(Axis::Y));
    QVERIFY(!m_sim->isTicking());
    QCOMPARE(m_sim->receivedCommands(), (QList<CommandFrame>{{Command::Move, Axis::Y, 150}}));
}

void TestLaserAxisSimulator::home_reportsHomeSwitchAtZero()
{
    m_sim->receive("1100000\r");
    QVERIFY(waitForStatuses(1));
    QCOMPARE(test::joinedBytes(*m_spy), QByteArray("1000002\r"));
    QVERIFY(m_sim->isHomed(Axis::X));
}

void TestLaserAxisSimulator::move_whileMoving_newTargetReplacesOld()
{
    m_sim->powerOn(Axis::X, 0);
    m_sim->setSpeed(2000);
    m_sim->receive(encodeMove(Axis::X, 90000)); // 45 s away
    QTRY_VERIFY(m_sim->position(Axis::X) > 0);
    m_sim->receive(encodeMove(Axis::X, 20));
    QVERIFY(waitForStatuses(1));
    QCOMPARE(statuses(), (QList<StatusFrame>{{Axis::X, 20, Status::TargetReached}}));
    QVERIFY(test::staysQuiet(*m_spy, 100)); // nothing about the discarded target
}

void TestLaserAxisSimulator::move_toCurrentPosition_reportsAtOnce()
{
    m_sim->receive(encodeMove(Axis::Z, 0)); // not homed: homes, then is at 0
    QVERIFY(waitForStatuses(1));
    m_sim->receive(encodeMove(Axis::Z, 0));
    QVERIFY(waitForStatuses(2));
    QCOMPARE(statuses().last(), (StatusFrame{Axis::Z, 0, Status::TargetReached}));
}

void TestLaserAxisSimulator::move_beyondEndSwitch_reportsEndSwitch()
{
    m_sim->config(Axis::Y).endSwitch = 300;
    m_sim->receive(encodeMove(Axis::Y, 500));
    QVERIFY(waitForStatuses(1));
    QCOMPARE(statuses(), (QList<StatusFrame>{{Axis::Y, 300, Status::EndSwitch}}));
    QCOMPARE(m_sim->position(Axis::Y), qint64(300));
    QVERIFY(!m_sim->isMoving(Axis::Y));
}

void TestLaserAxisSimulator::door_openHaltsAndReports3_closeResumesAndReports4()
{
    m_sim->powerOn(Axis::X, 0);
    m_sim->setSpeed(1000);
    m_sim->receive(encodeMove(Axis::X, 400));
    QTRY_VERIFY(m_sim->position(Axis::X) > 0);
    m_sim->setDoorOpen(true);
    const qint64 stoppedAt = m_sim->position(Axis::X);
    QVERIFY(stoppedAt < 400);
    QVERIFY(!m_sim->isMoving(Axis::X));
    QCOMPARE(statuses().size(), 1);
    QCOMPARE(statuses().first().status, Status::DoorOpened);
    QCOMPARE(statuses().first().axis, Axis::X);
    QVERIFY(test::staysQuiet(*m_spy, 100));
    QCOMPARE(m_sim->position(Axis::X), stoppedAt); // stands while the door is open
    m_sim->setDoorOpen(false);
    QVERIFY(waitForStatuses(3));
    QCOMPARE(statuses().at(1).status, Status::DoorClosed);
    QCOMPARE(statuses().at(2), (StatusFrame{Axis::X, 400, Status::TargetReached}));
}

void TestLaserAxisSimulator::door_idleMachine_axisXReports()
{
    m_sim->setDoorOpen(true);
    m_sim->setDoorOpen(true); // no change, no frame
    m_sim->setDoorOpen(false);
    QCOMPARE(test::joinedBytes(*m_spy), QByteArray("1000003\r1000004\r"));
}

void TestLaserAxisSimulator::malformedFrames_ignoredAndCounted()
{
    m_sim->receive("2x00500\r24005\r2400500\r0100500\r22005001\r");
    QCOMPARE(m_sim->rejectedFrames(), 5);
    QVERIFY(m_sim->receivedCommands().isEmpty());
    for (Axis a : {Axis::X, Axis::Y, Axis::Z})
        QVERIFY(!m_sim->isMoving(a));
    QVERIFY(test::staysQuiet(*m_spy, 50));
}

void TestLaserAxisSimulator::silentFault_movesButSaysNothing()
{
    m_sim->faults().silent = true;
    m_sim->receive(encodeMove(Axis::X, 100));
    QTRY_VERIFY(!m_sim->isMoving(Axis::X));
    QCOMPARE(m_sim->position(Axis::X), qint64(100));
    QCOMPARE(m_spy->count(), 0);
    QCOMPARE(m_sim->sentStatusFrames().size(), 1); // it would have said this
}

void TestLaserAxisSimulator::garbageFault_precedesEveryStatus()
{
    m_sim->setGarbageBeforeStatus(true);
    m_sim->receive(encodeHome(Axis::Z));
    QVERIFY(waitForStatuses(1));
    QCOMPARE(test::joinedBytes(*m_spy), QByteArray("9x\r3000002\r"));
}

void TestLaserAxisSimulator::threeAxes_independent()
{
    m_sim->receive(encodeMove(Axis::X, 10) + encodeMove(Axis::Y, 20) + encodeMove(Axis::Z, 30));
    QVERIFY(waitForStatuses(3));
    QList<StatusFrame> got = statuses();
    std::sort(got.begin(), got.end(),
              [](const StatusFrame& a, const StatusFrame& b) { return a.axis < b.axis; });
    QCOMPARE(got, (QList<StatusFrame>{{Axis::X, 10, Status::TargetReached},
                                      {Axis::Y, 20, Status::TargetReached},
                                      {Axis::Z, 30, Status::TargetReached}}));
}

void TestLaserAxisSimulator::acceptedMoves_journalAndEmergencyStop()
{
    // The soak's device journal: lengths from where the axis stood, zero-length moves and
    // home commands left out; the emergency stop leaves the axes where they are, silently.
    m_sim->receive(encodeMove(Axis::X, 100));
    QVERIFY(waitForStatuses(1));
    m_sim->receive(encodeMove(Axis::X, 100) + encodeHome(Axis::Y));
    QVERIFY(waitForStatuses(3));
    m_sim->receive(encodeMove(Axis::X, 40));
    QVERIFY(waitForStatuses(4));
    const auto moves = m_sim->acceptedMoves();
    QCOMPARE(moves.size(), 2);
    QCOMPARE(moves[0].steps, 100);
    QCOMPARE(moves[1].steps, -60);
    m_sim->clearAcceptedMoves();
    QVERIFY(m_sim->acceptedMoves().isEmpty());

    m_sim->setSpeed(2000);
    m_sim->receive(encodeMove(Axis::Z, 90000)); // 45 s away
    QTRY_VERIFY(m_sim->position(Axis::Z) > 0);
    const int before = int(statuses().size());
    m_sim->emergencyStop();
    QVERIFY(!m_sim->isMoving(Axis::Z));
    QVERIFY(!m_sim->isTicking());
    QVERIFY(m_sim->position(Axis::Z) < 90000);
    QVERIFY(test::staysQuiet(*m_spy, 100));
    QCOMPARE(statuses().size(), before);
}

STEPDECK_TEST_GUILESS_MAIN(TestLaserAxisSimulator)
#include "tst_laseraxissimulator.moc"
