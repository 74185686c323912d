// ElabExchangeQueue against a scripted peer: replies matched in order, overtaking, frames
// without a reply, flow-control bytes between replies, timeouts and garbage with resync.
#include "ElabTestSupport.h"
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabExchangeQueue.h"
#include "protocols/elab/ElabModel.h"
#include "transport/LoopbackTransport.h"
#include <QtTest>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::elab;

namespace {
using stepdeck::elab::testing::bytes;

// The queue on the host end; the test plays the board on the device end.
struct Peer
{
    Peer()
    {
        auto [h, d] = LoopbackTransport::createPair();
        host.reset(h);
        device.reset(d);
        host->open(lineSettings());
        device->open(lineSettings());
        queue = std::make_unique<ElabExchangeQueue>(host.get());
        queue->setTimeoutMs(300);
        queue->setCharacterTimeUs(lineSettings().characterTimeUs());
        received = std::make_unique<QSignalSpy>(device.get(), &Transport::dataReceived);
        QTRY_VERIFY(host->isOpen());
    }
    ~Peer() { queue.reset(); }

    QByteArray seen() const { return test::joinedBytes(*received); }
    void reply(const char* mnemonics) { device->write(bytes(mnemonics)); }

    // An exchange that records what it got.
    ElabExchange make(const QByteArray& frame, Expect expect, QStringList* log, const QString& tag)
    {
        ElabExchange ex;
        ex.frame = frame;
        ex.expect = expect;
        ex.onReply = [log, tag](const Reply& r) {
            *log << tag + QLatin1Char(':') +
                        (r.raw.isEmpty() ? QStringLiteral("written") : toMnemonics(r.raw));
        };
        ex.onError = [log, tag](ErrorKind kind, const QString&) {
            *log << tag + QStringLiteral(":error") + QString::number(int(kind));
        };
        return ex;
    }

    std::unique_ptr<LoopbackTransport> host;
    std::unique_ptr<LoopbackTransport> device;
    std::unique_ptr<ElabExchangeQueue> queue;
    std::unique_ptr<QSignalSpy> received;
};

// The two status words of a poll as one pipeline group (ElabCtlLine::readStatus).
QList<ElabExchange> statusWords(Peer& p, QStringList* log, bool poll = true)
{
    const quint64 group = ElabExchangeQueue::newPipelineGroup();
    QList<ElabExchange> words{
        p.make(encode::requestAxeState(), Expect::AxeState, log, "ht"),
        p.make(encode::requestMachineState(), Expect::MachineState, log, "enq")};
    for (ElabExchange& ex : words) {
        ex.pipelineGroup = group;
        ex.poll = poll;
        ex.retries = 2;
    }
    return words;
}

QString errorTag(const char* tag, ErrorKind kind)
{
    return QString::fromLatin1(tag) + QStringLiteral(":error") + QString::number(int(kind));
}
} // namespace

class TestElabExchangeQueue : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void oneInFlight_nextWrittenAfterReply();
    void overtake_repliesMatchedInOrder();
    void noReplyFrame_completesOnceWritten();
    void noReplyFrame_linkReportsNoQueue_completesWhenTheLineCarriedIt();
    void wireRoomFrame_builtToFitOneChunkBeyondTheLine();
    void flowControl_betweenReplies_isNotAReply();
    void timeout_failsAndSendsSynBurstThenMachineState();
    void garbage_failsProtocolAndResyncs();
    void dropQueued_keepsPollsAndInFlight();
    void pipelineGroup_readsWrittenBackToBack_repliesMatchedInOrder();
    void pipelineGroup_neverSplitByWorkQueuedAhead();
    void pipelineGroup_waitsBehindAnythingOutsideIt_data();
    void pipelineGroup_waitsBehindAnythingOutsideIt();
    void pipelineGroup_firstReplyLost_secondStillMatchedWithoutResync_data();
    void pipelineGroup_firstReplyLost_secondStillMatchedWithoutResync();
    void pipelineGroup_stopOvertakesBothReads();
};

