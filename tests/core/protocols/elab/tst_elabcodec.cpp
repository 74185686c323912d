// ElabCodec against every example of the E-LAB manual, byte for byte, both directions.
#include "ElabTestSupport.h"
#include "TestMain.h"
#include "protocols/elab/ElabCodec.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck::elab;

namespace {
using stepdeck::elab::testing::bytes;

// Concatenation of manual replies used by the streaming tests, with the expected kinds.
struct Stream
{
    QByteArray wire;
    QList<Reply::Kind> kinds;
};

Stream manualReplies()
{
    Stream s;
    const QList<QPair<const char*, Reply::Kind>> parts{
        {"<ETB>14#", Reply::Kind::Temperature},
        {"<ETX>FFFFFFFF,00000010;000000FF.", Reply::Kind::RelPosition},
        {"<NAK>", Reply::Kind::Nak},
        {"<ENQ>0080#", Reply::Kind::MachineState},
        {"<HT>05#", Reply::Kind::AxeState},
        {"<ACK>", Reply::Kind::Ack},
        {"<XOFF>", Reply::Kind::XOff},
        {"<HT>02#", Reply::Kind::AxeState},
        {"<XON>", Reply::Kind::XOn},
        {"<ETX>1F1F1F1F,1E1E1E1E;FFFFFFFF.", Reply::Kind::RelPosition},
    };
    for (const auto& p : parts) {
        s.wire += bytes(p.first);
        s.kinds << p.second;
    }
    return s;
}

QList<Reply::Kind> kindsOf(const QList<Reply>& replies)
{
    QList<Reply::Kind> out;
    for (const Reply& r : replies)
        out << r.kind;
    return out;
}
} // namespace

class TestElabCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void encode_matchesManual_data();
    void encode_matchesManual();
    void commandDecoder_manualExamples_data();
    void commandDecoder_manualExamples();
    void commandDecoder_lowerCaseAndSpaces_accepted();
    void commandDecoder_malformed_reportedThenResyncs();
    void commandDecoder_dc2DataByte_mayBeAnyValue();
    void commandDecoder_randomChunks_sameCommands();
    void replyDecoder_manualExamples_data();
    void replyDecoder_manualExamples();
    void replyDecoder_byteByByte_sameAsWhole();
    void replyDecoder_randomChunks_sameAsWhole();
    void replyDecoder_garbageBetweenFrames_resyncs();
    void replyDecoder_interruptedFrame_reportedAndNextDecoded();
    void replyDecoder_xonInsideFrame_passesThrough();
    void replyDecoder_endlessGarbage_bufferStaysBounded();
    void replyDecoder_longestManualReply_withinFrameBound();
    void commandDecoder_everyByteAccountedFor();
    void stepByte_roundTrip_data();
    void stepByte_roundTrip();
    void mnemonics_roundTripEveryByte();
    void mnemonics_unknownName_reportsPosition();
    void describeMachineState_namesBits();
};

