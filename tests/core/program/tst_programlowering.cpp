// A program's blocks lowered to motion commands and printed as LinuxCNC's rs274 prints its
// canonical calls (issue 49 items 1, 2 and 6; docs/cli.md "--canon"). Each golden is worked out
// by hand from the program, the machine "mill" (X 0..100, Y 0..200, Z -50..0 mm, A degrees) and
// the offsets the row sets: one row per block kind the lowering emits.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/CanonText.h"
#include "program/ProgramLowering.h"
#include "program/ProgramReader.h"
#include "program/language/ProgramExpansion.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

namespace {

// The canonical text of `program` as the check's walk lowers it, and the check's errors.
QStringList canonOf(const QString& program, const MachineFacts& facts, QStringList* errors)
{
    CanonText canon(facts.description);
    QStringList out;
    const ProgramCheckResult result =
        ProgramCheck::check(parsed(program, facts), facts, 1, {},
                            [&](const motion::MotionCommand& c) { out << canon.lines(c); });
    *errors = texts(result.errors);
    return out;
}

// The calls alone, without the sequence number: "N00002 STRAIGHT_TRAVERSE(...)".
QStringList calls(const QStringList& lines)
{
    QStringList out;
    for (const QString& line : lines)
        out << line.section(QLatin1Char(' '), 1, -1, QString::SectionSkipEmpty);
    return out;
}

const QString kFrame = QStringLiteral("N00001 USE_LENGTH_UNITS(CANON_UNITS_MM)|"
                                      "N00001 SELECT_PLANE(CANON_PLANE_XY)|");

} // namespace

class TestProgramLowering : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void canon_blockKinds_asWorkedOutByHand_data();
    void canon_blockKinds_asWorkedOutByHand();
    void canon_issue50Features_asWorkedOutByHand_data();
    void canon_issue50Features_asWorkedOutByHand();
    void canon_lines_numberedWithTheProgramLine();
    void canon_relativeFromUnknown_questionMarks();
    void lower_arcThatCannotBeLaid_errorAndNoMotion();
};