void TestElabExchangeQueue::oneInFlight_nextWrittenAfterReply()
{
    Peer p;
    QStringList log;
    p.queue->enqueue(p.make(encode::requestAxeState(), Expect::AxeState, &log, "a"));
    p.queue->enqueue(p.make(encode::requestMachineState(), Expect::MachineState, &log, "b"));
    QTRY_COMPARE(p.seen(), encode::requestAxeState());
    QVERIFY(test::staysQuiet(*p.received, 50)); // <ENQ> waits for the <HT> reply
    p.reply("<HT>05#");
    QTRY_COMPARE(p.seen(), encode::requestAxeState() + encode::requestMachineState());
    p.reply("<ENQ>0080#");
    QTRY_COMPARE(log, (QStringList{"a:<HT>05#", "b:<ENQ>0080#"}));
    QVERIFY(p.queue->isIdle());
}

void TestElabExchangeQueue::overtake_repliesMatchedInOrder()
{
    Peer p;
    QStringList log;
    p.queue->enqueue(p.make(bytes("<FF>00000010,00000000;"), Expect::AckNak, &log, "move"));
    p.queue->enqueue(p.make(encode::requestAxeState(), Expect::AxeState, &log, "queued"));
    QTRY_COMPARE(p.seen(), bytes("<FF>00000010,00000000;"));
    p.queue->dropQueued(ErrorKind::Cancelled, "stop", false);
    p.queue->overtake(p.make(encode::stopMove(), Expect::AckNak, &log, "stop"), false);
    // Written at once, behind the move that is still waiting for its reply.
    QTRY_COMPARE(p.seen(), bytes("<FF>00000010,00000000;") + encode::stopMove());
    p.reply("<NAK><ACK>");
    QTRY_COMPARE(log.size(), 3);
    QCOMPARE(log,
             (QStringList{errorTag("queued", ErrorKind::Cancelled), "move:<NAK>", "stop:<ACK>"}));
}

void TestElabExchangeQueue::noReplyFrame_completesOnceWritten()
{
    Peer p;
    QStringList log;
    p.queue->enqueue(
        p.make(encode::feedStep(0x10) + encode::feedStep(0x11), Expect::None, &log, "chunk"));
    p.queue->enqueue(p.make(encode::endOfFeed(), Expect::AckNak, &log, "end"));
    QTRY_COMPARE(log, QStringList{"chunk:written"});
    QTRY_COMPARE(p.seen(), encode::feedStep(0x10) + encode::feedStep(0x11) + encode::endOfFeed());
    p.reply("<ACK>");
    QTRY_COMPARE(log, (QStringList{"chunk:written", "end:<ACK>"}));
}

// A loopback link, like a pty, takes everything at once and reports nothing pending: only the
// wire budget (on an invented clock here) says when 16 bytes can have left at 57600 8N2.
void TestElabExchangeQueue::noReplyFrame_linkReportsNoQueue_completesWhenTheLineCarriedIt()
{
    Peer p;
    qint64 nowNs = 1000000000;
    p.queue->setWireClock([&nowNs] { return nowNs; });
    const double characterNs = lineSettings().characterTimeUs() * 1000.0;
    QStringList log;
    QByteArray chunk;
    for (int i = 0; i < 8; ++i)
        chunk += encode::feedStep(0x10);
    p.queue->enqueue(p.make(chunk, Expect::None, &log, "chunk"));
    p.queue->enqueue(p.make(encode::endOfFeed(), Expect::AckNak, &log, "end"));
    QTRY_COMPARE(p.seen(), chunk);
    QVERIFY(test::staysQuiet(*p.received, 50)); // the line has carried nothing yet
    QVERIFY(log.isEmpty());
    nowNs += qint64(13.5 * characterNs); // 2.5 bytes still on the line: more than one pair
    QVERIFY(test::staysQuiet(*p.received, 50));
    QVERIFY(log.isEmpty());
    nowNs += qint64(0.5 * characterNs) + 1; // one pair left
    QTRY_COMPARE(log, QStringList{"chunk:written"});
    QTRY_COMPARE(p.seen(), chunk + encode::endOfFeed());
}

