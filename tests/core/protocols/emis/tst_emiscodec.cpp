// EmisCodec against every example of chapter 9 of the SMC-IC4 manual: the encoder byte for
// byte, the reply decoder whole, byte by byte, in random chunks and with garbage.
#include "TestMain.h"
#include "protocols/emis/EmisCodec.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::emis;
Q_DECLARE_METATYPE(stepdeck::emis::Event::Kind)

namespace {
// Every reply example of chapter 9, in the order of the manual, as bytes on the wire, with
// the events the decoder must produce ("A:text" = Ack, "N:text" = Nak, "B:text" = Bell,
// "DC1".."DC4" = Arrived).
struct ManualReply
{
    const char* section;
    QByteArray wire;
    QStringList events;
};

const QList<ManualReply>& manualReplies()
{
    static const QList<ManualReply> list{
        {"9.1 version", "@V SMC-IC4 v1.07\x06", {"A:@V SMC-IC4 v1.07"}},
        {"9.2 one input", "@I1 0\x06", {"A:@I1 0"}},
        {"9.2 all inputs", "@IG 10000000\x06", {"A:@IG 10000000"}},
        {"9.3 output", "\x06", {"A:"}},
        {"9.9 reference X", "$Hx\x15\x11", {"N:$Hx", "DC1"}},
        {"9.9 reference XYZU one by one",
         "$Hxyzu\x15\x11\x12\x13\x14",
         {"N:$Hxyzu", "DC1", "DC2", "DC3", "DC4"}},
        {"9.9 reference XYZU simultaneous",
         "$Hxyzu\x15\x14\x12\x11\x13",
         {"N:$Hxyzu", "DC4", "DC2", "DC1", "DC3"}},
        {"9.11 vector X", "\x15 \x11", {"N:", "DC1"}},
        {"9.11 vector X, Y", "\x15 \x11\x12", {"N:", "DC1", "DC2"}},
        {"9.14 system parameters",
         "\x06 Ready! \x06 \x06 \x06 \x06",
         {"A:", "A:Ready!", "A:", "A:", "A:"}},
        {"9.16 clear system parameters", "*PESYS \x06", {"A:*PESYS"}},
        {"9.18 erase input program", "*PEIN1 \x06", {"A:*PEIN1"}},
        {"refusal", "\x07", {"B:"}},
    };
    return list;
}

QStringList describe(const QList<Event>& events)
{
    QStringList out;
    for (const Event& e : events) {
        switch (e.kind) {
        case Event::Kind::Ack:
            out << "A:" + QString::fromLatin1(e.text);
            break;
        case Event::Kind::Nak:
            out << "N:" + QString::fromLatin1(e.text);
            break;
        case Event::Kind::Bell:
            out << "B:" + QString::fromLatin1(e.text);
            break;
        case Event::Kind::Arrived:
            out << QStringLiteral("DC%1").arg(e.axis.index() + 1);
            break;
        case Event::Kind::Invalid:
            out << "INVALID";
            break;
        }
    }
    return out;
}

QByteArray allWire()
{
    QByteArray out;
    for (const ManualReply& r : manualReplies())
        out += r.wire;
    return out;
}

QStringList allEvents()
{
    QStringList out;
    for (const ManualReply& r : manualReplies())
        out += r.events;
    return out;
}
} // namespace

class TestEmisCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void encode_manualExamples_data();
    void encode_manualExamples();
    void encode_homeOrdersAxesXyzu();
    void decode_manualExamples_data();
    void decode_manualExamples();
    void decode_byteByByte_sameAsWhole();
    void decode_randomChunks_sameAsWhole();
    void decode_arrivalInsideAnswer_reportedAndAnswerKept();
    void decode_garbage_reportedAndResynchronised();
    void decode_overlongText_boundedAndDroppedToTerminator();
    void decode_blanksAndLineEnds_trimmed();
    void decode_everyByteAccountedFor();
    void answers_versionAndInputs();
    void answers_malformedInputs_rejected_data();
    void answers_malformedInputs_rejected();
    void answers_ready();
};

