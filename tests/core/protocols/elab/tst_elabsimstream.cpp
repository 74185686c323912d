// The <DC2> single-step stream of the E-LAB simulator: ElabSimStream's buffer bookkeeping and
// the stream as the host sees it through ElabSimulator (XOFF/XON, EndOfFeed, stop, flush).
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimStream.h"
#include "protocols/elab/ElabSimulator.h"
#include "sim/TrafficMeter.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::elab;

namespace {
const QByteArray kAck(1, ctrl::ACK);

bool setupSim(ElabSimulator& sim, quint16 feed)
{
    QSignalSpy spy(&sim, &Simulator::transmit);
    sim.receive(encode::ramp(RampKind::StartSpeed, {100, 100, 100}));
    sim.receive(encode::ramp(RampKind::MaxSpeed, {5000, 5000, 5000}));
    sim.receive(encode::ramp(RampKind::Acceleration, {1000, 1000, 1000}));
    sim.receive(encode::feedSpeed({feed, feed, feed}));
    return test::joinedBytes(spy) == QByteArray(4, ctrl::ACK);
}

// A correct host: sends DC2 frames in chunks as fast as the event loop allows, stops at the
// controller's XOFF and resumes at its XON.
class StreamingHost : public QObject
{
public:
    StreamingHost(ElabSimulator* sim, const QByteArray& steps, int chunk)
        : m_sim(sim), m_steps(steps), m_chunk(chunk)
    {
        connect(sim, &Simulator::transmit, this, &StreamingHost::onTransmit);
        m_timer.setInterval(0);
        connect(&m_timer, &QTimer::timeout, this, &StreamingHost::pump);
        m_timer.start();
    }
    bool done() const { return m_sent == m_steps.size(); }
    int xoffs = 0;
    int xons = 0;
    int pumpsWhilePaused = 0;
    QByteArray replies;

private:
    void onTransmit(const QByteArray& bytes)
    {
        for (char c : bytes) {
            if (c == ctrl::XOFF) {
                m_paused = true;
                ++xoffs;
            } else if (c == ctrl::XON) {
                m_paused = false;
                ++xons;
            } else {
                replies += c;
            }
        }
    }
    void pump()
    {
        if (m_paused) {
            ++pumpsWhilePaused;
            return;
        }
        QByteArray frames;
        for (int i = 0; i < m_chunk && m_sent < m_steps.size(); ++i)
            frames += encode::feedStep(quint8(m_steps.at(m_sent++)));
        m_sim->receive(frames);
        if (done())
            m_timer.stop();
    }
    ElabSimulator* m_sim;
    QByteArray m_steps;
    int m_chunk;
    qsizetype m_sent = 0;
    bool m_paused = false;
    QTimer m_timer;
};
} // namespace

class TestElabSimStream : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void meter_stepBytesLikeBelOrXoff_areSteps_thenPanicAndStopSeen();
    void buffer_watermarks_askForXoffThenXon();
    void buffer_full_countsOverflow();
    void buffer_underrun_earnsNoCredit();
    void buffer_pairsAfterXoff_countedUntilXon();
    void dc2Stream_sendsXoffXon_andExecutesEveryStep();
    void dc2Stream_hostIgnoringXoff_overflowsCounted();
    void dc2Stream_stopKeepsBuffer_flushSendsXon();
    void dc2Stream_refusedWithoutSetup_noReply();
};

void TestElabSimStream::buffer_watermarks_askForXoffThenXon()
{
    ElabSimStream s;
    s.configure(8, 6, 2);
    for (int i = 0; i < 5; ++i) {
        QVERIFY(s.push(0x10));
        QCOMPARE(s.flow(), ElabSimStream::Flow::None);
    }
    QVERIFY(s.push(0x10));
    QCOMPARE(s.flow(), ElabSimStream::Flow::SendXOff);
    QCOMPARE(s.flow(), ElabSimStream::Flow::None); // once
    s.start();
    QCOMPARE(s.due(10.0, 1.0), 6);
    for (int i = 0; i < 3; ++i)
        s.pop();
    QCOMPARE(s.flow(), ElabSimStream::Flow::None); // 3 left, low water is 2
    s.pop();
    QCOMPARE(s.flow(), ElabSimStream::Flow::SendXOn);
    QVERIFY(!s.hostPaused());
}

void TestElabSimStream::buffer_full_countsOverflow()
{
    ElabSimStream s;
    s.configure(4, 3, 1);
    for (int i = 0; i < 4; ++i)
        QVERIFY(s.push(0x10));
    QVERIFY(!s.push(0x10));
    QVERIFY(!s.push(0x10));
    QCOMPARE(s.overflows(), qint64(2));
    QCOMPARE(s.size(), 4);
}

