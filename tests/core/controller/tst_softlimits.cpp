// Soft limits as data: moves beyond a limit are refused with the axis and the limit named,
// nothing is enforced before the axis is referenced, a stream is checked at every step, a
// velocity move is refused on a limited axis, and jog brakes early enough to stop inside the
// limit but may always move back inside.
#include "TestMain.h"
#include "controller/JogRamp.h"
#include "controller/SoftLimits.h"
#include <QtTest>

using namespace stepdeck;

namespace {
MachineStatus at(qint64 x, bool referenced = true)
{
    MachineStatus s;
    AxisStatus a;
    a.referenced = a.positionKnown = referenced;
    a.position = x;
    s.axes.insert(Axis::X, a);
    s.axes.insert(Axis::Y, a);
    return s;
}

SoftLimits xWithin(qint64 min, qint64 max)
{
    SoftLimits l;
    l.set(Axis::X, AxisSoftLimit{true, true, min, max});
    return l;
}
} // namespace

class TestSoftLimits : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void move_data();
    void move();
    void stream_checkedAtEveryStep();
    void velocity_refusedOnLimitedAxis();
    void jog_brakesToStopInsideTheLimit();
    void jog_atTheLimit_mayOnlyMoveBack();
    void jog_driveRampedStopDistance_brakesEarlier();
    void clip_chunkEndsAtTheLimit();
};

void TestSoftLimits::move_data()
{
    QTest::addColumn<SoftLimits>("limits");
    QTest::addColumn<MachineStatus>("status");
    QTest::addColumn<qint64>("steps");
    QTest::addColumn<bool>("refused");
    const SoftLimits l = xWithin(-1000, 5000);
    QTest::newRow("inside") << l << at(0) << qint64(4000) << false;
    QTest::newRow("exactly to the max") << l << at(0) << qint64(5000) << false;
    QTest::newRow("one beyond the max") << l << at(0) << qint64(5001) << true;
    QTest::newRow("beyond the min") << l << at(0) << qint64(-1001) << true;
    QTest::newRow("back inside from beyond") << l << at(6000) << qint64(-2000) << false;
    QTest::newRow("not referenced: not enforced") << l << at(0, false) << qint64(99999) << false;
    SoftLimits off = l;
    off.set(Axis::X, AxisSoftLimit{false, true, -1000, 5000});
    QTest::newRow("disabled") << off << at(0) << qint64(99999) << false;
    SoftLimits unset;
    unset.set(Axis::X, AxisSoftLimit{true, false, 0, 0});
    QTest::newRow("no range set") << unset << at(0) << qint64(99999) << false;
}

void TestSoftLimits::move()
{
    QFETCH(SoftLimits, limits);
    QFETCH(MachineStatus, status);
    QFETCH(qint64, steps);
    QFETCH(bool, refused);
    const QString why = limits.checkRelative(status, {{Axis::X, steps}});
    QCOMPARE(!why.isEmpty(), refused);
    if (refused) {
        QVERIFY2(why.contains(QStringLiteral("axis X")), qPrintable(why));
        QVERIFY(why.contains(QStringLiteral("soft limit")));
    }
    const qint64 target = status.axes.value(Axis::X).position + steps;
    QCOMPARE(!limits.checkTargets(status, {{Axis::X, target}}).isEmpty(), refused);
    // Another axis without limits is never held back.
    QVERIFY(limits.checkRelative(status, {{Axis::Y, steps}}).isEmpty());
}

void TestSoftLimits::stream_checkedAtEveryStep()
{
    const SoftLimits l = xWithin(-10, 10);
    QVector<AxisVector> out(15, AxisVector{{Axis::X, 1}});
    QVector<AxisVector> back(15, AxisVector{{Axis::X, -1}});
    QVERIFY(!l.checkStream(at(0), out).isEmpty());        // passes 10 on the way
    QVERIFY(!l.checkStream(at(0), out + back).isEmpty()); // even if it ends inside
    QVERIFY(l.checkStream(at(0), QVector<AxisVector>(10, {{Axis::X, 1}})).isEmpty());
}

void TestSoftLimits::velocity_refusedOnLimitedAxis()
{
    const SoftLimits l = xWithin(-10, 10);
    QVERIFY(!l.checkVelocity(at(0), {{Axis::X, 100}}).isEmpty());
    QVERIFY(l.checkVelocity(at(0), {{Axis::Y, 100}}).isEmpty());
    QVERIFY(l.checkVelocity(at(0, false), {{Axis::X, 100}}).isEmpty());
}

