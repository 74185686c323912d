// The SMC-IC4 command grammar: every command example of chapter 9 parses to what it means,
// malformed and out-of-range commands are named, the device-side framing (CR, STX, ETX) and
// the system-parameter entries of 9.14 / 9.15.
#include "TestMain.h"
#include "protocols/emis/EmisGrammar.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::emis;
using K = Command::Kind;
Q_DECLARE_METATYPE(stepdeck::emis::Command::Kind)

class TestEmisGrammar : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_manualCommands_data();
    void parse_manualCommands();
    void parse_values();
    void parse_malformed_data();
    void parse_malformed();
    void range_data();
    void range();
    void program_allowedAndRefused_data();
    void program_allowedAndRefused();
    void system_manualEntries_data();
    void system_manualEntries();
    void system_motorCount();
    void system_malformed_data();
    void system_malformed();
    void prsys_lenientSeparators_data();
    void prsys_lenientSeparators();
    void prsys_formatRoundTrip();
    void prsys_partialEntry_keepsMotorsItDoesNotName();
    void decoder_framesCrStxEtx();
    void decoder_randomChunks_sameFrames();
    void decoder_overlong_boundedAndResyncs();
    void decoder_everyByteAccountedFor();
};

void TestEmisGrammar::parse_manualCommands_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<char>("terminator");
    QTest::addColumn<K>("kind");
    const char cr = kCr;
    QTest::newRow("9.1") << QByteArray("@V") << cr << K::Version;
    QTest::newRow("9.2 one") << QByteArray("@I1") << cr << K::Input;
    QTest::newRow("9.2 all") << QByteArray("@IG") << cr << K::AllInputs;
    QTest::newRow("9.3 set") << QByteArray("A1,1") << cr << K::Output;
    QTest::newRow("9.3 reset") << QByteArray("A1,0") << cr << K::Output;
    QTest::newRow("9.4 all") << QByteArray("#S200") << cr << K::StartSpeed;
    QTest::newRow("9.4 X") << QByteArray("#S,x200") << cr << K::StartSpeed;
    QTest::newRow("9.5 all") << QByteArray("#E1,1000") << cr << K::WorkSpeed;
    QTest::newRow("9.5 X") << QByteArray("#E1,x1000") << cr << K::WorkSpeed;
    QTest::newRow("9.5 reference") << QByteArray("#E9,400") << cr << K::ReferenceSpeed;
    QTest::newRow("9.6") << QByteArray("#R100") << cr << K::Ramp;
    QTest::newRow("9.7") << QByteArray("D,x32") << cr << K::StepResolution;
    QTest::newRow("9.8") << QByteArray("c,x100,20") << cr << K::Current;
    QTest::newRow("9.9 X") << QByteArray("$Hx") << cr << K::Home;
    QTest::newRow("9.9 XYZU") << QByteArray("$Hxyzu") << cr << K::Home;
    QTest::newRow("9.9 simultaneous") << QByteArray("$Hxyzu,a") << cr << K::Home;
    QTest::newRow("9.10") << QByteArray("#Ox,10") << cr << K::ReferenceOffset;
    QTest::newRow("9.11 +X") << QByteArray("L1,x1000") << cr << K::Vector;
    QTest::newRow("9.11 -X") << QByteArray("L1,x-1000") << cr << K::Vector;
    QTest::newRow("9.11 X,Y") << QByteArray("L1,x1000,y-2000") << cr << K::Vector;
    QTest::newRow("9.11 absolute") << QByteArray("L1,X1000") << cr << K::Vector;
    QTest::newRow("9.12 on") << QByteArray("IP1") << cr << K::Interpolation;
    QTest::newRow("9.12 off") << QByteArray("IP0") << cr << K::Interpolation;
    QTest::newRow("9.13") << QByteArray("W500") << cr << K::Wait;
    QTest::newRow("9.14 D") << QByteArray("##D,x32,y16,z64,u1") << cr << K::SystemWrite;
    QTest::newRow("9.14 c") << QByteArray("##c,x100,0,y100,0,z100,20,u100,0") << cr
                            << K::SystemWrite;
    QTest::newRow("9.14 REFSW") << QByteArray("##REFSW,xNO,yNO,zNO,uNC") << cr << K::SystemWrite;
    QTest::newRow("9.14 S") << QByteArray("##S,x200,y200,z200,u200") << cr << K::SystemWrite;
    QTest::newRow("9.14 E") << QByteArray("##E,x1800,y1800,z600,u1000") << cr << K::SystemWrite;
    QTest::newRow("9.14 E9") << QByteArray("##E9,x400,y400,z200,u300") << cr << K::SystemWrite;
    QTest::newRow("9.14 R") << QByteArray("##R,100") << cr << K::SystemWrite;
    QTest::newRow("9.14 SMCflex") << QByteArray("##S,200,1800,100") << cr << K::SystemWrite;
    QTest::newRow("9.15") << QByteArray("*PRSYS") << cr << K::ReadSystem;
    QTest::newRow("9.16") << QByteArray("*PESYS") << cr << K::ClearSystem;
    QTest::newRow("9.17 open") << QByteArray("*PWIN7") << cr << K::ProgramOpen;
    QTest::newRow("9.17 header") << QByteArray("IJ7,1 Eingang 7: Referenzfahrt X-Motor") << kStx
                                 << K::ProgramHeader;
    QTest::newRow("9.17 home") << QByteArray("$H,x") << cr << K::Home;
    QTest::newRow("9.17 end") << QByteArray() << kEtx << K::ProgramEnd;
    QTest::newRow("9.17 vector") << QByteArray("L1,x191") << cr << K::Vector;
    QTest::newRow("9.17 wait") << QByteArray("W1500") << cr << K::Wait;
    QTest::newRow("9.18") << QByteArray("*PEIN1") << cr << K::ProgramErase;
}