void TestElabSimStream::buffer_underrun_earnsNoCredit()
{
    ElabSimStream s;
    s.start();
    QCOMPARE(s.due(5.0, 100.0), 0); // empty for 5 s
    for (int i = 0; i < 10; ++i)
        s.push(0x10);
    // The next step is due at once, the others at the feed rate again.
    QCOMPARE(s.due(0.0, 100.0), 1);
    s.pop();
    QCOMPARE(s.due(0.005, 100.0), 0);
    QCOMPARE(s.due(0.005, 100.0), 1);
}

void TestElabSimStream::buffer_pairsAfterXoff_countedUntilXon()
{
    ElabSimStream s;
    s.configure(16, 4, 1);
    for (int i = 0; i < 4; ++i) {
        s.noteArrival(); // before the XOFF: not counted
        s.push(0x10);
    }
    QCOMPARE(s.flow(), ElabSimStream::Flow::SendXOff);
    for (int i = 0; i < 3; ++i) {
        s.noteArrival();
        s.push(0x10);
    }
    QCOMPARE(s.pairsAfterLastXOff(), 3);
    s.start();
    QCOMPARE(s.due(10.0, 1.0), 7);
    for (int i = 0; i < 7; ++i)
        s.pop();
    QCOMPARE(s.flow(), ElabSimStream::Flow::SendXOn);
    s.noteArrival(); // after the XON: not counted
    QCOMPARE(s.pairsAfterLastXOff(), 3);
    for (int i = 0; i < 4; ++i)
        s.push(0x10);
    QCOMPARE(s.flow(), ElabSimStream::Flow::SendXOff);
    QCOMPARE(s.pairsAfterLastXOff(), 0); // a new XOFF starts a new count
    s.noteArrival();
    QCOMPARE(s.pairsAfterLastXOff(), 1);
    QCOMPARE(s.mostPairsAfterXOff(), 3);
    s.clearCounters();
    QCOMPARE(s.mostPairsAfterXOff(), 0);
}

void TestElabSimStream::dc2Stream_sendsXoffXon_andExecutesEveryStep()
{
    ElabSimulator sim{SimulatorOptions{}};
    sim.setStreamBuffer(64, 48, 16);
    QVERIFY(setupSim(sim, 6000));

    // Every step byte value the manual allows, with XON/XOFF look-alikes (0x11, 0x13) first.
    QByteArray steps;
    steps += char(0x11);
    steps += char(0x13);
    steps += char(0x00);
    Triple<qint64> net{0, 0, 0};   // expected position per axis
    Triple<qint64> count{0, 0, 0}; // expected single steps per axis
    auto account = [&](quint8 b) {
        const Triple<int> d = decodeStepByte(b);
        for (int i = 0; i < 3; ++i) {
            net[size_t(i)] += d[size_t(i)];
            count[size_t(i)] += qAbs(d[size_t(i)]);
        }
    };
    for (char c : std::as_const(steps))
        account(quint8(c));
    QRandomGenerator rng(42);
    while (steps.size() < 2000) {
        const quint8 b = encodeStepByte(rng.bounded(3) - 1, rng.bounded(3) - 1, rng.bounded(3) - 1);
        steps += char(b);
        account(b);
    }

    StreamingHost host(&sim, steps, 16);
    QTRY_VERIFY_WITH_TIMEOUT(host.done(), 20000);
    QCOMPARE(sim.axeState(), quint8(axe::XMove | axe::YMove | axe::ZMove));
    sim.receive(encode::endOfFeed());
    QTRY_VERIFY_WITH_TIMEOUT(!sim.isBusy(), 20000);

    QVERIFY(host.xoffs >= 1);
    QVERIFY(host.xons >= 1);
    QVERIFY(host.pumpsWhilePaused > 0); // the host really waited
    QCOMPARE(host.replies, kAck);       // EndOfFeed only: DC2 has no reply
    QCOMPARE(sim.streamOverflows(), qint64(0));
    QCOMPARE(sim.streamRejected(), qint64(0));
    QCOMPARE(sim.executedStepBytes(), qint64(steps.size()));
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        QCOMPARE(sim.executedSteps(a), count[size_t(a.index())]);
        QCOMPARE(sim.position(a), net[size_t(a.index())]);
    }
    QCOMPARE(sim.axeState(), quint8(0));
}

