// Cutter radius compensation (issue 50 item 7, docs/programs.md "Cutter compensation"): the
// tool's path as the check's walk lowers it (the run takes the same blocks), worked out by hand
// on the machine "mill" (X 0..100, Y 0..200 mm) with G54 at X50 Y50 so that the paths lie
// inside the soft limits; and what LinuxCNC refuses, refused with its line.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/CanonText.h"
#include "program/MdiSession.h"
#include <QRandomGenerator>
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

namespace {

MachineFacts millAt5050()
{
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("X=50 Y=50 Z=0 A=0");
    facts.coordinateSystems[0] = positions("X=50 Y=50");
    facts.tools.insert(Tool{1, 0, 6, QStringLiteral("6 mm end mill")});
    return facts;
}

// The calls of the canonical text (without sequence numbers), and the check's errors.
QStringList canonCalls(const QString& program, const MachineFacts& facts, QStringList* errors,
                       ProgramPreview* preview = nullptr)
{
    CanonText canon(facts.description);
    QStringList out;
    const ProgramCheckResult result = ProgramCheck::check(
        parsed(program, facts), facts, 1, {}, [&](const motion::MotionCommand& c) {
            for (const QString& line : canon.lines(c))
                out << line.section(QLatin1Char(' '), 1, -1, QString::SectionSkipEmpty);
        });
    *errors = texts(result.errors);
    if (preview)
        *preview = result.preview;
    return out;
}

// The square of lines 4..6 (0,0) (0,20) (20,20) (20,0), entered along +X from X-10, G41 with a
// tool of 4 mm: the tool 2 mm to the left of the path.
// - Line 3, the entry, ends where the line from (-10,0) touches the circle of 2 about (0,0):
//   (-0.4, 1.9596); the corner to line 4 (+Y) turns left, towards the tool: inside, so the
//   entry ends where it meets line 4's path X-2: Y = 8 x 1.9596 / 9.6 = 1.6330.
// - Line 4 runs up X-2 to Y20; the corner to line 5 turns right: outside, so line 5 first goes
//   round (0,20) clockwise from (-2,20) to (0,22), then along Y22 to X20; the same round
//   (20,20) to (22,20), then down X22 to Y0 (G40 follows: no corner).
// - Line 7 (G40) goes from the tool at (22,0) to X30 Y0.
const QString kSquare = QStringLiteral("G0 X-10 Y0\nG41.1 D4\nG1 X0 Y0 F100\nG1 X0 Y20\n"
                                       "G1 X20 Y20\nG1 X20 Y0\nG40 G1 X30 Y0\nM2\n");
const QString kSquareCanon =
    QStringLiteral("N00001 STRAIGHT_TRAVERSE(-10.0000, 0.0000, 0.0000, 0.0000)|"
                   "N00003 SET_FEED_RATE(100.0000)|"
                   "N00003 STRAIGHT_FEED(-2.0000, 1.6330, 0.0000, 0.0000)|"
                   "N00004 STRAIGHT_FEED(-2.0000, 20.0000, 0.0000, 0.0000)|"
                   "N00005 ARC_FEED(0.0000, 22.0000, 0.0000, 20.0000, -1, 0.0000, 0.0000)|"
                   "N00005 STRAIGHT_FEED(20.0000, 22.0000, 0.0000, 0.0000)|"
                   "N00006 ARC_FEED(22.0000, 20.0000, 20.0000, 20.0000, -1, 0.0000, 0.0000)|"
                   "N00006 STRAIGHT_FEED(22.0000, 0.0000, 0.0000, 0.0000)|"
                   "N00007 STRAIGHT_FEED(30.0000, 0.0000, 0.0000, 0.0000)|");

} // namespace

class TestCutterCompensation : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void canon_toolPath_asWorkedOutByHand_data();
    void canon_toolPath_asWorkedOutByHand();
    void preview_extents_followTheToolNotTheProgram();
    void onePass_languageProgram_sameToolPath();
    void check_refusals_namedAtTheirLine_data();
    void check_refusals_namedAtTheirLine();
    void mdi_g41_refusedInMdi();
    void randomPaths_checkEndsFinite();
};