// A frame with wireRoom waits for room in the window and is built to fill it: never more
// than one chunk (16 bytes) beyond what the line can have carried, by the wire budget.
void TestElabExchangeQueue::wireRoomFrame_builtToFitOneChunkBeyondTheLine()
{
    Peer p;
    qint64 nowNs = 1000000000;
    p.queue->setWireClock([&nowNs] { return nowNs; });
    const double characterNs = lineSettings().characterTimeUs() * 1000.0;
    QStringList log;
    QList<qint64> roomAtBuild;
    auto paced = [&](const char* tag) {
        ElabExchange ex = p.make({}, Expect::None, &log, QString::fromLatin1(tag));
        ex.wireRoom = 2;
        ex.build = [&p, &roomAtBuild] {
            const qint64 room = p.queue->wireRoomBytes();
            roomAtBuild << room;
            return QByteArray(int(room), char(0x10));
        };
        return ex;
    };
    // 16 bytes answered at once (the loopback carries them instantly): the reply frees the
    // queue, but by the wire budget the line still has all 16 to carry.
    const QByteArray command(16, 'A');
    p.queue->enqueue(p.make(command, Expect::AckNak, &log, "cmd"));
    QTRY_COMPARE(p.seen(), command);
    p.reply("<ACK>");
    QTRY_COMPARE(log, QStringList{"cmd:<ACK>"});
    p.queue->enqueue(paced("a"));
    QVERIFY(test::staysQuiet(*p.received, 50)); // no room: not even one pair
    QVERIFY(roomAtBuild.isEmpty());
    nowNs += qint64(2 * characterNs) + 1; // two bytes carried: room for one pair
    QTRY_COMPARE(p.seen(), command + QByteArray(2, char(0x10)));
    QCOMPARE(roomAtBuild, QList<qint64>{2});
    // "a" completes once at most one pair is on its way; the next one gets the room left.
    nowNs += qint64(14 * characterNs) + 1;
    QTRY_COMPARE(log, (QStringList{"cmd:<ACK>", "a:written"}));
    p.queue->enqueue(paced("b"));
    QTRY_COMPARE(roomAtBuild, (QList<qint64>{2, 14}));
    QTRY_COMPARE(p.seen(), command + QByteArray(16, char(0x10)));
}

void TestElabExchangeQueue::flowControl_betweenReplies_isNotAReply()
{
    Peer p;
    QStringList log;
    QSignalSpy flow(p.queue.get(), &ElabExchangeQueue::flowControl);
    p.queue->enqueue(p.make(encode::requestMachineState(), Expect::MachineState, &log, "enq"));
    QTRY_VERIFY(!p.seen().isEmpty());
    p.reply("<XOFF><ENQ>00<XON>80#"); // flow control even inside a reply
    QTRY_COMPARE(log, QStringList{"enq:<ENQ>0080#"});
    QCOMPARE(flow.size(), 2);
    QCOMPARE(flow.at(0).at(0).toBool(), false);
    QCOMPARE(flow.at(1).at(0).toBool(), true);
}

void TestElabExchangeQueue::timeout_failsAndSendsSynBurstThenMachineState()
{
    Peer p;
    QStringList log;
    QSignalSpy started(p.queue.get(), &ElabExchangeQueue::resyncStarted);
    QSignalSpy finished(p.queue.get(), &ElabExchangeQueue::resyncFinished);
    p.queue->enqueue(p.make(encode::requestAxeState(), Expect::AxeState, &log, "ht"));
    p.queue->enqueue(p.make(encode::requestTemperature(), Expect::Temperature, &log, "etb"));
    // No reply: timeout, then <SYN> x16 and <ENQ> ahead of the queued <ETB>.
    const QByteArray expected =
        encode::requestAxeState() + QByteArray(16, ctrl::SYN) + encode::requestMachineState();
    QTRY_COMPARE_WITH_TIMEOUT(p.seen(), expected, 5000);
    QCOMPARE(log, QStringList{errorTag("ht", ErrorKind::Timeout)});
    QCOMPARE(started.size(), 1);
    QVERIFY(started.first().at(0).toString().contains("no reply"));
    p.reply("<HT>00#<ENQ>0000#"); // the late reply first: skipped
    QTRY_COMPARE(finished.size(), 1);
    QCOMPARE(finished.first().at(0).toBool(), true);
    QTRY_COMPARE(p.seen(), expected + encode::requestTemperature());
}

