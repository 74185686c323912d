// LaserSimAxis: the mechanics of one simulated laser motor axis, fed explicit time slices.
#include "TestMain.h"
#include "protocols/laser/LaserSimAxis.h"
#include <QtTest>

using namespace stepdeck::laser;
using Event = LaserSimAxis::Event;

namespace {
// Advances in 10 ms slices until an event or `seconds` are used up; returns the event.
Event run(LaserSimAxis& axis, double seconds)
{
    for (double t = 0; t < seconds; t += 0.01) {
        const Event e = axis.advance(0.01);
        if (e != Event::None)
            return e;
    }
    return Event::None;
}
} // namespace

class TestLaserSimAxis : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void moveTo_notHomed_homesFirstThenReachesTarget();
    void home_runsIntoSwitch_positionZero();
    void moveTo_whileMoving_newTargetReplacesOld();
    void moveTo_whileHomingOnTheWay_keepsHomingThenNewTarget();
    void moveTo_beyondEndSwitch_stopsThere();
    void halted_standsStillAndKeepsTarget();
    void idle_advanceDoesNothing();

private:
    LaserSimAxis m_axis;
};

void TestLaserSimAxis::init()
{
    m_axis = LaserSimAxis{};
    m_axis.config().speed = 1000;
    m_axis.powerOn(200);
}

void TestLaserSimAxis::moveTo_notHomed_homesFirstThenReachesTarget()
{
    QCOMPARE(m_axis.position(), qint64(0)); // its own count starts at 0 at power-up
    QVERIFY(!m_axis.homed());
    m_axis.moveTo(300);
    QCOMPARE(m_axis.advance(0.1), Event::None); // halfway home: physical 100
    QCOMPARE(m_axis.physical(), 100.0);
    QCOMPARE(run(m_axis, 1.0), Event::TargetReached); // no event at the home switch
    QVERIFY(m_axis.homed());
    QCOMPARE(m_axis.position(), qint64(300));
    QCOMPARE(m_axis.physical(), 300.0);
    QVERIFY(!m_axis.isMoving());
}

void TestLaserSimAxis::home_runsIntoSwitch_positionZero()
{
    m_axis.home();
    QCOMPARE(run(m_axis, 1.0), Event::HomeReached);
    QCOMPARE(m_axis.position(), qint64(0));
    QVERIFY(m_axis.homeSwitchActive());
    // Homing again runs into the switch again (and reports it).
    m_axis.moveTo(50);
    QCOMPARE(run(m_axis, 1.0), Event::TargetReached);
    m_axis.home();
    QCOMPARE(run(m_axis, 1.0), Event::HomeReached);
}

void TestLaserSimAxis::moveTo_whileMoving_newTargetReplacesOld()
{
    m_axis.home();
    run(m_axis, 1.0);
    m_axis.moveTo(900);
    QCOMPARE(m_axis.advance(0.2), Event::None);
    QCOMPARE(m_axis.position(), qint64(200));
    m_axis.moveTo(100); // back the other way
    QCOMPARE(run(m_axis, 1.0), Event::TargetReached);
    QCOMPARE(m_axis.position(), qint64(100));
}

void TestLaserSimAxis::moveTo_whileHomingOnTheWay_keepsHomingThenNewTarget()
{
    m_axis.moveTo(500);
    m_axis.advance(0.1);
    m_axis.moveTo(40);
    QCOMPARE(run(m_axis, 1.0), Event::TargetReached);
    QVERIFY(m_axis.homed());
    QCOMPARE(m_axis.position(), qint64(40));
}

void TestLaserSimAxis::moveTo_beyondEndSwitch_stopsThere()
{
    m_axis.config().endSwitch = 250;
    m_axis.home();
    run(m_axis, 1.0);
    m_axis.moveTo(400);
    QCOMPARE(run(m_axis, 1.0), Event::EndSwitch);
    QCOMPARE(m_axis.position(), qint64(250));
    QVERIFY(m_axis.endSwitchActive());
    QVERIFY(!m_axis.isMoving());
    m_axis.moveTo(100); // away from the switch works
    QCOMPARE(run(m_axis, 1.0), Event::TargetReached);
}

void TestLaserSimAxis::halted_standsStillAndKeepsTarget()
{
    m_axis.home();
    run(m_axis, 1.0);
    m_axis.moveTo(300);
    m_axis.advance(0.1);
    m_axis.setHalted(true);
    QVERIFY(!m_axis.isMoving());
    QVERIFY(m_axis.hasTarget());
    QCOMPARE(m_axis.advance(5.0), Event::None);
    QCOMPARE(m_axis.position(), qint64(100));
    m_axis.setHalted(false);
    QCOMPARE(run(m_axis, 1.0), Event::TargetReached);
    QCOMPARE(m_axis.position(), qint64(300));
}

void TestLaserSimAxis::idle_advanceDoesNothing()
{
    QCOMPARE(m_axis.advance(10), Event::None);
    QCOMPARE(m_axis.physical(), 200.0);
}

STEPDECK_TEST_GUILESS_MAIN(TestLaserSimAxis)
#include "tst_lasersimaxis.moc"
