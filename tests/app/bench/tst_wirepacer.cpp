// The bench's paced wire (app/bench/WirePacer): bytes arrive in order, none before its last bit
// can have arrived at the line's character time (less the wake-up latency the pacer arms early
// by, at most PreciseWakeup::kMaxLatencyNs), and towards the host whole writes at once.
// Lower bounds only: how late a wake-up comes is the machine's, not a property to assert.
#include "PreciseWakeup.h"
#include "TestMain.h"
#include "WirePacer.h"
#include <QtTest>

using namespace stepdeck::bench;

namespace {
constexpr double kCharacterUs = 191.0; // 57600 8N2: 11 bits

// The most a byte may come before its exact time.
constexpr double kEarliestNs = double(WirePacer::kCoalesceNs + PreciseWakeup::kMaxLatencyNs);

struct Delivery
{
    qint64 atNs = 0;
    QByteArray bytes;
};

struct Wire
{
    explicit Wire(WirePacer::Delivery mode)
        : pacer(
              kCharacterUs,
              [this](const QByteArray& b) {
                  got.push_back({PreciseWakeup::nowNs(), b});
                  if (expected > 0 && all().size() >= expected)
                      loop.quit();
              },
              nullptr, mode)
    {}
    QByteArray all() const
    {
        QByteArray out;
        for (const Delivery& d : got)
            out += d.bytes;
        return out;
    }
    // A real event loop (QTest::qWait sleeps between its passes, so every wake-up would wait
    // for the next pass and all bytes would come at once).
    QByteArray receive(qsizetype bytes)
    {
        expected = bytes;
        if (all().size() < expected) {
            QTimer::singleShot(5000, &loop, &QEventLoop::quit);
            loop.exec();
        }
        return all();
    }
    QList<Delivery> got;
    qsizetype expected = 0;
    QEventLoop loop;
    WirePacer pacer;
};
} // namespace

class TestWirePacer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void eachCharacter_noByteBeforeItsLastBitArrived();
    void eachCharacter_secondWriteQueuesBehindTheFirst();
    void wholeWrites_deliveredWholeOnceTheLastByteArrived();
};

void TestWirePacer::eachCharacter_noByteBeforeItsLastBitArrived()
{
    Wire wire(WirePacer::Delivery::EachCharacter);
    const QByteArray sent("0123456789ABCDEFGHIJ");
    const qint64 pushedNs = PreciseWakeup::nowNs();
    wire.pacer.push(sent);
    QCOMPARE(wire.receive(sent.size()), sent);
    qint64 index = 0;
    for (const Delivery& d : wire.got) {
        index += d.bytes.size(); // the last byte of this delivery
        const double arrivalNs = double(pushedNs) + double(index) * kCharacterUs * 1000.0;
        QVERIFY2(double(d.atNs) >= arrivalNs - kEarliestNs,
                 qPrintable(QStringLiteral("byte %1 delivered %2 us early")
                                .arg(index)
                                .arg((arrivalNs - double(d.atNs)) / 1000.0)));
    }
}

void TestWirePacer::eachCharacter_secondWriteQueuesBehindTheFirst()
{
    Wire wire(WirePacer::Delivery::EachCharacter);
    const qint64 pushedNs = PreciseWakeup::nowNs();
    wire.pacer.push(QByteArray(10, 'a'));
    wire.pacer.push(QByteArray("b"));
    QCOMPARE(wire.receive(11), QByteArray(10, 'a') + "b");
    const double bArrivalNs = double(pushedNs) + 11 * kCharacterUs * 1000.0;
    QVERIFY(wire.got.last().bytes.endsWith('b'));
    QVERIFY(double(wire.got.last().atNs) >= bArrivalNs - kEarliestNs);
}

void TestWirePacer::wholeWrites_deliveredWholeOnceTheLastByteArrived()
{
    Wire wire(WirePacer::Delivery::WholeWrites);
    const qint64 pushedNs = PreciseWakeup::nowNs();
    wire.pacer.push("<HT>05#");
    wire.pacer.push("<ENQ>0080#");
    QCOMPARE(wire.receive(17), QByteArray("<HT>05#<ENQ>0080#"));
    QCOMPARE(wire.got.size(), 2); // each write whole and on its own
    QCOMPARE(wire.got.at(0).bytes, QByteArray("<HT>05#"));
    const double firstEnd = double(pushedNs) + 7 * kCharacterUs * 1000.0;
    const double secondEnd = double(pushedNs) + 17 * kCharacterUs * 1000.0;
    QVERIFY(double(wire.got.at(0).atNs) >= firstEnd - kEarliestNs);
    QVERIFY(double(wire.got.at(1).atNs) >= secondEnd - kEarliestNs);
}

STEPDECK_TEST_GUILESS_MAIN(TestWirePacer)
#include "tst_wirepacer.moc"