void TestElabCodec::encode_matchesManual_data()
{
    QTest::addColumn<QByteArray>("encoded");
    QTest::addColumn<QByteArray>("manual");
    // Each row: the encoder's output and the example as printed in the manual.
    // Replies (the simulator's side), as printed under the requests.
    QTest::newRow("reply temperature 20 C") << encodeReply::temperature(20) << bytes("<ETB>14#");
    QTest::newRow("reply setup incomplete")
        << encodeReply::machineState(0x0080) << bytes("<ENQ>0080#");
    QTest::newRow("reply X and Y moving") << encodeReply::axeState(0x05) << bytes("<HT>05#");
    QTest::newRow("reply X jogging") << encodeReply::axeState(0x02) << bytes("<HT>02#");
    QTest::newRow("reply position -1/16/255")
        << encodeReply::relPosition({-1, 16, 255}) << bytes("<ETX>FFFFFFFF,00000010;000000FF.");
    QTest::newRow("reply position 1F1F1F1F")
        << encodeReply::relPosition({0x1F1F1F1F, 0x1E1E1E1E, -1})
        << bytes("<ETX>1F1F1F1F,1E1E1E1E;FFFFFFFF.");
    QTest::newRow("RequestTemperature") << encode::requestTemperature() << bytes("<ETB>");
    QTest::newRow("RequestRelPosition") << encode::requestRelPosition() << bytes("<ETX>");
    QTest::newRow("RequestStart") << encode::requestStart() << bytes("<LF>");
    QTest::newRow("RequestMachineState") << encode::requestMachineState() << bytes("<ENQ>");
    QTest::newRow("RequestAxeState") << encode::requestAxeState() << bytes("<HT>");
    QTest::newRow("RequestSync x3") << encode::requestSync(3) << bytes("<SYN><SYN><SYN>");
    QTest::newRow("SetLimitPolarity low")
        << encode::limitSwitchPolarity({false, false, false}) << bytes("<SO>00,00;00.");
    QTest::newRow("SetLimitPolarity FF,FF;00")
        << encode::limitSwitchPolarity({true, true, false}) << bytes("<SO>FF,FF;00.");
    QTest::newRow("SetRefPolarity high")
        << encode::referenceSwitchPolarity({true, true, true}) << bytes("<DLE>FF,FF;FF.");
    QTest::newRow("SetStartSpeed 100")
        << encode::ramp(RampKind::StartSpeed, {100, 100, 100}) << bytes("<ESC>S0064,0064;0064.");
    QTest::newRow("SetMaxSpeed 5000")
        << encode::ramp(RampKind::MaxSpeed, {5000, 5000, 5000}) << bytes("<ESC>M1388,1388;1388.");
    QTest::newRow("SetAcceleration 1000")
        << encode::ramp(RampKind::Acceleration, {1000, 1000, 1000})
        << bytes("<ESC>A03E8,03E8;03E8.");
    QTest::newRow("SetMaxSpeed 00FF")
        << encode::ramp(RampKind::MaxSpeed, {255, 255, 255}) << bytes("<ESC>M00FF,00FF;00FF.");
    QTest::newRow("SetFeedSpeed 100")
        << encode::feedSpeed({100, 100, 100}) << bytes("<FS>0064,0064;0064.");
    QTest::newRow("SetDrivePower 100") << encode::drivePower(100) << bytes("<STX>64");
    QTest::newRow("SetSpindleRPM 1000") << encode::spindleRpm(1000) << bytes("<SOH>000003E8#");
    QTest::newRow("SetCoolOnOff off") << encode::coolant(false) << bytes("<SI>00");
    QTest::newRow("SetCoolOnOff on") << encode::coolant(true) << bytes("<SI>FF");
    QTest::newRow("ForcePanicStop") << encode::panicStop() << bytes("<BEL>");
    QTest::newRow("ForceStopMove") << encode::stopMove() << bytes("<XOFF>");
    QTest::newRow("ForceFlushBuffer") << encode::flushBuffer() << bytes("<GS>");
    QTest::newRow("SetFastMoveXY")
        << encode::fastMoveXY(1000, -1000) << bytes("<FF>000003E8,FFFFFC18;");
    QTest::newRow("SetFastMoveXYZ")
        << encode::fastMoveXYZ({1000, -1000, 16}) << bytes("<EOT>000003E8,FFFFFC18;00000010.");
    QTest::newRow("SetFastMoveZ") << encode::fastMoveZ(1000) << bytes("<BS>000003E8.");
    QTest::newRow("SetClearPosition") << encode::clearPosition() << bytes("<RS>");
    QTest::newRow("SetFeedStepsX") << encode::feedStepsX(1000) << bytes("<EM>000003E8,");
    QTest::newRow("SetFeedStepsY") << encode::feedStepsY(1000) << bytes("<SUB>000003E8;");
    QTest::newRow("SetFeedStepsZ") << encode::feedStepsZ(1000) << bytes("<VT>000003E8.");
    QTest::newRow("EndOfFeed") << encode::endOfFeed() << bytes("<CR>");
    QTest::newRow("SetJogSpeed 00FF")
        << encode::jogSpeed({255, 255, 255}) << bytes("<DC4>00FF,00FF;00FF.");
    QTest::newRow("SetJogSpeed 100,100,-100")
        << encode::jogSpeed({100, 100, -100}) << bytes("<DC4>0064,0064;FF9C.");
    QTest::newRow("SetReferenceMove -1,0,+1")
        << encode::referenceMove({-1, 0, 1}) << bytes("<US>FFFF,0000;0001.");
    // The manual prints "03e9" in lower case; we emit upper case as the issue demands.
    QTest::newRow("SetVelocityMove")
        << encode::velocityMove({-1000, 0, 1001}) << bytes("<CAN>FC18,0000;03E9.");
    QTest::newRow("FeedStep +X") << encode::feedStep(encodeStepByte(1, 0, 0))
                                 << bytes("<DC2><x10>");
}

