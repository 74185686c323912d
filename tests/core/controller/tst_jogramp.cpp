// JogRamp: the host-side jog ramp the E-LAB manual demands ("Befehle im Jogbetrieb").
#include "TestMain.h"
#include "controller/JogRamp.h"
#include <QtTest>

using namespace stepdeck;

class TestJogRamp : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void advance_stepPerTick_boundedByAcceleration_data();
    void advance_stepPerTick_boundedByAcceleration();
    void jog_releasedKnob_rampsToZero();
    void setTarget_beyondMaxSpeed_isClamped_data();
    void setTarget_beyondMaxSpeed_isClamped();
    void setMaxSpeed_lowered_clampsExistingTargets();
    void reversal_passesThroughZero_data();
    void reversal_passesThroughZero();
    void reset_dropsRatesAtOnce();
    void setTargets_axesNotNamed_keepTarget();
    void setAcceleration_nonPositive_isIgnored();
    void advance_nonPositiveDt_changesNothing();
    void isIdle_onlyWhenRatesAndTargetsAreZero();
    void release_heldRates_travelWithinRampDistance_data();
    void release_heldRates_travelWithinRampDistance();
    void heldRates_speedingUpOrHolding_areTheCurrentRates();
    void heldRates_braking_neverPastTargetOrZero();
    void heldRates_changeSinceLastSent_boundedByAcceleration();
};

void TestJogRamp::advance_stepPerTick_boundedByAcceleration_data()
{
    QTest::addColumn<double>("acceleration");
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("target");
    QTest::addColumn<int>("ticksToTarget");

    // ticksToTarget = ceil(|target| / (acceleration * dt))
    QTest::newRow("2000/s2, 20 ms, +1000") << 2000.0 << 0.020 << 1000.0 << 25;
    QTest::newRow("2000/s2, 20 ms, -1000") << 2000.0 << 0.020 << -1000.0 << 25;
    QTest::newRow("500/s2, 10 ms, +333") << 500.0 << 0.010 << 333.0 << 67;
    QTest::newRow("10000/s2, 50 ms, +400") << 10000.0 << 0.050 << 400.0 << 1;
    QTest::newRow("1000/s2, 1 ms, -7") << 1000.0 << 0.001 << -7.0 << 7;
}

void TestJogRamp::advance_stepPerTick_boundedByAcceleration()
{
    QFETCH(double, acceleration);
    QFETCH(double, dt);
    QFETCH(double, target);
    QFETCH(int, ticksToTarget);

    JogRamp ramp(acceleration, 5000);
    ramp.setTarget(Axis::X, target);
    const double bound = acceleration * dt + 1e-9;
    double previous = 0;
    int ticks = 0;
    while (ramp.current(Axis::X) != target) {
        const double now = ramp.advance(dt).value(Axis::X);
        QVERIFY2(qAbs(now - previous) <= bound,
                 qPrintable(
                     QStringLiteral("step %1 -> %2 exceeds %3").arg(previous).arg(now).arg(bound)));
        previous = now;
        ++ticks;
        QVERIFY(ticks <= ticksToTarget);
    }
    QCOMPARE(ticks, ticksToTarget);
}

void TestJogRamp::jog_releasedKnob_rampsToZero()
{
    JogRamp ramp(2000, 1000);
    ramp.setTarget(Axis::Y, 800);
    for (int i = 0; i < 100; ++i)
        ramp.advance(0.02);
    QCOMPARE(ramp.current(Axis::Y), 800.0);

    ramp.releaseAll();
    QCOMPARE(ramp.target(Axis::Y), 0.0);
    double previous = ramp.current(Axis::Y);
    int ticks = 0;
    while (ramp.current(Axis::Y) != 0.0 && ticks < 1000) {
        const double now = ramp.advance(0.02).value(Axis::Y);
        QVERIFY(now < previous);                // monotonic
        QVERIFY(previous - now <= 40.0 + 1e-9); // 2000 * 0.02
        QVERIFY(now >= 0.0);                    // never overshoots into reverse
        previous = now;
        ++ticks;
    }
    QCOMPARE(ticks, 20);
    QVERIFY(ramp.isIdle());
}

void TestJogRamp::setTarget_beyondMaxSpeed_isClamped_data()
{
    QTest::addColumn<double>("maxSpeed");
    QTest::addColumn<double>("requested");
    QTest::addColumn<double>("expected");

    QTest::newRow("inside") << 1000.0 << 250.0 << 250.0;
    QTest::newRow("above") << 1000.0 << 1500.0 << 1000.0;
    QTest::newRow("below") << 1000.0 << -1e9 << -1000.0;
    QTest::newRow("exactly") << 300.0 << -300.0 << -300.0;
    QTest::newRow("not a number") << 300.0 << qQNaN() << 0.0;
    QTest::newRow("infinite") << 300.0 << qInf() << 0.0;
}

