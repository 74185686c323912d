// NanotecCodec against every example of the SMCI33/SMCI47-S command reference, both
// directions, fed whole, byte by byte, in random chunks and with garbage in between.
#include "TestMain.h"
#include "protocols/nanotec/NanotecCodec.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck::nanotec;
Q_DECLARE_METATYPE(stepdeck::nanotec::Reply::Kind)

namespace {
// Every reply example of the manual (sections 1.1, 1.2, 3, 5.19, 5.22, 5.24, 6.4) plus the
// status/position/error replies the adapter relies on.
const QList<QPair<QByteArray, Reply::Kind>>& manualReplies()
{
    static const QList<QPair<QByteArray, Reply::Kind>> list{
        {"001s1000\r", Reply::Kind::Echo},
        {"001A\r", Reply::Kind::Echo},
        {"001/?\r", Reply::Kind::Unknown},
        {"1:?\r", Reply::Kind::LongUnknown},
        {"1:CL_motor_pp+50\r", Reply::Kind::Long},
        {"1:CL_motor_pp=100\r", Reply::Kind::Long},
        {"001Zs1000\r", Reply::Kind::Read},
        {"001Z5s2000\r", Reply::Kind::Read},
        {"001v PD4_RS485_26-09-2007\r", Reply::Kind::Firmware},
        {"1L0\r", Reply::Kind::Echo},
        {"1L20\r", Reply::Kind::Echo},
        {"Zp+1s+1u+400o+860n+1000b+55800d+1t+0W+1P+0N+0\r", Reply::Kind::Record},
        {"Z5p+1s+400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0\r", Reply::Kind::Record},
        {"001$17\r", Reply::Kind::Echo},
        {"002j33\r", Reply::Kind::Echo},
        {"003C-1500\r", Reply::Kind::Echo},
        {"001ZE5+8\r", Reply::Kind::Read},
    };
    return list;
}

QList<Reply::Kind> kinds(const QList<Reply>& replies)
{
    QList<Reply::Kind> out;
    for (const Reply& r : replies)
        out << r.kind;
    return out;
}

QList<Reply::Kind> expectedKinds()
{
    QList<Reply::Kind> out;
    for (const auto& p : manualReplies())
        out << p.second;
    return out;
}

QByteArray wire()
{
    QByteArray out;
    for (const auto& p : manualReplies())
        out += p.first;
    return out;
}
} // namespace

class TestNanotecCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void encode_manualExamples_data();
    void encode_manualExamples();
    void encode_forbiddenCommands_areNeverProduced();
    void commandKey_data();
    void commandKey();
    void parseNumber_digitsNotSignBound_data();
    void parseNumber_digitsNotSignBound();
    void decode_manualExamples_data();
    void decode_manualExamples();
    void decode_longReplies_acceptBothAddressForms();
    void decode_firmwareString_splitsBlocks();
    void decode_recordString_fieldsInManualOrder();
    void decode_recordString_onlySection4Fields_data();
    void decode_recordString_onlySection4Fields();
    void decode_errorMemory_slotAndCode();
    void decode_byteByByte_sameAsWhole();
    void decode_randomChunks_sameAsWhole();
    void decode_garbageBetweenFrames_resynchronisesAtCr();
    void decode_overlongFrame_isBoundedAndResyncs();
    void decode_hostEchoOfAdapter_isRecognised();
    void status_bitsDecoded_data();
    void status_bitsDecoded();
    void record_formatRoundTrip();
    void commandDecoder_framesAndAddresses();
    void commandDecoder_garbageAndInterruptedFrames();
    void decoders_everyByteAccountedFor_data();
    void decoders_everyByteAccountedFor();
    void errorCodes_namedAsInManual();
};

