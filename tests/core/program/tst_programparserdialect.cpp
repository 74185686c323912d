// The parser on the CAM dialect's lines (issue 29, docs/programs.md "The modes CAM posts set",
// "Lines"): LinuxCNC's modal groups on every block, a CAM post's header (byte-order mark, "%",
// N numbers, CRLF), S on any line, and LinuxCNC's whole line (several actions, issue 50). The words
// and errors of every line: tst_programparser; drilling cycles: tst_drillcycle.
#include "ProgramParserTestSupport.h"
#include "TestMain.h"
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
    void parse_wholeLine_blocksInExecutionOrder_data();
    void parse_wholeLine_blocksInExecutionOrder();
    void parse_wholeLine_lengthOffsetAfterToolChange();
    void parse_polar_axisWordsOfThePoint_data();
    void parse_polar_axisWordsOfThePoint();
    void parse_wholeLine_refusedAsLinuxCNC_data();
    void parse_wholeLine_refusedAsLinuxCNC();
    void parse_inverseTime_fOnEveryG1_data();
    void parse_inverseTime_fOnEveryG1();
    void parse_aroundTheProgram_blocksNameAndNotes_data();
    void parse_aroundTheProgram_blocksNameAndNotes();
    void parse_dollarHAndSlashOff_keepTheirColumns();
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
    // Issue 50: G97 (rpm, LinuxCNC's default; Fanuc-style posts write "G97 S10000 M3") is the
    // spindle mode StepDeck runs in: accepted, nothing changes.
    QTest::newRow("G97 with S and M3")
        << "G97 S10000 M3\nG0 X1" << QStringList{"XY blend -", "XY blend -"};
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

// LinuxCNC's whole line (issue 50, docs/programs.md "Several words on one line"): a block per
// action, in LinuxCNC's order of execution (I/O, M6, spindle, coolant, G4, G28/G10/G92,
// motion, stop), each at its word's column; S with the line's M3/M4/M5, else with its first
// block; G43 with its last; the line's text on each.
void TestProgramParserDialect::parse_wholeLine_blocksInExecutionOrder_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("blocks"); // line:word@column, "S" where the speed goes out
    QTest::newRow("Vectric's spindle beside a rapid")
        << "G0X0.000Y0.000S12000M3" << QStringList{"1:M3@21 S", "1:G0@1"};
    QTest::newRow("coolant before a feed") << "M8 G1 X1 F100" << QStringList{"1:M8@1", "1:G1@4"};
    QTest::newRow("coolant off before an arc")
        << "G2 X2 I0.5 M9 F100" << QStringList{"1:M9@12", "1:G2@1"};
    QTest::newRow("spindle and coolant off") << "M5 M9" << QStringList{"1:M5@1", "1:M9@4"};
    QTest::newRow("as written the other way") << "M9 M5" << QStringList{"1:M5@4", "1:M9@1"};
    QTest::newRow("spindle with S, coolant") << "M8 M3 S1000" << QStringList{"1:M3@4 S", "1:M8@1"};
    QTest::newRow("mist and flood") << "M7 M8" << QStringList{"1:M7@1", "1:M8@4"};
    QTest::newRow("tool change then spindle")
        << "T1 M3 M6 S9000" << QStringList{"1:M6@7", "1:M3@4 S"};
    QTest::newRow("tool change, then the end") << "T1 M6 M2" << QStringList{"1:M6@4", "1:M2@7"};
    QTest::newRow("move, then hold") << "G0 X1 M0" << QStringList{"1:G0@1", "1:M0@7"};
    QTest::newRow("move, then the end") << "M2 G0 Z10" << QStringList{"1:G0@4", "1:M2@1"};
    QTest::newRow("dwell, then a move") << "G1 X5 F100 G4 P1" << QStringList{"1:G4@12", "1:G1@1"};
    QTest::newRow("output, then a move") << "G0 X1 M64 P2" << QStringList{"1:M64@7", "1:G0@1"};
    QTest::newRow("spindle before the modal move")
        << "G1 F100\nX5 M3 S500" << QStringList{"1:modal@1", "2:M3@4 S", "2:G1@0"};
    QTest::newRow("S first, then the tool change")
        << "T2 M6 S800" << QStringList{"1:S@0 S", "1:M6@4"};
    QTest::newRow("S with the move when nothing switches")
        << "M3 S100\nG1 X1 S200 F100" << QStringList{"1:M3@1 S", "2:G1@1 S"};
    QTest::newRow("after an N number") << "N10 M5 M9" << QStringList{"1:M5@5", "1:M9@8"};
    QTest::newRow("four M words") << "T1 M6 M3 M7 M8 S100"
                                  << QStringList{"1:M6@4", "1:M3@7 S", "1:M7@10", "1:M8@13"};
    QTest::newRow("G92.1 and a move") << "G92.1 G0 X0" << QStringList{"1:G92.1@1", "1:G0@7"};
}

