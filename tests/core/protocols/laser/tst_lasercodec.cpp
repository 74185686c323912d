// LaserCodec against the frames of the laser marker's motor-axis description, both
// directions, fed whole, byte by byte, in random chunks and with garbage in between.
#include "TestMain.h"
#include "protocols/laser/LaserCodec.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::laser;
Q_DECLARE_METATYPE(stepdeck::laser::DecodeError)

namespace {
// Laser -> axis: the frames the description builds from its tables.
const QList<QPair<QByteArray, CommandFrame>>& commandGoldens()
{
    static const QList<QPair<QByteArray, CommandFrame>> list{
        {"1100000\r", {Command::Home, Axis::X, 0}},     // "should be set to 00000"
        {"1200000\r", {Command::Home, Axis::Y, 0}},     //
        {"1300000\r", {Command::Home, Axis::Z, 0}},     //
        {"2200150\r", {Command::Move, Axis::Y, 150}},   // issue 9: move --abs Y=150
        {"2100000\r", {Command::Move, Axis::X, 0}},     // lower end of [0...99999]
        {"2399999\r", {Command::Move, Axis::Z, 99999}}, // upper end
        {"2112345\r", {Command::Move, Axis::X, 12345}},
    };
    return list;
}

// Axis -> laser: one frame per status byte of the description.
const QList<QPair<QByteArray, StatusFrame>>& statusGoldens()
{
    static const QList<QPair<QByteArray, StatusFrame>> list{
        {"2001500\r", {Axis::Y, 150, Status::TargetReached}},
        {"1999991\r", {Axis::X, 99999, Status::EndSwitch}},
        {"3000002\r", {Axis::Z, 0, Status::HomeSwitch}},
        {"1004203\r", {Axis::X, 420, Status::DoorOpened}},
        {"1004204\r", {Axis::X, 420, Status::DoorClosed}},
    };
    return list;
}

QByteArray commandWire()
{
    QByteArray out;
    for (const auto& g : commandGoldens())
        out += g.first;
    return out;
}

QList<CommandFrame> frames(const QList<DecodedCommand>& decoded)
{
    QList<CommandFrame> out;
    for (const DecodedCommand& d : decoded) {
        if (d.ok())
            out << *d.frame;
    }
    return out;
}

QList<CommandFrame> expectedCommands()
{
    QList<CommandFrame> out;
    for (const auto& g : commandGoldens())
        out << g.second;
    return out;
}

int errorCount(const QList<DecodedCommand>& decoded)
{
    int n = 0;
    for (const DecodedCommand& d : decoded)
        n += d.ok() ? 0 : 1;
    return n;
}
} // namespace

class TestLaserCodec : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void encodeCommand_goldens_data();
    void encodeCommand_goldens();
    void encodeCommand_outOfRange_isEmpty();
    void encodeHome_ignoresPosition();
    void encodeStatus_goldens_data();
    void encodeStatus_goldens();
    void decodeCommand_goldens();
    void decodeStatus_goldens();
    void decode_byteByByte_sameAsWhole();
    void decode_randomChunks_sameAsWhole();
    void decode_malformed_typedErrors_data();
    void decode_malformed_typedErrors();
    void decodeStatus_malformed_typedErrors_data();
    void decodeStatus_malformed_typedErrors();
    void decode_garbageBetweenFrames_resynchronisesAtCr();
    void decode_overlong_reportedOnceAndBounded();
    void decode_crLf_lineEndsAccepted();
    void decode_frameWithoutCr_staysBuffered();
    void decode_allByteValues_neverCrashesOrGrows();
    void directions_areNotMixedUp();
    void decode_everyByteAccountedFor();
};

void TestLaserCodec::encodeCommand_goldens_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<int>("index");
    for (int i = 0; i < commandGoldens().size(); ++i)
        QTest::newRow(commandGoldens().at(i).first.trimmed().constData())
            << commandGoldens().at(i).first << i;
}