void TestCutterCompensation::canon_toolPath_asWorkedOutByHand_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("expected");

    QTest::newRow("square G41.1 D4")
        << kSquare
        << kSquareCanon + "N00008 STOP_SPINDLE_TURNING(0)|N00008 MIST_OFF()|"
                          "N00008 FLOOD_OFF()|N00008 PROGRAM_END()";
    // The same square written in G91 (its moves from the programmed point, not the tool's),
    // with a plunge between the entry and the square: the plunge stays where the entry put the
    // tool, and the entry's corner is with line 5 (the next move in X or Y).
    QTest::newRow("square G91 with a plunge")
        << "G0 X-10 Y0\nG91 G41.1 D4\nG1 X10 F100\nG1 Z-1\nG1 Y20\nG1 X20\nG1 Y-20\nG40 G1 X10\n"
        << "N00001 STRAIGHT_TRAVERSE(-10.0000, 0.0000, 0.0000, 0.0000)|"
           "N00003 SET_FEED_RATE(100.0000)|"
           "N00003 STRAIGHT_FEED(-2.0000, 1.6330, 0.0000, 0.0000)|"
           "N00004 STRAIGHT_FEED(-2.0000, 1.6330, -1.0000, 0.0000)|"
           "N00005 STRAIGHT_FEED(-2.0000, 20.0000, -1.0000, 0.0000)|"
           "N00006 ARC_FEED(0.0000, 22.0000, 0.0000, 20.0000, -1, -1.0000, 0.0000)|"
           "N00006 STRAIGHT_FEED(20.0000, 22.0000, -1.0000, 0.0000)|"
           "N00007 ARC_FEED(22.0000, 20.0000, 20.0000, 20.0000, -1, -1.0000, 0.0000)|"
           "N00007 STRAIGHT_FEED(22.0000, 0.0000, -1.0000, 0.0000)|"
           "N00008 STRAIGHT_FEED(30.0000, 0.0000, -1.0000, 0.0000)";
    // G40 and G41 again with no move between: the tool stands at (22,0), the program at (20,0).
    // The new entry is laid from the programmed point, as LinuxCNC's current point after G40:
    // from (20,0) to (30,0) it touches the circle of 2 at (29.6, 1.9596) (from the tool's
    // (22,0) it would be (29.5, 1.9365)); G40 then leaves to (40,0).
    QTest::newRow("G40 then G41 without a move")
        << "G0 X-10 Y0\nG41.1 D4\nG1 X0 Y0 F100\nG1 X0 Y20\nG1 X20 Y20\nG1 X20 Y0\nG40\n"
           "G41.1 D4\nG1 X30 Y0\nG40 G1 X40 Y0\n"
        << kSquareCanon.section('|', 0, 7) +
               "|N00009 STRAIGHT_FEED(29.6000, 1.9596, 0.0000, 0.0000)|"
               "N00010 STRAIGHT_FEED(40.0000, 0.0000, 0.0000, 0.0000)";
    // A circle of radius 10 about (0,0) counter-clockwise with the tool (4 mm) on the left:
    // inside, on a circle of 8. The entry from (0,0) along +X touches the circle of 2 about
    // (10,0) at (9.6, 1.9596); the arc turns left at (10,0): inside, so the entry ends where
    // its line meets the circle of 8: 8 x (0.9798, 0.2) = (7.8384, 1.6). The arc runs from
    // there round to (8,0), where G40 follows.
    QTest::newRow("circle inside G41.1")
        << "G0 X0 Y0\nG41.1 D4\nG1 X10 Y0 F100\nG3 X10 Y0 I-10 J0\nG40 G1 X0 Y0\n"
        << "N00001 STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000)|"
           "N00003 SET_FEED_RATE(100.0000)|"
           "N00003 STRAIGHT_FEED(7.8384, 1.6000, 0.0000, 0.0000)|"
           "N00004 ARC_FEED(8.0000, 0.0000, 0.0000, 0.0000, 1, 0.0000, 0.0000)|"
           "N00005 STRAIGHT_FEED(0.0000, 0.0000, 0.0000, 0.0000)";
    // G42 with the table's tool 1 (6 mm, loaded by M6): the tool 3 mm to the right of +X.
    // The entry from (-10,0) to (0,0): alpha = pi, theta = acos(0.3); the point
    // (3 cos(pi + theta), 3 sin(pi + theta)) = (-0.9, -2.8618). G40 on the next line: the
    // exit from there to (10, 0).
    QTest::newRow("G42 tool table") << "T1 M6\nG0 X-10 Y0\nG42\nG1 X0 F100\nG40\nG1 X10\n"
                                    << "N00001 CHANGE_TOOL(1)|"
                                       "N00002 STRAIGHT_TRAVERSE(-10.0000, 0.0000, 0.0000, 0.0000)|"
                                       "N00004 SET_FEED_RATE(100.0000)|"
                                       "N00004 STRAIGHT_FEED(-0.9000, -2.8618, 0.0000, 0.0000)|"
                                       "N00006 STRAIGHT_FEED(10.0000, 0.0000, 0.0000, 0.0000)";
    // A G0 round an outside corner goes straight to the next line's start (no arc): from
    // (-2,20) to the end of the rapid's offset line, (20,22).
    QTest::newRow("G0 outside corner")
        << "G0 X-10 Y0\nG41.1 D4\nG1 X0 Y0 F100\nG1 X0 Y20\nG0 X20 Y20\nG40 G0 X30 Y30\n"
        << "N00001 STRAIGHT_TRAVERSE(-10.0000, 0.0000, 0.0000, 0.0000)|"
           "N00003 SET_FEED_RATE(100.0000)|"
           "N00003 STRAIGHT_FEED(-2.0000, 1.6330, 0.0000, 0.0000)|"
           "N00004 STRAIGHT_FEED(-2.0000, 20.0000, 0.0000, 0.0000)|"
           "N00005 STRAIGHT_TRAVERSE(20.0000, 22.0000, 0.0000, 0.0000)|"
           "N00006 STRAIGHT_TRAVERSE(30.0000, 30.0000, 0.0000, 0.0000)";
}