void TestJogRamp::setTarget_beyondMaxSpeed_isClamped()
{
    QFETCH(double, maxSpeed);
    QFETCH(double, requested);
    QFETCH(double, expected);

    JogRamp ramp(1e6, maxSpeed);
    ramp.setTarget(Axis::Z, requested);
    QCOMPARE(ramp.target(Axis::Z), expected);
    ramp.advance(1.0);
    QCOMPARE(ramp.current(Axis::Z), expected);
}

void TestJogRamp::setMaxSpeed_lowered_clampsExistingTargets()
{
    JogRamp ramp(1e6, 1000);
    ramp.setTargets({{Axis::X, 900}, {Axis::Y, -900}});
    ramp.setMaxSpeed(500);
    QCOMPARE(ramp.target(Axis::X), 500.0);
    QCOMPARE(ramp.target(Axis::Y), -500.0);
}

void TestJogRamp::reversal_passesThroughZero_data()
{
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<double>("acceleration");

    QTest::newRow("+ to -") << 100.0 << -100.0 << 2000.0;
    QTest::newRow("- to +") << -100.0 << 100.0 << 2000.0;
    // A step large enough to jump the whole way still stops at zero for one tick.
    QTest::newRow("huge acceleration") << 100.0 << -100.0 << 1e9;
}

void TestJogRamp::reversal_passesThroughZero()
{
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(double, acceleration);

    JogRamp ramp(acceleration, 1000);
    ramp.setTarget(Axis::X, from);
    while (ramp.current(Axis::X) != from)
        ramp.advance(0.01);

    ramp.setTarget(Axis::X, to);
    QList<double> seen;
    for (int i = 0; i < 1000 && ramp.current(Axis::X) != to; ++i)
        seen << ramp.advance(0.01).value(Axis::X);
    QCOMPARE(seen.last(), to);
    QVERIFY(seen.contains(0.0));
    double previous = from;
    for (double v : seen) {
        // No tick changes sign without standing at zero in between.
        QVERIFY2(!(previous > 0 && v < 0) && !(previous < 0 && v > 0),
                 qPrintable(QStringLiteral("%1 -> %2").arg(previous).arg(v)));
        previous = v;
    }
}

void TestJogRamp::reset_dropsRatesAtOnce()
{
    JogRamp ramp(2000, 1000);
    ramp.setTargets({{Axis::X, 500}, {Axis::Z, -500}});
    for (int i = 0; i < 10; ++i)
        ramp.advance(0.02);
    QVERIFY(ramp.current(Axis::X) > 0);
    ramp.reset();
    QCOMPARE(ramp.current(Axis::X), 0.0);
    QCOMPARE(ramp.current(Axis::Z), 0.0);
    QCOMPARE(ramp.target(Axis::X), 0.0);
    QVERIFY(ramp.isIdle());
    // Nothing left to ramp back up to.
    ramp.advance(0.02);
    QCOMPARE(ramp.current(Axis::X), 0.0);
}

void TestJogRamp::setTargets_axesNotNamed_keepTarget()
{
    JogRamp ramp;
    ramp.setTargets({{Axis::X, 100}, {Axis::Y, 200}});
    ramp.setTargets({{Axis::Y, -50}});
    QCOMPARE(ramp.target(Axis::X), 100.0);
    QCOMPARE(ramp.target(Axis::Y), -50.0);
    QCOMPARE(ramp.target(Axis::Z), 0.0);
}

void TestJogRamp::setAcceleration_nonPositive_isIgnored()
{
    JogRamp ramp(1500, 1000);
    ramp.setAcceleration(0);
    QCOMPARE(ramp.acceleration(), 1500.0);
    ramp.setAcceleration(-5);
    QCOMPARE(ramp.acceleration(), 1500.0);
    ramp.setAcceleration(3000);
    QCOMPARE(ramp.acceleration(), 3000.0);
}

void TestJogRamp::advance_nonPositiveDt_changesNothing()
{
    JogRamp ramp(2000, 1000);
    ramp.setTarget(Axis::X, 500);
    ramp.advance(0);
    ramp.advance(-1);
    QCOMPARE(ramp.current(Axis::X), 0.0);
}

void TestJogRamp::isIdle_onlyWhenRatesAndTargetsAreZero()
{
    JogRamp ramp(2000, 1000);
    QVERIFY(ramp.isIdle());
    ramp.setTarget(Axis::X, 10);
    QVERIFY(!ramp.isIdle()); // target set, rate still zero
    ramp.advance(1.0);
    ramp.releaseAll();
    QVERIFY(!ramp.isIdle()); // target zero, rate not yet
    ramp.advance(1.0);
    QVERIFY(ramp.isIdle());
}

