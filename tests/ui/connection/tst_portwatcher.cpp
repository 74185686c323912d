// Auto-reconnect's matching (issue 10): the watcher follows one USB device by VID:PID and
// serial number through fake port lists, and the scanner lists ports off the GUI thread.
#include "TestMain.h"
#include "connection/PortScanner.h"
#include "connection/PortWatcher.h"
#include <QSignalSpy>
#include <QThread>
#include <QtTest>

using stepdeck::ui::PortEntry;
using stepdeck::ui::PortScanner;
using stepdeck::ui::PortWatcher;
Q_DECLARE_METATYPE(stepdeck::ui::PortEntry)

namespace {
PortEntry usb(const QString& path, quint16 vid, quint16 pid, const QString& serial)
{
    PortEntry e;
    e.path = path;
    e.label = path;
    e.usb = true;
    e.vendorId = vid;
    e.productId = pid;
    e.serialNumber = serial;
    return e;
}
PortEntry plain(const QString& path)
{
    PortEntry e;
    e.path = path;
    e.label = path;
    return e;
}
const PortEntry kFtdiA = usb(QStringLiteral("/dev/ttyUSB0"), 0x0403, 0x6001, QStringLiteral("A1"));
} // namespace

class TestPortWatcher : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void watch_needsAUsbDeviceAtThePath();
    void sameDevice_backUnderNewPath_emittedOnce();
    void present_withoutVanishing_notEmitted();
    void otherDevice_notTakenForTheWatchedOne_data();
    void otherDevice_notTakenForTheWatchedOne();
    void noSerialNumber_onlyUnderTheOldPath();
    void forget_endsFollowing();
    void reconnectFailed_triesAgain_boundedly();
    void scanner_listsOffTheGuiThread_andReportsChangesOnly();
};

void TestPortWatcher::watch_needsAUsbDeviceAtThePath()
{
    PortWatcher w;
    QVERIFY(!w.watch(QStringLiteral("/dev/ttyS0"), {plain(QStringLiteral("/dev/ttyS0"))}));
    QVERIFY(!w.watch(QStringLiteral("/dev/pts/3"), {kFtdiA})); // not listed at all
    QVERIFY(!w.isWatching());
    QVERIFY(w.watch(kFtdiA.path, {plain(QStringLiteral("/dev/ttyS0")), kFtdiA}));
    QVERIFY(w.isWatching());
    QCOMPARE(w.device().serialNumber, QStringLiteral("A1"));
}

void TestPortWatcher::sameDevice_backUnderNewPath_emittedOnce()
{
    PortWatcher w;
    QSignalSpy returned(&w, &PortWatcher::deviceReturned);
    QVERIFY(w.watch(kFtdiA.path, {kFtdiA}));
    w.update({plain(QStringLiteral("/dev/ttyS0"))}); // unplugged
    QVERIFY(w.isGone());
    QCOMPARE(returned.count(), 0);
    const PortEntry back =
        usb(QStringLiteral("/dev/ttyUSB1"), 0x0403, 0x6001, QStringLiteral("A1"));
    w.update({plain(QStringLiteral("/dev/ttyS0")), back});
    QCOMPARE(returned.count(), 1);
    QCOMPARE(returned.at(0).at(0).toString(), QStringLiteral("/dev/ttyUSB1"));
    QVERIFY(!w.isGone());
    w.update({back}); // still there: nothing more
    QCOMPARE(returned.count(), 1);
}

void TestPortWatcher::present_withoutVanishing_notEmitted()
{
    PortWatcher w;
    QSignalSpy returned(&w, &PortWatcher::deviceReturned);
    QVERIFY(w.watch(kFtdiA.path, {kFtdiA}));
    for (int i = 0; i < 3; ++i)
        w.update({kFtdiA});
    QCOMPARE(returned.count(), 0);
}

