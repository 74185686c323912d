// EmisController and the work speed (#E1, 9.5): a jog changes it, the board cannot report it,
// so every positioning move sets the work speed it runs at. The tests assert the speed each
// move ran at on the simulated board (AcceptedMove::workSpeed), also after a jog that could not
// give its speed back (closed while a chunk ran), in the same session and in the next one.
#include "EmisControllerRig.h"
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/emis/EmisWorkSpeeds.h"

using namespace stepdeck;
using namespace stepdeck::emis;
using stepdeck::test::EmisRig;

class TestEmisControllerWorkSpeed : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void move_afterJogInSameSession_runsAtWorkSpeed();
    void jogCutByClose_reconnect_moveRunsAtWrittenSpeed();
    void jogCutByClose_nextSession_moveRunsAtStoredOrAssumedSpeed_data();
    void jogCutByClose_nextSession_moveRunsAtStoredOrAssumedSpeed();
    void jog_nothingKnown_noMessage_speedGivenBack();
    void silence_boardSpeedForgotten_nextMoveWritesItAgain();
    void speedWriteRefused_moveNotSent();

private:
    void jogUntilChunkRuns(Axis axis, double rate);
    void closeWhileJogChunkRuns(Axis axis, double rate);
    CommandResult move(Axis axis, qint64 steps);
    // The work speed the board ran its last accepted move of `axis` at.
    qint64 lastMoveSpeed(Axis axis) const;
    EmisRig m_rig;
    QTimer m_renew; // the jog input renews the lease every 50 ms
};

void TestEmisControllerWorkSpeed::init()
{
    QVERIFY(m_rig.setUp());
    m_renew.disconnect();
    m_renew.setInterval(50);
}

void TestEmisControllerWorkSpeed::cleanup()
{
    m_renew.stop();
    m_rig.tearDown();
}

void TestEmisControllerWorkSpeed::jogUntilChunkRuns(Axis axis, double rate)
{
    m_renew.disconnect();
    connect(&m_renew, &QTimer::timeout, this, [this, axis, rate] {
        m_rig.ctl->setJogVelocity({{axis, rate}});
    });
    m_renew.start();
    m_rig.ctl->setJogVelocity({{axis, rate}});
    QTRY_VERIFY(m_rig.sim->isMoving(axis));
}

void TestEmisControllerWorkSpeed::closeWhileJogChunkRuns(Axis axis, double rate)
{
    jogUntilChunkRuns(axis, rate);
    QSignalSpy closed(m_rig.ctl, &Controller::closeFinished);
    m_rig.ctl->closeLink(); // no chance to give the work speed back
    m_renew.stop();
    QTRY_COMPARE(closed.size(), 1);
    QTRY_VERIFY(!m_rig.sim->anyMoving());
    QCOMPARE(m_rig.sim->working().workSpeed.value(axis), qRound64(qAbs(rate))); // left behind
}

CommandResult TestEmisControllerWorkSpeed::move(Axis axis, qint64 steps)
{
    const CommandResult r = m_rig.run([&](RequestId id) {
        m_rig.ctl->moveRelative(id, {{axis, steps}});
    });
    if (r.ok() &&
        !QTest::qWaitFor([this] { return !m_rig.anyMoving() && !m_rig.sim->anyMoving(); }, 10000))
        return CommandResult::failure(r.id, ErrorKind::Timeout, "the move did not arrive");
    return r;
}

qint64 TestEmisControllerWorkSpeed::lastMoveSpeed(Axis axis) const
{
    const auto moves = m_rig.sim->acceptedMovesWithSpeed();
    for (auto it = moves.crbegin(); it != moves.crend(); ++it) {
        if (it->axis == axis)
            return it->workSpeed;
    }
    return -1;
}

void TestEmisControllerWorkSpeed::move_afterJogInSameSession_runsAtWorkSpeed()
{
    QVERIFY(m_rig.write({"ramp=20", "start-speed=300", "work-speed=2000"}).ok());
    jogUntilChunkRuns(Axis::X, 700);
    m_renew.stop();
    m_rig.ctl->endJog();
    QTRY_VERIFY(m_rig.ctl->jogRamp().isIdle() && !m_rig.anyMoving() && !m_rig.sim->anyMoving());
    const CommandResult r = move(Axis::X, 150);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(lastMoveSpeed(Axis::X), 2000);
    QCOMPARE(m_rig.axis(Axis::X).position, m_rig.sim->position(Axis::X));
    QCOMPARE(m_rig.ctl->status()
                 .knownParameters.value(QStringLiteral("work-speed"))
                 .perAxis.value(Axis::X)
                 .toLongLong(),
             2000); // written in this session: the speed a program's G0 gets back
}

void TestEmisControllerWorkSpeed::jogCutByClose_reconnect_moveRunsAtWrittenSpeed()
{
    QVERIFY(m_rig.write({"ramp=20", "start-speed=300", "work-speed=2000"}).ok());
    closeWhileJogChunkRuns(Axis::Y, -600);
    QVERIFY(m_rig.run([this](RequestId id) { m_rig.ctl->openLink(id); }).ok());
    m_rig.sim->clearReceivedCommands();
    const CommandResult r = move(Axis::Y, 100);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(m_rig.commands().mid(0, 2), (QList<QByteArray>{"#E1,y2000", "L1,y100"}));
    QCOMPARE(lastMoveSpeed(Axis::Y), 2000);
}