void TestCutterCompensation::canon_toolPath_asWorkedOutByHand()
{
    QFETCH(QString, program);
    QFETCH(QString, expected);
    QStringList errors;
    const QStringList calls = canonCalls(program, millAt5050(), &errors);
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
    QStringList motion;
    for (const QString& c : calls)
        if (!c.contains(QLatin1String("USE_LENGTH_UNITS")) &&
            !c.contains(QLatin1String("SELECT_PLANE")) && !c.contains(QLatin1String("G5X")))
            motion << c;
    QCOMPARE(motion.join('|'), expected);
}

// The preview draws the tool's path: the square's tool reaches Y22 (the program Y20) and X-10
// at its start, X30 at its end, in work coordinates.
void TestCutterCompensation::preview_extents_followTheToolNotTheProgram()
{
    QStringList errors;
    ProgramPreview preview;
    canonCalls(kSquare, millAt5050(), &errors, &preview);
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
    QCOMPARE(preview.extents.value("Y").maximum, 22.0);
    QCOMPARE(preview.extents.value("Y").minimum, 0.0);
    QCOMPARE(preview.extents.value("X").minimum, -10.0);
    QCOMPARE(preview.extents.value("X").maximum, 30.0);
}

// The one pass over a source (the window's and the CLI's check), here of a LinuxCNC-language
// program worked out first, with 5000 comment lines between the entry and the square: the look
// ahead reads on past the reader's window and the walk reads its blocks again; the same path.
void TestCutterCompensation::onePass_languageProgram_sameToolPath()
{
    QString text = QStringLiteral("#<d> = 4\nG0 X-10 Y0\nG41.1 D[#<d>]\nG1 X0 Y0 F100\n");
    for (int i = 0; i < 5000; ++i)
        text += QStringLiteral("(between)\n");
    text += QStringLiteral("G1 X0 Y20\nG1 X20 Y20\nG1 X20 Y0\nG40 G1 X30 Y0\nM2\n");
    const ProgramCheckResult result = ProgramCheck::check(ProgramSource::bytes(text.toUtf8()),
                                                          {"X", "Y", "Z", "A"}, millAt5050());
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    QCOMPARE(result.preview.extents.value("Y").maximum, 22.0);
    QCOMPARE(result.preview.extents.value("X").maximum, 30.0);
    QCOMPARE(result.preview.extents.value("X").minimum, -10.0);
    // The entry's end, cut back to X-2 at Y1.633 (work coordinates), is on the path (to the
    // step the board holds: 100 steps/mm).
    bool entry = false;
    for (const PreviewPoint& p : result.preview.path)
        entry = entry || (std::abs(p.position.value("X") + 2) < 1e-9 &&
                          std::abs(p.position.value("Y") - 1.633) <= 0.005);
    QVERIFY(entry);
}

