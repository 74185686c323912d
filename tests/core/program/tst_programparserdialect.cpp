// The parser on the CAM dialect's lines (issue 29, docs/programs.md "The modes CAM posts set",
// "Lines"): LinuxCNC's modal groups on every block, a CAM post's header (byte-order mark, "%",
// N numbers, CRLF), S on any line, and a spindle or coolant word beside a motion. The words
// and errors of every line: tst_programparser; drilling cycles: tst_drillcycle.
#include "ProgramParserTestSupport.h"
#include "program/ProgramParser.h"
#include <QtTest>

using namespace stepdeck::program;

using namespace stepdeck::program::parsertest;

class TestProgramParserDialect : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_modalGroups_stateOnEveryBlock_data();
    void parse_modalGroups_stateOnEveryBlock();
    void parse_camHeader_percentBomAndModes_blocksAsWithout();
    void parse_spindleSpeed_modalOnAnyLine();
    void parse_switchBesideMotion_keptToRunFirst();
    void parse_inverseTime_fOnEveryG1_data();
    void parse_inverseTime_fOnEveryG1();
};

void TestProgramParserDialect::parse_modalGroups_stateOnEveryBlock_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("states"); // per block: plane, path mode, tolerance
    QTest::newRow("defaults") << "G0 X1" << QStringList{"XY blend -"};
    QTest::newRow("planes modal") << "G18\nG0 X1\nG19 G0 Y1\nG17\nG0 Z1"
                                  << QStringList{"XZ blend -", "XZ blend -", "YZ blend -",
                                                 "XY blend -", "XY blend -"};
    QTest::newRow("path modes") << "G61\nG0 X1\nG61.1\nG64 P0.02 Q0.01\nG0 X2\nG64\nG0 X3"
                                << QStringList{"XY exact-path -", "XY exact-path -",
                                               "XY exact-stop -", "XY blend 0.02",
                                               "XY blend 0.02",   "XY blend -",
                                               "XY blend -"};
}

void TestProgramParserDialect::parse_modalGroups_stateOnEveryBlock()
{
    QFETCH(QString, program);
    QFETCH(QStringList, states);
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(program.toUtf8(), kAxes, &errors);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QStringList got;
    for (const ProgramBlock& b : p->allBlocks()) {
        const QString plane = b.plane == Plane::XY   ? QStringLiteral("XY")
                              : b.plane == Plane::XZ ? QStringLiteral("XZ")
                                                     : QStringLiteral("YZ");
        const QString mode = b.pathMode == PathMode::ExactPath   ? QStringLiteral("exact-path")
                             : b.pathMode == PathMode::ExactStop ? QStringLiteral("exact-stop")
                                                                 : QStringLiteral("blend");
        got << QStringLiteral("%1 %2 %3")
                   .arg(plane, mode,
                        b.pathTolerance ? QString::number(*b.pathTolerance) : QStringLiteral("-"));
    }
    QCOMPARE(got, states);
}