void TestElabCodec::encode_matchesManual()
{
    QFETCH(QByteArray, encoded);
    QFETCH(QByteArray, manual);
    QCOMPARE(encoded.toHex(' '), manual.toHex(' '));
}

void TestElabCodec::commandDecoder_manualExamples_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<int>("code");
    QTest::addColumn<QList<qint64>>("values");
    QTest::newRow("ETB") << bytes("<ETB>") << int(ctrl::ETB) << QList<qint64>{};
    QTest::newRow("SO") << bytes("<SO>FF,FF;00.") << int(ctrl::SO) << QList<qint64>{255, 255, 0};
    QTest::newRow("ESC S") << bytes("<ESC>S0064,0064;0064.") << int(ctrl::ESC)
                           << QList<qint64>{100, 100, 100};
    QTest::newRow("ESC M") << bytes("<ESC>M1388,1388;1388.") << int(ctrl::ESC)
                           << QList<qint64>{5000, 5000, 5000};
    QTest::newRow("FS") << bytes("<FS>0064,0064;0064.") << int(ctrl::FS)
                        << QList<qint64>{100, 100, 100};
    QTest::newRow("STX") << bytes("<STX>64") << int(ctrl::STX) << QList<qint64>{100};
    QTest::newRow("SOH") << bytes("<SOH>FFFFFFFF#") << int(ctrl::SOH)
                         << QList<qint64>{0xFFFFFFFFll};
    QTest::newRow("SI") << bytes("<SI>FF") << int(ctrl::SI) << QList<qint64>{255};
    QTest::newRow("FF") << bytes("<FF>000003E8,FFFFFC18;") << int(ctrl::FF)
                        << QList<qint64>{1000, -1000};
    QTest::newRow("EOT") << bytes("<EOT>000003E8,FFFFFC18;00000010.") << int(ctrl::EOT)
                         << QList<qint64>{1000, -1000, 16};
    QTest::newRow("BS") << bytes("<BS>000003E8.") << int(ctrl::BS) << QList<qint64>{1000};
    QTest::newRow("EM") << bytes("<EM>000003E8,") << int(ctrl::EM) << QList<qint64>{1000};
    QTest::newRow("SUB") << bytes("<SUB>000003E8;") << int(ctrl::SUB) << QList<qint64>{1000};
    QTest::newRow("VT") << bytes("<VT>000003E8.") << int(ctrl::VT) << QList<qint64>{1000};
    QTest::newRow("DC4") << bytes("<DC4>0064,0064;FF9C.") << int(ctrl::DC4)
                         << QList<qint64>{100, 100, -100};
    QTest::newRow("US") << bytes("<US>FFFF,0000;0001.") << int(ctrl::US) << QList<qint64>{-1, 0, 1};
    QTest::newRow("CAN") << bytes("<CAN>FC18,0000;03e9.") << int(ctrl::CAN)
                         << QList<qint64>{-1000, 0, 1001};
    QTest::newRow("XOFF is ForceStopMove") << bytes("<XOFF>") << int(ctrl::XOFF) << QList<qint64>{};
}

void TestElabCodec::commandDecoder_manualExamples()
{
    QFETCH(QByteArray, wire);
    QFETCH(int, code);
    QFETCH(QList<qint64>, values);
    CommandDecoder decoder;
    const QList<Command> cmds = decoder.feed(wire);
    QCOMPARE(cmds.size(), 1);
    QVERIFY2(cmds[0].valid, qPrintable(cmds[0].error));
    QCOMPARE(int(cmds[0].code), code);
    QCOMPARE(cmds[0].valueCount, values.size());
    for (int i = 0; i < values.size(); ++i)
        QCOMPARE(cmds[0].values[i], values[i]);
    QCOMPARE(cmds[0].raw, wire);
}

void TestElabCodec::commandDecoder_lowerCaseAndSpaces_accepted()
{
    // The manual itself prints "<SO>FF, FF;00." and "<CAN> FC18,0000;03e9.".
    CommandDecoder decoder;
    const QList<Command> cmds = decoder.feed(bytes("<SO>FF, FF;00.<ESC> A03e8,03E8;03E8."));
    QCOMPARE(cmds.size(), 2);
    QVERIFY(cmds[0].valid);
    QCOMPARE(cmds[0].values[1], 255);
    QVERIFY(cmds[1].valid);
    QCOMPARE(cmds[1].ramp, RampKind::Acceleration);
    QCOMPARE(cmds[1].values[0], 1000);
}