void TestEmisCodec::encode_manualExamples_data()
{
    QTest::addColumn<QByteArray>("actual");
    QTest::addColumn<QByteArray>("expected");
    using A = Axis;
    QTest::newRow("9.1") << encode::version() << QByteArray("@V\r");
    QTest::newRow("9.2 one") << encode::input(1) << QByteArray("@I1\r");
    QTest::newRow("9.2 all") << encode::allInputs() << QByteArray("@IG\r");
    QTest::newRow("9.3 set") << encode::output(1, true) << QByteArray("A1,1\r");
    QTest::newRow("9.3 reset") << encode::output(1, false) << QByteArray("A1,0\r");
    QTest::newRow("9.4 all") << encode::startSpeedAll(200) << QByteArray("#S200\r");
    QTest::newRow("9.4 X") << encode::startSpeed(A::X, 200) << QByteArray("#S,x200\r");
    QTest::newRow("9.5 all") << encode::workSpeedAll(1000) << QByteArray("#E1,1000\r");
    QTest::newRow("9.5 X") << encode::workSpeed(A::X, 1000) << QByteArray("#E1,x1000\r");
    QTest::newRow("9.5 reference") << encode::referenceSpeed(400) << QByteArray("#E9,400\r");
    QTest::newRow("9.6") << encode::ramp(100) << QByteArray("#R100\r");
    QTest::newRow("9.7") << encode::stepResolution(A::X, 32) << QByteArray("D,x32\r");
    QTest::newRow("9.8") << encode::current(A::X, 100, 20) << QByteArray("c,x100,20\r");
    QTest::newRow("9.9 X") << encode::home({A::X}, false) << QByteArray("$Hx\r");
    QTest::newRow("9.9 XYZU") << encode::home({A::X, A::Y, A::Z, A::U}, false)
                              << QByteArray("$Hxyzu\r");
    QTest::newRow("9.9 XYZU simultaneous")
        << encode::home({A::X, A::Y, A::Z, A::U}, true) << QByteArray("$Hxyzu,a\r");
    QTest::newRow("9.10") << encode::referenceOffset(A::X, 10) << QByteArray("#Ox,10\r");
    QTest::newRow("9.11 +X") << encode::vector({{A::X, 1000, false}}) << QByteArray("L1,x1000\r");
    QTest::newRow("9.11 -X") << encode::vector({{A::X, -1000, false}}) << QByteArray("L1,x-1000\r");
    QTest::newRow("9.11 X,Y") << encode::vector({{A::X, 1000, false}, {A::Y, -2000, false}})
                              << QByteArray("L1,x1000,y-2000\r");
    QTest::newRow("9.11 absolute")
        << encode::vector({{A::X, 1000, true}}) << QByteArray("L1,X1000\r");
    QTest::newRow("9.11 absolute U")
        << encode::vector({{A::U, -5, true}}) << QByteArray("L1,U-5\r");
    QTest::newRow("9.12 on") << encode::interpolation(true) << QByteArray("IP1\r");
    QTest::newRow("9.12 off") << encode::interpolation(false) << QByteArray("IP0\r");
    QTest::newRow("9.13") << encode::wait(500) << QByteArray("W500\r");
    QTest::newRow("9.14 D") << encode::systemPerAxis(
                                   "D", {{A::X, 32}, {A::Y, 16}, {A::Z, 64}, {A::U, 1}})
                            << QByteArray("##D,x32,y16,z64,u1\r");
    QTest::newRow("9.14 c") << encode::systemCurrents({{A::X, {100, 0}},
                                                       {A::Y, {100, 0}},
                                                       {A::Z, {100, 20}},
                                                       {A::U, {100, 0}}})
                            << QByteArray("##c,x100,0,y100,0,z100,20,u100,0\r");
    QTest::newRow("9.14 REFSW") << encode::systemReferenceSwitches(
                                       {{A::X, false}, {A::Y, false}, {A::Z, false}, {A::U, true}})
                                << QByteArray("##REFSW,xNO,yNO,zNO,uNC\r");
    QTest::newRow("9.14 S") << encode::systemPerAxis(
                                   "S", {{A::X, 200}, {A::Y, 200}, {A::Z, 200}, {A::U, 200}})
                            << QByteArray("##S,x200,y200,z200,u200\r");
    QTest::newRow("9.14 E") << encode::systemPerAxis(
                                   "E", {{A::X, 1800}, {A::Y, 1800}, {A::Z, 600}, {A::U, 1000}})
                            << QByteArray("##E,x1800,y1800,z600,u1000\r");
    QTest::newRow("9.14 E9") << encode::systemPerAxis(
                                    "E9", {{A::X, 400}, {A::Y, 400}, {A::Z, 200}, {A::U, 300}})
                             << QByteArray("##E9,x400,y400,z200,u300\r");
    QTest::newRow("9.14 R") << encode::systemRamp(100) << QByteArray("##R,100\r");
    QTest::newRow("9.15") << encode::readSystem() << QByteArray("*PRSYS\r");
    QTest::newRow("9.16") << encode::clearSystem() << QByteArray("*PESYS\r");
    QTest::newRow("9.17 open 7") << encode::programOpen(7) << QByteArray("*PWIN7\r");
    QTest::newRow("9.17 header 7") << encode::programHeader(7, "Eingang 7: Referenzfahrt X-Motor")
                                   << QByteArray("IJ7,1 Eingang 7: Referenzfahrt X-Motor\x02");
    QTest::newRow("9.17 home line") << encode::programLine("$H,x") << QByteArray("$H,x\r");
    QTest::newRow("9.17 end") << encode::programEnd() << QByteArray("\x03");
    QTest::newRow("9.17 open 8") << encode::programOpen(8) << QByteArray("*PWIN8\r");
    QTest::newRow("9.17 header 8") << encode::programHeader(8, "Eingang 8: Vektorfahrt X-Motor")
                                   << QByteArray("IJ8,1 Eingang 8: Vektorfahrt X-Motor\x02");
    QTest::newRow("9.17 vector line") << encode::programLine("L1,x191") << QByteArray("L1,x191\r");
    QTest::newRow("9.17 wait line") << encode::programLine("W1500") << QByteArray("W1500\r");
    QTest::newRow("9.18") << encode::programErase(1) << QByteArray("*PEIN1\r");
}