// A header as CAM posts write it: a byte-order mark, "%" first and last, N numbers, a
// program comment, the safety line of modes, CRLF line ends. The blocks are those of the same
// program without any of it.
void TestProgramParserDialect::parse_camHeader_percentBomAndModes_blocksAsWithout()
{
    const QByteArray cam = "\xEF\xBB\xBF%\r\n(PART 1001 -- FACING)\r\n"
                           "N10 G90 G94 G17 G40 G49 G80\r\nN15 G21\r\nN20 G0 X10 Y5\r\n"
                           "N25 G1 Z-1 F300\r\nN30 M30\r\n%\r\n"
                           "anything after the closing percent is ignored\r\n";
    const QByteArray plain = "\n\nG90\nG21\nG0 X10 Y5\nG1 Z-1 F300\nM30\n";
    QList<ProgramError> errors;
    const std::optional<Program> a = ProgramParser::parse(cam, kAxes, &errors);
    QVERIFY2(a, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    const std::optional<Program> b = ProgramParser::parse(plain, kAxes, &errors);
    QVERIFY(b);
    QCOMPARE(describeAll(*a), describeAll(*b));
    // A "%" line of its own, even after blank lines, opens the program (LinuxCNC).
    QVERIFY(ProgramParser::parse("\n  %  \nG0 X1\n%\n", kAxes, &errors));
}

// S as LinuxCNC reads it (issue 29): modal, on any line; alone (or with G1 and no axis
// words, LightBurn's "G1 S0") a block that sets the speed; M3 without S starts at the S in
// effect (0 before any).
void TestProgramParserDialect::parse_spindleSpeed_modalOnAnyLine()
{
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(
        "M3\nG00 S10000\nM3\nG1 X5 S500 F100\nG1 X6\nG1 S0\nM5\n", kAxes, &errors);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QStringList got;
    for (const ProgramBlock& b : p->allBlocks())
        got << QStringLiteral("%1 %2%3")
                   .arg(blockWord(b.kind))
                   .arg(b.rpm)
                   .arg(b.spindleChange ? QStringLiteral(" new") : QString());
    QCOMPARE(got, (QStringList{"M3 0", "S 10000 new", "M3 10000", "G1 500 new", "G1 500", "S 0 new",
                               "M5 0"}));
}

// M3/M4/M5/M7/M8/M9 beside a motion (Vectric's "G0X0.000Y0.000S12000M3"): the motion is the
// block, the switch is kept to run before it (LinuxCNC's order), at its own column. Beside
// anything else, or two of them, it stays an error.
void TestProgramParserDialect::parse_switchBesideMotion_keptToRunFirst()
{
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(
        "G0X0.000Y0.000S12000M3\nM8 G1 X1 F100\nG2 X2 I0.5 M9\n", kAxes, &errors);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QCOMPARE(p->allBlocks().size(), 3);
    QCOMPARE(p->allBlocks().at(0).kind, BlockKind::Rapid);
    QCOMPARE(p->allBlocks().at(0).switchFirst, std::optional<BlockKind>(BlockKind::SpindleOn));
    QCOMPARE(p->allBlocks().at(0).switchColumn, 21);
    QCOMPARE(p->allBlocks().at(0).rpm, 12000.0);
    QCOMPARE(switchBlock(p->allBlocks().at(0)).kind, BlockKind::SpindleOn);
    QCOMPARE(switchBlock(p->allBlocks().at(0)).columnOf({}), 21);
    QVERIFY(switchBlock(p->allBlocks().at(0)).axes.isEmpty());
    QCOMPARE(p->allBlocks().at(1).kind, BlockKind::Feed);
    QCOMPARE(p->allBlocks().at(1).switchFirst, std::optional<BlockKind>(BlockKind::CoolantFlood));
    QCOMPARE(p->allBlocks().at(2).kind, BlockKind::ArcClockwise);
    QCOMPARE(p->allBlocks().at(2).switchFirst, std::optional<BlockKind>(BlockKind::CoolantOff));
    for (const char* bad : {"M3 M8", "G4 P1 M3", "G0 X1 M3 M8", "G0 X1 M6"}) {
        QVERIFY2(!ProgramParser::parse(bad, kAxes, &errors), bad);
        QVERIFY2(errors.first().message.startsWith(QStringLiteral("one action per line")),
                 qPrintable(errors.first().text()));
    }
}

// G93 (LinuxCNC): F is the move's inverse time and stands on every G1, G2, G3 that moves;
// drilling cycles in G93 are not run yet; G94 after G93 needs a new F.
void TestProgramParserDialect::parse_inverseTime_fOnEveryG1_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("error"); // empty: parses; then the last block is an inverse-time G1
    QTest::newRow("G93 G1 with F") << "G93 G1 X10 F2"
                                   << "";
    QTest::newRow("F on each line") << "G93\nG1 X10 F2\nX20 F4"
                                    << "";
    QTest::newRow("G1 without F")
        << "G93\nG1 X10 F2\nG1 X20"
        << "3:1: G1 in inverse time (G93) needs F on its line: the move takes 1/F minutes";
    QTest::newRow("axis words without F")
        << "G93 G1 X10 F2\nX20"
        << "2:1: G1 in inverse time (G93) needs F on its line: the move "
           "takes 1/F minutes";
    QTest::newRow("arc") << "G93\nG2 X2 Y0 I1 J0 F5"
                         << "";
    QTest::newRow("arc without F")
        << "G93 G1 X1 F5\nG3 X2 Y0 I1 J0"
        << "2:1: G3 in inverse time (G93) needs F on its line: the move takes 1/F minutes";
    QTest::newRow("drilling cycle") << "G93\nG81 X1 Y1 Z-1 R1 F5"
                                    << "2:1: a drilling cycle cannot run in inverse time (G93), as "
                                       "in LinuxCNC: switch to G94 and give F before the cycle";
    QTest::newRow("G94 after G93 needs F") << "G93 G1 X1 F2\nG94\nG1 X2"
                                           << "3:1: G1 needs a feed rate: F on this line or an "
                                              "earlier one";
    QTest::newRow("G93 and G94 on one line")
        << "G93 G94"
        << "1:5: G93 and G94 on one line: they are of one modal group";
}

void TestProgramParserDialect::parse_inverseTime_fOnEveryG1()
{
    QFETCH(QString, program);
    QFETCH(QString, error);
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(program.toUtf8(), kAxes, &errors);
    if (!error.isEmpty()) {
        QVERIFY(!p);
        QCOMPARE(texts(errors).value(0), error);
        return;
    }
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    const ProgramBlock last = p->allBlocks().last();
    QVERIFY(last.kind == BlockKind::Feed || isArc(last.kind));
    QVERIFY(last.inverseTime);
}

QTEST_APPLESS_MAIN(TestProgramParserDialect)
#include "tst_programparserdialect.moc"