void TestSoftLimits::jog_brakesToStopInsideTheLimit()
{
    // Simulate the controller's tick: limit, advance the ramp, integrate the position.
    const SoftLimits l = xWithin(-100000, 5000);
    JogRamp ramp(2000, 1000);
    MachineStatus s = at(0);
    double position = 0;
    const double dt = 0.02;
    QString said;
    for (int tick = 0; tick < 1000; ++tick) {
        ramp.setTarget(Axis::X, 1000); // the operator keeps pushing
        s.axes[Axis::X].position = qint64(position);
        QString why;
        const AxisVelocities limited = l.limitJog(
            s, {{Axis::X, ramp.target(Axis::X)}}, ramp.currentVelocities(), ramp.acceleration(), dt,
            SoftLimits::rampStopDistance(ramp.acceleration()), &why);
        ramp.setTarget(Axis::X, limited.value(Axis::X));
        if (!why.isEmpty())
            said = why;
        const double before = ramp.current(Axis::X);
        const double after = ramp.advance(dt).value(Axis::X);
        position += (before + after) / 2 * dt;
        QVERIFY2(position <= 5000, qPrintable(QString::number(position)));
    }
    QVERIFY2(position > 4900, qPrintable(QString::number(position))); // it got close
    QCOMPARE(ramp.current(Axis::X), 0.0);
    QVERIFY(said.contains(QStringLiteral("soft limit 5000")));
}

void TestSoftLimits::jog_atTheLimit_mayOnlyMoveBack()
{
    const SoftLimits l = xWithin(-1000, 5000);
    const SoftLimits::StopDistance brake = SoftLimits::rampStopDistance(2000);
    QString why;
    QCOMPARE(l.limitJog(at(5000), {{Axis::X, 300}}, {}, 2000, 0.02, brake, &why).value(Axis::X),
             0.0);
    QVERIFY(!why.isEmpty());
    QCOMPARE(l.limitJog(at(5000), {{Axis::X, -300}}, {}, 2000, 0.02, brake, &why).value(Axis::X),
             -300.0);
    QVERIFY(why.isEmpty());
    QCOMPARE(l.limitJog(at(7000), {{Axis::X, -300}}, {}, 2000, 0.02, brake, &why).value(Axis::X),
             -300.0); // beyond (limits changed): back inside is allowed
    QCOMPARE(l.limitJog(at(0, false), {{Axis::X, 300}}, {}, 2000, 0.02, brake, &why).value(Axis::X),
             300.0); // not referenced: not enforced
}

void TestSoftLimits::jog_driveRampedStopDistance_brakesEarlier()
{
    // A drive that ramps by itself (Nanotec) needs its own, longer stop distance: at 4000
    // the host ramp would go on, the drive's distance of 600 steps holds it back.
    const SoftLimits l = xWithin(-100000, 5000);
    QString why;
    const AxisVelocities fast{{Axis::X, 1000}};
    QCOMPARE(l.limitJog(at(4000), fast, fast, 2000, 0.02, SoftLimits::rampStopDistance(2000), &why)
                 .value(Axis::X),
             1000.0);
    QVERIFY(why.isEmpty());
    const SoftLimits::StopDistance drive = [](Axis, double) { return 1000.0; };
    QCOMPARE(l.limitJog(at(4000), fast, fast, 2000, 0.02, drive, &why).value(Axis::X), 0.0);
    QVERIFY(why.contains(QStringLiteral("soft limit 5000")));
}

void TestSoftLimits::clip_chunkEndsAtTheLimit()
{
    const SoftLimits l = xWithin(-10, 100);
    QString why;
    QCOMPARE(l.clipRelative(at(90), {{Axis::X, 40}, {Axis::Y, 40}}, &why),
             (AxisVector{{Axis::X, 10}, {Axis::Y, 40}}));
    QVERIFY(why.isEmpty()); // it still moves: the next chunk says it
    QCOMPARE(l.clipRelative(at(100), {{Axis::X, 40}}, &why), (AxisVector{{Axis::X, 0}}));
    QVERIFY(why.contains(QStringLiteral("soft limit 100")));
    QCOMPARE(l.clipRelative(at(100), {{Axis::X, -40}}, &why), (AxisVector{{Axis::X, -40}}));
    QCOMPARE(l.clipRelative(at(-5), {{Axis::X, -40}}, &why), (AxisVector{{Axis::X, -5}}));
    QCOMPARE(l.clipRelative(at(100, false), {{Axis::X, 40}}, &why), (AxisVector{{Axis::X, 40}}));
    QCOMPARE(l.room(Axis::X, +1, at(90)), qint64(10));
    QCOMPARE(l.room(Axis::X, +1, at(90, false)), qint64(-1));
}

STEPDECK_TEST_MAIN(TestSoftLimits)
#include "tst_softlimits.moc"