void TestEmisCodec::encode_manualExamples()
{
    QFETCH(QByteArray, actual);
    QFETCH(QByteArray, expected);
    QCOMPARE(actual, expected);
}

void TestEmisCodec::encode_homeOrdersAxesXyzu()
{
    QCOMPARE(encode::home({Axis::U, Axis::X}, false), QByteArray("$Hxu\r"));
    QCOMPARE(arrivalCode(Axis::X), char(0x11));
    QCOMPARE(arrivalCode(Axis::U), char(0x14));
}

void TestEmisCodec::decode_manualExamples_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<QStringList>("events");
    for (const ManualReply& r : manualReplies())
        QTest::newRow(r.section) << r.wire << r.events;
}

void TestEmisCodec::decode_manualExamples()
{
    QFETCH(QByteArray, wire);
    QFETCH(QStringList, events);
    ReplyDecoder decoder;
    QCOMPARE(describe(decoder.feed(wire)), events);
    QCOMPARE(decoder.buffered(), 0);
}

void TestEmisCodec::decode_byteByByte_sameAsWhole()
{
    ReplyDecoder decoder;
    QList<Event> events;
    for (char c : allWire())
        events += decoder.feed(QByteArray(1, c));
    QCOMPARE(describe(events), allEvents());
}

void TestEmisCodec::decode_randomChunks_sameAsWhole()
{
    const QByteArray wire = allWire();
    QRandomGenerator rng(4711);
    for (int round = 0; round < 50; ++round) {
        ReplyDecoder decoder;
        QList<Event> events;
        int at = 0;
        while (at < wire.size()) {
            const int n = rng.bounded(1, 12);
            events += decoder.feed(wire.mid(at, n));
            at += n;
        }
        QCOMPARE(describe(events), allEvents());
    }
}

void TestEmisCodec::decode_arrivalInsideAnswer_reportedAndAnswerKept()
{
    // A move ends while the board is answering a poll: the DC1 is its own event.
    ReplyDecoder decoder;
    QCOMPARE(describe(decoder.feed("@IG 1000\x11"
                                   "0000\x06")),
             (QStringList{"DC1", "A:@IG 10000000"}));
}

void TestEmisCodec::decode_garbage_reportedAndResynchronised()
{
    ReplyDecoder decoder;
    static const char wire[] = "@IG 10\xff\x80"
                               "000000\x06\x00\x06\x15 \x12";
    const QList<Event> events = decoder.feed(QByteArray(wire, sizeof(wire) - 1));
    QCOMPARE(describe(events), (QStringList{"INVALID", "A:000000", "INVALID", "A:", "N:", "DC2"}));
    QCOMPARE(events[0].raw, QByteArray("@IG 10\xff\x80"));
    QVERIFY(!events[0].error.isEmpty());
    QCOMPARE(events[2].raw, QByteArray(1, '\0'));
}