void TestLaserCodec::encodeCommand_goldens()
{
    QFETCH(QByteArray, wire);
    QFETCH(int, index);
    const QByteArray encoded = encodeCommand(commandGoldens().at(index).second);
    QCOMPARE(encoded, wire);
    QCOMPARE(encoded.size(), kFrameSize);
}

void TestLaserCodec::encodeCommand_outOfRange_isEmpty()
{
    QVERIFY(encodeMove(Axis::X, 100000).isEmpty());
    QVERIFY(encodeMove(Axis::X, -1).isEmpty());
    QVERIFY(encodeMove(Axis::U, 5).isEmpty());
    QVERIFY(encodeStatus({Axis::U, 0, Status::TargetReached}).isEmpty());
    QVERIFY(encodeStatus({Axis::Y, 100000, Status::TargetReached}).isEmpty());
}

void TestLaserCodec::encodeHome_ignoresPosition()
{
    // "The <target-position> is ignored in this command and should be set to 00000."
    QCOMPARE(encodeCommand({Command::Home, Axis::Z, 4711}), QByteArray("1300000\r"));
    QCOMPARE(encodeHome(Axis::X), QByteArray("1100000\r"));
}

void TestLaserCodec::encodeStatus_goldens_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<int>("index");
    for (int i = 0; i < statusGoldens().size(); ++i)
        QTest::newRow(statusGoldens().at(i).first.trimmed().constData())
            << statusGoldens().at(i).first << i;
}

void TestLaserCodec::encodeStatus_goldens()
{
    QFETCH(QByteArray, wire);
    QFETCH(int, index);
    QCOMPARE(encodeStatus(statusGoldens().at(index).second), wire);
}

void TestLaserCodec::decodeCommand_goldens()
{
    CommandDecoder decoder;
    const QList<DecodedCommand> decoded = decoder.feed(commandWire());
    QCOMPARE(errorCount(decoded), 0);
    QCOMPARE(frames(decoded), expectedCommands());
    QCOMPARE(decoder.buffered(), 0);
}

void TestLaserCodec::decodeStatus_goldens()
{
    StatusDecoder decoder;
    QByteArray wire;
    for (const auto& g : statusGoldens())
        wire += g.first;
    const QList<DecodedStatus> decoded = decoder.feed(wire);
    QCOMPARE(decoded.size(), statusGoldens().size());
    for (int i = 0; i < decoded.size(); ++i) {
        QVERIFY(decoded.at(i).ok());
        QCOMPARE(*decoded.at(i).frame, statusGoldens().at(i).second);
    }
}

void TestLaserCodec::decode_byteByByte_sameAsWhole()
{
    CommandDecoder decoder;
    QList<DecodedCommand> decoded;
    for (char c : commandWire())
        decoded += decoder.feed(QByteArray(1, c));
    QCOMPARE(errorCount(decoded), 0);
    QCOMPARE(frames(decoded), expectedCommands());
}

void TestLaserCodec::decode_randomChunks_sameAsWhole()
{
    QRandomGenerator rng(9);
    const QByteArray wire = commandWire().repeated(20);
    QList<CommandFrame> expected;
    for (int i = 0; i < 20; ++i)
        expected += expectedCommands();
    for (int round = 0; round < 50; ++round) {
        CommandDecoder decoder;
        QList<DecodedCommand> decoded;
        for (qsizetype at = 0; at < wire.size();) {
            const int n = int(rng.bounded(1, 12));
            decoded += decoder.feed(wire.mid(at, n));
            at += n;
        }
        QCOMPARE(errorCount(decoded), 0);
        QCOMPARE(frames(decoded), expected);
    }
}