void TestProgramParserDialect::parse_wholeLine_blocksInExecutionOrder()
{
    QFETCH(QString, program);
    QFETCH(QStringList, blocks);
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(program.toUtf8(), kAxes, &errors);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QStringList got;
    const QStringList lines = program.split(QLatin1Char('\n'));
    for (const ProgramBlock& b : p->allBlocks()) {
        const QString word = blockWord(b.kind).isEmpty() ? QStringLiteral("modal") : blockWord(b);
        got << QStringLiteral("%1:%2@%3%4")
                   .arg(b.line)
                   .arg(word)
                   .arg(b.actionColumn)
                   .arg(b.spindleChange ? QStringLiteral(" S") : QString());
        QCOMPARE(b.text, lines.at(b.line - 1).trimmed());
    }
    QCOMPARE(got, blocks);
}

// G43 on a tool change's line applies after the change (LinuxCNC's steps 8 and 18): the line's
// last block names it; the modal state is the line's on every block.
void TestProgramParserDialect::parse_wholeLine_lengthOffsetAfterToolChange()
{
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse("T1 M6 G43 H1 M8 (drill)\nG0 Z5", kAxes, &errors);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    const QList<ProgramBlock> blocks = p->allBlocks();
    QCOMPARE(blocks.size(), 3);
    QCOMPARE(blocks.at(0).kind, BlockKind::ToolChange);
    QCOMPARE(blocks.at(0).prompt, QStringLiteral("Load tool 1 (drill)"));
    QCOMPARE(blocks.at(1).kind, BlockKind::CoolantFlood);
    for (const ProgramBlock& b : blocks)
        QCOMPARE(b.lengthTool, 1);
    QVERIFY(!blocks.at(0).appliesLengthOffset);
    QVERIFY(blocks.at(1).appliesLengthOffset);
    QVERIFY(!blocks.at(2).appliesLengthOffset);
}

