// ContourFeed (issue 30): a contour given by one thread and pulled by another. The ticks the
// consumer gets while a producer thread appends moves are the ticks of the same moves laid in
// one thread; the wake-up is called for every move given and for the close; a consumer that
// finds nothing counts it (the stream had to wait).
#include "TestMain.h"
#include "motion/ContourFeed.h"
#include <QThread>
#include <QtTest>
#include <atomic>

using namespace stepdeck::motion;

class TestContourFeed : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void producerThread_consumerGetsTheSameTicksAsOneThread();
    void wakeUp_calledPerMoveAndClose_starvedPullsCounted();
    void hold_noTickUntilReleasedThenTheSameTicks();
};

namespace {

constexpr double kFeedTickRate = 2000;

ContourSteps fresh()
{
    StepScale s;
    s.axisCount = 2;
    s.stepsPerUnit = {100, 100};
    return ContourSteps(s, {}, {}, kFeedTickRate, 1.0, 8);
}

// A zigzag of 200 short lines, 1 mm each, at 5 mm/s.
CanonicalMove zig(int i)
{
    const double y0 = (i % 2) ? 1.0 : 0.0;
    return CanonicalMove::straight(2, {double(i), y0}, {double(i + 1), 1.0 - y0}, 5, i + 1);
}

QList<StepPosition> drain(ContourFeed& feed)
{
    QList<StepPosition> out;
    StepPosition at{};
    StepTick ticks[32];
    while (!feed.finished()) {
        const int n = feed.pull(ticks, 32);
        for (int i = 0; i < n; ++i) {
            for (int a = 0; a < 2; ++a)
                at[size_t(a)] += ticks[i].step[size_t(a)];
            out << at;
        }
        if (n == 0)
            QThread::yieldCurrentThread(); // the producer's turn
    }
    return out;
}

} // namespace

void TestContourFeed::producerThread_consumerGetsTheSameTicksAsOneThread()
{
    ContourFeed reference(fresh());
    QThread* one = QThread::create([&] {
        for (int i = 0; i < 200; ++i)
            while (!reference.append(zig(i)).isEmpty())
                QThread::yieldCurrentThread(); // full: wait for the consumer
        reference.close();
    });
    // The same moves laid in this thread alone, for comparison.
    ContourSteps alone = fresh();
    QList<StepPosition> expected;
    StepPosition at{};
    StepTick ticks[32];
    for (int i = 0; i < 200; ++i) {
        while (!alone.append(zig(i)).isEmpty()) {
            const int n = alone.pull(ticks, 32);
            for (int k = 0; k < n; ++k) {
                for (int a = 0; a < 2; ++a)
                    at[size_t(a)] += ticks[k].step[size_t(a)];
                expected << at;
            }
        }
    }
    alone.close();
    while (const int n = alone.pull(ticks, 32))
        for (int k = 0; k < n; ++k) {
            for (int a = 0; a < 2; ++a)
                at[size_t(a)] += ticks[k].step[size_t(a)];
            expected << at;
        }
    one->start();
    const QList<StepPosition> got = drain(reference);
    QVERIFY(one->wait(30000));
    delete one;
    QCOMPARE(got.size(), expected.size());
    QCOMPARE(got, expected);
    QCOMPARE(got.last(), (StepPosition{20000, 0}));
}

void TestContourFeed::wakeUp_calledPerMoveAndClose_starvedPullsCounted()
{
    ContourFeed feed(fresh());
    std::atomic<int> wakes{0};
    feed.setWakeUp([&] { ++wakes; });
    StepTick ticks[4];
    QCOMPARE(feed.pull(ticks, 4), 0); // nothing given yet
    QCOMPARE(feed.starvedPulls(), qint64(1));
    QVERIFY(feed.append(zig(0)).isEmpty());
    QVERIFY(feed.append(zig(1)).isEmpty());
    QVERIFY(!feed.append(CanonicalMove::straight(2, {5, 5}, {6, 6}, 5, 9)).isEmpty()); // elsewhere
    feed.close();
    QCOMPARE(wakes.load(), 3); // two moves and the close; a refused move wakes nobody
    feed.setWakeUp({});
    QVERIFY(!feed.canAppend());
    while (feed.pull(ticks, 4) > 0) {
    }
    QVERIFY(feed.finished());
    QCOMPARE(feed.steps()[0], qint64(200));
    QCOMPARE(feed.starvedPulls(), qint64(1)); // finished is not starved
}

// A feed hold gives no tick (and is not counted as starved); released, it wakes the consumer
// and the rest of the path comes, the ticks the same as without the hold.
void TestContourFeed::hold_noTickUntilReleasedThenTheSameTicks()
{
    ContourFeed plain(fresh());
    ContourFeed held(fresh());
    std::atomic<int> wakes{0};
    held.setWakeUp([&] { ++wakes; });
    for (int i = 0; i < 4; ++i) {
        QVERIFY(plain.append(zig(i)).isEmpty());
        QVERIFY(held.append(zig(i)).isEmpty());
    }
    plain.close();
    held.close();
    const int before = wakes.load();
    StepTick ticks[64];
    QCOMPARE(held.pull(ticks, 64), 64);
    held.setHeld(true);
    QVERIFY(held.isHeld());
    QCOMPARE(held.pull(ticks, 64), 0);
    QCOMPARE(held.pull(ticks, 64), 0);
    QCOMPARE(held.starvedPulls(), qint64(0));
    QVERIFY(!held.finished());
    held.setHeld(false);
    QCOMPARE(wakes.load(), before + 1);
    const QList<StepPosition> rest = drain(held);
    const QList<StepPosition> all = drain(plain);
    QCOMPARE(rest.size() + 64, all.size());
    QCOMPARE(held.steps(), plain.steps());
    QCOMPARE(held.ticks(), plain.ticks());
}

STEPDECK_TEST_GUILESS_MAIN(TestContourFeed)
#include "tst_contourfeed.moc"