void TestProgramLowering::canon_blockKinds_asWorkedOutByHand_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("g54");  // "X=10 Y=20": G54's offsets
    QTest::addColumn<QString>("tool"); // "1 10": tool 1 of length 10 in the table
    QTest::addColumn<QString>("expected");

    QTest::newRow("G0 G1 M2") << "G21 G90 G17\nG0 X10 Y5\nG1 Z-1 F300\nM2\n"
                              << ""
                              << ""
                              << kFrame +
                                     "N00002 STRAIGHT_TRAVERSE(10.0000, 5.0000, 0.0000, 0.0000)|"
                                     "N00003 SET_FEED_RATE(300.0000)|"
                                     "N00003 STRAIGHT_FEED(10.0000, 5.0000, -1.0000, 0.0000)|"
                                     "N00004 STOP_SPINDLE_TURNING(0)|"
                                     "N00004 MIST_OFF()|N00004 FLOOD_OFF()|"
                                     "N00004 PROGRAM_END()";
    // G54 at X10 Y20: the moves in program coordinates; G53's Z in machine coordinates is Z0
    // of the program too (no Z offset); G55 (no offsets) leaves Y at machine 22.
    QTest::newRow("G54 G53 G55")
        << "G0 X1 Y2\nG53 G0 Z0\nG55 G0 X0\n"
        << "X=10 Y=20"
        << ""
        << "N00001 USE_LENGTH_UNITS(CANON_UNITS_MM)|N00001 SELECT_PLANE(CANON_PLANE_XY)|"
           "N00001 SET_G5X_OFFSET(1, 10.0000, 20.0000, 0.0000, 0.0000)|"
           "N00001 STRAIGHT_TRAVERSE(1.0000, 2.0000, 0.0000, 0.0000)|"
           "N00002 STRAIGHT_TRAVERSE(1.0000, 2.0000, 0.0000, 0.0000)|"
           "N00003 SET_G5X_OFFSET(2, 0.0000, 0.0000, 0.0000, 0.0000)|"
           "N00003 STRAIGHT_TRAVERSE(0.0000, 22.0000, 0.0000, 0.0000)";
    // G20: X1 is 25.4 mm at the machine, 1 in the program's inches.
    QTest::newRow("G20") << "G20 G0 X1 Y0.5\n"
                         << ""
                         << ""
                         << "N00001 USE_LENGTH_UNITS(CANON_UNITS_INCHES)|"
                            "N00001 SELECT_PLANE(CANON_PLANE_XY)|"
                            "N00001 STRAIGHT_TRAVERSE(1.0000, 0.5000, 0.0000, 0.0000)";
    QTest::newRow("G91") << "G91 G0 X5\nG0 X5 Z-2\n"
                         << ""
                         << ""
                         << kFrame + "N00001 STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000, 0.0000)|"
                                     "N00002 STRAIGHT_TRAVERSE(10.0000, 0.0000, -2.0000, 0.0000)";
    // Centre at X15 Y10, clockwise: rotation -1; Z (the plane's third axis) then A.
    QTest::newRow("G2") << "G0 X10 Y10\nG2 X20 Y10 I5 J0 F100\n"
                        << ""
                        << ""
                        << kFrame + "N00001 STRAIGHT_TRAVERSE(10.0000, 10.0000, 0.0000, 0.0000)|"
                                    "N00002 SET_FEED_RATE(100.0000)|"
                                    "N00002 ARC_FEED(20.0000, 10.0000, 15.0000, 10.0000, -1, "
                                    "0.0000, 0.0000)";
    // Two full turns counter-clockwise down to Z-2: a helix.
    QTest::newRow("G3 helix P2")
        << "G0 X10 Y10\nG3 X10 Y10 Z-2 I5 J0 P2 F100\n"
        << ""
        << ""
        << kFrame + "N00001 STRAIGHT_TRAVERSE(10.0000, 10.0000, 0.0000, 0.0000)|"
                    "N00002 SET_FEED_RATE(100.0000)|"
                    "N00002 ARC_FEED(10.0000, 10.0000, 15.0000, 10.0000, 2, -2.0000, 0.0000)";
    // G18: LinuxCNC's first axis is Z, the second X; the third (axis_end_point) Y.
    QTest::newRow("G18 G2")
        << "G18 G0 X10 Z-10\nG2 X20 Z-10 I5 K0 F100\n"
        << ""
        << ""
        << "N00001 USE_LENGTH_UNITS(CANON_UNITS_MM)|N00001 SELECT_PLANE(CANON_PLANE_XZ)|"
           "N00001 STRAIGHT_TRAVERSE(10.0000, 0.0000, -10.0000, 0.0000)|"
           "N00002 SET_FEED_RATE(100.0000)|"
           "N00002 ARC_FEED(-10.0000, 20.0000, -10.0000, 15.0000, -1, 0.0000, 0.0000)";
    // G81 in G98 from Z-1: X Y at Z-1, down to R-2 fast, to Z-5 at F, back to Z-1 fast.
    QTest::newRow("G81") << "G0 X10 Y10 Z-1\nG81 X20 Y20 Z-5 R-2 F100\n"
                         << ""
                         << ""
                         << kFrame + "N00001 STRAIGHT_TRAVERSE(10.0000, 10.0000, -1.0000, 0.0000)|"
                                     "N00002 SET_FEED_RATE(100.0000)|"
                                     "N00002 STRAIGHT_TRAVERSE(20.0000, 20.0000, -1.0000, 0.0000)|"
                                     "N00002 STRAIGHT_TRAVERSE(20.0000, 20.0000, -2.0000, 0.0000)|"
                                     "N00002 STRAIGHT_FEED(20.0000, 20.0000, -5.0000, 0.0000)|"
                                     "N00002 STRAIGHT_TRAVERSE(20.0000, 20.0000, -1.0000, 0.0000)";
    // G82's dwell at the bottom. The hole is where X Y stand: DrillCycle lays no move of
    // nothing (LinuxCNC's interpreter would print that traverse to where the tool is).
    QTest::newRow("G82") << "G0 X10 Y10 Z-1\nG82 X10 Y10 Z-5 R-2 P0.5 F100\n"
                         << ""
                         << ""
                         << kFrame + "N00001 STRAIGHT_TRAVERSE(10.0000, 10.0000, -1.0000, 0.0000)|"
                                     "N00002 SET_FEED_RATE(100.0000)|"
                                     "N00002 STRAIGHT_TRAVERSE(10.0000, 10.0000, -2.0000, 0.0000)|"
                                     "N00002 STRAIGHT_FEED(10.0000, 10.0000, -5.0000, 0.0000)|"
                                     "N00002 DWELL(0.5000)|"
                                     "N00002 STRAIGHT_TRAVERSE(10.0000, 10.0000, -1.0000, 0.0000)";
    // G92 X0 at machine X10: the offset is 10; X5 then goes to machine 15, program 5.
    QTest::newRow("G92") << "G0 X10\nG92 X0\nG0 X5\nG92.1\n"
                         << ""
                         << ""
                         << kFrame + "N00001 STRAIGHT_TRAVERSE(10.0000, 0.0000, 0.0000, 0.0000)|"
                                     "N00002 SET_G92_OFFSET(10.0000, 0.0000, 0.0000, 0.0000)|"
                                     "N00003 STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000, 0.0000)|"
                                     "N00004 SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000)";
    // G92.2 suspends the offset (the frame without it), G92.3 applies it again.
    QTest::newRow("G92.2 G92.3") << "G0 X10\nG92 X0\nG92.2\nG0 X20\nG92.3\n"
                                 << ""
                                 << ""
                                 << kFrame +
                                        "N00001 STRAIGHT_TRAVERSE(10.0000, 0.0000, 0.0000, 0.0000)|"
                                        "N00002 SET_G92_OFFSET(10.0000, 0.0000, 0.0000, 0.0000)|"
                                        "N00003 SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000)|"
                                        "N00004 STRAIGHT_TRAVERSE(20.0000, 0.0000, 0.0000, 0.0000)|"
                                        "N00005 SET_G92_OFFSET(10.0000, 0.0000, 0.0000, 0.0000)";
    // G10 L2 P1 writes G54's table: the frame of the blocks after it; X5 of the program is
    // then machine 12, still printed as 5.
    QTest::newRow("G10 L2") << "G10 L2 P1 X7\nG0 X5\n"
                            << ""
                            << ""
                            << kFrame + "N00001 SET_G5X_OFFSET(1, 7.0000, 0.0000, 0.0000, 0.0000)|"
                                        "N00002 STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000, 0.0000)";
    // In G20 the offsets are printed in inches too: G54's X 25.4 mm is 1 in.
    QTest::newRow("G20 offsets")
        << "G20 G0 X1\n"
        << "X=25.4"
        << ""
        << "N00001 USE_LENGTH_UNITS(CANON_UNITS_INCHES)|N00001 SELECT_PLANE(CANON_PLANE_XY)|"
           "N00001 SET_G5X_OFFSET(1, 1.0000, 0.0000, 0.0000, 0.0000)|"
           "N00001 STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000)";
    QTest::newRow("M64 M65 M66") << "M64 P1\nM65 P1\nM66 P2 L4 Q2.5\n"
                                 << ""
                                 << ""
                                 << kFrame + "N00001 SET_AUX_OUTPUT_BIT(1)|"
                                             "N00002 CLEAR_AUX_OUTPUT_BIT(1)|"
                                             "N00003 WAIT(2, 1, 4, 2.5000)";
    // Tool 1 is 10 long: Z-20 of the program is machine Z-10, printed as the program's -20.
    QTest::newRow("M6 G43") << "T1 M6\nG43 H1\nG0 Z-20\n"
                            << ""
                            << "1 10"
                            << kFrame +
                                   "N00001 CHANGE_TOOL(1)|"
                                   "N00002 USE_TOOL_LENGTH_OFFSET(0.0000, 0.0000, 10.0000, 0.0000)|"
                                   "N00003 STRAIGHT_TRAVERSE(0.0000, 0.0000, -20.0000, 0.0000)";
    QTest::newRow("G93") << "G93 G1 X10 F2\nG94 G1 X20 F100\n"
                         << ""
                         << ""
                         << kFrame + "N00001 SET_FEED_MODE(0, 1)|N00001 SET_FEED_RATE(2.0000)|"
                                     "N00001 STRAIGHT_FEED(10.0000, 0.0000, 0.0000, 0.0000)|"
                                     "N00002 SET_FEED_MODE(0, 0)|N00002 SET_FEED_RATE(100.0000)|"
                                     "N00002 STRAIGHT_FEED(20.0000, 0.0000, 0.0000, 0.0000)";
    QTest::newRow("spindle coolant dwell")
        << "M3 S1000\nM8\nM7\nG4 P1.5\nM9\nM4\nS2000\nM5\n"
        << ""
        << ""
        << kFrame + "N00001 SET_SPINDLE_SPEED(0, 1000.0000)|N00001 START_SPINDLE_CLOCKWISE(0)|"
                    "N00002 FLOOD_ON()|N00003 MIST_ON()|N00004 DWELL(1.5000)|"
                    "N00005 MIST_OFF()|N00005 FLOOD_OFF()|"
                    "N00006 START_SPINDLE_COUNTERCLOCKWISE(0)|"
                    "N00007 SET_SPINDLE_SPEED(0, 2000.0000)|N00008 STOP_SPINDLE_TURNING(0)";
    // Issue 50 item 2: a line of several words runs in LinuxCNC's order of execution (feed,
    // speed, tool change, spindle, coolant, tool length, dwell, motion, stop), and the canonical
    // text shows that order.
    QTest::newRow("line: G0 Z-2 S10000 M3")
        << "G0 Z-2 S10000 M3\n"
        << ""
        << ""
        << kFrame + "N00001 SET_SPINDLE_SPEED(0, 10000.0000)|N00001 START_SPINDLE_CLOCKWISE(0)|"
                    "N00001 STRAIGHT_TRAVERSE(0.0000, 0.0000, -2.0000, 0.0000)";
    QTest::newRow("line: M5 M9") << "M3 S100\nM5 M9\n"
                                 << ""
                                 << ""
                                 << kFrame + "N00001 SET_SPINDLE_SPEED(0, 100.0000)|"
                                             "N00001 START_SPINDLE_CLOCKWISE(0)|"
                                             "N00002 STOP_SPINDLE_TURNING(0)|"
                                             "N00002 MIST_OFF()|N00002 FLOOD_OFF()";
    QTest::newRow("line: T1 M6 G43 H1")
        << "T1 M6 G43 H1\nG0 Z-20\n"
        << ""
        << "1 10"
        << kFrame + "N00001 CHANGE_TOOL(1)|"
                    "N00001 USE_TOOL_LENGTH_OFFSET(0.0000, 0.0000, 10.0000, 0.0000)|"
                    "N00002 STRAIGHT_TRAVERSE(0.0000, 0.0000, -20.0000, 0.0000)";
    QTest::newRow("line: G4 P1 G1 X5 F100")
        << "G4 P1 G1 X5 F100\n"
        << ""
        << ""
        << kFrame + "N00001 SET_FEED_RATE(100.0000)|N00001 DWELL(1.0000)|"
                    "N00001 STRAIGHT_FEED(5.0000, 0.0000, 0.0000, 0.0000)";
    QTest::newRow("line: G0 X1 M2")
        << "G0 X1 M2\n"
        << ""
        << ""
        << kFrame + "N00001 STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000)|"
                    "N00001 STOP_SPINDLE_TURNING(0)|N00001 MIST_OFF()|N00001 FLOOD_OFF()|"
                    "N00001 PROGRAM_END()";
    QTest::newRow("M0 M1 MSG G28")
        << "(MSG, Clamp the part)\nM0\nM1\nG28 X0 Y0\n"
        << ""
        << ""
        << kFrame + "N00001 MESSAGE(\"Clamp the part\")|N00002 PROGRAM_STOP()|"
                    "N00003 OPTIONAL_PROGRAM_STOP()|N00004 REFERENCE_AXES(X, Y)";
}