// LinuxCNC's polar coordinates (issue 50 item 6): "@r ^a" is X = r cos a, Y = r sin a, at the
// columns of @ and ^, on any move in G90 and G17; what depends on where the tool stands (one of
// the two alone, G91) and what LinuxCNC refuses is refused with what to write instead.
void TestProgramParserDialect::parse_polar_axisWordsOfThePoint_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("result"); // the last block's X@column Y@column, or the error
    QTest::newRow("on +X") << "G0 @10 ^0"
                           << "X10@4 Y0@8";
    QTest::newRow("a right angle is exactly 0 on X") << "G1 @10 ^90 F100"
                                                     << "X0@4 Y10@8";
    QTest::newRow("the angle first, negative") << "G0 ^-45 @2"
                                               << "X1.414@9 Y-1.414@4";
    QTest::newRow("with the modal motion and Z") << "G1 F100\n@5 ^180 Z-1"
                                                 << "X-5@1 Y0@4";
    QTest::newRow("an arc's end") << "G3 @10 ^90 I-10 J0 F100"
                                  << "X0@4 Y10@8";
    QTest::newRow("a drilling cycle's hole") << "G81 @3 ^270 Z-2 R1 F100"
                                             << "X0@5 Y-3@8";
    QTest::newRow("one alone")
        << "G0 @10"
        << "1:4: @10 alone takes the other from where the tool stands: not supported; "
           "give both @ (the distance) and ^ (the angle)";
    QTest::newRow("in G91") << "G91 G0 @1 ^2"
                            << "1:8: polar coordinates in G91 add to where the tool stands: not "
                               "supported; write @ and ^ in G90";
    QTest::newRow("another plane") << "G18 G0 @1 ^2"
                                   << "1:8: polar coordinates (@, ^) work in the XY plane (G17) "
                                      "only, as in LinuxCNC";
    QTest::newRow("beside Y") << "G0 @1 ^2 Y3"
                              << "1:10: Y3 beside polar coordinates (@, ^): give one or the "
                                 "other, as in LinuxCNC";
    QTest::newRow("with G53") << "G53 G0 @1 ^2"
                              << "1:8: polar coordinates (@, ^) are not machine coordinates: not "
                                 "with G53, as in LinuxCNC";
    QTest::newRow("not a move") << "G92 @1 ^2"
                                << "1:5: @1 is not used by G92: polar coordinates give a move's "
                                   "end";
    QTest::newRow("twice") << "G0 @1 ^2 @3"
                           << "1:10: @ appears twice on the line";
}

void TestProgramParserDialect::parse_polar_axisWordsOfThePoint()
{
    QFETCH(QString, program);
    QFETCH(QString, result);
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(program.toUtf8(), kAxes, &errors);
    if (!p) {
        QCOMPARE(texts(errors).join(QLatin1Char('\n')), result);
        return;
    }
    const ProgramBlock b = p->allBlocks().last();
    QStringList got;
    for (const QString& axis : {QStringLiteral("X"), QStringLiteral("Y")})
        got << QStringLiteral("%1%2@%3")
                   .arg(axis, figure(b.axes.value(axis)))
                   .arg(b.columnOf(axis));
    QCOMPARE(got.join(QLatin1Char(' ')), result);
}

// Words LinuxCNC refuses together stay refused, with its reason.
void TestProgramParserDialect::parse_wholeLine_refusedAsLinuxCNC_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("error");
    QTest::newRow("two spindle words") << "M3 M5"
                                       << "1:4: M3 and M5 on one line: they are of one modal group";
    QTest::newRow("coolant off with flood")
        << "M8 M9"
        << "1:4: M8 and M9 on one line: they are of one modal group";
    QTest::newRow("two stops") << "M0 M2"
                               << "1:4: M0 and M2 on one line: they are of one modal group";
    QTest::newRow("two outputs") << "M64 P1 M65"
                                 << "1:8: M64 and M65 on one line: they are of one modal group";
    QTest::newRow("two motions") << "G0 X1 G1 Y1 F10"
                                 << "1:7: G0 and G1 on one line: they are of one modal group";
    QTest::newRow("two of group 0") << "G4 P1 G28"
                                    << "1:7: G4 and G28 on one line: they are of one modal group";
    QTest::newRow("G28 beside a move")
        << "G0 G28 X0"
        << "1:4: G0 and G28 both take axis words: write them on two lines";
    QTest::newRow("G92 beside a move")
        << "G92 X0 G1 Y1 F10"
        << "1:8: G92 and G1 both take axis words: write them on two lines";
    QTest::newRow("dwell and an output") << "G4 P1 M64"
                                         << "1:7: G4 and M64 both take P: write them on two lines";
    QTest::newRow("five M words") << "T1 M6 M3 M7 M8 M2"
                                  << "1:16: M2: more than 4 M words on one line (LinuxCNC runs at "
                                     "most 4)";
    QTest::newRow("M6 without T") << "M3 M6"
                                  << "1:4: M6 needs a tool: T on this line or an earlier one";
    QTest::newRow("a word none takes") << "M5 M9 Q2"
                                       << "1:7: Q2 is not used by M5";
}