void TestCutterCompensation::check_refusals_namedAtTheirLine_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("expected"); // the first error: "line:column: ..." starts so

    const QString entry = QStringLiteral("G0 X-10 Y0\nG41.1 D4\nG1 X0 Y0 F100\n");
    QTest::newRow("on twice") << "G41.1 D4\nG42.1 D4\n"
                              << "2:1: G42.1: cutter compensation is on";
    QTest::newRow("G18") << "G18\nG41.1 D4\n"
                         << "2:1: G41.1: cutter compensation works in the XY";
    QTest::newRow("no D, no tool") << "G41\n"
                                   << "1:1: G41 needs D<tool>";
    QTest::newRow("G41.1 without D") << "G41.1\n"
                                     << "1:1: G41.1 needs D";
    QTest::newRow("D with G40") << "G40 D1\n"
                                << "1:5: ";
    QTest::newRow("arc entry") << "G41.1 D4\nG2 X10 Y0 I5 J0 F100\n"
                               << "2:1: G2 enters cutter compensation";
    QTest::newRow("arc exit") << entry + "G40\nG3 X10 Y10 I5 J5\n"
                              << "5:1: G3 leaves cutter compensation";
    QTest::newRow("M6") << entry + "T1 M6\n"
                        << "4:4: M6 with cutter compensation on";
    QTest::newRow("G28") << entry + "G28\n"
                         << "4:1: G28 with cutter compensation on";
    QTest::newRow("G92") << entry + "G92 X0\n"
                         << "4:1: G92 changes the offsets";
    QTest::newRow("G55") << entry + "G55\n"
                         << "4:1: the coordinate system cannot change";
    QTest::newRow("G20") << entry + "G20\n"
                         << "4:1: the units cannot change";
    QTest::newRow("G53") << entry + "G53 G0 X0\n"
                         << "4:5: G53 with cutter compensation on";
    QTest::newRow("drilling") << entry + "G81 X5 Y5 Z-1 R1\n"
                              << "4:1: a drilling cycle with";
    QTest::newRow("repeat") << entry + "O1 repeat [2]\nO1 endrepeat\n"
                            << "4:1: O1 with cutter";
    QTest::newRow("tool not in the table") << "G41 D7\nG1 X10 F100\n"
                                           << "2:1: cutter compensation: tool 7 is not in";
    QTest::newRow("entry too short") << "G41.1 D4\nG1 X1 F100\n"
                                     << "2:1: cutter compensation: the entry move (1)";
    // A circle of 10 with a tool of 24 inside it.
    QTest::newRow("tool larger than the arc")
        << "G0 X-30 Y0\nG41.1 D24\nG1 X10 Y0 F100\nG3 X10 Y0 I-10 J0\n"
        << "4:1: cutter compensation: the tool's radius (12) is not less than the arc's (10)";
    // A slot 1 mm wide for a tool of 4: the inside corner at (10,0) lies past line 5's end.
    QTest::newRow("inside corner too tight")
        << entry + "G1 X10 Y0\nG1 X10 Y1\nG1 X0 Y1\n"
        << "4:1: cutter compensation: the tool (diameter 4) cannot reach the inside corner of "
           "lines 4 and 5";
    QTest::newRow("run from inside") << entry + "G1 X0 Y20\nG40 G1 X-10\n"
                                     << "";
}