void TestProgramLowering::canon_blockKinds_asWorkedOutByHand()
{
    QFETCH(QString, program);
    QFETCH(QString, g54);
    QFETCH(QString, tool);
    QFETCH(QString, expected);
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("X=0 Y=0 Z=0 A=0");
    facts.coordinateSystems[0] = positions(g54);
    if (!tool.isEmpty()) {
        const QStringList t = tool.split(' ');
        facts.tools.insert(Tool{t.at(0).toInt(), t.at(1).toDouble(), 0, {}});
    }
    QStringList errors;
    const QStringList lines = canonOf(program, facts, &errors);
    QCOMPARE(calls(lines).join('|'), expected);
}

// Issue 50's features in the canonical text, each worked out by hand on the mill (X 0..100,
// Y 0..200, Z -50..0 mm, all at 0). --canon prints the program's reading, as LinuxCNC's
// interpreter does: the machine's limits (a feed above the highest, a laser's M4 run as M3)
// apply after it, at the executors, and the check's notes name them (docs/cli.md).
void TestProgramLowering::canon_issue50Features_asWorkedOutByHand_data()
{
    QTest::addColumn<QString>("machine"); // "mill", "touchOff" (tool 1 of length 10), "laser"
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("expected");

    // Item 1: F100000 is far above what the contour stream runs; the text keeps F100000 (the
    // check notes the F it runs at).
    QTest::newRow("1 limits: F above the highest")
        << "mill"
        << "G1 X10 F100000\n"
        << kFrame + "N00001 SET_FEED_RATE(100000.0000)|"
                    "N00001 STRAIGHT_FEED(10.0000, 0.0000, 0.0000, 0.0000)";
    // Item 3: "%", the program number, and the G0 after M2 that is never read.
    QTest::newRow("3 around the program")
        << "mill"
        << "%\nO1234 (NAME)\nG0 X1\nM2\nG0 X5\n%\n"
        << QStringLiteral("N00003 USE_LENGTH_UNITS(CANON_UNITS_MM)|"
                          "N00003 SELECT_PLANE(CANON_PLANE_XY)|"
                          "N00003 STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000)|"
                          "N00004 STOP_SPINDLE_TURNING(0)|N00004 MIST_OFF()|"
                          "N00004 FLOOD_OFF()|N00004 PROGRAM_END()");
    // Item 4, touch-off: G43 H1 is told with no length: the table's 10 mm is not added (Z was
    // set for the tool by hand).
    QTest::newRow("4 touch-off: G43 adds nothing")
        << "touchOff"
        << "T1 M6\nG43 H1\nG0 Z-20\n"
        << kFrame + "N00001 CHANGE_TOOL(1)|"
                    "N00002 USE_TOOL_LENGTH_OFFSET(0.0000, 0.0000, 0.0000, 0.0000)|"
                    "N00003 STRAIGHT_TRAVERSE(0.0000, 0.0000, -20.0000, 0.0000)";
    // Item 5: the program's M4 as written (the laser's executor switches the beam as M3).
    QTest::newRow("5 laser M4")
        << "laser"
        << "M4 S500\nM5\n"
        << kFrame + "N00001 SET_SPINDLE_SPEED(0, 500.0000)|"
                    "N00001 START_SPINDLE_COUNTERCLOCKWISE(0)|N00002 STOP_SPINDLE_TURNING(0)";
    // Item 6: block delete on (LinuxCNC's default) skips line 1; @10 ^90 is X0 Y10; $H
    // references every axis, $32=1 is not run.
    QTest::newRow("6 block delete")
        << "mill"
        << "/G0 X5\nG0 X1\n"
        << QStringLiteral("N00002 USE_LENGTH_UNITS(CANON_UNITS_MM)|"
                          "N00002 SELECT_PLANE(CANON_PLANE_XY)|"
                          "N00002 STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000)");
    QTest::newRow("6 polar") << "mill"
                             << "G0 @10 ^90\nG0 @5 ^0\n"
                             << kFrame +
                                    "N00001 STRAIGHT_TRAVERSE(0.0000, 10.0000, 0.0000, 0.0000)|"
                                    "N00002 STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000, 0.0000)";
    QTest::newRow("6 GRBL $ lines")
        << "mill"
        << "$H\n$32=1\nG0 X1\n"
        << kFrame + "N00001 REFERENCE_AXES(X, Y, Z, A)|"
                    "N00003 STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000)";
    // Item 8: K0 on a G17 arc is no offset at all: the arc of the "G2" row.
    QTest::newRow("8 K0 on a G17 arc")
        << "mill"
        << "G0 X10 Y10\nG2 X20 Y10 I5 J0 K0.000 F100\n"
        << kFrame + "N00001 STRAIGHT_TRAVERSE(10.0000, 10.0000, 0.0000, 0.0000)|"
                    "N00002 SET_FEED_RATE(100.0000)|"
                    "N00002 ARC_FEED(20.0000, 10.0000, 15.0000, 10.0000, -1, 0.0000, "
                    "0.0000)";
    // Item 9: a return with a value inside the sub's if (#<_value> = 3 x 2), EXISTS of a named
    // parameter that is set (Y5) and of one that is not (no Y7).
    QTest::newRow("9 language: return in an if, EXISTS")
        << "mill"
        << "o100 sub\n  o101 if [#1 GT 0]\n    o100 return [#1 * 2]\n  o101 endif\n"
           "  o100 return [0]\no100 endsub\no100 call [3]\nG0 X#<_value>\n#<set> = 1\n"
           "o102 if [EXISTS[#<set>]]\n  G0 Y5\no102 endif\n"
           "o103 if [EXISTS[#<unset>]]\n  G0 Y7\no103 endif\nM2\n"
        << QStringLiteral("N00008 USE_LENGTH_UNITS(CANON_UNITS_MM)|"
                          "N00008 SELECT_PLANE(CANON_PLANE_XY)|"
                          "N00008 STRAIGHT_TRAVERSE(6.0000, 0.0000, 0.0000, 0.0000)|"
                          "N00011 STRAIGHT_TRAVERSE(6.0000, 5.0000, 0.0000, 0.0000)|"
                          "N00016 STOP_SPINDLE_TURNING(0)|N00016 MIST_OFF()|"
                          "N00016 FLOOD_OFF()|N00016 PROGRAM_END()");
}

