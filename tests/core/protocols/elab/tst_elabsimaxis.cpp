// ElabSimAxis: the per-axis motion model of the E-LAB simulator, driven with explicit time
// slices (deterministic, no event loop).
#include "TestMain.h"
#include "protocols/elab/ElabSimAxis.h"
#include <QtTest>

using namespace stepdeck::elab;

namespace {
ElabSimAxis makeAxis(quint16 start, quint16 max, quint16 accel, quint16 feed = 100)
{
    ElabSimAxis axis;
    axis.ramp() = {start, max, accel, feed};
    return axis;
}

struct RunStats
{
    double minSpeed = 1e12;
    double maxSpeed = 0;
    int slices = 0;
    ElabSimAxis::Event lastEvent = ElabSimAxis::Event::None;
};

// Advances in 1 ms slices until the axis stops (bounded).
RunStats runToIdle(ElabSimAxis& axis, int maxSlices = 200000)
{
    RunStats stats;
    while (axis.isMoving() && stats.slices < maxSlices) {
        stats.minSpeed = qMin(stats.minSpeed, axis.speed());
        stats.maxSpeed = qMax(stats.maxSpeed, axis.speed());
        const ElabSimAxis::Event e = axis.advance(0.001);
        if (e != ElabSimAxis::Event::None)
            stats.lastEvent = e;
        ++stats.slices;
    }
    return stats;
}
} // namespace

class TestElabSimAxis : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void fastMove_reachesExactTarget_data();
    void fastMove_reachesExactTarget();
    void fastMove_shortMove_neverReachesPlateau();
    void rampStop_brakesWithoutLosingSteps();
    void hardStop_keepsRemainingSteps();
    void fastMove_limitSwitch_stopsAtFirstActiveStep();
    void jog_runsAtRate_ignoresLimit();
    void referenceMove_stopsAtWindowEdge_data();
    void referenceMove_stopsAtWindowEdge();
    void velocity_belowStartSpeed_isStop();
    void velocity_repeat_ignoresSign_rampsToStop();
    void polarity_mismatch_readsActiveAtRest_data();
    void polarity_mismatch_readsActiveAtRest();
    void feed_runsAtFeedSpeed_rampStopIsImmediate();
};

void TestElabSimAxis::fastMove_reachesExactTarget_data()
{
    QTest::addColumn<qint64>("steps");
    QTest::addColumn<int>("start");
    QTest::addColumn<int>("max");
    QTest::addColumn<int>("accel");
    QTest::newRow("one step") << qint64(1) << 100 << 5000 << 1000;
    QTest::newRow("manual example +1000") << qint64(1000) << 100 << 5000 << 1000;
    QTest::newRow("negative") << qint64(-5000) << 200 << 8000 << 2000;
    QTest::newRow("long plateau") << qint64(100000) << 500 << 20000 << 20000;
    QTest::newRow("no acceleration: start rate only") << qint64(300) << 1000 << 5000 << 0;
    QTest::newRow("max below start") << qint64(500) << 2000 << 100 << 1000;
}

void TestElabSimAxis::fastMove_reachesExactTarget()
{
    QFETCH(qint64, steps);
    QFETCH(int, start);
    QFETCH(int, max);
    QFETCH(int, accel);
    ElabSimAxis axis = makeAxis(quint16(start), quint16(max), quint16(accel));
    axis.setPosition(7);
    axis.startFastMove(steps);
    QCOMPARE(axis.mode(), ElabSimAxis::Mode::FastMove);
    QCOMPARE(axis.remaining(), steps);
    const RunStats stats = runToIdle(axis);
    QCOMPARE(stats.lastEvent, ElabSimAxis::Event::Finished);
    QCOMPARE(axis.position(), 7 + steps);
    QCOMPARE(axis.remaining(), qint64(0));
    QVERIFY(stats.minSpeed >= start);
    QVERIFY(stats.maxSpeed <= qMax(start, max));
}

void TestElabSimAxis::fastMove_shortMove_neverReachesPlateau()
{
    ElabSimAxis axis = makeAxis(100, 30000, 1000);
    axis.startFastMove(200);
    const RunStats stats = runToIdle(axis);
    QCOMPARE(axis.position(), qint64(200));
    // Triangle profile: it turns into the stop ramp long before 30000 steps/s.
    QVERIFY2(stats.maxSpeed < 1000, qPrintable(QString::number(stats.maxSpeed)));
    QVERIFY(stats.maxSpeed > 100);
}

void TestElabSimAxis::rampStop_brakesWithoutLosingSteps()
{
    ElabSimAxis axis = makeAxis(500, 20000, 20000);
    axis.startFastMove(100000);
    while (axis.position() < 2000)
        axis.advance(0.001);
    const qint64 atStop = axis.position();
    QVERIFY(axis.speed() > 500);
    axis.rampStop();
    QVERIFY(axis.isStopping());
    runToIdle(axis);
    QVERIFY2(axis.position() > atStop, "a ramped stop keeps moving while it brakes");
    QVERIFY(axis.remaining() > 0);
    QCOMPARE(axis.position() + axis.remaining(), qint64(100000)); // no step lost
}

void TestElabSimAxis::hardStop_keepsRemainingSteps()
{
    ElabSimAxis axis = makeAxis(1000, 5000, 5000);
    axis.startFastMove(-10000);
    for (int i = 0; i < 100; ++i)
        axis.advance(0.001);
    axis.hardStop();
    QVERIFY(!axis.isMoving());
    QVERIFY(axis.position() < 0);
    QCOMPARE(axis.position() + axis.remaining(), qint64(-10000));
    axis.clearRemaining();
    QCOMPARE(axis.remaining(), qint64(0));
}