void TestElabCodec::commandDecoder_malformed_reportedThenResyncs()
{
    CommandDecoder decoder;
    // A bad hex digit, a wrong separator, an unknown control byte, then a good command.
    const QList<Command> cmds =
        decoder.feed(bytes("<FS>00G4,0064;0064.<ESC>S0064.0064;0064.<NAK><ENQ>"));
    QVERIFY(cmds.size() >= 4);
    QCOMPARE(cmds.first().valid, false);
    QCOMPARE(int(cmds.first().code), int(ctrl::FS));
    QCOMPARE(cmds.last().valid, true);
    QCOMPARE(int(cmds.last().code), int(ctrl::ENQ));
    int invalid = 0;
    for (const Command& c : cmds)
        invalid += c.valid ? 0 : 1;
    QVERIFY(invalid >= 3);
}

void TestElabCodec::commandDecoder_dc2DataByte_mayBeAnyValue()
{
    // DC2 data bytes like 0x11 or 0x13 must not be read as control characters.
    CommandDecoder decoder;
    const QByteArray wire =
        encode::feedStep(0x11) + encode::feedStep(0x13) + encode::feedStep(0x77);
    const QList<Command> cmds = decoder.feed(wire);
    QCOMPARE(cmds.size(), 3);
    QCOMPARE(int(cmds[0].stepByte), 0x11);
    QCOMPARE(int(cmds[1].stepByte), 0x13);
    QVERIFY(cmds[0].valid && cmds[1].valid);
    QCOMPARE(cmds[2].valid, true);
    const QList<Command> bad = decoder.feed(encode::feedStep(0x88));
    QCOMPARE(bad.size(), 1);
    QCOMPARE(bad[0].valid, false);
}

void TestElabCodec::commandDecoder_randomChunks_sameCommands()
{
    QByteArray wire;
    for (int i = 0; i < 50; ++i) {
        wire += encode::fastMoveXYZ({i * 1000, -i, i});
        wire += encode::feedStep(encodeStepByte(i % 3 - 1, 1, -1));
        wire += encode::requestAxeState();
        wire += encode::jogSpeed({qint16(-i), qint16(i), 0});
    }
    CommandDecoder whole;
    const QList<Command> expected = whole.feed(wire);
    QCOMPARE(expected.size(), 200);
    QRandomGenerator rng(42);
    CommandDecoder chunked;
    QList<Command> got;
    for (int pos = 0; pos < wire.size();) {
        const int n = 1 + int(rng.bounded(7));
        got += chunked.feed(wire.mid(pos, n));
        pos += n;
    }
    QCOMPARE(got.size(), expected.size());
    for (int i = 0; i < got.size(); ++i) {
        QCOMPARE(got[i].raw, expected[i].raw);
        QCOMPARE(got[i].values, expected[i].values);
    }
}

void TestElabCodec::replyDecoder_manualExamples_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<int>("kind");
    QTest::addColumn<qint64>("value");
    QTest::newRow("temperature 20 C")
        << bytes("<ETB>14#") << int(Reply::Kind::Temperature) << qint64(20);
    QTest::newRow("start not pressed") << bytes("<NAK>") << int(Reply::Kind::Nak) << qint64(0);
    QTest::newRow("setup incomplete")
        << bytes("<ENQ>0080#") << int(Reply::Kind::MachineState) << qint64(machine::InvSetup);
    QTest::newRow("X and Y moving")
        << bytes("<HT>05#") << int(Reply::Kind::AxeState) << qint64(axe::XMove | axe::YMove);
    QTest::newRow("X jogging") << bytes("<HT>02#") << int(Reply::Kind::AxeState)
                               << qint64(axe::XJog);
    QTest::newRow("accepted") << bytes("<ACK>") << int(Reply::Kind::Ack) << qint64(0);
}

void TestElabCodec::replyDecoder_manualExamples()
{
    QFETCH(QByteArray, wire);
    QFETCH(int, kind);
    QFETCH(qint64, value);
    ReplyDecoder decoder;
    const QList<Reply> replies = decoder.feed(wire);
    QCOMPARE(replies.size(), 1);
    QCOMPARE(int(replies[0].kind), kind);
    QCOMPARE(replies[0].raw, wire);
    switch (replies[0].kind) {
    case Reply::Kind::Temperature:
        QCOMPARE(qint64(replies[0].temperature), value);
        break;
    case Reply::Kind::MachineState:
        QCOMPARE(qint64(replies[0].machineState), value);
        break;
    case Reply::Kind::AxeState:
        QCOMPARE(qint64(replies[0].axeState), value);
        break;
    default:
        break;
    }
    // RequestRelPosition: "<ETX>FFFFFFFF,00000010;000000FF. dies ist die Position (-1/16/255)"
    const QList<Reply> pos = decoder.feed(bytes("<ETX>FFFFFFFF,00000010;000000FF."));
    QCOMPARE(pos.size(), 1);
    QCOMPARE(pos[0].kind, Reply::Kind::RelPosition);
    QCOMPARE(pos[0].positions, (Triple<qint32>{-1, 16, 255}));
}