void TestPortWatcher::otherDevice_notTakenForTheWatchedOne_data()
{
    QTest::addColumn<PortEntry>("other");
    const QString path = QStringLiteral("/dev/ttyUSB0");
    QTest::newRow("other serial") << usb(path, 0x0403, 0x6001, QStringLiteral("B7"));
    QTest::newRow("other product") << usb(path, 0x0403, 0x6015, QStringLiteral("A1"));
    QTest::newRow("other vendor") << usb(path, 0x1a86, 0x6001, QStringLiteral("A1"));
    QTest::newRow("no serial") << usb(path, 0x0403, 0x6001, QString());
    QTest::newRow("not usb") << plain(path);
}

void TestPortWatcher::otherDevice_notTakenForTheWatchedOne()
{
    QFETCH(PortEntry, other);
    PortWatcher w;
    QSignalSpy returned(&w, &PortWatcher::deviceReturned);
    QVERIFY(w.watch(kFtdiA.path, {kFtdiA}));
    w.update({});
    w.update({other});
    QCOMPARE(returned.count(), 0);
    QVERIFY(w.isGone());
    w.update({other, kFtdiA}); // the right one plugged in beside it
    QCOMPARE(returned.count(), 1);
}

void TestPortWatcher::noSerialNumber_onlyUnderTheOldPath()
{
    const PortEntry anon = usb(QStringLiteral("/dev/ttyUSB0"), 0x1a86, 0x7523, QString());
    PortWatcher w;
    QSignalSpy returned(&w, &PortWatcher::deviceReturned);
    QVERIFY(w.watch(anon.path, {anon}));
    w.update({});
    w.update({usb(QStringLiteral("/dev/ttyUSB1"), 0x1a86, 0x7523, QString())});
    QCOMPARE(returned.count(), 0); // could be any adapter of that type
    w.update({anon});
    QCOMPARE(returned.count(), 1);
}

void TestPortWatcher::forget_endsFollowing()
{
    PortWatcher w;
    QSignalSpy returned(&w, &PortWatcher::deviceReturned);
    QVERIFY(w.watch(kFtdiA.path, {kFtdiA}));
    w.update({});
    w.forget(); // the operator disconnected or chose another port
    w.update({kFtdiA});
    QCOMPARE(returned.count(), 0);
    QVERIFY(!w.isWatching());
}

void TestPortWatcher::reconnectFailed_triesAgain_boundedly()
{
    PortWatcher w;
    QSignalSpy returned(&w, &PortWatcher::deviceReturned);
    QVERIFY(w.watch(kFtdiA.path, {kFtdiA}));
    w.update({});
    for (int i = 0; i < PortWatcher::kAttempts + 2; ++i) {
        w.update({kFtdiA});
        w.reconnectFailed(); // e.g. udev has not set the permissions yet
    }
    QCOMPARE(returned.count(), PortWatcher::kAttempts);
    // Unplugged and plugged in again: a fresh round of attempts.
    w.update({});
    w.update({kFtdiA});
    QCOMPARE(returned.count(), PortWatcher::kAttempts + 1);
}

void TestPortWatcher::scanner_listsOffTheGuiThread_andReportsChangesOnly()
{
    QList<PortEntry> list{kFtdiA};
    QMutex mutex;
    QThread* scannedIn = nullptr;
    PortScanner scanner(nullptr, [&] {
        QMutexLocker lock(&mutex);
        scannedIn = QThread::currentThread();
        return list;
    });
    scanner.setInterval(60000); // scans only on request here
    QSignalSpy changed(&scanner, &PortScanner::portsChanged);
    QTRY_COMPARE(changed.count(), 1); // the first scan, started by the constructor
    QCOMPARE(scanner.ports(), QList<PortEntry>{kFtdiA});
    {
        QMutexLocker lock(&mutex);
        QVERIFY(scannedIn && scannedIn != QThread::currentThread());
    }
    int scans = 0;
    connect(&scanner, &PortScanner::scanned, this, [&scans] { ++scans; });
    scanner.rescan();
    QTRY_COMPARE(scans, 1);
    QCOMPARE(changed.count(), 1); // same list: no change
    {
        QMutexLocker lock(&mutex);
        list.clear();
    }
    scanner.rescan();
    QTRY_COMPARE(changed.count(), 2);
    QVERIFY(scanner.ports().isEmpty());
}

STEPDECK_TEST_GUILESS_MAIN(TestPortWatcher)
#include "tst_portwatcher.moc"
