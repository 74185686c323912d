// StatusPoller: one poll in flight, link loss after N unanswered polls, achieved rate.
#include "TestMain.h"
#include "TestSupport.h"
#include "controller/StatusPoller.h"
#include <QElapsedTimer>
#include <QtTest>

using namespace stepdeck;

class TestStatusPoller : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void start_firstPollDueAtOnce();
    void pollInFlight_noFurtherPollDue();
    void pollFinished_nextPollDueAgain();
    void expedited_nextPollDueLongBeforeTheInterval();
    void misses_linkLostExactlyOnceAtLimit_data();
    void misses_linkLostExactlyOnceAtLimit();
    void answeredPoll_resetsMissCount();
    void pollFinished_withoutStart_isIgnored();
    void stop_noMorePollDue();
    void answeredPolls_rateReported();
};

void TestStatusPoller::start_firstPollDueAtOnce()
{
    StatusPoller poller;
    QSignalSpy due(&poller, &StatusPoller::pollDue);
    QVERIFY(!poller.isDue()); // not started yet
    poller.start();
    QVERIFY(poller.isActive());
    QVERIFY(poller.isDue());
    QVERIFY(due.wait(1000));
}

void TestStatusPoller::pollInFlight_noFurtherPollDue()
{
    StatusPoller poller;
    poller.setInterval(10);
    QSignalSpy due(&poller, &StatusPoller::pollDue);
    poller.start();
    QVERIFY(due.wait(1000));
    poller.pollStarted();
    QVERIFY(poller.isPollInFlight());
    QVERIFY(!poller.isDue());
    // Many intervals pass; with a poll in flight nothing new is due.
    QVERIFY(test::staysQuiet(due, 150));
    QVERIFY(!poller.isDue());
}

void TestStatusPoller::pollFinished_nextPollDueAgain()
{
    StatusPoller poller;
    poller.setInterval(20);
    QSignalSpy due(&poller, &StatusPoller::pollDue);
    poller.start();
    QVERIFY(due.wait(1000));
    poller.pollStarted();
    poller.pollFinished(true);
    QVERIFY(!poller.isPollInFlight());
    due.clear();
    QVERIFY(due.wait(1000));
    QVERIFY(poller.isDue());
}

void TestStatusPoller::expedited_nextPollDueLongBeforeTheInterval()
{
    StatusPoller poller;
    poller.setInterval(60000);
    QSignalSpy due(&poller, &StatusPoller::pollDue);
    poller.start();
    QVERIFY(due.wait(1000));
    poller.pollStarted();
    poller.pollFinished(true);
    due.clear();
    QVERIFY(test::staysQuiet(due, 100)); // a minute's interval
    QCOMPARE(poller.effectiveInterval(), 60000);
    poller.setExpedited(true);
    QCOMPARE(poller.effectiveInterval(), StatusPoller::kExpeditedIntervalMs);
    QVERIFY(due.wait(1000));
    QVERIFY(poller.isDue());
    poller.pollStarted();
    poller.pollFinished(true);
    poller.setExpedited(false);
    due.clear();
    QVERIFY(test::staysQuiet(due, 100));
    QVERIFY(!poller.isDue());
    // A shorter interval of the user's own is kept.
    poller.setInterval(5);
    poller.setExpedited(true);
    QCOMPARE(poller.effectiveInterval(), 5);
    // stop() ends the expedited pace.
    poller.stop();
    QVERIFY(!poller.isExpedited());
}

void TestStatusPoller::misses_linkLostExactlyOnceAtLimit_data()
{
    QTest::addColumn<int>("limit");
    QTest::addColumn<int>("misses");
    QTest::addColumn<int>("expectedLinkLost");

    QTest::newRow("2 of 3") << 3 << 2 << 0;
    QTest::newRow("3 of 3") << 3 << 3 << 1;
    QTest::newRow("7 of 3") << 3 << 7 << 1;
    QTest::newRow("1 of 1") << 1 << 1 << 1;
    QTest::newRow("4 of 5") << 5 << 4 << 0;
}

void TestStatusPoller::misses_linkLostExactlyOnceAtLimit()
{
    QFETCH(int, limit);
    QFETCH(int, misses);
    QFETCH(int, expectedLinkLost);

    StatusPoller poller;
    poller.setMissLimit(limit);
    QSignalSpy lost(&poller, &StatusPoller::linkLost);
    poller.start();
    for (int i = 0; i < misses; ++i) {
        poller.pollStarted();
        poller.pollFinished(false);
    }
    QCOMPARE(poller.consecutiveMisses(), misses);
    QCOMPARE(lost.count(), expectedLinkLost);
    if (expectedLinkLost)
        QCOMPARE(lost.first().at(0).toInt(), limit);
}

void TestStatusPoller::answeredPoll_resetsMissCount()
{
    StatusPoller poller;
    QSignalSpy lost(&poller, &StatusPoller::linkLost);
    poller.start();
    for (int round = 0; round < 3; ++round) {
        for (int i = 0; i < 2; ++i) {
            poller.pollStarted();
            poller.pollFinished(false);
        }
        QCOMPARE(poller.consecutiveMisses(), 2);
        poller.pollStarted();
        poller.pollFinished(true);
        QCOMPARE(poller.consecutiveMisses(), 0);
    }
    // 6 misses in total, never 3 in a row.
    QCOMPARE(lost.count(), 0);
}

void TestStatusPoller::pollFinished_withoutStart_isIgnored()
{
    StatusPoller poller;
    QSignalSpy lost(&poller, &StatusPoller::linkLost);
    poller.setMissLimit(1);
    poller.start();
    poller.pollFinished(false); // a late report for a poll that was never started
    QCOMPARE(poller.consecutiveMisses(), 0);
    QCOMPARE(lost.count(), 0);
}

void TestStatusPoller::stop_noMorePollDue()
{
    StatusPoller poller;
    poller.setInterval(5);
    QSignalSpy due(&poller, &StatusPoller::pollDue);
    poller.start();
    QVERIFY(due.wait(1000));
    poller.stop();
    QVERIFY(!poller.isActive());
    QVERIFY(!poller.isDue());
    QVERIFY(test::staysQuiet(due, 100));
}

void TestStatusPoller::answeredPolls_rateReported()
{
    StatusPoller poller;
    poller.setInterval(10);
    QSignalSpy rate(&poller, &StatusPoller::rateChanged);
    // An instant "adapter": starts every due poll and answers it at once.
    connect(&poller, &StatusPoller::pollDue, &poller, [&poller] {
        poller.pollStarted();
        poller.pollFinished(true);
    });
    QElapsedTimer clock;
    clock.start();
    poller.start();
    QTRY_VERIFY_WITH_TIMEOUT(poller.achievedRateHz() >= 5.0, 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!rate.isEmpty() && rate.last().at(0).toDouble() > 0.0, 5000);
    // Throttled: at most one report per 500 ms (plus the first).
    QVERIFY2(
        rate.count() <= clock.elapsed() / 500 + 1,
        qPrintable(QStringLiteral("%1 reports in %2 ms").arg(rate.count()).arg(clock.elapsed())));
    // Never faster than the interval allows (1000 ms / 10 ms), whatever the load.
    QVERIFY(poller.achievedRateHz() <= 101.0);

    poller.stop();
    QCOMPARE(poller.achievedRateHz(), 0.0);
    QCOMPARE(rate.last().at(0).toDouble(), 0.0);
}

STEPDECK_TEST_GUILESS_MAIN(TestStatusPoller)
#include "tst_statuspoller.moc"