void TestEmisGrammar::parse_manualCommands()
{
    QFETCH(QByteArray, text);
    QFETCH(char, terminator);
    QFETCH(K, kind);
    const Command c = parseCommand(text, terminator);
    QVERIFY2(c.kind == kind, qPrintable(c.error));
    QCOMPARE(rangeError(c), QString());
    QCOMPARE(c.text, text);
}

void TestEmisGrammar::parse_values()
{
    Command c = parseCommand("#S,x200");
    QCOMPARE(c.axis, std::optional<Axis>(Axis::X));
    QCOMPARE(c.value, 200);
    c = parseCommand("#S200");
    QVERIFY(!c.axis);
    QCOMPARE(c.value, 200);
    c = parseCommand("c,z100,20");
    QCOMPARE(c.axis, std::optional<Axis>(Axis::Z));
    QCOMPARE(c.value, 100);
    QCOMPARE(c.idle, 20);
    c = parseCommand("$Hxyzu,a");
    QCOMPARE(c.axes, (QList<Axis>{Axis::X, Axis::Y, Axis::Z, Axis::U}));
    QVERIFY(c.simultaneous);
    c = parseCommand("$H,x");
    QCOMPARE(c.axes, QList<Axis>{Axis::X});
    QVERIFY(!c.simultaneous);
    c = parseCommand("L1,x1000,Y-2000");
    QCOMPARE(c.targets.size(), 2);
    QCOMPARE(c.targets[0].value, 1000);
    QVERIFY(!c.targets[0].absolute);
    QCOMPARE(c.targets[1].axis, Axis::Y);
    QCOMPARE(c.targets[1].value, -2000);
    QVERIFY(c.targets[1].absolute);
    c = parseCommand("A7,0");
    QCOMPARE(c.number, 7);
    QVERIFY(!c.on);
    c = parseCommand("IJ8,1 Eingang 8: Vektorfahrt X-Motor", kStx);
    QCOMPARE(c.number, 8);
    QCOMPARE(c.title, QByteArray("Eingang 8: Vektorfahrt X-Motor"));
    c = parseCommand("#Ou,25");
    QCOMPARE(c.axis, std::optional<Axis>(Axis::U));
    QCOMPARE(c.value, 25);
}

void TestEmisGrammar::parse_malformed_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::newRow("unknown") << QByteArray("Q1");
    QTest::newRow("empty") << QByteArray();
    QTest::newRow("octal-looking ok but letters") << QByteArray("#S2x0");
    QTest::newRow("hex") << QByteArray("#S0x20");
    QTest::newRow("axis w") << QByteArray("#S,w200");
    QTest::newRow("upper axis speed") << QByteArray("#S,X200");
    QTest::newRow("negative speed") << QByteArray("#S-200");
    QTest::newRow("vector twice") << QByteArray("L1,x10,x20");
    QTest::newRow("vector empty") << QByteArray("L1,");
    QTest::newRow("vector L2") << QByteArray("L2,x10");
    QTest::newRow("home none") << QByteArray("$H");
    QTest::newRow("home twice") << QByteArray("$Hxx");
    QTest::newRow("home bad suffix") << QByteArray("$Hx,b");
    QTest::newRow("output value") << QByteArray("A1,2");
    QTest::newRow("output no state") << QByteArray("A1");
    QTest::newRow("current one value") << QByteArray("c,x100");
    QTest::newRow("header with CR") << QByteArray("IJ7,1 title");
    QTest::newRow("control char") << QByteArray("@\x01V");
    QTest::newRow("interpolation 2") << QByteArray("IP2");
    QTest::newRow("huge number") << QByteArray("W99999999999999999999");
    QTest::newRow("offset upper") << QByteArray("#OX,10");
    QTest::newRow("prsys typo") << QByteArray("*PRSYZ");
}