void TestLaserCodec::decode_malformed_typedErrors_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<DecodeError>("error");
    QTest::newRow("short") << QByteArray("220015\r") << DecodeError::WrongLength;
    QTest::newRow("bare CR") << QByteArray("\r") << DecodeError::WrongLength;
    QTest::newRow("long") << QByteArray("22001500\r") << DecodeError::Overlong;
    QTest::newRow("letter") << QByteArray("22001x0\r") << DecodeError::NotDigit;
    QTest::newRow("sign") << QByteArray("22-0150\r") << DecodeError::NotDigit;
    QTest::newRow("space") << QByteArray("2 00150\r") << DecodeError::NotDigit;
    QTest::newRow("NUL") << QByteArray("22\0"
                                       "0150\r",
                                       8)
                         << DecodeError::NotDigit;
    QTest::newRow("axis 0") << QByteArray("2000150\r") << DecodeError::UnknownAxis;
    QTest::newRow("axis 4") << QByteArray("2400150\r") << DecodeError::UnknownAxis;
    QTest::newRow("command 0") << QByteArray("0100150\r") << DecodeError::UnknownCommand;
    QTest::newRow("command 3") << QByteArray("3100150\r") << DecodeError::UnknownCommand;
}

void TestLaserCodec::decode_malformed_typedErrors()
{
    QFETCH(QByteArray, wire);
    QFETCH(DecodeError, error);
    CommandDecoder decoder;
    const QList<DecodedCommand> decoded = decoder.feed(wire);
    QCOMPARE(decoded.size(), 1);
    QVERIFY(!decoded.first().ok());
    QCOMPARE(decoded.first().error, error);
    QVERIFY(!describeError(error).isEmpty());
    // The decoder is ready for the next good frame at once.
    const QList<DecodedCommand> next = decoder.feed("2200150\r");
    QCOMPARE(frames(next), (QList<CommandFrame>{{Command::Move, Axis::Y, 150}}));
}

void TestLaserCodec::decodeStatus_malformed_typedErrors_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<DecodeError>("error");
    QTest::newRow("status 5") << QByteArray("2001505\r") << DecodeError::UnknownStatus;
    QTest::newRow("status 9") << QByteArray("2001509\r") << DecodeError::UnknownStatus;
    QTest::newRow("axis 0") << QByteArray("0001500\r") << DecodeError::UnknownAxis;
    QTest::newRow("letter") << QByteArray("20015A0\r") << DecodeError::NotDigit;
    QTest::newRow("short") << QByteArray("200150\r") << DecodeError::WrongLength;
}

void TestLaserCodec::decodeStatus_malformed_typedErrors()
{
    QFETCH(QByteArray, wire);
    QFETCH(DecodeError, error);
    StatusDecoder decoder;
    const QList<DecodedStatus> decoded = decoder.feed(wire);
    QCOMPARE(decoded.size(), 1);
    QVERIFY(!decoded.first().ok());
    QCOMPARE(decoded.first().error, error);
}

void TestLaserCodec::decode_garbageBetweenFrames_resynchronisesAtCr()
{
    CommandDecoder decoder;
    const QByteArray wire = QByteArray("2100010\r") + "zz\r" + "\x01\x02\xff\r" + "2200020\r" +
                            "garbage without end of any length\r" + "2300030\r";
    const QList<DecodedCommand> decoded = decoder.feed(wire);
    QCOMPARE(frames(decoded), (QList<CommandFrame>{{Command::Move, Axis::X, 10},
                                                   {Command::Move, Axis::Y, 20},
                                                   {Command::Move, Axis::Z, 30}}));
    QCOMPARE(errorCount(decoded), 3);
}

void TestLaserCodec::decode_overlong_reportedOnceAndBounded()
{
    CommandDecoder decoder;
    const QByteArray junk(10000, '7'); // digits only: no CR for a long time
    const QList<DecodedCommand> decoded = decoder.feed(junk);
    QCOMPARE(decoded.size(), 1);
    QCOMPARE(decoded.first().error, DecodeError::Overlong);
    QVERIFY(decoded.first().raw.size() <= kFrameSize);
    QVERIFY(decoder.buffered() <= kBodySize);
    // The first frame after the junk's CR is dropped with the junk; the one after it decodes.
    QCOMPARE(errorCount(decoder.feed("2100010\r")), 0);
    QCOMPARE(frames(decoder.feed("2100011\r")),
             (QList<CommandFrame>{{Command::Move, Axis::X, 11}}));
}