void TestNanotecCodec::encode_manualExamples_data()
{
    QTest::addColumn<QByteArray>("actual");
    QTest::addColumn<QByteArray>("expected");
    QTest::newRow("1.1 set travel") << encode::command(1, "s", 1000) << QByteArray("#1s1000\r");
    QTest::newRow("1.1 start record") << encode::command(1, "A") << QByteArray("#1A\r");
    QTest::newRow("1.1 unknown") << encode::command(1, "/") << QByteArray("#1/\r");
    QTest::newRow("1.1 broadcast stop") << encode::command(kBroadcast, "S") << QByteArray("#*S\r");
    QTest::newRow("1.2 read pole pairs")
        << encode::longRead(1, "CL_motor_pp") << QByteArray("#1:CL_motor_pp\r");
    QTest::newRow("1.2 set pole pairs")
        << encode::longWrite(1, "CL_motor_pp", 100) << QByteArray("#1:CL_motor_pp=100\r");
    QTest::newRow("3 read travel") << encode::read(1, "s") << QByteArray("#1Zs\r");
    QTest::newRow("5.19 read record 5") << encode::read(1, "s", 5) << QByteArray("#1Z5s\r");
    QTest::newRow("5.24 mask 0") << encode::command(1, "L", 0) << QByteArray("#1L0\r");
    QTest::newRow("5.24 mask 20") << encode::command(1, "L", 20) << QByteArray("#1L20\r");
    QTest::newRow("5.15 error slot") << encode::readErrorMemory(1, 5) << QByteArray("#1ZE5\r");
    QTest::newRow("6.4 current record") << encode::readRecord(1) << QByteArray("#1Z|\r");
    QTest::newRow("6.4 record 5") << encode::readRecord(1, 5) << QByteArray("#1Z5|\r");
    QTest::newRow("negative travel") << encode::command(254, "s", -50) << QByteArray("#254s-50\r");
    QTest::newRow("status") << encode::command(3, "$") << QByteArray("#3$\r");
}

void TestNanotecCodec::encode_manualExamples()
{
    QFETCH(QByteArray, actual);
    QFETCH(QByteArray, expected);
    QCOMPARE(actual, expected);
}

void TestNanotecCodec::encode_forbiddenCommands_areNeverProduced()
{
    QVERIFY(encode::command(1, "|", 0).isEmpty());
    QVERIFY(encode::command(1, "|").isEmpty());
    QVERIFY(encode::command(1, "@A").isEmpty());
    QVERIFY(!forbiddenReason("|0").isEmpty());
    QVERIFY(!forbiddenReason("@A\r").isEmpty());
    QCOMPARE(encode::command(1, "|", 1), QByteArray("#1|1\r"));
    QVERIFY(forbiddenReason("s1000").isEmpty());
}

void TestNanotecCodec::commandKey_data()
{
    QTest::addColumn<QByteArray>("body");
    QTest::addColumn<QByteArray>("key");
    QTest::newRow("value") << QByteArray("s1000") << QByteArray("s");
    QTest::newRow("plain") << QByteArray("A") << QByteArray("A");
    QTest::newRow("read") << QByteArray("Zs") << QByteArray("Zs");
    QTest::newRow("read record") << QByteArray("Z5s") << QByteArray("Z5s");
    QTest::newRow("read record 32") << QByteArray("Z32N") << QByteArray("Z32N");
    QTest::newRow("error slot") << QByteArray("ZE12") << QByteArray("ZE");
    QTest::newRow("record") << QByteArray("Z|") << QByteArray("Z|");
    QTest::newRow("record 5") << QByteArray("Z5|") << QByteArray("Z5|");
    QTest::newRow("long read") << QByteArray(":CL_motor_pp") << QByteArray(":CL_motor_pp");
    QTest::newRow("long write") << QByteArray(":brake_ta=10") << QByteArray(":brake_ta");
}

void TestNanotecCodec::commandKey()
{
    QFETCH(QByteArray, body);
    QFETCH(QByteArray, key);
    QCOMPARE(stepdeck::nanotec::commandKey(body), key);
}