void TestElabCodec::replyDecoder_byteByByte_sameAsWhole()
{
    const Stream s = manualReplies();
    ReplyDecoder decoder;
    QList<Reply> got;
    for (char c : s.wire)
        got += decoder.feed(QByteArray(1, c));
    QCOMPARE(kindsOf(got), s.kinds);
    QCOMPARE(decoder.buffered(), 0);
}

void TestElabCodec::replyDecoder_randomChunks_sameAsWhole()
{
    const Stream s = manualReplies();
    for (quint32 seed = 1; seed <= 20; ++seed) {
        QRandomGenerator rng(seed);
        ReplyDecoder decoder;
        QList<Reply> got;
        for (int pos = 0; pos < s.wire.size();) {
            const int n = 1 + int(rng.bounded(9));
            got += decoder.feed(s.wire.mid(pos, n));
            pos += n;
        }
        QCOMPARE(kindsOf(got), s.kinds);
    }
}

void TestElabCodec::replyDecoder_garbageBetweenFrames_resyncs()
{
    const Stream s = manualReplies();
    QRandomGenerator rng(7);
    QByteArray wire;
    // Printable garbage (never a control byte) between frames: must not hide any frame.
    ReplyDecoder splitter;
    for (const Reply& r : splitter.feed(s.wire)) {
        QByteArray junk;
        for (int i = 0, n = int(rng.bounded(5)); i < n; ++i)
            junk += char(0x20 + rng.bounded(0x5F));
        wire += junk + r.raw;
    }
    ReplyDecoder decoder;
    QList<Reply::Kind> valid;
    for (const Reply& r : decoder.feed(wire)) {
        if (r.kind != Reply::Kind::Invalid)
            valid << r.kind;
        else
            QVERIFY(!r.error.isEmpty());
    }
    QCOMPARE(valid, s.kinds);
}

void TestElabCodec::replyDecoder_interruptedFrame_reportedAndNextDecoded()
{
    ReplyDecoder decoder;
    const QList<Reply> r = decoder.feed(bytes("<ENQ>00<HT>05#<ETB>1G#<ACK>"));
    QCOMPARE(r.size(), 4);
    QCOMPARE(r[0].kind, Reply::Kind::Invalid);
    QCOMPARE(r[0].raw, bytes("<ENQ>00"));
    QCOMPARE(r[1].kind, Reply::Kind::AxeState);
    QCOMPARE(r[2].kind, Reply::Kind::Invalid); // 'G' is no hex digit
    QCOMPARE(r[3].kind, Reply::Kind::Ack);
}

void TestElabCodec::replyDecoder_xonInsideFrame_passesThrough()
{
    ReplyDecoder decoder;
    const QList<Reply> r = decoder.feed(bytes("<ENQ>00<XOFF>80#"));
    QCOMPARE(r.size(), 2);
    QCOMPARE(r[0].kind, Reply::Kind::XOff);
    QCOMPARE(r[1].kind, Reply::Kind::MachineState);
    QCOMPARE(int(r[1].machineState), 0x80);
}

void TestElabCodec::replyDecoder_endlessGarbage_bufferStaysBounded()
{
    ReplyDecoder decoder;
    int invalid = 0;
    for (int i = 0; i < 1000; ++i) {
        for (const Reply& r : decoder.feed(QByteArray(100, 'A')))
            invalid += r.kind == Reply::Kind::Invalid ? 1 : 0;
        QVERIFY(decoder.buffered() <= ReplyDecoder::kMaxFrame);
    }
    QVERIFY(invalid > 0);
    const QList<Reply> after = decoder.feed(bytes("<ACK>"));
    QCOMPARE(after.last().kind, Reply::Kind::Ack);
}