void TestProgramParserDialect::parse_wholeLine_refusedAsLinuxCNC()
{
    QFETCH(QString, program);
    QFETCH(QString, error);
    QList<ProgramError> errors;
    QVERIFY(!ProgramParser::parse(program.toUtf8(), kAxes, &errors));
    QCOMPARE(texts(errors), QStringList{error});
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

namespace {
// The parser's notes (issue 50), as ProgramError::text() gives them: "line:column: message".
QString unreadNote(const char* at, int lines)
{
    return QStringLiteral("%1: %2 line(s) after the program's end are not read, as in LinuxCNC "
                          "(nothing after M2, M30 or the closing \"%\" runs)")
        .arg(QLatin1String(at))
        .arg(lines);
}
QString deletedNote(const char* at, int lines)
{
    return QStringLiteral("%1: block delete is on: %2 line(s) starting with \"/\" are skipped, "
                          "this one the first (switch it off to run them)")
        .arg(QLatin1String(at))
        .arg(lines);
}
QString grblNote(const char* at, const char* command)
{
    return QStringLiteral("%1: %2 is a GRBL command (a setting, the alarm lock, a report or a "
                          "jog): not run")
        .arg(QLatin1String(at), QLatin1String(command));
}
QString zeroNormalNote(const char* at, const char* word, int arcs)
{
    return QStringLiteral("%1: %2 on %3 arc(s), this one the first: an offset along the plane's "
                          "normal that is 0 is left out, as GRBL does (LinuxCNC refuses it; any "
                          "other value is refused)")
        .arg(QLatin1String(at), QLatin1String(word))
        .arg(arcs);
}
} // namespace

// Issue 50 items 3, 6 and 8: what CAM posts and senders write around the G-code. A Fanuc
// program number before the first block is the name; nothing after M2/M30 or the closing "%"
// is read (LinuxCNC), one note counts it; "/" lines follow the block delete switch; GRBL's "$H"
// references, its other "$" lines are named; a zero offset along the arc plane's normal is left
// out with one note for the program. The blocks are read back through the index (allBlocks), so
// a reading again skips what the first one skipped.
void TestProgramParserDialect::parse_aroundTheProgram_blocksNameAndNotes_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<bool>("blockDelete");
    QTest::addColumn<QStringList>("blocks");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QStringList>("notes");
    QTest::newRow("Fanuc wrapper: % and the program number")
        << "%\nO1001 (BRACKET)\nG0 X1\nM30\n%\n"
        << true << QStringList{"3: G0 X=1 abs mm F-", "4: M2 abs mm F-"} << "O1001 (BRACKET)"
        << QStringList{};
    QTest::newRow("colon number after a comment")
        << "(T1 D=3)\n:0012\nG0 X1\n"
        << true << QStringList{"3: G0 X=1 abs mm F-"} << ":0012" << QStringList{};
    QTest::newRow("number before the opening %")
        << "O1001\n%\nG0 X1\n%\n"
        << true << QStringList{"3: G0 X=1 abs mm F-"} << "O1001" << QStringList{};
    QTest::newRow("after M30: not read, counted")
        << "G0 X1\nM30\nG0 X2\n\n(the post's trailer)\nM99\n"
        << true << QStringList{"1: G0 X=1 abs mm F-", "2: M2 abs mm F-"} << QString()
        << QStringList{unreadNote("2:1", 3)};
    QTest::newRow("after the closing %: not read, counted")
        << "%\nG0 X1\n%\nG0 X2\n%\n"
        << true << QStringList{"2: G0 X=1 abs mm F-"} << QString()
        << QStringList{unreadNote("3:1", 2)};
    QTest::newRow("the % closing after M2 is the end")
        << "%\nG0 X1\nM2\n%\n\n"
        << true << QStringList{"2: G0 X=1 abs mm F-", "3: M2 abs mm F-"} << QString()
        << QStringList{};
    QTest::newRow("block delete on: skipped, modal words too")
        << "G0 X1\n/G91\n / M0 (clamps)\nG0 X2\n"
        << true << QStringList{"1: G0 X=1 abs mm F-", "4: G0 X=2 abs mm F-"} << QString()
        << QStringList{deletedNote("2:1", 2)};
    QTest::newRow("block delete off: run without the slash")
        << "G0 X1\n/G91\n / M0 (clamps)\nG0 X2\n"
        << false
        << QStringList{"1: G0 X=1 abs mm F-", "2: modal rel mm F-", "3: M0 rel mm F- \"clamps\"",
                       "4: G0 X=2 rel mm F-"}
        << QString() << QStringList{};
    QTest::newRow("GRBL sender: $H references, the others are named")
        << "$X\n$H\n$32=1\n$$\nG0 X1\n"
        << true << QStringList{"2: G28 abs mm F-", "5: G0 X=1 abs mm F-"} << QString()
        << QStringList{grblNote("1:1", "$X"), grblNote("3:1", "$32=1"), grblNote("4:1", "$$")};
    QTest::newRow("$h in lower case with a comment")
        << "  $h (home first)\nG0 X1" << true
        << QStringList{"1: G28 abs mm F-", "2: G0 X=1 abs mm F-"} << QString() << QStringList{};
    QTest::newRow("K0.000 on every G17 arc: one note")
        << "G1 X0 Y0 F300\nG2 X10 Y0 I5 J0 K0.000\nG3 X0 Y0 I-5 J0 K0.000\n"
        << true
        << QStringList{"1: G1 X=0 Y=0 abs mm F300", "2: G2 X=10 Y=0 abs mm F300 G17 I5 J0 P1",
                       "3: G3 X=0 Y=0 abs mm F300 G17 I-5 J0 P1"}
        << QString() << QStringList{zeroNormalNote("2:17", "K0.000", 2)};
    QTest::newRow("J0 on a G18 arc") << "G18 G2 X2 Z0 I1 J0 K0 F60" << true
                                     << QStringList{"1: G2 X=2 Z=0 abs mm F60 G18 I1 K0 P1"}
                                     << QString() << QStringList{zeroNormalNote("1:17", "J0", 1)};
}