void TestEmisGrammar::parse_malformed()
{
    QFETCH(QByteArray, text);
    const Command c = parseCommand(text);
    QCOMPARE(c.kind, K::Invalid);
    QVERIFY(!c.error.isEmpty());
}

void TestEmisGrammar::range_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("inRange");
    QTest::newRow("input 0") << QByteArray("@I0") << false;
    QTest::newRow("input 9") << QByteArray("@I9") << false;
    QTest::newRow("input 8") << QByteArray("@I8") << true;
    QTest::newRow("output 7") << QByteArray("A7,1") << true;
    QTest::newRow("output 8") << QByteArray("A8,1") << false;
    QTest::newRow("speed 0") << QByteArray("#S0") << false;
    QTest::newRow("speed max") << QByteArray("#E1,x65535") << true;
    QTest::newRow("speed over") << QByteArray("#E1,x65536") << false;
    QTest::newRow("ramp 0") << QByteArray("#R0") << false;
    QTest::newRow("resolution 256") << QByteArray("D,u256") << true;
    QTest::newRow("resolution 3") << QByteArray("D,u3") << false;
    QTest::newRow("resolution 512") << QByteArray("D,u512") << false;
    QTest::newRow("idle 25") << QByteArray("c,x100,25") << true;
    QTest::newRow("idle 26") << QByteArray("c,x100,26") << false;
    QTest::newRow("run 101") << QByteArray("c,x101,0") << false;
    QTest::newRow("vector max") << QByteArray("L1,x-2147483647") << true;
    QTest::newRow("vector over") << QByteArray("L1,x2147483648") << false;
    QTest::newRow("program 9") << QByteArray("*PWIN9") << false;
    QTest::newRow("erase 0") << QByteArray("*PEIN0") << false;
    QTest::newRow("system idle 30") << QByteArray("##c,x100,30") << false;
    QTest::newRow("system resolution 5") << QByteArray("##D,x5") << false;
    QTest::newRow("system speed 0") << QByteArray("##E,x0,y100") << false;
    QTest::newRow("system ramp 0") << QByteArray("##R,0") << false;
}

void TestEmisGrammar::range()
{
    QFETCH(QByteArray, text);
    QFETCH(bool, inRange);
    const Command c = parseCommand(text);
    QVERIFY2(c.kind != K::Invalid, qPrintable(c.error));
    QCOMPARE(rangeError(c).isEmpty(), inRange);
}

void TestEmisGrammar::program_allowedAndRefused_data()
{
    QTest::addColumn<QByteArray>("line");
    QTest::addColumn<bool>("allowed");
    QTest::newRow("9.17 home") << QByteArray("$H,x") << true;
    QTest::newRow("9.17 vector") << QByteArray("L1,x191") << true;
    QTest::newRow("9.17 wait") << QByteArray("W1500") << true;
    QTest::newRow("speed") << QByteArray("#E1,x1000") << true;
    QTest::newRow("output") << QByteArray("A3,1") << true;
    QTest::newRow("query") << QByteArray("@IG") << false;
    QTest::newRow("version") << QByteArray("@V") << false;
    QTest::newRow("system") << QByteArray("##R,100") << false;
    QTest::newRow("nested program") << QByteArray("*PWIN3") << false;
    QTest::newRow("erase") << QByteArray("*PEIN3") << false;
    QTest::newRow("unknown") << QByteArray("HELLO") << false;
    QTest::newRow("out of range") << QByteArray("W700000") << false;
}

void TestEmisGrammar::program_allowedAndRefused()
{
    QFETCH(QByteArray, line);
    QFETCH(bool, allowed);
    QCOMPARE(validateProgramLine(line).isEmpty(), allowed);
}