void TestNanotecCodec::decode_manualExamples_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<Reply::Kind>("kind");
    QTest::addColumn<int>("address");
    QTest::addColumn<QByteArray>("key");
    QTest::addColumn<qint64>("value"); // -999999: no value
    const qint64 none = -999999;
    QTest::newRow("1.1 echo") << QByteArray("001s1000\r") << Reply::Kind::Echo << 1
                              << QByteArray("s") << qint64(1000);
    QTest::newRow("1.1 start") << QByteArray("001A\r") << Reply::Kind::Echo << 1 << QByteArray("A")
                               << none;
    QTest::newRow("1.1 unknown") << QByteArray("001/?\r") << Reply::Kind::Unknown << 1
                                 << QByteArray("/") << none;
    QTest::newRow("1.2 unknown") << QByteArray("1:?\r") << Reply::Kind::LongUnknown << 1
                                 << QByteArray(":?") << none;
    QTest::newRow("1.2 read") << QByteArray("1:CL_motor_pp+50\r") << Reply::Kind::Long << 1
                              << QByteArray(":CL_motor_pp") << qint64(50);
    QTest::newRow("1.2 write") << QByteArray("1:CL_motor_pp=100\r") << Reply::Kind::Long << 1
                               << QByteArray(":CL_motor_pp") << qint64(100);
    QTest::newRow("3 read") << QByteArray("001Zs1000\r") << Reply::Kind::Read << 1
                            << QByteArray("Zs") << qint64(1000);
    QTest::newRow("5.19 record value") << QByteArray("001Z5s2000\r") << Reply::Kind::Read << 1
                                       << QByteArray("Z5s") << qint64(2000);
    QTest::newRow("5.22 firmware") << QByteArray("001v PD4_RS485_26-09-2007\r")
                                   << Reply::Kind::Firmware << 1 << QByteArray("v") << none;
    QTest::newRow("5.24 mask 0") << QByteArray("1L0\r") << Reply::Kind::Echo << 1 << QByteArray("L")
                                 << qint64(0);
    QTest::newRow("5.24 mask 20") << QByteArray("1L20\r") << Reply::Kind::Echo << 1
                                  << QByteArray("L") << qint64(20);
    QTest::newRow("6.4 record") << QByteArray("Zp+1s+1u+400o+860n+1000b+55800d+1t+0W+1P+0N+0\r")
                                << Reply::Kind::Record << 0 << QByteArray("Z|") << none;
    QTest::newRow("6.4 record 5") << QByteArray(
                                         "Z5p+1s+400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0\r")
                                  << Reply::Kind::Record << 0 << QByteArray("Z5|") << none;
    QTest::newRow("5.21 status") << QByteArray("001$17\r") << Reply::Kind::Echo << 1
                                 << QByteArray("$") << qint64(17);
    QTest::newRow("5.31 auto status")
        << QByteArray("002j33\r") << Reply::Kind::Echo << 2 << QByteArray("j") << qint64(33);
    QTest::newRow("5.17 position") << QByteArray("254C-1500\r") << Reply::Kind::Echo << 254
                                   << QByteArray("C") << qint64(-1500);
    QTest::newRow("signed echo") << QByteArray("001s+1000\r") << Reply::Kind::Echo << 1
                                 << QByteArray("s") << qint64(1000);
}

void TestNanotecCodec::decode_manualExamples()
{
    QFETCH(QByteArray, bytes);
    QFETCH(Reply::Kind, kind);
    QFETCH(int, address);
    QFETCH(QByteArray, key);
    QFETCH(qint64, value);
    ReplyDecoder decoder;
    const QList<Reply> replies = decoder.feed(bytes);
    QCOMPARE(replies.size(), 1);
    const Reply& r = replies.first();
    QVERIFY2(r.kind == kind, qPrintable(r.error));
    QCOMPARE(r.address, address);
    QCOMPARE(r.key, key);
    QCOMPARE(r.value.has_value(), value != -999999);
    if (r.value)
        QCOMPARE(*r.value, value);
    QCOMPARE(r.raw + '\r', bytes);
    QCOMPARE(decoder.buffered(), 0);
}