void TestEmisControllerWorkSpeed::jogCutByClose_nextSession_moveRunsAtStoredOrAssumedSpeed_data()
{
    QTest::addColumn<qint64>("stored"); // 0: nothing stored
    QTest::addColumn<qint64>("expected");
    QTest::newRow("nothing stored") << qint64(0) << EmisWorkSpeeds::kAssumedDefault;
    QTest::newRow("stored 1500") << qint64(1500) << qint64(1500);
}

void TestEmisControllerWorkSpeed::jogCutByClose_nextSession_moveRunsAtStoredOrAssumedSpeed()
{
    // The next CLI call: a new controller that knows nothing of the jog before it.
    QFETCH(qint64, stored);
    QFETCH(qint64, expected);
    if (stored > 0) {
        const ParameterSet set{
            {"work-speed",
             ParameterValue{
                 {},
                 {{Axis::X, stored}, {Axis::Y, stored}, {Axis::Z, stored}, {Axis::U, stored}}}}};
        QVERIFY(
            m_rig.operation("store-parameters", {{"parameters", QVariant::fromValue(set)}}).ok());
    }
    closeWhileJogChunkRuns(Axis::U, 500);
    delete m_rig.ctl;
    m_rig.ctl = new EmisController(m_rig.host, EmisRig::defaults(), m_rig.owner);
    QVERIFY(m_rig.run([this](RequestId id) { m_rig.ctl->openLink(id); }).ok());
    const CommandResult r = move(Axis::U, -80);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(lastMoveSpeed(Axis::U), expected);
    // What a program's G1 would replace (issue 29): published only where it is known, never
    // the assumed default.
    const ParameterValue known =
        m_rig.ctl->status().knownParameters.value(QStringLiteral("work-speed"));
    QCOMPARE(known.perAxis.contains(Axis::U), stored > 0);
    if (stored > 0)
        QCOMPARE(known.perAxis.value(Axis::U).toLongLong(), stored);
}

void TestEmisControllerWorkSpeed::jog_nothingKnown_noMessage_speedGivenBack()
{
    // Nothing written, nothing stored: the jog gives the axis the speed moves run at (the
    // assumed default) and says nothing about a speed left behind (issue 16).
    QSignalSpy errors(m_rig.ctl, &Controller::errorOccurred);
    jogUntilChunkRuns(Axis::Z, 450);
    m_renew.stop();
    m_rig.ctl->endJog();
    QTRY_VERIFY(m_rig.ctl->jogRamp().isIdle() && !m_rig.anyMoving() && !m_rig.sim->anyMoving());
    QTRY_COMPARE(m_rig.sim->working().workSpeed.value(Axis::Z), EmisWorkSpeeds::kAssumedDefault);
    QVERIFY2(errors.isEmpty(), qPrintable(errors.value(0).value(0).toString()));
    QVERIFY(move(Axis::Z, 60).ok());
    QCOMPARE(lastMoveSpeed(Axis::Z), EmisWorkSpeeds::kAssumedDefault);
}

void TestEmisControllerWorkSpeed::silence_boardSpeedForgotten_nextMoveWritesItAgain()
{
    QVERIFY(m_rig.write({"work-speed=1200"}).ok());
    QVERIFY(move(Axis::X, 50).ok());
    // The board goes quiet for a moment (a reset, 5.8, would look like this) and comes back
    // with another work speed; the host cannot tell, so it writes its own again.
    auto* link = const_cast<EmisLink*>(&m_rig.ctl->link());
    QSignalSpy timedOut(link, &EmisLink::timedOut);
    connect(link, &EmisLink::timedOut, this, [this] { m_rig.sim->faults().silent = false; });
    m_rig.sim->faults().silent = true;
    m_rig.sim->receive("#E1,x333\r"); // its <ACK> is lost in the silence
    QTRY_COMPARE(timedOut.size(), 1);
    QCOMPARE(m_rig.ctl->linkState(), LinkState::Connected);
    m_rig.sim->clearReceivedCommands();
    QVERIFY(move(Axis::X, 50).ok());
    QCOMPARE(m_rig.commands().mid(0, 2), (QList<QByteArray>{"#E1,x1200", "L1,x50"}));
    QCOMPARE(lastMoveSpeed(Axis::X), 1200);
}

void TestEmisControllerWorkSpeed::speedWriteRefused_moveNotSent()
{
    m_rig.sim->bellOn("#E1,x1000");
    const CommandResult r = move(Axis::X, 40);
    QCOMPARE(r.error, ErrorKind::Nak);
    QVERIFY2(r.message.contains("#E1,x1000"), qPrintable(r.message));
    QVERIFY(m_rig.commandsStartingWith("L1").isEmpty());
    QVERIFY(!m_rig.sim->anyMoving());
    QVERIFY(!m_rig.ctl->status().motionUnconfirmed);
    QVERIFY(move(Axis::X, 40).ok()); // the next move writes it again
    QCOMPARE(m_rig.commandsStartingWith("#E1"), (QList<QByteArray>{"#E1,x1000", "#E1,x1000"}));
    QCOMPARE(lastMoveSpeed(Axis::X), 1000);
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisControllerWorkSpeed)
#include "tst_emiscontrollerworkspeed.moc"