void TestProgramParserDialect::parse_aroundTheProgram_blocksNameAndNotes()
{
    QFETCH(QString, program);
    QFETCH(bool, blockDelete);
    QFETCH(QStringList, blocks);
    QFETCH(QString, name);
    QFETCH(QStringList, notes);
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse(program.toUtf8(), kAxes, &errors, {}, blockDelete);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QCOMPARE(describeAll(*p), blocks);
    QCOMPARE(p->name, name);
    QCOMPARE(texts(p->notes), notes);
}

// "$H" is a G28 block at the "$"'s column, its text as written; with block delete off a "/"
// line's words keep their columns, so that the check names them where they stand.
void TestProgramParserDialect::parse_dollarHAndSlashOff_keepTheirColumns()
{
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse("  $h (home first)\n/G0 X15\n", kAxes, &errors, {}, false);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    const QList<ProgramBlock> blocks = p->allBlocks();
    QCOMPARE(blocks.size(), 2);
    QCOMPARE(blocks.at(0).kind, BlockKind::Home);
    QVERIFY(blocks.at(0).axes.isEmpty());
    QCOMPARE(blocks.at(0).columnOf({}), 3);
    QCOMPARE(blocks.at(0).text, QStringLiteral("$h (home first)"));
    QCOMPARE(blocks.at(1).kind, BlockKind::Rapid);
    QCOMPARE(blocks.at(1).columnOf(QStringLiteral("X")), 5);
    QVERIFY(!p->index->blockDelete); // kept for every reading again
}

STEPDECK_TEST_APPLESS_MAIN(TestProgramParserDialect)
#include "tst_programparserdialect.moc"
