// The check's preview (issue 20, docs/programs.md "Preview", "Coordinates"): its figures
// (extents, path, estimated time), its bounds over a million-pass repeat, and the work
// coordinates it and the check use (issue 28, item 3).
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

class TestProgramPreview : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void preview_figures_extentsPathAndEstimatedSeconds();
    void preview_millionPassRepeat_countedOutPathThinnedToTheEnd();
    void preview_arc_chordPointsWithinToleranceRapidsMarked();
    void preview_cycle_movesRapidsAndDwellTimed();
    void check_workOffsets_targetsInWorkLimitsInMachine_data();
    void check_workOffsets_targetsInWorkLimitsInMachine();
    void preview_softLimitErrors_pathKeptFlaggedWithErrors();
    void preview_parseErrorsOrRefusedStart_noPath();
    void preview_points_feedSecondsAndBlocksDoneAsTheRunnerCounts();
    void preview_thinnedPath_pointsKeepTheirFeedSecondsAndBlockCounts();
    void preview_issue50Features_pathAsWorkedOutByHand_data();
    void preview_issue50Features_pathAsWorkedOutByHand();
};

void TestProgramPreview::preview_figures_extentsPathAndEstimatedSeconds()
{
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("Z=-10");
    const Program p = parsed("G28 X0 Y0\n"   // no time known
                             "G0 X50 Y50\n"  // X 50 mm at 50 mm/s, Y at 5000/200 = 25 mm/s: 2 s
                             "G1 X60 F600\n" // 10 mm at 10 mm/s: 1 s
                             "G0\n"          // only the motion mode: no point, no time
                             "G4 P2\n"       // 2 s
                             "G91 G0 Y-10\n" // 10 mm at 25 mm/s: 0.4 s
                             "M30\n",
                             facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    const ProgramPreview& v = result.preview;
    QCOMPARE(v.lines, 7);
    QCOMPARE(v.blocksRun, qint64(7));
    QCOMPARE(v.estimatedSeconds, 5.4);
    QCOMPARE(v.extents.keys(), (QStringList{"X", "Y", "Z"})); // A never known
    QCOMPARE(v.extents["X"].minimum, 0.0);
    QCOMPARE(v.extents["X"].maximum, 60.0);
    QVERIFY(v.extents["X"].moved);
    QCOMPARE(v.extents["Y"].minimum, 0.0);
    QCOMPARE(v.extents["Y"].maximum, 50.0);
    QCOMPARE(v.extents["Z"].minimum, -10.0);
    QCOMPARE(v.extents["Z"].maximum, -10.0);
    QVERIFY(!v.extents["Z"].moved);
    QCOMPARE(v.path.size(), 6); // the start, G28, G0, G1, G4, G0
    QVERIFY(!v.pathDecimated);
    QCOMPARE(v.path.first().line, 0);
    QCOMPARE(v.path.first().position, (QMap<QString, double>{{"Z", -10}}));
    QCOMPARE(v.path.at(2).line, 2);
    QCOMPARE(v.path.at(2).seconds, 2.0);
    QCOMPARE(v.path.at(2).position, (QMap<QString, double>{{"X", 50}, {"Y", 50}, {"Z", -10}}));
    QCOMPARE(v.path.last().line, 6);
    QCOMPARE(v.path.last().seconds, 5.4);
    QCOMPARE(v.path.last().position, (QMap<QString, double>{{"X", 60}, {"Y", 40}, {"Z", -10}}));
    // How the machine's controllers follow F (issue 30): the E-LAB's streams and blocks.
    QVERIFY2(v.motionNote.startsWith("contours (G64) run on the path at F as one step stream; a "
                                     "block of its own (G61) moves each axis at its own rate"),
             qPrintable(v.motionNote));
}

void TestProgramPreview::preview_millionPassRepeat_countedOutPathThinnedToTheEnd()
{
    const MachineFacts facts = machineFacts("mill");
    const Program p =
        parsed("G28 X0\nG91\nO1 repeat [1000000]\n  G0 X1\n  G0 X-1\nO1 endrepeat", facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    QCOMPARE(result.preview.blocksRun, qint64(2 + 2000000));
    // The path is thinned, not cut (issue 29): within its bound, it still reaches the run's
    // end, in order, and its points stand on the run's positions (X 0 or 1).
    const QList<PreviewPoint>& path = result.preview.path;
    QVERIFY(path.size() <= ProgramPreview::kMaxPathPoints + 1);
    QVERIFY(path.size() > ProgramPreview::kMaxPathPoints / 2);
    QVERIFY(result.preview.pathDecimated);
    QCOMPARE(path.last().line, 5);
    QCOMPARE(path.last().position.value("X"), 0.0);
    QCOMPARE(path.last().seconds, result.preview.estimatedSeconds);
    for (qsizetype i = 1; i < path.size(); ++i) {
        QVERIFY(path.at(i).seconds >= path.at(i - 1).seconds);
        const double x = path.at(i).position.value("X");
        QVERIFY2(x == 0.0 || x == 1.0, qPrintable(QString::number(x)));
    }
    QVERIFY(path.at(path.size() / 2).seconds > result.preview.estimatedSeconds / 4);
    // 1 mm at 50 mm/s each, summed two million times.
    QVERIFY(qAbs(result.preview.estimatedSeconds - 2000000 * 1.0 / 50) < 1e-3);
    QCOMPARE(result.preview.extents["X"].maximum, 1.0);
}

// Issue 28, item 3: absolute targets are work coordinates (machine = work + offset), the soft
// limits machine coordinates; the preview's path and extents are work coordinates.
// An arc's path in the preview: every chord's end on the circle (work coordinates), the
// chords' middles within 0.01 mm of it, the extents at the curve's extremes, only G0's points
// marked rapid; its time from the chords (each axis at F: X at 100 steps/mm).
void TestProgramPreview::preview_arc_chordPointsWithinToleranceRapidsMarked()
{
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = {{"X", 0.0}, {"Y", 0.0}};
    facts.coordinateSystems[0] = {{"X", 20.0}, {"Y", 30.0}};
    const Program p = parsed("G0 X10 Y10\nG3 X10 Y10 I5 J0 F600\nG1 X0 F600\n", facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    const ProgramPreview& v = result.preview;
    QVERIFY(v.path.at(1).rapid);
    QCOMPARE(v.path.at(1).line, 1);
    QList<PreviewPoint> arc;
    for (const PreviewPoint& point : v.path)
        if (point.line == 2)
            arc << point;
    QVERIFY(arc.size() >= 50); // 2 acos(1 - 0.01 / 5) = 0.1265 rad a chord: 50 for the circle
    QPointF previous(10, 10);
    for (const PreviewPoint& point : arc) {
        QVERIFY(!point.rapid);
        const QPointF at(point.position.value("X"), point.position.value("Y"));
        QVERIFY(std::abs(std::hypot(at.x() - 15, at.y() - 10) - 5) < 0.006); // steps: 0.005
        const QPointF middle = (at + previous) / 2;
        QVERIFY(5 - std::hypot(middle.x() - 15, middle.y() - 10) <= 0.01 + 0.006);
        previous = at;
    }
    QCOMPARE(arc.last().position.value("X"), 10.0);
    QCOMPARE(arc.last().position.value("Y"), 10.0);
    QVERIFY(!v.path.last().rapid);
    // Machine 0 is work -20 / -30 (the start); X reaches 20 at the circle's right.
    QCOMPARE(v.extents["X"].minimum, -20.0);
    QCOMPARE(v.extents["X"].maximum, 20.0);
    QCOMPARE(v.extents["Y"].minimum, -30.0);
    QCOMPARE(v.extents["Y"].maximum, 15.0);
    // F600 = 10 mm/s an axis: the circle's chords take about its perimeter over the axis speed,
    // each chord as long as its longer axis; between 2 x 10 / 10 and 2 pi 5 / 10 seconds.
    const double arcSeconds = arc.last().seconds - v.path.at(1).seconds;
    QVERIFY2(arcSeconds > 2.0 && arcSeconds < 3.15, qPrintable(QString::number(arcSeconds)));
}

// A drilling cycle in the preview: a point per move, rapids marked, the feed at F and the
// dwell counted in the estimate; the current point after it is the retract level.
void TestProgramPreview::preview_cycle_movesRapidsAndDwellTimed()
{
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = {{"X", 0.0}, {"Y", 0.0}, {"Z", 0.0}};
    const Program p = parsed("G82 X10 Z-6 R-1 P2 F60\nG80\nG1 Y5\n", facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    const QList<PreviewPoint>& path = result.preview.path;
    // The start, X10, Z-1, Z-6 (feed), the dwell, Z0 (G98: back to where Z began), Y5.
    QCOMPARE(path.size(), 7);
    const QList<bool> rapid{true, true, false, false, true, false};
    for (int i = 1; i < path.size(); ++i) {
        QCOMPARE(path.at(i).rapid, rapid.at(i - 1));
    }
    QCOMPARE(path.at(3).position.value("Z"), -6.0);
    QCOMPARE(path.at(5).position.value("Z"), 0.0);
    QCOMPARE(path.at(6).position.value("X"), 10.0);
    // 5 mm at F60 (1 mm/s) and 2 s of dwell between the point at R and the bottom's dwell.
    QCOMPARE(path.at(4).seconds - path.at(2).seconds, 7.0);
    QCOMPARE(result.preview.extents["Z"].minimum, -6.0);
}

void TestProgramPreview::check_workOffsets_targetsInWorkLimitsInMachine_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<double>("xFrom"); // the preview's X extent, work coordinates
    QTest::addColumn<double>("xTo");
    // X zeroed at machine 30 (soft limits 0..100 machine = -30..70 work).
    QTest::newRow("work 0 is machine 30") << "G90 G0 X0\n" << QStringList{} << -10.0 << 0.0;
    QTest::newRow("work 70 is the machine's maximum") << "G90 G0 X70\n"
                                                      << QStringList{} << -10.0 << 70.0;
    QTest::newRow("work 80 is machine 110, beyond the limit")
        << "G90 G0 X80\n"
        << QStringList{"1:8: X reaches 80 mm in work coordinates, 110 mm in machine coordinates: "
                       "outside the soft limits 0..100 mm (machine)"}
        << 0.0 << 0.0;
    QTest::newRow("work -25 is machine 5, inside although below work 0")
        << "G90 G0 X-25\n"
        << QStringList{} << -25.0 << -10.0;
    QTest::newRow("relative moves are not offset") << "G91 G0 X5\n"
                                                   << QStringList{} << -10.0 << -5.0;
    QTest::newRow("after G28 the machine is at 0, work -30") << "G28 X0\nG91 G0 X1\n"
                                                             << QStringList{} << -30.0 << -10.0;
}

void TestProgramPreview::check_workOffsets_targetsInWorkLimitsInMachine()
{
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    QFETCH(double, xFrom);
    QFETCH(double, xTo);
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("X=20"); // machine 20 = work -10
    facts.coordinateSystems[0] = {{QStringLiteral("X"), 30.0}};
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors), errors);
    if (!errors.isEmpty())
        return;
    QCOMPARE(result.preview.workOffsets, facts.workOffsets());
    QCOMPARE(result.preview.extents["X"].minimum, xFrom);
    QCOMPARE(result.preview.extents["X"].maximum, xTo);
    QCOMPARE(result.preview.path.first().position.value("X"), -10.0);
}

// Issue 47, item 11: each point carries the estimate's seconds of feed moves up to it (what
// the feed override re-times; rapids and dwells not) and the blocks a run has finished there,
// counted as ProgramRunner::blocksDone() counts them: lines of modal words only are not blocks
// of their own there, repeats are counted out. blocksRun, the preview's figure, counts every
// block but the repeat lines.
void TestProgramPreview::preview_points_feedSecondsAndBlocksDoneAsTheRunnerCounts()
{
    const MachineFacts facts = machineFacts("mill");
    const Program p = parsed("G28 X0 Y0\n"     // 1: no time; block 1
                             "G91\n"           // 2: modal words only
                             "O1 repeat [2]\n" // 3
                             "  G1 X10 F600\n" // 4: 10 mm at 10 mm/s: 1 s of feed
                             "  G4 P0.5\n"     // 5: 0.5 s of dwell
                             "  G0 X-10\n"     // 6: 10 mm at 50 mm/s: 0.2 s of rapid
                             "O1 endrepeat\n"  // 7
                             "M2\n",           // 8: no point; the last block
                             facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    const ProgramPreview& v = result.preview;
    QCOMPARE(v.blocksRun, qint64(1 + 1 + 2 * 3 + 1));
    struct Expected
    {
        int line;
        double seconds;
        double feedSeconds;
        qint64 blocksDone;
    };
    const QList<Expected> expected{{0, 0, 0, 0},   {1, 0, 0, 1},   {4, 1, 1, 2},   {5, 1.5, 1, 3},
                                   {6, 1.7, 1, 4}, {4, 2.7, 2, 5}, {5, 3.2, 2, 6}, {6, 3.4, 2, 7}};
    QCOMPARE(v.path.size(), expected.size());
    for (qsizetype i = 0; i < expected.size(); ++i) {
        const PreviewPoint& point = v.path.at(i);
        const Expected& e = expected.at(i);
        QCOMPARE(point.line, e.line);
        QVERIFY2(qAbs(point.seconds - e.seconds) < 1e-9, qPrintable(QString::number(i)));
        QVERIFY2(qAbs(point.feedSeconds - e.feedSeconds) < 1e-9, qPrintable(QString::number(i)));
        QCOMPARE(point.blocksDone, e.blocksDone);
    }
    QVERIFY(qAbs(v.estimatedSeconds - 3.4) < 1e-9);
}

// A path thinned to its bound keeps each kept point's times and count as the run has them
// there: counts and seconds rise, and the last point is the run's end.
void TestProgramPreview::preview_thinnedPath_pointsKeepTheirFeedSecondsAndBlockCounts()
{
    const MachineFacts facts = machineFacts("mill");
    const Program p =
        parsed("G28 X0\nG91\nO1 repeat [15000]\n  G1 X1 F600\n  G0 X-1\nO1 endrepeat\n", facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    const QList<PreviewPoint>& path = result.preview.path;
    QVERIFY(result.preview.pathDecimated);
    for (qsizetype i = 1; i < path.size(); ++i) {
        QVERIFY(path.at(i).blocksDone > path.at(i - 1).blocksDone);
        QVERIFY(path.at(i).seconds >= path.at(i - 1).seconds);
        QVERIFY(path.at(i).feedSeconds >= path.at(i - 1).feedSeconds);
        QVERIFY(path.at(i).feedSeconds <= path.at(i).seconds + 1e-9);
    }
    QCOMPARE(path.last().blocksDone, qint64(1 + 2 * 15000)); // G91 is no block of its own
    QCOMPARE(result.preview.blocksRun, qint64(2 + 2 * 15000));
    // 1 mm at 10 mm/s of feed, 1 mm at 50 mm/s of rapid, 15000 times.
    QVERIFY(qAbs(path.last().feedSeconds - 15000 * 0.1) < 1e-6);
    QVERIFY(qAbs(path.last().seconds - 15000 * (0.1 + 0.02)) < 1e-6);
    QCOMPARE(path.last().seconds, result.preview.estimatedSeconds);
}

// Issue 47 item 12: a program beyond the soft limits (a CAM job before its work zero is set)
// keeps the path the check walked, flagged as having errors so that nothing runs it: its
// points and extents as the walk reached them, the error listed as ever.
void TestProgramPreview::preview_softLimitErrors_pathKeptFlaggedWithErrors()
{
    const MachineFacts facts = machineFacts("mill"); // X 0..100 mm, Y 0..200 mm
    const Program p = parsed("G28 X0 Y0\n"
                             "G0 X50 Y20\n"
                             "G0 X120 Y20\n" // X beyond its soft limits
                             "G0 X10 Y20\n"
                             "M30\n",
                             facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QCOMPARE(texts(result.errors),
             QStringList{"3:4: X reaches 120 mm, outside the soft limits 0..100 mm"});
    QVERIFY(!result.ok());
    QVERIFY(!result.program); // nothing to run
    QVERIFY(result.hasPreview());
    const ProgramPreview& v = result.preview;
    QVERIFY(v.hasErrors);
    QCOMPARE(v.lines, 5);
    QCOMPARE(v.path.size(), 5); // the start, G28, the three G0
    QCOMPARE(v.path.at(3).line, 3);
    QCOMPARE(v.path.at(3).position, (QMap<QString, double>{{"X", 120}, {"Y", 20}}));
    QCOMPARE(v.path.last().position, (QMap<QString, double>{{"X", 10}, {"Y", 20}}));
    QCOMPARE(v.extents["X"].minimum, 0.0);
    QCOMPARE(v.extents["X"].maximum, 120.0);
    QCOMPARE(v.extents["Y"].minimum, 0.0);
    QCOMPARE(v.extents["Y"].maximum, 20.0);

    // Within the limits: the same path, no errors, not flagged.
    const ProgramCheckResult fits =
        ProgramCheck::check(parsed("G28 X0 Y0\nG0 X50 Y20\nG0 X90 Y20\nM30\n", facts), facts);
    QVERIFY2(fits.ok(), qPrintable(texts(fits.errors).join('\n')));
    QVERIFY(fits.hasPreview());
    QVERIFY(!fits.preview.hasErrors);
}

// Where the check walked nothing, there is no path to show: a program that does not parse (the
// one pass stops walking at its first parse error), a run from a line past the last block.
void TestProgramPreview::preview_parseErrorsOrRefusedStart_noPath()
{
    const MachineFacts facts = machineFacts("mill");
    QStringList names;
    for (const MachineAxis& a : facts.description.axes)
        names << a.name;
    const ProgramCheckResult parse = ProgramCheck::check(
        ProgramSource::bytes("G28 X0\nG0 X10\nG0 Q1 X20\nG0 X120\n"), names, facts);
    QVERIFY(!parse.ok());
    QCOMPARE(parse.errors.size(), 1);
    QCOMPARE(parse.errors.first().line, 3);
    QVERIFY(!parse.program);
    QVERIFY(!parse.hasPreview());
    QVERIFY(parse.preview.path.isEmpty());
    QVERIFY(parse.preview.extents.isEmpty());
    QVERIFY(parse.preview.hasErrors);

    const ProgramCheckResult from =
        ProgramCheck::check(parsed("G28 X0\nG0 X10\nM30\n", facts), facts, 90);
    QVERIFY(!from.ok());
    QVERIFY(!from.hasPreview());
    QCOMPARE(from.preview.lines, 3);
}

// Issue 50's features in the preview, worked out by hand on the mill (all at 0; "$H" from
// unknown positions): the last point of each line "line:X,Y" (an arc's chords end at its end),
// the highest Y, and the estimated seconds.
void TestProgramPreview::preview_issue50Features_pathAsWorkedOutByHand_data()
{
    QTest::addColumn<QString>("machine"); // "mill", "laser"
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("points");
    QTest::addColumn<double>("yMax");
    QTest::addColumn<double>("seconds");

    // Item 2: the line's switches, then its move; "M5 M9 G0 X0" moves back. X 10 mm at X's
    // 50 mm/s, Y 5 mm at 25 mm/s: 0.2 s each way.
    QTest::newRow("2 whole line") << "mill"
                                  << "G0 X10 Y5 M3 S1000\nM5 M9 G0 X0 Y0\n"
                                  << "1:10,5 2:0,0" << 5.0 << 0.4;
    // Item 3: nothing after M2 is read.
    QTest::newRow("3 around the program") << "mill"
                                          << "%\nO1234\nG0 X1\nM2\nG0 X5\n%\n"
                                          << "3:1,0" << 0.0 << 0.02;
    // Item 5: a laser's M4 cuts as M3 does: 10 mm at F600 (10 mm/s), 1 s.
    QTest::newRow("5 laser M4") << "laser"
                                << "M4 S500\nG1 X10 F600\nM5\n"
                                << "2:10,0" << 0.0 << 1.0;
    // Item 6: the deleted line is not drawn; polar X0 Y10 (Y at 25 mm/s: 0.4 s); $H references.
    QTest::newRow("6 block delete") << "mill"
                                    << "/G0 X5\nG0 X1\n"
                                    << "2:1,0" << 0.0 << 0.02;
    QTest::newRow("6 polar") << "mill"
                             << "G0 @10 ^90\n"
                             << "1:0,10" << 10.0 << 0.4;
    QTest::newRow("6 $H") << "unknown"
                          << "$H\n$32=1\nG0 X1\n"
                          << "1:0,0 3:1,0" << 0.0 << 0.02;
    // Item 8: G2 K0 from (10,10) about (15,10) clockwise over the top: Y up to 15. The G0
    // takes 0.4 s (Y); the arc, a contour of the E-LAB's stream, runs its path at F600
    // (10 mm/s): pi x 5 / 10 = 1.571 s (its chords a hair shorter).
    QTest::newRow("8 K0 on a G17 arc") << "mill"
                                       << "G0 X10 Y10\nG2 X20 Y10 I5 J0 K0 F600\n"
                                       << "1:10,10 2:20,10" << 15.0 << 1.971;
    // Item 9: the sub's return inside its if gives X6; EXISTS of a set name gives Y5.
    QTest::newRow("9 language")
        << "mill"
        << "o100 sub\n  o101 if [#1 GT 0]\n    o100 return [#1 * 2]\n  o101 endif\n"
           "  o100 return [0]\no100 endsub\no100 call [3]\nG0 X#<_value>\n#<set> = 1\n"
           "o102 if [EXISTS[#<set>]]\n  G0 Y5\no102 endif\nM2\n"
        << "8:6,0 11:6,5" << 5.0 << 0.32;
}

void TestProgramPreview::preview_issue50Features_pathAsWorkedOutByHand()
{
    QFETCH(QString, machine);
    QFETCH(QString, program);
    QFETCH(QString, points);
    QFETCH(double, yMax);
    QFETCH(double, seconds);
    MachineFacts facts = machineFacts("mill");
    if (machine != QLatin1String("unknown"))
        facts.knownPositions = positions("X=0 Y=0 Z=0 A=0");
    if (machine == QLatin1String("laser"))
        facts.description.spindle.laser = true;
    // The one pass over the text, as the window checks a file (a LinuxCNC-language program is
    // worked out first).
    const ProgramCheckResult result =
        ProgramCheck::check(ProgramSource::bytes(program.toUtf8()), {"X", "Y", "Z", "A"}, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    QStringList ends;
    const QList<PreviewPoint>& path = result.preview.path;
    for (qsizetype i = 1; i < path.size(); ++i)
        if (i + 1 == path.size() || path.at(i + 1).line != path.at(i).line)
            ends << QStringLiteral("%1:%2,%3")
                        .arg(path.at(i).line)
                        .arg(figure(path.at(i).position.value("X")))
                        .arg(figure(path.at(i).position.value("Y")));
    QCOMPARE(ends.join(' '), points);
    QCOMPARE(result.preview.extents.value("Y").maximum, yMax);
    QVERIFY2(std::abs(result.preview.estimatedSeconds - seconds) < 0.01,
             qPrintable(QString::number(result.preview.estimatedSeconds)));
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramPreview)
#include "tst_programpreview.moc"