void TestEmisGrammar::system_manualEntries_data()
{
    QTest::addColumn<QByteArray>("entry");
    QTest::newRow("D") << QByteArray("D,x32,y16,z64,u1");
    QTest::newRow("c") << QByteArray("c,x100,0,y100,0,z100,20,u100,0");
    QTest::newRow("REFSW") << QByteArray("REFSW,xNO,yNO,zNO,uNC");
    QTest::newRow("S") << QByteArray("S,x200,y200,z200,u200");
    QTest::newRow("E") << QByteArray("E,x1800,y1800,z600,u1000");
    QTest::newRow("E9") << QByteArray("E9,x400,y400,z200,u300");
    QTest::newRow("R") << QByteArray("R,100");
    QTest::newRow("SMCflex") << QByteArray("S,200,1800,100");
}

void TestEmisGrammar::system_manualEntries()
{
    QFETCH(QByteArray, entry);
    QString error;
    const auto parsed = parseSystemEntry(entry, &error);
    QVERIFY2(parsed.has_value(), qPrintable(error));
    QCOMPARE(formatSystemEntry(*parsed), entry); // the manual's own spelling comes back
    QCOMPARE(parsed->motorCount(), 4);           // every example names (or applies to) all four
}

void TestEmisGrammar::system_motorCount()
{
    const auto e = parseSystemEntry("D,x32,z64", nullptr);
    QVERIFY(e);
    QCOMPARE(e->motorCount(), 2);
    QCOMPARE(e->values.value(Axis::Z), 64);
    const auto c = parseSystemEntry("c,x100,0,y100,0,z100,20,u100,0", nullptr);
    QCOMPARE(c->idle.value(Axis::Z), 20);
    QCOMPARE(c->values.value(Axis::U), 100);
    const auto r = parseSystemEntry("REFSW,xNO,yNO,zNO,uNC", nullptr);
    QVERIFY(r->normallyClosed.value(Axis::U));
    QVERIFY(!r->normallyClosed.value(Axis::X));
}

void TestEmisGrammar::system_malformed_data()
{
    QTest::addColumn<QByteArray>("entry");
    QTest::newRow("unknown key") << QByteArray("Q,x1");
    QTest::newRow("no values") << QByteArray("D");
    QTest::newRow("axis twice") << QByteArray("D,x32,x16");
    QTest::newRow("c odd") << QByteArray("c,x100");
    QTest::newRow("REFSW type") << QByteArray("REFSW,xPNP");
    QTest::newRow("R two") << QByteArray("R,100,200");
    QTest::newRow("S two numbers") << QByteArray("S,200,1800");
}

void TestEmisGrammar::system_malformed()
{
    QFETCH(QByteArray, entry);
    QString error;
    QVERIFY(!parseSystemEntry(entry, &error));
    QVERIFY(!error.isEmpty());
}

void TestEmisGrammar::prsys_lenientSeparators_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::newRow("CR LF with ##") << QByteArray("*PRSYS:##D,x32,y16,z64,u1\r\n##R,100");
    QTest::newRow("glued ##") << QByteArray("*PRSYS:##D,x32,y16,z64,u1##R,100");
    QTest::newRow("blanks without ##") << QByteArray("*PRSYS: D,x32,y16,z64,u1 R,100");
    QTest::newRow("semicolons") << QByteArray("*PRSYS:D,x32,y16,z64,u1;R,100;");
    QTest::newRow("no echo") << QByteArray(":D,x32,y16,z64,u1\nR,100");
    QTest::newRow("with junk") << QByteArray("*PRSYS: D,x32,y16,z64,u1 ??? R,100");
}

void TestEmisGrammar::prsys_lenientSeparators()
{
    QFETCH(QByteArray, text);
    const SystemParameters p = parseSystemParameters(text);
    QCOMPARE(p.entries.size(), 2);
    const SystemEntry* d = p.find(SystemEntry::Key::StepResolution);
    QVERIFY(d);
    QCOMPARE(d->values.value(Axis::Z), 64);
    QCOMPARE(p.find(SystemEntry::Key::Ramp)->ramp, 100);
    QVERIFY(!p.find(SystemEntry::Key::WorkSpeed));
    QCOMPARE(p.unparsed.isEmpty(), !text.contains("???"));
}

void TestEmisGrammar::prsys_formatRoundTrip()
{
    QList<SystemEntry> entries;
    for (const char* e : {"D,x32,y16,z64,u1", "REFSW,xNO,yNC,zNO,uNC", "R,250", "R,300"})
        entries << *parseSystemEntry(e, nullptr);
    const QByteArray text = formatSystemParameters(entries);
    QVERIFY(text.startsWith("*PRSYS:##D,"));
    const SystemParameters p = parseSystemParameters(text);
    QCOMPARE(p.entries.size(), 3);
    QCOMPARE(p.find(SystemEntry::Key::Ramp)->ramp, 300); // the later entry wins
    QVERIFY(p.find(SystemEntry::Key::ReferenceSwitch)->normallyClosed.value(Axis::Y));
    QVERIFY(p.unparsed.isEmpty());
}