void TestElabSimAxis::fastMove_limitSwitch_stopsAtFirstActiveStep()
{
    ElabSimAxis axis = makeAxis(5000, 60000, 60000);
    axis.switches().limitMax = 50;
    axis.startFastMove(100);
    const RunStats stats = runToIdle(axis);
    QCOMPARE(stats.lastEvent, ElabSimAxis::Event::LimitHit);
    QCOMPARE(axis.position(), qint64(50));
    QVERIFY(axis.limitActive());
    QCOMPARE(axis.remaining(), qint64(50));
}

void TestElabSimAxis::jog_runsAtRate_ignoresLimit()
{
    ElabSimAxis axis = makeAxis(100, 5000, 1000);
    axis.switches().limitMin = -100;
    axis.setJogRate(-2000);
    QCOMPARE(axis.mode(), ElabSimAxis::Mode::Jog);
    QCOMPARE(axis.speed(), 2000.0); // no ramp: the host ramps jog rates
    for (int i = 0; i < 100; ++i)
        QCOMPARE(axis.advance(0.001), ElabSimAxis::Event::None);
    QCOMPARE(axis.position(), qint64(-200)); // 0.1 s at 2000 steps/s, past the limit at -100
    QVERIFY(axis.limitActive());
    QVERIFY(axis.isMoving());
    axis.setJogRate(0);
    QVERIFY(!axis.isMoving());
}

void TestElabSimAxis::referenceMove_stopsAtWindowEdge_data()
{
    QTest::addColumn<qint64>("from");
    QTest::addColumn<int>("direction");
    QTest::addColumn<qint64>("stopsAt");
    QTest::newRow("from above, negative") << qint64(0) << -1 << qint64(-295);
    QTest::newRow("from below, positive") << qint64(-1000) << 1 << qint64(-305);
}

void TestElabSimAxis::referenceMove_stopsAtWindowEdge()
{
    QFETCH(qint64, from);
    QFETCH(int, direction);
    QFETCH(qint64, stopsAt);
    ElabSimAxis axis = makeAxis(1000, 20000, 50000);
    axis.switches().referencePosition = -300;
    axis.switches().referenceWindow = 5;
    axis.setPosition(from);
    axis.startReference(direction);
    const RunStats stats = runToIdle(axis);
    QCOMPARE(stats.lastEvent, ElabSimAxis::Event::ReferenceHit);
    QCOMPARE(axis.position(), stopsAt);
    QVERIFY(axis.referenceActive());
    QCOMPARE(axis.remaining(), qint64(0));
}

void TestElabSimAxis::velocity_belowStartSpeed_isStop()
{
    ElabSimAxis axis = makeAxis(500, 5000, 1000);
    axis.setVelocity(499);
    QVERIFY(!axis.isMoving());
    axis.setVelocity(-500);
    QCOMPARE(axis.mode(), ElabSimAxis::Mode::Velocity);
    QCOMPARE(axis.direction(), -1);
}

void TestElabSimAxis::velocity_repeat_ignoresSign_rampsToStop()
{
    ElabSimAxis axis = makeAxis(200, 5000, 10000);
    axis.setVelocity(3000);
    for (int i = 0; i < 500; ++i)
        axis.advance(0.001);
    QCOMPARE(axis.speed(), 3000.0);
    axis.setVelocity(-1000); // sign ignored while running
    for (int i = 0; i < 500; ++i)
        axis.advance(0.001);
    QCOMPARE(axis.direction(), 1);
    QCOMPARE(axis.speed(), 1000.0);
    const qint64 before = axis.position();
    axis.setVelocity(0);
    const RunStats stats = runToIdle(axis);
    QCOMPARE(stats.lastEvent, ElabSimAxis::Event::Finished);
    QVERIFY(axis.position() > before); // braked with a ramp, still forwards
}

void TestElabSimAxis::polarity_mismatch_readsActiveAtRest_data()
{
    QTest::addColumn<bool>("wiredHigh");
    QTest::addColumn<bool>("configuredHigh");
    QTest::addColumn<bool>("activeAtRest");
    QTest::newRow("low wired, low configured") << false << false << false;
    QTest::newRow("high wired, high configured") << true << true << false;
    QTest::newRow("low wired, high configured") << false << true << true;
    QTest::newRow("high wired, low configured") << true << false << true;
}

void TestElabSimAxis::polarity_mismatch_readsActiveAtRest()
{
    QFETCH(bool, wiredHigh);
    QFETCH(bool, configuredHigh);
    QFETCH(bool, activeAtRest);
    ElabSimAxis axis;
    axis.switches().limitWiredActiveHigh = wiredHigh;
    axis.setLimitPolarity(configuredHigh);
    QCOMPARE(axis.limitActive(), activeAtRest);
    axis.setLimitForced(true); // pressed: the level flips, so does the reading
    QCOMPARE(axis.limitLevelHigh(), wiredHigh);
    QCOMPARE(axis.limitActive(), !activeAtRest);
}

void TestElabSimAxis::feed_runsAtFeedSpeed_rampStopIsImmediate()
{
    ElabSimAxis axis = makeAxis(1000, 5000, 1000, 400);
    axis.startFeed(1000);
    QCOMPARE(axis.mode(), ElabSimAxis::Mode::Feed);
    for (int i = 0; i < 500; ++i)
        axis.advance(0.001);
    QVERIFY(qAbs(axis.position() - 200) <= 1); // 0.5 s at 400 steps/s
    axis.rampStop();
    QVERIFY(!axis.isMoving());
    QCOMPARE(axis.remaining(), 1000 - axis.position());
}

STEPDECK_TEST_GUILESS_MAIN(TestElabSimAxis)
#include "tst_elabsimaxis.moc"