void TestNanotecCodec::decode_longReplies_acceptBothAddressForms()
{
    ReplyDecoder decoder;
    const QList<Reply> r = decoder.feed("001:CL_motor_pp+50\r1:CL_motor_pp+50\r002:brake_ta-1\r");
    QCOMPARE(r.size(), 3);
    QCOMPARE(r[0].address, 1);
    QCOMPARE(r[1].address, 1);
    QCOMPARE(r[0].key, r[1].key);
    QVERIFY(!r[0].assignment);
    QCOMPARE(r[2].address, 2);
    QCOMPARE(*r[2].value, qint64(-1));
}

void TestNanotecCodec::decode_firmwareString_splitsBlocks()
{
    ReplyDecoder decoder;
    const QList<Reply> r =
        decoder.feed("001v PD4_RS485_26-09-2007\r012v SMCI47-S_RS485_04-12-2008\r");
    QCOMPARE(r.size(), 2);
    QCOMPARE(r[0].firmware.hardware, QStringLiteral("PD4"));
    QCOMPARE(r[0].firmware.interface, QStringLiteral("RS485"));
    QCOMPARE(r[0].firmware.date, QStringLiteral("26-09-2007"));
    QCOMPARE(r[1].address, 12);
    QCOMPARE(r[1].firmware.hardware, QStringLiteral("SMCI47-S"));
    QCOMPARE(r[1].firmware.text, QStringLiteral("SMCI47-S_RS485_04-12-2008"));
    QVERIFY(!parseFirmware("garbage").has_value());
}

void TestNanotecCodec::decode_recordString_fieldsInManualOrder()
{
    ReplyDecoder decoder;
    const QList<Reply> r = decoder.feed("001Z5p+1s-400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0\r");
    QCOMPARE(r.size(), 1);
    QCOMPARE(r[0].kind, Reply::Kind::Record);
    QCOMPARE(r[0].address, 1);
    QCOMPARE(r[0].record, 5);
    const RecordData& d = r[0].recordData;
    QCOMPARE(d.fields.size(), recordFieldOrder().size());
    for (int i = 0; i < d.fields.size(); ++i)
        QCOMPARE(d.fields[i].first, recordFieldOrder().at(i));
    QCOMPARE(*d.value('s'), qint64(-400));
    QCOMPARE(*d.value('b'), qint64(2364));
    QCOMPARE(*d.value('W'), qint64(1));
    QVERIFY(!d.value('x').has_value());
}

// Issue 12: "001Z0E1s0" was taken as a record with fields E and s. A record string (6.4)
// carries the settings of section 4 (p s u o n b d t W P N), each once, of record 1..32 or RAM.
void TestNanotecCodec::decode_recordString_onlySection4Fields_data()
{
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<QString>("why"); // part of the error when invalid
    QTest::newRow("6.4 example") << QByteArray("Zp+1s+1u+400o+860n+1000b+55800d+1t+0W+1P+0N+0")
                                 << true << "";
    QTest::newRow("6.4 example, record 5, address")
        << QByteArray("001Z5p+1s+400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0") << true << "";
    QTest::newRow("record 32") << QByteArray("001Z32p+1s+4") << true << "";
    QTest::newRow("a subset") << QByteArray("001Zp+1N+0") << true << "";
    QTest::newRow("issue example") << QByteArray("001Z0E1s0") << false << "record '0'";
    QTest::newRow("letter E in RAM record") << QByteArray("001Zs+0E1") << false << "'E'";
    QTest::newRow("any letter") << QByteArray("001Zp+1Q+5") << false << "'Q'";
    QTest::newRow("lower-case w of the table") << QByteArray("001Zp+1w+1") << false << "'w'";
    QTest::newRow("a symbol") << QByteArray("001Zp+1$+1") << false << "'$'";
    QTest::newRow("field twice") << QByteArray("001Zp+1s+1p+2") << false << "twice";
    QTest::newRow("record 0") << QByteArray("001Z0p+1s+1") << false << "record '0'";
    QTest::newRow("record 33") << QByteArray("001Z33p+1s+1") << false << "record '33'";
    QTest::newRow("record with leading zero")
        << QByteArray("001Z05p+1s+1") << false << "record '05'";
    QTest::newRow("record number overflow")
        << QByteArray("001Z99999999999p+1s+1") << false << "record";
    QTest::newRow("read of record 40") << QByteArray("001Z40s100") << false << "record '40'";
    QTest::newRow("field without value") << QByteArray("001Zp+1s") << false << "malformed";
}