void TestProgramLowering::canon_issue50Features_asWorkedOutByHand()
{
    QFETCH(QString, machine);
    QFETCH(QString, program);
    QFETCH(QString, expected);
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("X=0 Y=0 Z=0 A=0");
    if (machine == QLatin1String("touchOff")) {
        facts.description.toolLength = machine::ToolLength::TouchOff;
        facts.tools.insert(Tool{1, 10, 0, {}});
    }
    if (machine == QLatin1String("laser"))
        facts.description.spindle.laser = true;
    Program p;
    const QByteArray text = program.toUtf8();
    if (ProgramExpansion::usesLanguage(text)) { // worked out first, as the CLI reads it
        QList<ProgramError> errors;
        const auto expanded =
            ProgramExpansion::expand(ProgramSource::bytes(text), NgcContext{}, &errors);
        QVERIFY2(expanded, qPrintable(texts(errors).join('\n')));
        ProgramReader reader(expanded->source, {"X", "Y", "Z", "A"}, expanded->info->lines);
        const std::optional<Program> parsedProgram = reader.finish(&errors);
        QVERIFY2(parsedProgram, qPrintable(texts(errors).join('\n')));
        p = *parsedProgram;
        p.expansion = expanded->info;
    } else {
        p = parsed(program, facts);
    }
    CanonText canon(facts.description);
    QStringList out;
    const ProgramCheckResult result = ProgramCheck::check(
        p, facts, 1, {}, [&](const motion::MotionCommand& c) { out << canon.lines(c); });
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    QCOMPARE(calls(out).join('|'), expected);
}

