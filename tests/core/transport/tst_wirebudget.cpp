// WireBudget: what a serial line can have carried of the host's bytes, on an invented clock.
#include "TestMain.h"
#include "transport/WireBudget.h"
#include <QtTest>

using namespace stepdeck;

namespace {
constexpr qint64 kMs = 1000000; // ns
// 57600 baud, 8N2: 11 bits per character.
constexpr double kCharacterUs = 11.0 * 1e6 / 57600.0; // 190.97 us
qint64 characters(double n)
{
    return qint64(n * kCharacterUs * 1000.0);
}
} // namespace

class TestWireBudget : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void backlog_drainsAtCharacterRate_data();
    void backlog_drainsAtCharacterRate();
    void write_behindBacklog_queuesBackToBack();
    void write_afterIdleLine_earnsNoCredit();
    void nsUntilBacklog_landsExactlyOnTheLimit_data();
    void nsUntilBacklog_landsExactlyOnTheLimit();
    void clear_lineEmpty();
    void write_clockFarPastTwoSeconds_exactTimes_data();
    void write_clockFarPastTwoSeconds_exactTimes();
};

void TestWireBudget::backlog_drainsAtCharacterRate_data()
{
    QTest::addColumn<qint64>("atNs");
    QTest::addColumn<qint64>("backlog");
    const qint64 t0 = 5 * kMs;
    QTest::newRow("just written") << t0 << qint64(16);
    QTest::newRow("first byte half sent") << t0 + characters(0.5) << qint64(16);
    QTest::newRow("one byte sent") << t0 + characters(1) + 1 << qint64(15);
    QTest::newRow("a byte before the last") << t0 + characters(14.9) << qint64(2);
    QTest::newRow("last byte partly sent") << t0 + characters(15.99) << qint64(1);
    QTest::newRow("all sent") << t0 + characters(16) + 1 << qint64(0);
    QTest::newRow("long after") << t0 + 100 * kMs << qint64(0);
}

void TestWireBudget::backlog_drainsAtCharacterRate()
{
    QFETCH(qint64, atNs);
    QFETCH(qint64, backlog);
    WireBudget wire(kCharacterUs);
    wire.write(16, 5 * kMs);
    QCOMPARE(wire.backlog(atNs), backlog);
}

void TestWireBudget::write_behindBacklog_queuesBackToBack()
{
    WireBudget wire(kCharacterUs);
    const qint64 t0 = 1 * kMs;
    QCOMPARE(wire.write(16, t0), t0);
    // Half of it still on the way: the next bytes start behind it, not now.
    const qint64 t1 = t0 + characters(8) + 1;
    QCOMPARE(wire.write(16, t1), t0 + characters(16) + 1);
    QCOMPARE(wire.backlog(t1), qint64(8 + 16));
    QCOMPARE(wire.backlog(t0 + characters(31.5)), qint64(1));
    QCOMPARE(wire.backlog(t0 + characters(32) + 2), qint64(0));
}

void TestWireBudget::write_afterIdleLine_earnsNoCredit()
{
    WireBudget wire(kCharacterUs);
    wire.write(2, 0);
    // 100 ms idle: the line could have carried 500 bytes, but none of the next ones earlier
    // than they are written.
    const qint64 t = 100 * kMs;
    QCOMPARE(wire.write(16, t), t);
    QCOMPARE(wire.backlog(t), qint64(16));
}

void TestWireBudget::nsUntilBacklog_landsExactlyOnTheLimit_data()
{
    QTest::addColumn<qint64>("limit");
    for (qint64 limit : {0, 1, 2, 8, 15})
        QTest::newRow(qPrintable(QString::number(limit))) << limit;
}

void TestWireBudget::nsUntilBacklog_landsExactlyOnTheLimit()
{
    QFETCH(qint64, limit);
    WireBudget wire(kCharacterUs);
    const qint64 t0 = 3 * kMs;
    wire.write(16, t0);
    const qint64 wait = wire.nsUntilBacklog(limit, t0);
    QVERIFY(wait > 0);
    QVERIFY2(wire.backlog(t0 + wait) <= limit, qPrintable(QString::number(wait)));
    // Not much earlier: a microsecond before, the limit is not reached yet.
    QVERIFY2(wire.backlog(t0 + wait - 1000) > limit, qPrintable(QString::number(wait)));
    QCOMPARE(wire.nsUntilBacklog(limit, t0 + wait), qint64(0));
    QCOMPARE(wire.nsUntilBacklog(16, t0), qint64(0)); // already so
}

void TestWireBudget::clear_lineEmpty()
{
    WireBudget wire(kCharacterUs);
    wire.write(100, 0);
    wire.clear();
    QCOMPARE(wire.backlog(0), qint64(0));
    QCOMPARE(wire.write(4, 7), qint64(7));
}

void TestWireBudget::write_clockFarPastTwoSeconds_exactTimes_data()
{
    QTest::addColumn<qint64>("nowNs");
    QTest::newRow("1 s") << 1000 * kMs;
    // Past 2^31 ns: start times were once rounded through int and came back negative, so a
    // paced wire stopped pacing 2.1 s after its clock started.
    QTest::newRow("3 s") << 3000 * kMs;
    QTest::newRow("1 h") << 3600 * 1000 * kMs;
    QTest::newRow("30 days") << qint64(30) * 24 * 3600 * 1000 * kMs;
}

void TestWireBudget::write_clockFarPastTwoSeconds_exactTimes()
{
    QFETCH(qint64, nowNs);
    WireBudget wire(kCharacterUs);
    QCOMPARE(wire.write(16, nowNs), nowNs);
    QCOMPARE(wire.write(16, nowNs), nowNs + characters(16) + 1); // behind the first 16
    QCOMPARE(wire.backlog(nowNs), qint64(32));
    // A backlog of more than 2^31 ns (12 000 000 characters, 2.3 s) is waited for in full.
    wire.write(12000000, nowNs);
    QVERIFY(wire.nsUntilBacklog(0, nowNs) >= characters(12000032));
    QVERIFY(wire.nsUntilBacklog(0, nowNs) <= characters(12000032) + 2);
}

STEPDECK_TEST_GUILESS_MAIN(TestWireBudget)
#include "tst_wirebudget.moc"