void TestNanotecCodec::decode_recordString_onlySection4Fields()
{
    QFETCH(QByteArray, frame);
    QFETCH(bool, valid);
    QFETCH(QString, why);
    const Reply r = ReplyDecoder::parse(frame);
    if (valid) {
        QVERIFY2(r.kind == Reply::Kind::Record, qPrintable(r.error));
        for (const auto& field : r.recordData.fields)
            QVERIFY(recordFieldOrder().contains(field.first));
    } else {
        QCOMPARE(r.kind, Reply::Kind::Invalid);
        QVERIFY2(r.error.contains(why), qPrintable(r.error));
        QCOMPARE(r.raw, frame); // every byte accounted for
    }
}

void TestNanotecCodec::decode_errorMemory_slotAndCode()
{
    ReplyDecoder decoder;
    const QList<Reply> r = decoder.feed("001ZE5+8\r001ZE12+16\r001E5\r");
    QCOMPARE(r.size(), 3);
    QCOMPARE(r[0].index, 5);
    QCOMPARE(*r[0].value, qint64(error::Eeprom));
    QCOMPARE(r[1].index, 12);
    QCOMPARE(*r[1].value, qint64(error::Position));
    QCOMPARE(r[2].key, QByteArray("E"));
    QCOMPARE(*r[2].value, qint64(5));
}

void TestNanotecCodec::decode_byteByByte_sameAsWhole()
{
    ReplyDecoder decoder;
    QList<Reply> out;
    for (char c : wire())
        out += decoder.feed(QByteArray(1, c));
    QCOMPARE(kinds(out), expectedKinds());
    QCOMPARE(decoder.buffered(), 0);
}

void TestNanotecCodec::decode_randomChunks_sameAsWhole()
{
    QRandomGenerator rng(42);
    const QByteArray all = wire();
    for (int round = 0; round < 50; ++round) {
        ReplyDecoder decoder;
        QList<Reply> out;
        for (int i = 0; i < all.size();) {
            const int n = 1 + int(rng.bounded(12));
            out += decoder.feed(all.mid(i, n));
            i += n;
        }
        QCOMPARE(kinds(out), expectedKinds());
    }
}

void TestNanotecCodec::decode_garbageBetweenFrames_resynchronisesAtCr()
{
    ReplyDecoder decoder;
    QByteArray in("\x01\xff\x80junk\r");
    in += "001s1000\r";
    in += "001s10x0\r"; // non-numeric value
    in += "\n\n001A\r"; // LF from some adapters is ignored
    in += "abc\r";      // no address
    in += "1:CL_motor_pp+\r";
    in += "002$49\r";
    const QList<Reply> r = decoder.feed(in);
    const QList<Reply::Kind> expected{
        Reply::Kind::Invalid, Reply::Kind::Echo,    Reply::Kind::Invalid, Reply::Kind::Echo,
        Reply::Kind::Invalid, Reply::Kind::Invalid, Reply::Kind::Echo};
    QCOMPARE(kinds(r), expected);
    QVERIFY(!r[0].error.isEmpty());
    QCOMPARE(r[6].address, 2);
}

void TestNanotecCodec::decode_overlongFrame_isBoundedAndResyncs()
{
    ReplyDecoder decoder;
    QList<Reply> r = decoder.feed(QByteArray(1000, '7'));
    QCOMPARE(r.size(), 1);
    QCOMPARE(r[0].kind, Reply::Kind::Invalid);
    QVERIFY(decoder.buffered() <= ReplyDecoder::kMaxFrame);
    r = decoder.feed(QByteArray(500, '7') + "\r001A\r");
    QCOMPARE(r.size(), 1); // the rest of the long frame is dropped up to its CR
    QCOMPARE(r[0].kind, Reply::Kind::Echo);
    QCOMPARE(r[0].key, QByteArray("A"));
}