// "    3 N00002 STRAIGHT_TRAVERSE(...)": the sequence right-aligned in five, the program's line
// in five digits; commands of no program line (none in a program today) would say "N.....".
void TestProgramLowering::canon_lines_numberedWithTheProgramLine()
{
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("X=0 Y=0 Z=0 A=0");
    QStringList errors;
    const QStringList lines = canonOf("G0 X1\n\nG0 X2\n", facts, &errors);
    QCOMPARE(lines.size(), 4);
    QCOMPARE(lines.at(2),
             QStringLiteral("    3 N00001 STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000)"));
    QCOMPARE(lines.at(3),
             QStringLiteral("    4 N00003 STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000, 0.0000)"));

    CanonText canon(facts.description);
    QCOMPARE(canon.lines(motion::Dwell{0, 1.0}),
             QStringList{QStringLiteral("    1 N..... DWELL(1.0000)")});
}

// A relative move from an axis whose position is unknown: the check allows it, the lowering
// cannot say where it ends, and the text says so.
void TestProgramLowering::canon_relativeFromUnknown_questionMarks()
{
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("Y=0 Z=0 A=0");
    QStringList errors;
    const QStringList lines = canonOf("G91 G0 X5 Y1\n", facts, &errors);
    QCOMPARE(calls(lines).join('|'),
             kFrame + "N00001 STRAIGHT_TRAVERSE(?, 1.0000, 0.0000, 0.0000)");
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
}

// An arc whose end is not on its circle: the check names it, the lowering lays no motion.
void TestProgramLowering::lower_arcThatCannotBeLaid_errorAndNoMotion()
{
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("X=0 Y=0 Z=0 A=0");
    ProgramLowering lowering(facts.description);
    const Program p = parsed("G0 X10 Y10\nG2 X30 Y10 I5 J0 F100\n", facts);
    ProgramReader reader(p);
    const ProgramBlock* arc = reader.at(1);
    QVERIFY(arc);
    std::vector<motion::MotionCommand> out;
    const auto error =
        lowering.lower(*arc, ProgramCoordinates{}, AxisPositions{10.0, 10.0, 0.0, 0.0}, &out);
    QVERIFY(error);
    QVERIFY2(!error->message.isEmpty(), "the arc's reason");
    for (const motion::MotionCommand& c : out)
        QVERIFY(!std::holds_alternative<motion::ArcFeed>(c));
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramLowering)
#include "tst_programlowering.moc"