void TestEmisCodec::decode_overlongText_boundedAndDroppedToTerminator()
{
    ReplyDecoder decoder;
    const QByteArray flood(ReplyDecoder::kMaxText * 3, 'A');
    QList<Event> events;
    for (int i = 0; i < flood.size(); i += 100) {
        events += decoder.feed(flood.mid(i, 100));
        QVERIFY(decoder.buffered() <= ReplyDecoder::kMaxText);
    }
    events += decoder.feed("\x06"
                           "@V SMC-IC4 v1.07\x06");
    QCOMPARE(describe(events), (QStringList{"INVALID", "A:@V SMC-IC4 v1.07"}));
    // Arrivals are never swallowed, not even while an overlong text is being dropped.
    events = decoder.feed(QByteArray(ReplyDecoder::kMaxText + 5, 'B') + "\x13\x06\x06");
    QCOMPARE(describe(events), (QStringList{"INVALID", "DC3", "A:"}));
}

void TestEmisCodec::decode_blanksAndLineEnds_trimmed()
{
    ReplyDecoder decoder;
    QCOMPARE(describe(decoder.feed("\r\n @IG 01000001 \r\n\x06  \x15\t\x14")),
             (QStringList{"A:@IG 01000001", "N:", "DC4"}));
}

void TestEmisCodec::decode_everyByteAccountedFor()
{
    // Found while writing the fuzz target: blanks and overlong tails vanished without a count.
    // Every byte is in an event (text, raw, terminator), buffered or skipped.
    const QByteArray in = QByteArray("\r\n @IG 01000001 \r\n\x06  \x15\t\x14\x80x\x06") +
                          QByteArray(ReplyDecoder::kMaxText + 3, 'A') + "zz\x06" + " @V";
    ReplyDecoder decoder;
    qint64 accounted = 0;
    for (const Event& e : decoder.feed(in))
        accounted += e.kind == Event::Kind::Invalid ? e.raw.size() : 1 + e.text.size();
    QCOMPARE(decoder.buffered(), 2); // "@V", the blank before it skipped
    // ten blanks; the overlong text's last two 'A', "zz" and its <ACK>
    QCOMPARE(decoder.skippedBytes(), 10 + 5);
    QCOMPARE(accounted + decoder.buffered() + decoder.skippedBytes(), in.size());
}

void TestEmisCodec::answers_versionAndInputs()
{
    QCOMPARE(parseVersion("@V SMC-IC4 v1.07").value(), QStringLiteral("SMC-IC4 v1.07"));
    QCOMPARE(parseVersion("SMC-IC4 v1.07").value(), QStringLiteral("SMC-IC4 v1.07"));
    QVERIFY(!parseVersion("@V").has_value());
    const auto levels = parseAllInputs("@IG 10000000");
    QVERIFY(levels.has_value());
    QCOMPARE(*levels, (QList<bool>{true, false, false, false, false, false, false, false}));
    QCOMPARE(parseAllInputs("00000011").value().last(), true); // without the echo
    QCOMPARE(parseInput("@I1 0", 1), std::optional<bool>(false));
    QCOMPARE(parseInput("@I8 1", 8), std::optional<bool>(true));
}

void TestEmisCodec::answers_malformedInputs_rejected_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::newRow("seven") << QByteArray("@IG 1000000");
    QTest::newRow("nine") << QByteArray("@IG 100000000");
    QTest::newRow("letter") << QByteArray("@IG 1000000x");
    QTest::newRow("empty") << QByteArray("@IG");
    QTest::newRow("ready") << QByteArray("Ready!");
}

void TestEmisCodec::answers_malformedInputs_rejected()
{
    QFETCH(QByteArray, text);
    QVERIFY(!parseAllInputs(text).has_value());
}

void TestEmisCodec::answers_ready()
{
    QVERIFY(isReady("Ready!"));
    QVERIFY(isReady(" READY! "));
    QVERIFY(!isReady("Ready"));
    QVERIFY(!isReady(""));
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisCodec)
#include "tst_emiscodec.moc"