void TestNanotecCodec::decode_hostEchoOfAdapter_isRecognised()
{
    ReplyDecoder decoder;
    const QList<Reply> r = decoder.feed("#1A\r001A\r");
    QCOMPARE(r.size(), 2);
    QCOMPARE(r[0].kind, Reply::Kind::HostEcho);
    QCOMPARE(r[1].kind, Reply::Kind::Echo);
}

void TestNanotecCodec::status_bitsDecoded_data()
{
    QTest::addColumn<int>("word");
    QTest::addColumn<bool>("ready");
    QTest::addColumn<bool>("zero");
    QTest::addColumn<bool>("posError");
    QTest::addColumn<bool>("input1");
    QTest::addColumn<int>("mode");
    QTest::newRow("ready positioning") << 0x11 << true << false << false << false << 1;
    QTest::newRow("busy speed") << 0x20 << false << false << false << false << 2;
    QTest::newRow("zero reached") << 0x13 << true << true << false << false << 1;
    QTest::newRow("position error") << 0x15 << true << false << true << false << 1;
    QTest::newRow("input 1") << 0x69 << true << false << false << true << 6;
}

void TestNanotecCodec::status_bitsDecoded()
{
    QFETCH(int, word);
    const DriveState s = decodeStatus(word);
    QTEST(s.ready, "ready");
    QTEST(s.zeroReached, "zero");
    QTEST(s.positionError, "posError");
    QTEST(s.input1WhileReady, "input1");
    QTEST(s.mode, "mode");
    QCOMPARE(int(encodeStatus(s)), word);
    QVERIFY(!describeStatus(word).isEmpty());
}

void TestNanotecCodec::record_formatRoundTrip()
{
    RecordData d;
    d.record = 7;
    const qint64 values[] = {1, -400, 400, 1000, 1000, 2364, 0, 0, 1, 0, 0};
    for (int i = 0; i < recordFieldOrder().size(); ++i)
        d.fields << qMakePair(recordFieldOrder().at(i), values[i]);
    const QByteArray text = formatRecord(d);
    QCOMPARE(text, QByteArray("Z7p+1s-400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0"));
    const Reply r = ReplyDecoder::parse("001" + text);
    QCOMPARE(r.kind, Reply::Kind::Record);
    QCOMPARE(r.recordData.fields, d.fields);
}

void TestNanotecCodec::commandDecoder_framesAndAddresses()
{
    CommandDecoder decoder;
    const QList<Command> c = decoder.feed("#1s1000\r#*S\r#254:CL_motor_pp=100\r#12Z5|\r");
    QCOMPARE(c.size(), 4);
    QCOMPARE(c[0].address, 1);
    QCOMPARE(c[0].body, QByteArray("s1000"));
    QVERIFY(c[1].broadcast);
    QCOMPARE(c[1].body, QByteArray("S"));
    QCOMPARE(c[2].address, 254);
    QCOMPARE(c[2].body, QByteArray(":CL_motor_pp=100"));
    QCOMPARE(c[3].address, 12);
    QCOMPARE(c[3].raw, QByteArray("#12Z5|\r"));
    for (const Command& cmd : c)
        QVERIFY(cmd.valid);
}

void TestNanotecCodec::commandDecoder_garbageAndInterruptedFrames()
{
    CommandDecoder decoder;
    QList<Command> c;
    for (char ch : QByteArray("noise\r#1s10#2A\r#x\r#3\r"))
        c += decoder.feed(QByteArray(1, ch));
    QCOMPARE(c.size(), 4);
    QVERIFY(!c[0].valid); // interrupted by '#'
    QVERIFY(c[1].valid);
    QCOMPARE(c[1].address, 2);
    QVERIFY(!c[2].valid); // no address
    QVERIFY(!c[3].valid); // no body
    c = decoder.feed(QByteArray("#1") + QByteArray(200, 's'));
    QCOMPARE(c.size(), 1);
    QVERIFY(!c[0].valid);
    c = decoder.feed("\r#1A\r");
    QCOMPARE(c.size(), 1);
    QCOMPARE(c[0].body, QByteArray("A"));
}