// Issue 28 item 6: what the device travels after a release, as the Controller drives the
// ramp: the rate held since the last tick runs on until the next one (the release comes just
// after a tick: the worst case), then each tick advances the ramp and the device holds
// heldRates() until the following tick. The total stays within JogRamp::stopDistance (v^2 /
// (2a) unless braking is shorter than two ticks), the distance the jog panel shows; the rates
// at the start of each tick (current()) overshoot it.
void TestJogRamp::release_heldRates_travelWithinRampDistance_data()
{
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("acceleration");
    QTest::addColumn<double>("tick");

    // 10 mm/s at 400 steps/mm with the machine default (stops within 1 mm = 400 steps).
    QTest::newRow("E-LAB 4000 steps/s, 20000/s2, 20 ms") << 4000.0 << 20000.0 << 0.020;
    QTest::newRow("E-LAB default ramp, 5000 steps/s") << 5000.0 << 2000.0 << 0.020;
    QTest::newRow("slow, 5 ms ticks") << 300.0 << 1000.0 << 0.005;
    QTest::newRow("stops within one tick") << 100.0 << 1e6 << 0.020;
    QTest::newRow("negative") << -3000.0 << 15000.0 << 0.020;
}

void TestJogRamp::release_heldRates_travelWithinRampDistance()
{
    QFETCH(double, speed);
    QFETCH(double, acceleration);
    QFETCH(double, tick);

    JogRamp ramp(acceleration, 5000);
    ramp.setTarget(Axis::X, speed);
    for (int i = 0; i < 10000 && ramp.current(Axis::X) != speed; ++i)
        ramp.advance(tick);
    QCOMPARE(ramp.heldRates(tick).value(Axis::X), speed);

    ramp.releaseAll();
    double travelled = qAbs(speed) * tick; // held until the next tick
    int ticks = 0;
    while (!ramp.isIdle() && ticks++ < 100000) {
        ramp.advance(tick);
        travelled += qAbs(ramp.heldRates(tick).value(Axis::X)) * tick;
    }
    const double bound = JogRamp::stopDistance(speed, acceleration, tick);
    if (qAbs(speed) >= 2 * acceleration * tick) // braking spans two ticks: the ramp's distance
        QCOMPARE(bound, speed * speed / (2 * acceleration));
    QVERIFY2(travelled <= bound + 1e-6,
             qPrintable(
                 QStringLiteral("%1 steps after the release, bound %2").arg(travelled).arg(bound)));
}

void TestJogRamp::heldRates_speedingUpOrHolding_areTheCurrentRates()
{
    JogRamp ramp(2000, 5000);
    ramp.setTargets({{Axis::X, 1000}, {Axis::Y, -1000}});
    ramp.advance(0.1);
    QCOMPARE(ramp.heldRates(0.02), ramp.currentVelocities()); // speeding up
    ramp.advance(1.0);
    QCOMPARE(ramp.heldRates(0.02), ramp.currentVelocities()); // at the target
}

void TestJogRamp::heldRates_braking_neverPastTargetOrZero()
{
    JogRamp ramp(1000, 5000);
    ramp.setTargets({{Axis::X, 100}, {Axis::Y, -100}, {Axis::Z, 100}});
    ramp.advance(1.0);
    ramp.setTargets({{Axis::X, 90}, {Axis::Y, 50}, {Axis::Z, 0}});
    const AxisVelocities held = ramp.heldRates(0.02); // 20 steps/s a tick
    QCOMPARE(held.value(Axis::X), 90.0);              // lowered: not below the new target
    QCOMPARE(held.value(Axis::Y), -80.0);             // reversing: towards zero first
    QCOMPARE(held.value(Axis::Z), 80.0);
    QCOMPARE(ramp.heldRates(10.0).value(Axis::Y), 0.0);
    QCOMPARE(ramp.heldRates(10.0).value(Axis::Z), 0.0);
}

// The look ahead never makes a change the motor could not follow: at most acceleration x the
// time since the rates were last sent below them; and an axis stopped at once stays stopped.
void TestJogRamp::heldRates_changeSinceLastSent_boundedByAcceleration()
{
    JogRamp ramp(1000, 5000);
    ramp.setTargets({{Axis::X, 100}, {Axis::Y, 100}});
    ramp.advance(1.0);
    ramp.releaseAll();
    ramp.advance(0.02); // 80 steps/s now
    const AxisVelocities sent{{Axis::X, 100}, {Axis::Y, 100}};
    // Sent 20 ms ago: no further than 100 - 20 = 80, the ramp's own step.
    QCOMPARE(ramp.heldRates(0.02, sent, 0.02).value(Axis::X), 80.0);
    // Sent 40 ms ago (it ran at 100 for a tick): the whole look ahead, 60.
    QCOMPARE(ramp.heldRates(0.02, sent, 0.04).value(Axis::X), 60.0);
    QCOMPARE(ramp.heldRates(0.02).value(Axis::X), 60.0);
    ramp.stopAxis(Axis::Y);
    QCOMPARE(ramp.heldRates(0.02, sent, 0.0).value(Axis::Y), 0.0);
}

STEPDECK_TEST_GUILESS_MAIN(TestJogRamp)
#include "tst_jogramp.moc"