void TestCutterCompensation::check_refusals_namedAtTheirLine()
{
    QFETCH(QString, program);
    QFETCH(QString, expected);
    const MachineFacts facts = millAt5050();
    QStringList names{"X", "Y", "Z", "A"};
    QList<ProgramError> parseErrors;
    const std::optional<Program> p = ProgramParser::parse(program.toUtf8(), names, &parseErrors);
    QStringList errors = texts(parseErrors);
    if (p) {
        const int fromLine = QByteArray(QTest::currentDataTag()) == "run from inside" ? 4 : 1;
        errors = texts(ProgramCheck::check(*p, facts, fromLine).errors);
        if (fromLine == 4) {
            QCOMPARE(errors.size(), 1);
            QVERIFY2(errors.first().contains("cutter compensation (G41/G42) is on there"),
                     qPrintable(errors.first()));
            return;
        }
    }
    QVERIFY2(!errors.isEmpty(), "no error");
    QVERIFY2(errors.first().startsWith(expected), qPrintable(errors.join('\n')));
}

void TestCutterCompensation::mdi_g41_refusedInMdi()
{
    MdiSession mdi;
    QList<ProgramError> errors;
    QVERIFY(!mdi.prepare(QStringLiteral("G41.1 D4"), {"X", "Y", "Z"}, &errors));
    QCOMPARE(errors.size(), 1);
    QVERIFY2(errors.first().message.contains("not in MDI"), qPrintable(errors.first().message));
    QVERIFY(mdi.prepare(QStringLiteral("G40"), {"X", "Y", "Z"}, &errors)); // off: fine
}

// Degenerate geometry must end in a path or an error, never a hang or a position that is not a
// number: 1000 programs from a fixed seed (about 30 s under ASan), G41 or G42 with tools from 0 to
// 12 mm, lines and arcs (some of no length, reversals, full circles, tiny and huge radii) in G90
// and G91.
void TestCutterCompensation::randomPaths_checkEndsFinite()
{
    const MachineFacts facts = millAt5050();
    QRandomGenerator rng(50007);
    const auto coordinate = [&rng] { return double(int(rng.bounded(41)) - 20) / 2; };
    int ok = 0;
    int refused = 0;
    for (int n = 0; n < 1000; ++n) {
        QString text = QStringLiteral("G0 X0 Y0\nG%1.1 D%2\n")
                           .arg(rng.bounded(2) ? 41 : 42)
                           .arg(figure(double(rng.bounded(25)) / 2));
        text += QStringLiteral("G1 X%1 Y%2 F600\n").arg(coordinate()).arg(coordinate());
        for (int b = 0; b < 6; ++b) {
            const bool relative = rng.bounded(4) == 0;
            text += relative ? QStringLiteral("G91 ") : QStringLiteral("G90 ");
            switch (rng.bounded(4)) {
            case 0:
            case 1:
                text += QStringLiteral("G1 X%1 Y%2\n").arg(coordinate()).arg(coordinate());
                break;
            case 2:
                text += QStringLiteral("G1 Z%1\n").arg(relative ? 0.5 : -1.0);
                break;
            default:
                text += QStringLiteral("G%1 X%2 Y%3 I%4 J%5\n")
                            .arg(rng.bounded(2) ? 2 : 3)
                            .arg(coordinate())
                            .arg(coordinate())
                            .arg(coordinate())
                            .arg(coordinate());
                break;
            }
        }
        text += QStringLiteral("G90 G40 G1 X0 Y0\n");
        const ProgramCheckResult result =
            ProgramCheck::check(ProgramSource::bytes(text.toUtf8()), {"X", "Y", "Z", "A"}, facts);
        (result.ok() ? ok : refused) += 1;
        for (const PreviewPoint& p : result.preview.path)
            for (double v : p.position)
                QVERIFY2(std::isfinite(v), qPrintable(text));
    }
    // Both outcomes occur: the table exercises the geometry rather than one of its refusals.
    QVERIFY2(ok > 30 && refused > 30,
             qPrintable(QStringLiteral("%1 ok, %2 refused").arg(ok).arg(refused)));
}

STEPDECK_TEST_GUILESS_MAIN(TestCutterCompensation)
#include "tst_cuttercompensation.moc"