void TestEmisGrammar::prsys_partialEntry_keepsMotorsItDoesNotName()
{
    SystemParameters p = parseSystemParameters("*PRSYS:##c,x100,0,y100,0,z100,20,u100,0\r\n"
                                               "##c,x50,10");
    QCOMPARE(p.entries.size(), 1);
    const SystemEntry* c = p.find(SystemEntry::Key::Currents);
    QCOMPARE(c->values,
             (QMap<Axis, qint64>{{Axis::X, 50}, {Axis::Y, 100}, {Axis::Z, 100}, {Axis::U, 100}}));
    QCOMPARE(c->idle.value(Axis::X), 10);
    QCOMPARE(c->idle.value(Axis::Z), 20);
    p.store(*parseSystemEntry("REFSW,uNC", nullptr));
    p.store(*parseSystemEntry("REFSW,xNC", nullptr));
    QCOMPARE(p.find(SystemEntry::Key::ReferenceSwitch)->normallyClosed,
             (QMap<Axis, bool>{{Axis::X, true}, {Axis::U, true}}));
}

void TestEmisGrammar::decoder_framesCrStxEtx()
{
    CommandDecoder decoder;
    const QList<CommandDecoder::Frame> frames =
        decoder.feed("*PWIN7\r\nIJ7,1 Eingang 7: Referenzfahrt X-Motor\x02$H,x\r\x03\r\n  @V\r\r");
    QCOMPARE(frames.size(), 5);
    QCOMPARE(frames[0].text, QByteArray("*PWIN7"));
    QCOMPARE(frames[1].terminator, kStx);
    QCOMPARE(frames[1].text, QByteArray("IJ7,1 Eingang 7: Referenzfahrt X-Motor"));
    QCOMPARE(frames[2].text, QByteArray("$H,x"));
    QCOMPARE(frames[3].terminator, kEtx);
    QVERIFY(frames[3].text.isEmpty());
    QCOMPARE(frames[4].text, QByteArray("@V"));
}

void TestEmisGrammar::decoder_randomChunks_sameFrames()
{
    const QByteArray wire("A1,1\r#S,x200\rIJ2,1 t\x02L1,x-5\r\x03##R,100\r");
    QRandomGenerator rng(99);
    for (int round = 0; round < 30; ++round) {
        CommandDecoder decoder;
        QList<QByteArray> texts;
        for (int at = 0; at < wire.size();) {
            const int n = rng.bounded(1, 6);
            for (const auto& f : decoder.feed(wire.mid(at, n)))
                texts << f.text;
            at += n;
        }
        QCOMPARE(texts, (QList<QByteArray>{"A1,1", "#S,x200", "IJ2,1 t", "L1,x-5", "", "##R,100"}));
    }
}

void TestEmisGrammar::decoder_overlong_boundedAndResyncs()
{
    CommandDecoder decoder;
    QList<CommandDecoder::Frame> frames =
        decoder.feed(QByteArray(CommandDecoder::kMaxFrame * 4, 'L') + "\r@V\r");
    QCOMPARE(frames.size(), 2);
    QVERIFY(frames[0].overlong);
    QVERIFY(frames[0].text.isEmpty());
    QCOMPARE(frames[1].text, QByteArray("@V"));
}

void TestEmisGrammar::decoder_everyByteAccountedFor()
{
    const QByteArray in = QByteArray("\r\n @V\r\n\r IJ7,1 t\x02\x03") +
                          QByteArray(CommandDecoder::kMaxFrame + 10, 'L') + "\r" + "@I";
    CommandDecoder decoder;
    qint64 accounted = 0;
    const QList<CommandDecoder::Frame> frames = decoder.feed(in);
    QCOMPARE(frames.size(), 4); // @V, the header, <ETX>, the overlong frame
    for (const CommandDecoder::Frame& f : frames)
        accounted += f.text.size() + 1;
    QCOMPARE(decoder.buffered(), 2);
    // CR, LF, blank; LF, empty CR, blank; the overlong frame's kMaxFrame + 10 bytes
    QCOMPARE(decoder.skippedBytes(), 6 + CommandDecoder::kMaxFrame + 10);
    QCOMPARE(accounted + decoder.buffered() + decoder.skippedBytes(), in.size());
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisGrammar)
#include "tst_emisgrammar.moc"