void TestElabExchangeQueue::garbage_failsProtocolAndResyncs()
{
    Peer p;
    QStringList log;
    QSignalSpy started(p.queue.get(), &ElabExchangeQueue::resyncStarted);
    p.queue->enqueue(p.make(encode::requestAxeState(), Expect::AxeState, &log, "ht"));
    QTRY_VERIFY(!p.seen().isEmpty());
    p.reply("<ETB>19#"); // a reply of another kind
    QTRY_COMPARE(log, QStringList{errorTag("ht", ErrorKind::Protocol)});
    QCOMPARE(started.size(), 1);
    QTRY_VERIFY(p.seen().endsWith(QByteArray(16, ctrl::SYN) + encode::requestMachineState()));
}

void TestElabExchangeQueue::dropQueued_keepsPollsAndInFlight()
{
    Peer p;
    QStringList log;
    p.queue->enqueue(p.make(encode::requestAxeState(), Expect::AxeState, &log, "inflight"));
    ElabExchange poll = p.make(encode::requestMachineState(), Expect::MachineState, &log, "poll");
    poll.droppable = false;
    p.queue->enqueue(poll);
    p.queue->enqueue(p.make(bytes("<BS>00000001."), Expect::AckNak, &log, "move"));
    QTRY_VERIFY(!p.seen().isEmpty());
    p.queue->dropQueued(ErrorKind::Cancelled, "stop", false);
    QCOMPARE(log, QStringList{errorTag("move", ErrorKind::Cancelled)});
    p.reply("<HT>00#");
    QTRY_COMPARE(p.seen(), encode::requestAxeState() + encode::requestMachineState());
    p.reply("<ENQ>0000#");
    QTRY_COMPARE(log.size(), 3);
}

// Issue 21: both requests before the first reply; the board answers in order.
void TestElabExchangeQueue::pipelineGroup_readsWrittenBackToBack_repliesMatchedInOrder()
{
    Peer p;
    QStringList log;
    for (ElabExchange& ex : statusWords(p, &log))
        p.queue->enqueue(std::move(ex));
    QTRY_COMPARE(p.seen(), encode::requestAxeState() + encode::requestMachineState());
    QCOMPARE(p.queue->inFlightCount(), 2);
    p.reply("<HT>05#<ENQ>0080#"); // both in one read
    QTRY_COMPARE(log, (QStringList{"ht:<HT>05#", "enq:<ENQ>0080#"}));
    QVERIFY(p.queue->isIdle());
}

// A command put at the front of the queue (the next step of a sequence) while a group's reads
// are on their way goes out after both replies, never between the two reads: the second read's
// status would otherwise describe the board after the command and the first before it.
void TestElabExchangeQueue::pipelineGroup_neverSplitByWorkQueuedAhead()
{
    Peer p;
    QStringList log;
    for (ElabExchange& ex : statusWords(p, &log))
        p.queue->enqueue(std::move(ex));
    const QByteArray move = bytes("<FF>00000010,00000000;");
    p.queue->enqueueNext(p.make(move, Expect::AckNak, &log, "move"));
    const QByteArray words = encode::requestAxeState() + encode::requestMachineState();
    QTRY_COMPARE(p.seen(), words);
    p.reply("<HT>00#");
    QVERIFY(test::staysQuiet(*p.received, 50)); // the move waits for the second reply too
    p.reply("<ENQ>0000#");
    QTRY_COMPARE(p.seen(), words + move);
    p.reply("<ACK>");
    QTRY_COMPARE(log, (QStringList{"ht:<HT>00#", "enq:<ENQ>0000#", "move:<ACK>"}));
}