void TestElabSimStream::dc2Stream_hostIgnoringXoff_overflowsCounted()
{
    ElabSimulator sim{SimulatorOptions{}};
    sim.setStreamBuffer(64, 48, 16);
    QVERIFY(setupSim(sim, 100));
    QSignalSpy spy(&sim, &Simulator::transmit);
    QByteArray frames;
    for (int i = 0; i < 200; ++i)
        frames += encode::feedStep(encodeStepByte(1, 0, 0));
    sim.receive(frames);
    QCOMPARE(test::joinedBytes(spy), QByteArray(1, ctrl::XOFF));
    // Everything behind the XOFF (the first step ran at once, so the 49th pair made 48).
    QCOMPARE(sim.streamMostPairsAfterXOff(), 200 - 49);
    QVERIFY(sim.streamOverflows() > 0);
    QCOMPARE(sim.streamOverflows() + sim.streamBuffered() + sim.executedStepBytes(), qint64(200));
    QCOMPARE(sim.executedSteps(Axis::X), sim.executedStepBytes());
    sim.receive(encode::panicStop());
    QCOMPARE(sim.streamBuffered(), 0);
}

void TestElabSimStream::dc2Stream_stopKeepsBuffer_flushSendsXon()
{
    ElabSimulator sim{SimulatorOptions{}};
    sim.setStreamBuffer(64, 48, 16);
    QVERIFY(setupSim(sim, 100)); // slow: the buffer stays full
    QSignalSpy spy(&sim, &Simulator::transmit);
    QByteArray frames;
    for (int i = 0; i < 50; ++i)
        frames += encode::feedStep(encodeStepByte(0, -1, 1));
    sim.receive(frames);
    QCOMPARE(test::joinedBytes(spy), QByteArray(1, ctrl::XOFF));
    QVERIFY(sim.isBusy());

    spy.clear();
    sim.receive(encode::stopMove()); // ForceStopMove: the stream halts, the buffer stays
    QCOMPARE(test::joinedBytes(spy), kAck);
    QVERIFY(!sim.isBusy());
    const int kept = sim.streamBuffered();
    QVERIFY(kept > 16);
    sim.receive(encode::feedStep(encodeStepByte(1, 0, 0))); // after a stop: not executed
    QCOMPARE(sim.streamRejected(), qint64(1));
    QCOMPARE(sim.streamBuffered(), kept);

    spy.clear();
    sim.receive(encode::flushBuffer()); // ForceFlushBuffer: ACK, and the host may send again
    QCOMPARE(test::joinedBytes(spy), kAck + QByteArray(1, ctrl::XON));
    QCOMPARE(sim.streamBuffered(), 0);
    const qint64 executed = sim.executedStepBytes();
    QCOMPARE(sim.position(Axis::Y), -executed);
    QCOMPARE(sim.position(Axis::Z), executed);

    spy.clear();
    sim.receive(encode::clearPosition()); // SetClearPosition clears the counters
    QCOMPARE(test::joinedBytes(spy), kAck);
    QCOMPARE(sim.executedStepBytes(), qint64(0));
    QCOMPARE(sim.executedSteps(Axis::Y), qint64(0));
}

void TestElabSimStream::dc2Stream_refusedWithoutSetup_noReply()
{
    ElabSimulator sim{SimulatorOptions{}};
    QSignalSpy spy(&sim, &Simulator::transmit);
    sim.receive(encode::feedStep(encodeStepByte(1, 1, 1)));
    sim.receive(encode::feedStep(0x88)); // invalid step byte (bits 7 and 3)
    QCOMPARE(spy.count(), 0);
    QCOMPARE(sim.streamRejected(), qint64(2));
    QVERIFY(!sim.isBusy());
    QCOMPARE(sim.position(Axis::X), qint64(0));
}

// stepdeck-bench's meter (ElabSimProfile): a <DC2> step byte may be 0x07 or 0x13, which are
// steps, not <BEL> (panic) or <XOFF> (stop); only a bare control character is.
void TestElabSimStream::meter_stepBytesLikeBelOrXoff_areSteps_thenPanicAndStopSeen()
{
    const std::unique_ptr<TrafficMeter> meter = findModel("elab")->streamBench.createMeter();
    meter->scan(encode::feedStep(0x07) + encode::feedStep(0x13), 10);
    QCOMPARE(meter->stepBytes(), qint64(2));
    QCOMPARE(meter->panicSeenNs(), qint64(-1));
    QCOMPARE(meter->stopSeenNs(), qint64(-1));
    meter->scan(encode::stopMove(), 20);
    meter->scan(encode::panicStop() + encode::stopMove(), 30);
    QCOMPARE(meter->stopSeenNs(), qint64(20)); // the first one
    QCOMPARE(meter->panicSeenNs(), qint64(30));
    meter->reset();
    QCOMPARE(meter->stopSeenNs(), qint64(-1));
}

STEPDECK_TEST_GUILESS_MAIN(TestElabSimStream)
#include "tst_elabsimstream.moc"
