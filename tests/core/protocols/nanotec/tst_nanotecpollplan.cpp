// The Nanotec poll plan (issue 32, step 4): moving drives in every sweep, the idle ones in
// turn within the wire budget of one poll interval, silent ones now and then. The plan is pure,
// so these tests walk sweeps, not time: at the poll interval of 50 ms, 100 sweeps are 5 s.
#include "TestMain.h"
#include "protocols/nanotec/NanotecPollPlan.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::nanotec;

namespace {
constexpr double kCharUs19200 = 1e6 * 10 / 19200; // 8N1
using Plan = NanotecPollPlan;

QList<Plan::Drive> bus(int drives, QList<int> activeIndices = {}, QList<int> silentIndices = {})
{
    QList<Plan::Drive> list;
    for (int i = 0; i < drives; ++i)
        list << Plan::Drive{Axis::at(i), activeIndices.contains(i), !silentIndices.contains(i)};
    return list;
}

double cost(const Plan& plan, const QList<Plan::Read>& sweep)
{
    double ms = 0;
    for (const Plan::Read& r : sweep)
        ms += plan.statusMs() +
              ((r.active ? r.positionWhileRunning : r.position) ? plan.positionMs() : 0) +
              (r.inputs ? plan.inputsMs() : 0);
    return ms;
}

QList<Axis> axesOf(const QList<Plan::Read>& sweep)
{
    QList<Axis> axes;
    for (const Plan::Read& r : sweep)
        axes << r.axis;
    return axes;
}
} // namespace

class TestNanotecPollPlan : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void smallBus_everyDriveEverySweep_data();
    void smallBus_everyDriveEverySweep();
    void fullBus_movingDriveEverySweep_idleEachWithin5s_data();
    void fullBus_movingDriveEverySweep_idleEachWithin5s();
    void manyMoving_allEverySweep_idleNeverStarved();
    void idleVisits_positionAndInputsEveryEighth();
    void lean_runningPositionEveryOtherSweep();
    void lean_smallBus_idleEveryOtherSweep_fullBusEverySweep();
    void silentDrives_oneEveryTenthSweep_inTurn();
    void nobodyAnswers_everyDriveInTurn();
};

void TestNanotecPollPlan::smallBus_everyDriveEverySweep_data()
{
    QTest::addColumn<int>("drives");
    QTest::newRow("1") << 1;
    QTest::newRow("2") << 2;
}

// A bus that fits the budget keeps the sweep it always had: every drive, '$' and 'C', the
// inputs every fourth sweep.
void TestNanotecPollPlan::smallBus_everyDriveEverySweep()
{
    QFETCH(int, drives);
    Plan plan(kCharUs19200);
    for (int s = 1; s <= 8; ++s) {
        const QList<Plan::Read> sweep = plan.next(bus(drives), false);
        QCOMPARE(sweep.size(), drives);
        for (const Plan::Read& r : sweep) {
            QVERIFY(r.position);
            QCOMPARE(r.inputs, s % 4 == 1);
        }
    }
}

void TestNanotecPollPlan::fullBus_movingDriveEverySweep_idleEachWithin5s_data()
{
    QTest::addColumn<int>("drives");
    QTest::addColumn<int>("moving"); // index, -1: none
    QTest::newRow("8, one moving") << 8 << 5;
    QTest::newRow("32, one moving") << 32 << 0;
    QTest::newRow("254, one moving") << 254 << 200;
    QTest::newRow("254, none moving") << 254 << -1;
}

// The measure as logic: the moving drive is read in every sweep, first, and the sweep
// stays within one 50 ms interval of wire time, so it is read at least every 50 ms; each idle
// drive comes again within 5 s. A sweep starts one interval after the last one started, or
// when it ended if it took longer (StatusPoller); a pending run expedites the interval to
// 10 ms. Time here is that model over the plan's own estimate of each sweep's wire time.
void TestNanotecPollPlan::fullBus_movingDriveEverySweep_idleEachWithin5s()
{
    QFETCH(int, drives);
    QFETCH(int, moving);
    Plan plan(kCharUs19200);
    const QList<Plan::Drive> list = bus(drives, moving >= 0 ? QList<int>{moving} : QList<int>{});
    QMap<Axis, double> lastSeen;
    double longestGapMs = 0;
    double nowMs = 0;
    const double intervalMs = moving >= 0 ? 10 : 50;
    for (int s = 1; s <= 300; ++s) {
        // A pending run expedites the poller: lean sweeps (NanotecStatus::onPollDue).
        const QList<Plan::Read> sweep = plan.next(list, moving >= 0);
        QVERIFY(!sweep.isEmpty());
        if (moving >= 0) {
            QCOMPARE(sweep.first().axis, Axis::at(moving));
            QVERIFY(sweep.first().active);
            QCOMPARE(axesOf(sweep).count(Axis::at(moving)), 1);
        }
        QVERIFY2(cost(plan, sweep) <= 50, // the poll interval
                 qPrintable(QStringLiteral("sweep %1 costs %2 ms").arg(s).arg(cost(plan, sweep))));
        for (Axis a : axesOf(sweep)) {
            longestGapMs = qMax(longestGapMs, nowMs - lastSeen.value(a, 0.0));
            lastSeen.insert(a, nowMs);
        }
        nowMs += qMax(intervalMs, cost(plan, sweep));
    }
    QCOMPARE(lastSeen.size(), drives); // nobody starved
    QVERIFY2(longestGapMs <= 5000, qPrintable(QString::number(longestGapMs)));
    if (drives == 254)
        QVERIFY2(longestGapMs > 1000, "a full bus cannot read every idle drive every sweep");
}

