// NanotecHeldSettings: which read-back values survive which exchanges (issue 30: a chain of
// chords need not write '!1' and 'p2' again), and that anything that may have changed them,
// or may hide a reset of the drive (5.32), forgets them.
#include "TestMain.h"
#include "protocols/nanotec/NanotecCodec.h"
#include "protocols/nanotec/NanotecHeldSettings.h"
#include <QtTest>

using stepdeck::nanotec::kBroadcast;
using stepdeck::nanotec::NanotecHeldSettings;

class TestNanotecHeldSettings : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void exchange_keepsOrForgetsMode_data();
    void exchange_keepsOrForgetsMode();
    void plainSetting_forgetsOnlyItsOwnKey();
    void start_withoutFollowUpRecordHeld_forgetsAll();
    void silence_longerThanBoot_forgetsEvenWithoutExchange();
    void otherDrive_untouched();
    void heldValue_otherValue_notHeld();
};

namespace {
constexpr int kDrive = 1;

// A drive known to hold '!1', 'p2', 'N0' and 'o1000' at t = 0.
NanotecHeldSettings positioningDrive()
{
    NanotecHeldSettings h;
    h.confirm(kDrive, '!', 1, 0);
    h.confirm(kDrive, 'p', 2, 0);
    h.confirm(kDrive, 'N', 0, 0);
    h.confirm(kDrive, 'o', 1000, 0);
    return h;
}
} // namespace

void TestNanotecHeldSettings::exchange_keepsOrForgetsMode_data()
{
    QTest::addColumn<int>("address");
    QTest::addColumn<QByteArray>("body");
    QTest::addColumn<bool>("answered");
    QTest::addColumn<qint64>("atMs");
    QTest::addColumn<bool>("modeHeld");

    QTest::newRow("status read") << kDrive << QByteArray("$") << true << qint64(10) << true;
    QTest::newRow("position read") << kDrive << QByteArray("C") << true << qint64(10) << true;
    QTest::newRow("parameter read") << kDrive << QByteArray("Zp") << true << qint64(10) << true;
    QTest::newRow("target written") << kDrive << QByteArray("s3000") << true << qint64(10) << true;
    QTest::newRow("top speed written")
        << kDrive << QByteArray("o1200") << true << qint64(10) << true;
    QTest::newRow("start, no follow-up") << kDrive << QByteArray("A") << true << qint64(10) << true;
    QTest::newRow("stop") << kDrive << QByteArray("S") << true << qint64(10) << true;
    QTest::newRow("mode written") << kDrive << QByteArray("!2") << true << qint64(10) << false;
    QTest::newRow("position mode written")
        << kDrive << QByteArray("p1") << true << qint64(10) << false;
    QTest::newRow("record loaded") << kDrive << QByteArray("y3") << true << qint64(10) << false;
    QTest::newRow("address changed") << kDrive << QByteArray("m5") << true << qint64(10) << false;
    QTest::newRow("position reset") << kDrive << QByteArray("c") << true << qint64(10) << false;
    QTest::newRow("read unanswered") << kDrive << QByteArray("$") << false << qint64(10) << false;
    QTest::newRow("broadcast stop") << kBroadcast << QByteArray("S") << true << qint64(10) << false;
    QTest::newRow("answer after 0.4 s")
        << kDrive << QByteArray("$") << true << NanotecHeldSettings::kMaxSilenceMs << true;
    QTest::newRow("answer after a silence a boot could hide")
        << kDrive << QByteArray("$") << true << NanotecHeldSettings::kMaxSilenceMs + 1 << false;
    QTest::newRow("setting with garbage value")
        << kDrive << QByteArray("sx") << true << qint64(10) << false;
}

void TestNanotecHeldSettings::exchange_keepsOrForgetsMode()
{
    QFETCH(int, address);
    QFETCH(QByteArray, body);
    QFETCH(bool, answered);
    QFETCH(qint64, atMs);
    QFETCH(bool, modeHeld);
    NanotecHeldSettings h = positioningDrive();
    h.onExchange(address, body, answered, atMs);
    QCOMPARE(h.holds(kDrive, '!', 1, atMs) && h.holds(kDrive, 'p', 2, atMs), modeHeld);
}

void TestNanotecHeldSettings::plainSetting_forgetsOnlyItsOwnKey()
{
    NanotecHeldSettings h = positioningDrive();
    h.onExchange(kDrive, "o1200", true, 5); // echoed, not read back: not proven
    QVERIFY(!h.holds(kDrive, 'o', 1000, 5));
    QVERIFY(!h.holds(kDrive, 'o', 1200, 5));
    QVERIFY(h.holds(kDrive, 'p', 2, 5));
    h.onExchange(kDrive, "Zo", true, 8);
    h.confirm(kDrive, 'o', 1200, 8);
    QVERIFY(h.holds(kDrive, 'o', 1200, 8));
}

void TestNanotecHeldSettings::start_withoutFollowUpRecordHeld_forgetsAll()
{
    // 6.16: a follow-up record loads its own settings when the run ends.
    NanotecHeldSettings h;
    h.confirm(kDrive, '!', 1, 0);
    h.confirm(kDrive, 'p', 2, 0);
    h.onExchange(kDrive, "A", true, 5);
    QVERIFY(!h.holds(kDrive, 'p', 2, 5));
    h.confirm(kDrive, 'p', 2, 6);
    h.confirm(kDrive, 'N', 3, 6);
    h.onExchange(kDrive, "A", true, 7);
    QVERIFY(!h.holds(kDrive, 'p', 2, 7));
}

void TestNanotecHeldSettings::silence_longerThanBoot_forgetsEvenWithoutExchange()
{
    const NanotecHeldSettings h = positioningDrive();
    QVERIFY(h.holds(kDrive, 'p', 2, NanotecHeldSettings::kMaxSilenceMs));
    QVERIFY(!h.holds(kDrive, 'p', 2, NanotecHeldSettings::kMaxSilenceMs + 1));
}

void TestNanotecHeldSettings::otherDrive_untouched()
{
    NanotecHeldSettings h = positioningDrive();
    h.confirm(2, 'p', 2, 0);
    h.onExchange(2, "p1", true, 5);
    h.onExchange(3, "$", false, 5);
    QVERIFY(!h.holds(2, 'p', 2, 5));
    QVERIFY(h.holds(kDrive, 'p', 2, 5));
}

void TestNanotecHeldSettings::heldValue_otherValue_notHeld()
{
    const NanotecHeldSettings h = positioningDrive();
    QVERIFY(h.holds(kDrive, 'p', 2, 1));
    QVERIFY(!h.holds(kDrive, 'p', 1, 1));
    QVERIFY(!h.holds(kDrive, 's', 0, 1)); // never read back
    QVERIFY(!h.holds(2, 'p', 2, 1));      // another drive
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecHeldSettings)
#include "tst_nanotecheldsettings.moc"