// Found by fuzz_elab_reply: kMaxFrame said 27, but <ETX>XXXXXXXX,YYYYYYYY;ZZZZZZZZ. is 28.
void TestElabCodec::replyDecoder_longestManualReply_withinFrameBound()
{
    ReplyDecoder decoder;
    const QList<Reply> replies = decoder.feed(manualReplies().wire);
    QCOMPARE(kindsOf(replies), manualReplies().kinds);
    for (const Reply& r : replies)
        QVERIFY2(r.raw.size() <= ReplyDecoder::kMaxFrame, qPrintable(toMnemonics(r.raw)));
    // Garbage of any length leaves in pieces no longer than that bound.
    for (const Reply& r : decoder.feed(bytes("<ETX>") + QByteArray(100, 'F')))
        QVERIFY(r.raw.size() <= ReplyDecoder::kMaxFrame);
    QVERIFY(decoder.buffered() <= ReplyDecoder::kMaxFrame);
}

// Every byte fed is in a command's raw, still buffered, or a tolerated blank.
void TestElabCodec::commandDecoder_everyByteAccountedFor()
{
    const QByteArray wire = bytes("<SO>FF, FF;00.<ESC>S0064, 0064;0064.junk<DC2><x25><ENQ><FS>00");
    CommandDecoder decoder;
    qsizetype inRaw = 0;
    for (char c : wire) {
        for (const Command& cmd : decoder.feed(QByteArray(1, c)))
            inRaw += cmd.raw.size();
    }
    QCOMPARE(decoder.unframedBytes(), qint64(2)); // the two blanks
    QCOMPARE(decoder.buffered(), 3);              // "<FS>00" is not complete yet
    QCOMPARE(inRaw + decoder.buffered() + decoder.unframedBytes(), wire.size());
}

void TestElabCodec::stepByte_roundTrip_data()
{
    QTest::addColumn<int>("dx");
    QTest::addColumn<int>("dy");
    QTest::addColumn<int>("dz");
    QTest::addColumn<int>("byte");
    QTest::newRow("none") << 0 << 0 << 0 << 0x00;
    QTest::newRow("+X") << 1 << 0 << 0 << 0x10;
    QTest::newRow("-X") << -1 << 0 << 0 << 0x11;
    QTest::newRow("+Y") << 0 << 1 << 0 << 0x20;
    QTest::newRow("-Z") << 0 << 0 << -1 << 0x44;
    QTest::newRow("-X-Y-Z") << -1 << -1 << -1 << 0x77;
    QTest::newRow("+X-Y+Z") << 1 << -1 << 1 << 0x72;
}

void TestElabCodec::stepByte_roundTrip()
{
    QFETCH(int, dx);
    QFETCH(int, dy);
    QFETCH(int, dz);
    QFETCH(int, byte);
    QCOMPARE(int(encodeStepByte(dx, dy, dz)), byte);
    QVERIFY(isValidStepByte(quint8(byte)));
    QCOMPARE(decodeStepByte(quint8(byte)), (Triple<int>{dx, dy, dz}));
}

void TestElabCodec::mnemonics_roundTripEveryByte()
{
    QByteArray all;
    for (int b = 0; b < 256; ++b)
        all += char(b);
    QByteArray back;
    QString error;
    QVERIFY2(fromMnemonics(toMnemonics(all), &back, &error), qPrintable(error));
    QCOMPARE(back, all);
    QCOMPARE(toMnemonics(bytes("<ESC>S0064,0064;0064.")), QStringLiteral("<ESC>S0064,0064;0064."));
    QCOMPARE(toMnemonics(encode::feedStep(0x13)), QStringLiteral("<DC2><x13>"));
}

void TestElabCodec::mnemonics_unknownName_reportsPosition()
{
    QByteArray out;
    QString error;
    QVERIFY(!fromMnemonics(QStringLiteral("<ENQ><BOGUS>"), &out, &error));
    QVERIFY(error.contains(QStringLiteral("BOGUS")));
    QVERIFY(error.contains(QStringLiteral("6")));
    QVERIFY(!fromMnemonics(QStringLiteral("<ENQ"), &out, &error));
}

void TestElabCodec::describeMachineState_namesBits()
{
    const QString text = describeMachineState(machine::InvSetup | machine::LimSwX);
    QVERIFY(text.contains(QStringLiteral("tmInvSetup")));
    QVERIFY(text.contains(QStringLiteral("tmLimSwX")));
    QVERIFY(!text.contains(QStringLiteral("tmDriveOn")));
    QVERIFY(describeAxeState(axe::LimSw).contains(QStringLiteral("taLimSw")));
}

STEPDECK_TEST_GUILESS_MAIN(TestElabCodec)
#include "tst_elabcodec.moc"