// Ten drives moving at once: all ten in every sweep (moving first), and still one idle drive
// per sweep, so the idle ones are slower but never forgotten.
void TestNanotecPollPlan::manyMoving_allEverySweep_idleNeverStarved()
{
    Plan plan(kCharUs19200);
    QList<int> movingIndices;
    for (int i = 0; i < 10; ++i)
        movingIndices << i * 3;
    const QList<Plan::Drive> list = bus(40, movingIndices);
    QSet<Axis> idleSeen;
    for (int s = 1; s <= 40; ++s) {
        const QList<Plan::Read> sweep = plan.next(list, false);
        for (int i = 0; i < 10; ++i) {
            QCOMPARE(sweep.at(i).axis, Axis::at(movingIndices.at(i)));
            QVERIFY(sweep.at(i).active);
        }
        QVERIFY(sweep.size() >= 11);
        for (int i = 10; i < sweep.size(); ++i)
            idleSeen.insert(sweep.at(i).axis);
    }
    QCOMPARE(idleSeen.size(), 30);
}

// On a full bus an idle drive's 'C' and 'ZY' come every eighth visit, four visits apart, and
// the drives start at different places of that cycle.
void TestNanotecPollPlan::idleVisits_positionAndInputsEveryEighth()
{
    Plan plan(kCharUs19200);
    const QList<Plan::Drive> list = bus(254);
    QMap<Axis, QList<Plan::Read>> visits;
    for (int s = 0; s < 1000; ++s) {
        for (const Plan::Read& r : plan.next(list, false))
            visits[r.axis] << r;
    }
    for (int index : {0, 5, 253}) {
        const QList<Plan::Read>& seen = visits.value(Axis::at(index));
        QVERIFY2(seen.size() >= 9, qPrintable(QString::number(seen.size())));
        const int start = index % 8;
        for (int v = 0; v < seen.size(); ++v) {
            QCOMPARE(seen.at(v).position, (start + v) % 8 == 0);
            QCOMPARE(seen.at(v).inputs, (start + v) % 8 == 4);
        }
    }
}

// While a run is pending and the poller is expedited, the running drive's '$' is read every
// sweep and its 'C' every other (issue 30); without lean every sweep.
void TestNanotecPollPlan::lean_runningPositionEveryOtherSweep()
{
    Plan plan(kCharUs19200);
    const QList<Plan::Drive> list = bus(3, {1});
    QList<bool> withPosition;
    for (int s = 0; s < 4; ++s)
        withPosition << plan.next(list, true).first().positionWhileRunning;
    QCOMPARE(withPosition, (QList<bool>{false, true, false, true}));
    QVERIFY(plan.next(list, false).first().positionWhileRunning);
}

// Issue 30's lean sweeps: on a small bus the idle drives wait three sweeps of four while a run
// is pending; on a full bus they cannot (they would wait past 5 s).
void TestNanotecPollPlan::lean_smallBus_idleEveryOtherSweep_fullBusEverySweep()
{
    for (int drives : {3, 33, 34, 254}) {
        Plan plan(kCharUs19200);
        const QList<Plan::Drive> list = bus(drives, {0});
        QList<int> sizes;
        for (int s = 0; s < 4; ++s)
            sizes << int(plan.next(list, true).size());
        const bool skips = drives - 1 <= Plan::kLeanSkipMaxIdle;
        QCOMPARE(sizes.at(0) == 1, skips); // sweeps 1..3: the running drive alone
        QCOMPARE(sizes.at(1) == 1, skips);
        QCOMPARE(sizes.at(2) == 1, skips);
        QVERIFY(sizes.at(3) > 1);
    }
}

void TestNanotecPollPlan::silentDrives_oneEveryTenthSweep_inTurn()
{
    Plan plan(kCharUs19200);
    const QList<Plan::Drive> list = bus(6, {}, {1, 4});
    QList<Axis> silentAsked;
    for (int s = 1; s <= 40; ++s) {
        for (const Plan::Read& r : plan.next(list, false)) {
            if (r.axis == Axis::at(1) || r.axis == Axis::at(4)) {
                QCOMPARE(s % Plan::kSilentEverySweeps, 0);
                silentAsked << r.axis;
            }
        }
    }
    QCOMPARE(silentAsked, (QList<Axis>{Axis::at(1), Axis::at(4), Axis::at(1), Axis::at(4)}));
}

// No drive answers (a cable pulled): every drive is asked in turn, within the budget; the
// poller counts the sweeps as misses and loses the link.
void TestNanotecPollPlan::nobodyAnswers_everyDriveInTurn()
{
    Plan plan(kCharUs19200);
    QList<int> all;
    for (int i = 0; i < 20; ++i)
        all << i;
    const QList<Plan::Drive> list = bus(20, {}, all);
    QSet<Axis> asked;
    for (int s = 0; s < 20; ++s) {
        const QList<Plan::Read> sweep = plan.next(list, false);
        QVERIFY(!sweep.isEmpty());
        for (Axis a : axesOf(sweep))
            asked.insert(a);
    }
    QCOMPARE(asked.size(), 20);
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecPollPlan)
#include "tst_nanotecpollplan.moc"