// Every byte fed is in a frame's raw, still buffered, or counted as outside frames
// (terminators, filler, garbage before '#', dropped tails). fuzz_nanotec_command found "##"
// losing the first '#'.
void TestNanotecCodec::decoders_everyByteAccountedFor_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<bool>("commands"); // CommandDecoder, else ReplyDecoder
    QTest::newRow("double hash") << QByteArray("##1A\r") << true;
    QTest::newRow("hashes and garbage") << QByteArray("x#\r##2s5#3A\r###") << true;
    QTest::newRow("overlong command")
        << QByteArray("#1s" + QByteArray(200, '9') + "\r#1A\r") << true;
    QTest::newRow("replies with filler")
        << QByteArray("001A\r\n") + QByteArray(2, '\0') + QByteArray("002$17\r\r") << false;
    QTest::newRow("overlong reply")
        << QByteArray("001s" + QByteArray(200, '1') + "\r001A\r") << false;
    QTest::newRow("unfinished reply") << QByteArray("001A\r002s10") << false;
}

void TestNanotecCodec::decoders_everyByteAccountedFor()
{
    QFETCH(QByteArray, wire);
    QFETCH(bool, commands);
    qsizetype inRaw = 0;
    qsizetype buffered = 0;
    qint64 outside = 0;
    if (commands) {
        CommandDecoder decoder;
        for (char c : wire) {
            for (const Command& cmd : decoder.feed(QByteArray(1, c)))
                inRaw += cmd.raw.size();
        }
        buffered = decoder.buffered();
        outside = decoder.unframedBytes();
    } else {
        ReplyDecoder decoder;
        for (const Reply& r : decoder.feed(wire))
            inRaw += r.raw.size();
        buffered = decoder.buffered();
        outside = decoder.unframedBytes();
    }
    QCOMPARE(inRaw + buffered + outside, wire.size());
}

void TestNanotecCodec::errorCodes_namedAsInManual()
{
    QCOMPARE(errorCodeName(0x01), QStringLiteral("ERROR_LOWVOLTAGE"));
    QCOMPARE(errorCodeName(0x10), QStringLiteral("ERROR_QEI"));
    QCOMPARE(errorCodeName(0x20), QStringLiteral("ERROR_INTERNAL"));
    QCOMPARE(errorCodeName(0), QStringLiteral("none"));
    QVERIFY(errorCodeDescription(0x10).contains(QStringLiteral("position")));
}

// The limit is on the digits: a value read without a sign must read again as formatSigned()
// writes it, with its '+' (fuzz_nanotec_reply found "949995009994" taken, "+949995009994" not).
void TestNanotecCodec::parseNumber_digitsNotSignBound_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<qint64>("value");
    QTest::newRow("plain") << QByteArray("1000") << true << qint64(1000);
    QTest::newRow("plus") << QByteArray("+50") << true << qint64(50);
    QTest::newRow("minus") << QByteArray("-3") << true << qint64(-3);
    QTest::newRow("11 digits") << QByteArray("94999500999") << true << qint64(94999500999);
    QTest::newRow("11 digits signed") << QByteArray("+94999500999") << true << qint64(94999500999);
    QTest::newRow("12 digits") << QByteArray("949995009994") << false << qint64(0);
    QTest::newRow("12 digits signed") << QByteArray("+949995009994") << false << qint64(0);
    QTest::newRow("sign only") << QByteArray("-") << false << qint64(0);
    QTest::newRow("empty") << QByteArray() << false << qint64(0);
    QTest::newRow("letter") << QByteArray("1a") << false << qint64(0);
}

void TestNanotecCodec::parseNumber_digitsNotSignBound()
{
    QFETCH(QByteArray, text);
    QFETCH(bool, ok);
    QFETCH(qint64, value);
    qint64 parsed = 0;
    QCOMPARE(parseNumber(text, &parsed), ok);
    if (ok) {
        QCOMPARE(parsed, value);
        qint64 again = 0;
        QVERIFY(parseNumber(formatSigned(parsed), &again));
        QCOMPARE(again, parsed);
    }
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecCodec)
#include "tst_nanoteccodec.moc"