void TestElabExchangeQueue::pipelineGroup_waitsBehindAnythingOutsideIt_data()
{
    QTest::addColumn<QByteArray>("first");
    QTest::addColumn<int>("expect");
    QTest::addColumn<QByteArray>("reply");
    QTest::newRow("command") << bytes("<BS>00000001.") << int(Expect::AckNak) << bytes("<ACK>");
    QTest::newRow("read of another group")
        << encode::requestTemperature() << int(Expect::Temperature) << bytes("<ETB>19#");
}

void TestElabExchangeQueue::pipelineGroup_waitsBehindAnythingOutsideIt()
{
    QFETCH(QByteArray, first);
    QFETCH(int, expect);
    QFETCH(QByteArray, reply);
    Peer p;
    QStringList log;
    ElabExchange before = p.make(first, Expect(expect), &log, "first");
    if (Expect(expect) != Expect::AckNak)
        before.pipelineGroup = ElabExchangeQueue::newPipelineGroup();
    p.queue->enqueue(std::move(before));
    for (ElabExchange& ex : statusWords(p, &log))
        p.queue->enqueue(std::move(ex));
    QTRY_COMPARE(p.seen(), first);
    QVERIFY(test::staysQuiet(*p.received, 50));
    p.device->write(reply);
    QTRY_COMPARE(p.seen(), first + encode::requestAxeState() + encode::requestMachineState());
}

void TestElabExchangeQueue::pipelineGroup_firstReplyLost_secondStillMatchedWithoutResync_data()
{
    QTest::addColumn<bool>("poll");
    QTest::newRow("poll: a miss") << true;
    QTest::newRow("request: asked again") << false;
}

// The <HT> reply destroyed by noise: the <ENQ> reply that follows shows the line in step, so
// the <HT> read ends at once (a poll counts a miss; a request's read is asked again) instead of
// waiting for its timeout, and no resynchronisation is needed.
void TestElabExchangeQueue::pipelineGroup_firstReplyLost_secondStillMatchedWithoutResync()
{
    QFETCH(bool, poll);
    Peer p;
    p.queue->setTimeoutMs(5000); // a timeout would not end the test's waits
    QStringList log;
    QSignalSpy resync(p.queue.get(), &ElabExchangeQueue::resyncStarted);
    for (ElabExchange& ex : statusWords(p, &log, poll))
        p.queue->enqueue(std::move(ex));
    const QByteArray words = encode::requestAxeState() + encode::requestMachineState();
    QTRY_COMPARE(p.seen(), words);
    p.reply("<HT>0");      // cut short by noise ...
    p.reply("<ENQ>0080#"); // ... then the second reply intact
    if (poll) {
        QTRY_COMPARE(log, (QStringList{errorTag("ht", ErrorKind::Timeout), "enq:<ENQ>0080#"}));
        QVERIFY(test::staysQuiet(*p.received, 50));
    } else {
        QTRY_COMPARE(log, QStringList{"enq:<ENQ>0080#"});
        QTRY_COMPARE(p.seen(), words + encode::requestAxeState());
        p.reply("<HT>05#");
        QTRY_COMPARE(log, (QStringList{"enq:<ENQ>0080#", "ht:<HT>05#"}));
    }
    QCOMPARE(resync.size(), 0);
    QVERIFY(p.queue->isIdle());
}

void TestElabExchangeQueue::pipelineGroup_stopOvertakesBothReads()
{
    Peer p;
    QStringList log;
    for (ElabExchange& ex : statusWords(p, &log))
        p.queue->enqueue(std::move(ex));
    const QByteArray words = encode::requestAxeState() + encode::requestMachineState();
    QTRY_COMPARE(p.seen(), words);
    p.queue->overtake(p.make(encode::stopMove(), Expect::AckNak, &log, "stop"), false);
    QTRY_COMPARE(p.seen(), words + encode::stopMove()); // at once, before any reply
    p.reply("<HT>00#<ENQ>0000#<ACK>");
    QTRY_COMPARE(log, (QStringList{"ht:<HT>00#", "enq:<ENQ>0000#", "stop:<ACK>"}));
}

STEPDECK_TEST_GUILESS_MAIN(TestElabExchangeQueue)
#include "tst_elabexchangequeue.moc"
