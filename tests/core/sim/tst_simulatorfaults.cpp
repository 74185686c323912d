// Simulator base: the random faults of issue 12 (drop, corrupt, delay, noise, freeze), drawn
// from the seeded generator so that a run can be repeated.
#include "TestMain.h"
#include "sim/Simulator.h"
#include <QSignalSpy>
#include <QtTest>

using namespace stepdeck;

namespace {
// Answers every chunk it receives with the same bytes: one reply per receive().
class EchoSimulator : public Simulator
{
public:
    using Simulator::Simulator;
    void receive(const QByteArray& bytes) override { send(bytes); }
    bool standingStill() override { return true; } // nothing ever moves
    bool isMoving(Axis) override { return false; }
    qint64 position(Axis) override { return 0; }
    QList<SimulatedMove> acceptedMoves() const override { return {}; }
    void emergencyStop() override {}
};

SimulatorOptions seeded(quint32 seed)
{
    SimulatorOptions o;
    o.seed = seed;
    return o;
}

// Sends `count` numbered requests; returns what came back per request (empty: nothing).
QList<QByteArray> exchange(Simulator& sim, int count)
{
    QList<QByteArray> out;
    QByteArray last;
    const auto connection =
        QObject::connect(&sim, &Simulator::transmit, [&](const QByteArray& b) { last += b; });
    for (int i = 0; i < count; ++i) {
        last.clear();
        sim.receive(QByteArray::number(1000 + i) + '\r');
        out << last;
    }
    QObject::disconnect(connection);
    return out;
}

QByteArray request(int i)
{
    return QByteArray::number(1000 + i) + '\r';
}
} // namespace

class TestSimulatorFaults : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void noFaults_everyReplyUnchanged();
    void drop_probabilityOne_losesEveryReply();
    void drop_sameSeed_sameRepliesLost();
    void drop_otherSeed_otherRepliesLost();
    void corrupt_replacesExactlyOneByte();
    void delay_holdsRepliesBackButDeliversThem();
    void noise_sendsRandomBytesUnasked_sameSeedSameBytes();
    void noise_zero_stops();
    void freeze_answersUntilTheTimeThenNothing();
};

void TestSimulatorFaults::noFaults_everyReplyUnchanged()
{
    EchoSimulator sim(seeded(1));
    const QList<QByteArray> replies = exchange(sim, 50);
    for (int i = 0; i < replies.size(); ++i)
        QCOMPARE(replies[i], request(i));
    QCOMPARE(sim.faultCounts().replies, qint64(50));
    QCOMPARE(sim.faultCounts().dropped + sim.faultCounts().corrupted, qint64(0));
}

void TestSimulatorFaults::drop_probabilityOne_losesEveryReply()
{
    EchoSimulator sim(seeded(1));
    sim.faults().dropProbability = 1.0;
    for (const QByteArray& reply : exchange(sim, 20))
        QVERIFY(reply.isEmpty());
    QCOMPARE(sim.faultCounts().dropped, qint64(20));
}

void TestSimulatorFaults::drop_sameSeed_sameRepliesLost()
{
    EchoSimulator a(seeded(7));
    EchoSimulator b(seeded(7));
    a.faults().dropProbability = b.faults().dropProbability = 0.3;
    const QList<QByteArray> ra = exchange(a, 300);
    QCOMPARE(exchange(b, 300), ra);
    // About 30 % lost (the generator is seeded: this count is the same on every run).
    QVERIFY2(a.faultCounts().dropped > 45 && a.faultCounts().dropped < 135,
             qPrintable(QString::number(a.faultCounts().dropped)));
    for (int i = 0; i < ra.size(); ++i)
        QVERIFY(ra[i].isEmpty() || ra[i] == request(i)); // a reply is lost whole or not at all
}

void TestSimulatorFaults::drop_otherSeed_otherRepliesLost()
{
    EchoSimulator a(seeded(7));
    EchoSimulator b(seeded(8));
    a.faults().dropProbability = b.faults().dropProbability = 0.3;
    QVERIFY(exchange(a, 300) != exchange(b, 300));
}

void TestSimulatorFaults::corrupt_replacesExactlyOneByte()
{
    EchoSimulator sim(seeded(3));
    sim.faults().corruptProbability = 1.0;
    const QList<QByteArray> replies = exchange(sim, 100);
    for (int i = 0; i < replies.size(); ++i) {
        const QByteArray sent = request(i);
        QCOMPARE(replies[i].size(), sent.size());
        int differing = 0;
        for (int k = 0; k < sent.size(); ++k)
            differing += replies[i][k] != sent[k] ? 1 : 0;
        QCOMPARE(differing, 1);
    }
    QCOMPARE(sim.faultCounts().corrupted, qint64(100));
}

void TestSimulatorFaults::delay_holdsRepliesBackButDeliversThem()
{
    EchoSimulator sim(seeded(5));
    sim.faults().delayProbability = 1.0;
    sim.faults().delayMaxMs = 20;
    QSignalSpy spy(&sim, &Simulator::transmit);
    sim.receive("A\r");
    sim.receive("B\r");
    QCOMPARE(spy.count(), 0); // held back
    QTRY_COMPARE(spy.count(), 2);
    QByteArray all;
    for (const auto& args : spy)
        all += args.at(0).toByteArray();
    QVERIFY2(all == "A\rB\r" || all == "B\rA\r", all.constData()); // delays may reorder
    QCOMPARE(sim.faultCounts().delayed, qint64(2));
}

void TestSimulatorFaults::noise_sendsRandomBytesUnasked_sameSeedSameBytes()
{
    QByteArray first[2];
    for (QByteArray& out : first) {
        EchoSimulator sim(seeded(11));
        QObject::connect(&sim, &Simulator::transmit, [&out](const QByteArray& b) { out += b; });
        sim.setNoise(2000);
        QTRY_VERIFY(out.size() >= 64);
        QCOMPARE(sim.faultCounts().noiseBytes, qint64(out.size()));
        out.truncate(64);
    }
    QCOMPARE(first[0], first[1]);
    QVERIFY(first[0] != QByteArray(64, first[0].at(0))); // not one repeated byte
}

void TestSimulatorFaults::noise_zero_stops()
{
    EchoSimulator sim(seeded(1));
    sim.setNoise(5000);
    QTRY_VERIFY(sim.faultCounts().noiseBytes > 0);
    sim.setNoise(0);
    const qint64 before = sim.faultCounts().noiseBytes;
    // Replies still work, and the noise counter no longer moves while they do.
    QCOMPARE(exchange(sim, 5).last(), request(4));
    QCOMPARE(sim.faultCounts().noiseBytes, before);
    QCOMPARE(sim.noise(), 0.0);
}

void TestSimulatorFaults::freeze_answersUntilTheTimeThenNothing()
{
    EchoSimulator sim(seeded(1));
    sim.freezeAfter(30);
    QCOMPARE(exchange(sim, 3).last(), request(2)); // the clock starts at the first reply
    QTRY_VERIFY(sim.faultCounts().frozen);
    QVERIFY(exchange(sim, 3).last().isEmpty());
    QVERIFY(sim.faults().silent);
    sim.freezeAfter(-1); // thawed
    QCOMPARE(exchange(sim, 1).last(), request(0));
}

STEPDECK_TEST_GUILESS_MAIN(TestSimulatorFaults)
#include "tst_simulatorfaults.moc"