void TestLaserCodec::decode_crLf_lineEndsAccepted()
{
    CommandDecoder decoder;
    const QList<DecodedCommand> decoded = decoder.feed("2100010\r\n2200020\r\n");
    QCOMPARE(errorCount(decoded), 0);
    QCOMPARE(frames(decoded),
             (QList<CommandFrame>{{Command::Move, Axis::X, 10}, {Command::Move, Axis::Y, 20}}));
    // A LF anywhere else is a character of the frame, and so an error.
    QCOMPARE(decoder.feed("21\n0010\r").first().error, DecodeError::NotDigit);
}

void TestLaserCodec::decode_frameWithoutCr_staysBuffered()
{
    CommandDecoder decoder;
    QVERIFY(decoder.feed("2200150").isEmpty()); // complete only at its CR, never by silence
    QCOMPARE(decoder.buffered(), 7);
    QCOMPARE(frames(decoder.feed("\r")), (QList<CommandFrame>{{Command::Move, Axis::Y, 150}}));
    decoder.feed("22");
    decoder.reset();
    QCOMPARE(decoder.buffered(), 0);
}

void TestLaserCodec::decode_allByteValues_neverCrashesOrGrows()
{
    CommandDecoder commands;
    StatusDecoder statuses;
    QRandomGenerator rng(3);
    for (int i = 0; i < 20000; ++i) {
        const QByteArray b(1, char(rng.bounded(256)));
        for (const DecodedCommand& d : commands.feed(b))
            QVERIFY(d.raw.size() <= kFrameSize);
        for (const DecodedStatus& d : statuses.feed(b))
            QVERIFY(d.raw.size() <= kFrameSize);
        QVERIFY(commands.buffered() <= kBodySize);
        QVERIFY(statuses.buffered() <= kBodySize);
    }
}

void TestLaserCodec::directions_areNotMixedUp()
{
    // Both kinds are seven digits: each decoder reads its own direction. "2001500" is a status
    // (Y at 150, reached) on the laser side; on the axis side its axis byte 0 is invalid.
    StatusDecoder statuses;
    QCOMPARE(*statuses.feed("2001500\r").first().frame,
             (StatusFrame{Axis::Y, 150, Status::TargetReached}));
    CommandDecoder commands;
    QCOMPARE(commands.feed("2001500\r").first().error, DecodeError::UnknownAxis);
    QCOMPARE(commandText({Command::Move, Axis::Y, 150}), QStringLiteral("move Y to 150"));
    QCOMPARE(statusText({Axis::Y, 150, Status::EndSwitch}), QStringLiteral("Y at 150: end switch"));
}

void TestLaserCodec::decode_everyByteAccountedFor()
{
    // Every byte is in a frame's raw, its CR, buffered, or dropped (LF after CR, overlong tail).
    const QByteArray in = "2200150\r\n1234567890\r12\r\r\n\n220";
    CommandDecoder decoder;
    qint64 accounted = 0;
    for (const DecodedCommand& d : decoder.feed(in))
        accounted += d.raw.size() + (d.error == DecodeError::Overlong ? 0 : 1);
    QCOMPARE(decoder.buffered(), 4);             // the second LF is a character of the next frame
    QCOMPARE(decoder.droppedBytes(), 1 + 3 + 1); // LF; "890" and CR of the overlong run; LF
    QCOMPARE(accounted + decoder.buffered() + decoder.droppedBytes(), in.size());
}

STEPDECK_TEST_GUILESS_MAIN(TestLaserCodec)
#include "tst_lasercodec.moc"
