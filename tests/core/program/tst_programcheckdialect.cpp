// The check of the CAM dialect's machine state (issue 29, docs/programs.md "Coordinates",
// "Tools", "Spindle speed"): G54..G59, G53, G10 and G92 with the soft limits where the words
// land, G43 with the tool table, and S within the machine's spindle scale. The check's
// other errors: tst_programcheck.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/ProgramCheck.h"
#include "program/ProgramParser.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;

using namespace stepdeck::program::checktest;

class TestProgramCheckDialect : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void check_coordinates_targetsLimitsAndErrors_data();
    void check_coordinates_targetsLimitsAndErrors();
    void check_tools_lengthOffsetAndTable_data();
    void check_tools_lengthOffsetAndTable();
    void check_toolLength_touchOffTakesNoLengthTableAsBefore_data();
    void check_toolLength_touchOffTakesNoLengthTableAsBefore();
    void check_spindleAboveMaxRpm_refusedAtS_data();
    void check_spindleAboveMaxRpm_refusedAtS();
    void check_spindleAboveMaxRpm_runsAtMaxRpmWithNote_data();
    void check_spindleAboveMaxRpm_runsAtMaxRpmWithNote();
    void check_inverseTime_eachAxisItsRate_data();
    void check_inverseTime_eachAxisItsRate();
    void check_coordinatedFeed_alongThePathAtF_data();
    void check_coordinatedFeed_alongThePathAtF();
    void check_acrossControllers_approximateOrForbidden_data();
    void check_acrossControllers_approximateOrForbidden();
};

// G54..G59, G53, G10 L2/L20 and G92 (issue 29): where absolute words go, the soft limits there,
// and the positions G10 L20 and G92 need. "systems": "<index>:<axis>=<offset>;...", 0 = G54;
// "end": the last point of the preview, in the work coordinates of the system active at the
// start.
void TestProgramCheckDialect::check_coordinates_targetsLimitsAndErrors_data()
{
    QTest::addColumn<QString>("known");
    QTest::addColumn<QString>("systems");
    QTest::addColumn<int>("active");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<double>("endX");
    QTest::newRow("G55 selects its offsets")
        << "X=0"
        << "1:X=50" << 0 << "G55 G0 X10" << QStringList{} << 60.0;
    QTest::newRow("G55 past the soft limit")
        << "X=0"
        << "1:X=50" << 0 << "G55 G0 X60"
        << QStringList{"1:8: X reaches 60 mm in work coordinates, 110 mm in machine coordinates: "
                       "outside the soft limits 0..100 mm (machine)"}
        << 110.0;
    // Issue 50 item 6: polar coordinates from the work zero, checked and previewed as X and Y.
    QTest::newRow("polar in G55") << "X=0 Y=0"
                                  << "1:X=50" << 0 << "G55 G0 @10 ^60" << QStringList{} << 55.0;
    QTest::newRow("polar past the soft limit")
        << "X=0 Y=0"
        << "1:X=50" << 0 << "G55 G0 @60 ^0"
        << QStringList{"1:8: X reaches 60 mm in work coordinates, 110 mm in machine coordinates: "
                       "outside the soft limits 0..100 mm (machine)"}
        << 110.0;
    QTest::newRow("no G5x: the active system")
        << "X=0"
        << "1:X=50" << 1 << "G0 X10" << QStringList{} << 10.0;
    QTest::newRow("G54 named: G54 whatever is active")
        << "X=0"
        << "1:X=50" << 1 << "G54 G0 X10" << QStringList{} << -40.0;
    QTest::newRow("G53: machine coordinates")
        << "X=0"
        << "1:X=50" << 1 << "G53 G0 X10" << QStringList{} << -40.0;
    QTest::newRow("G10 L2 then G56")
        << "X=0"
        << "" << 0 << "G10 L2 P3 X20\nG56 G0 X5" << QStringList{} << 25.0;
    QTest::newRow("G10 L2 P0: the system in effect")
        << "X=0"
        << "" << 0 << "G57\nG10 L2 P0 X20\nG0 X5\nG54 G0 X5" << QStringList{} << 5.0;
    QTest::newRow("G10 L20: the current point reads the words")
        << "X=30"
        << "" << 0 << "G10 L20 P1 X0\nG0 X5" << QStringList{} << 35.0;
    QTest::newRow("G92, G92.2, G92.3")
        << "X=30"
        << "" << 0 << "G92 X0\nG0 X5\nG92.2\nG0 X5\nG92.3\nG0 X1" << QStringList{} << 31.0;
    QTest::newRow("G92.1 clears it") << "X=30"
                                     << "" << 0 << "G92 X0\nG92.1\nG0 X5" << QStringList{} << 5.0;
    QTest::newRow("G92 in inches")
        << "X=0"
        << "" << 0 << "G20 G92 X1\nG21 G0 X0"
        << QStringList{"2:8: X reaches 0 mm in work coordinates, -25.4 mm in machine coordinates: "
                       "outside the soft limits 0..100 mm (machine)"}
        << -25.4;
    QTest::newRow("G92 on an unknown position")
        << ""
        << "" << 0 << "G92 X0"
        << QStringList{"1:1: G92: the position of X is unknown: reference it first (G28 X)"} << 0.0;
    QTest::newRow("G10 L20 on an unknown position")
        << ""
        << "" << 0 << "G10 L20 P2 X0"
        << QStringList{"1:1: G10 L20: the position of X is unknown: reference it first (G28 X)"}
        << 0.0;
}

void TestProgramCheckDialect::check_coordinates_targetsLimitsAndErrors()
{
    QFETCH(QString, known);
    QFETCH(QString, systems);
    QFETCH(int, active);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    QFETCH(double, endX);
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions(known);
    for (const QString& entry : systems.split(';', Qt::SkipEmptyParts)) {
        const QStringList parts = entry.split(':');
        const QStringList axis = parts.at(1).split('=');
        facts.coordinateSystems[size_t(parts.at(0).toInt())].insert(axis.at(0),
                                                                    axis.at(1).toDouble());
    }
    facts.activeSystem = active;
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors), errors);
    if (!known.isEmpty())
        QCOMPARE(result.preview.path.last().position.value("X"), endX);
}

// G43's length on Z and the tool table (issue 29); "tools" as tool.tbl text.
void TestProgramCheckDialect::check_tools_lengthOffsetAndTable_data()
{
    QTest::addColumn<QByteArray>("tools");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<double>("endZ"); // work coordinates; NaN: not compared
    const QByteArray table = "T1 Z10 ;long\nT2 Z-20 ;short\n";
    QTest::newRow("no table, M6 as before")
        << QByteArray() << "T7 M6\nG0 Z-5" << QStringList{} << -5.0;
    QTest::newRow("no table, G43 H") << QByteArray() << "G43 H1 G0 Z-5"
                                     << QStringList{"1:5: G43: the machine's tool table is empty: "
                                                    "enter tool 1's length first"}
                                     << -5.0;
    QTest::newRow("G43 H2: Z goes down by its length")
        << table << "T2 M6\nG43 H2 G0 Z-5" << QStringList{} << -25.0;
    QTest::newRow("G43 H1 past Z's upper limit")
        << table << "T1 M6 G43 H1\nG0 Z-5"
        << QStringList{"2:4: Z reaches -5 mm in work coordinates, 5 mm in machine coordinates: "
                       "outside the soft limits -50..0 mm (machine)"}
        << 5.0;
    QTest::newRow("G49 cancels") << table << "T2 M6 G43\nG49\nG0 Z-5" << QStringList{} << -5.0;
    QTest::newRow("G53 ignores it") << table << "T2 M6 G43\nG53 G0 Z-5" << QStringList{} << -5.0;
    QTest::newRow("T not in the table")
        << table << "T3 M6" << QStringList{"1:4: T3: tool 3 is not in the machine's tool table"}
        << qQNaN();
    QTest::newRow("H not in the table")
        << table << "G43 H4" << QStringList{"1:5: G43: tool 4 is not in the machine's tool table"}
        << qQNaN();
}

void TestProgramCheckDialect::check_tools_lengthOffsetAndTable()
{
    QFETCH(QByteArray, tools);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    QFETCH(double, endZ);
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions("Z=0");
    const std::optional<ToolTable> table = ToolTable::parse(tools, nullptr);
    QVERIFY(table);
    facts.tools = *table;
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors), errors);
    if (!qIsNaN(endZ))
        QCOMPARE(result.preview.path.last().position.value("Z"), endZ);
}

// Issue 50 item 4: the machine file's toolLength. With "touchOff" G43 H adds no length and needs
// no table entry (an empty table is no error), an M6 needs none either, and the preview's note
// names the M6s the run holds at for the work Z; with "table" (the default) as before.
void TestProgramCheckDialect::check_toolLength_touchOffTakesNoLengthTableAsBefore_data()
{
    QTest::addColumn<bool>("touchOff");
    QTest::addColumn<QByteArray>("tools");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<double>("endZ");  // work coordinates
    QTest::addColumn<QString>("note"); // ProgramPreview::toolNote
    const QString twoChanges = "tool lengths by touch-off (the machine file's toolLength): the "
                               "run holds at 2 tool change(s) (M6, line(s) 1, 3) until the work "
                               "Z is set for the new tool; G43 adds no length";
    QTest::newRow("table: G43 H2 with an empty table refused")
        << false << QByteArray() << "T1 M6\nG0 Z-1\nT2 M6\nG43 H2 G0 Z-5"
        << QStringList{"4:5: G43: the machine's tool table is empty: enter tool 2's length first"}
        << -5.0 << QString();
    QTest::newRow("touchOff: G43 H2 with an empty table")
        << true << QByteArray() << "T1 M6\nG0 Z-1\nT2 M6\nG43 H2 G0 Z-5" << QStringList{} << -5.0
        << twoChanges;
    QTest::newRow("table: the table's length")
        << false << QByteArray("T2 Z-20 ;short\n") << "T2 M6\nG43 H2 G0 Z-5" << QStringList{}
        << -25.0 << QString();
    QTest::newRow("touchOff: the table's length adds nothing")
        << true << QByteArray("T2 Z-20 ;short\n") << "T2 M6\nG43 H2 G0 Z-5" << QStringList{} << -5.0
        << "tool lengths by touch-off (the machine file's toolLength): the run holds at 1 tool "
           "change(s) (M6, line(s) 1) until the work Z is set for the new tool; G43 adds no "
           "length";
    QTest::newRow("touchOff: T and H not in the table")
        << true << QByteArray("T1 Z10\n") << "T3 M6\nG0 Z-1\nT3 M6\nG43 H3 G0 Z-5" << QStringList{}
        << -5.0 << twoChanges;
    QTest::newRow("touchOff: G43 without M6")
        << true << QByteArray() << "G43 H1 G0 Z-5" << QStringList{} << -5.0
        << "tool lengths by touch-off (the machine file's toolLength): G43 adds no length; set "
           "the work Z for the tool in the spindle before the run";
    QTest::newRow("touchOff: no tool words")
        << true << QByteArray() << "G0 Z-5" << QStringList{} << -5.0 << QString();
}

void TestProgramCheckDialect::check_toolLength_touchOffTakesNoLengthTableAsBefore()
{
    QFETCH(bool, touchOff);
    QFETCH(QByteArray, tools);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    QFETCH(double, endZ);
    QFETCH(QString, note);
    MachineFacts facts = machineFacts("mill");
    facts.description.toolLength = touchOff ? ToolLength::TouchOff : ToolLength::Table;
    facts.knownPositions = positions("Z=0");
    const std::optional<ToolTable> table = ToolTable::parse(tools, nullptr);
    QVERIFY(table);
    facts.tools = *table;
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors), errors);
    QCOMPARE(result.preview.path.last().position.value("Z"), endZ);
    QCOMPARE(result.preview.toolNote, note);
}

// Issue 29: with the machine's spindle scale, S is in rpm up to maxRpm (mapped onto the
// E-LAB's 0..1000); above it, with the machine file's "limits": "refuse" (issue 50), an error at
// the S word naming maxRpm. Without the scale, S is the controller's own value.
void TestProgramCheckDialect::check_spindleAboveMaxRpm_refusedAtS_data()
{
    QTest::addColumn<double>("maxRpm"); // 0: none
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::newRow("S12000 of 24000") << 24000.0 << "G0 X1\nM3 S12000" << QStringList{};
    QTest::newRow("S24000 of 24000") << 24000.0 << "M3 S24000" << QStringList{};
    QTest::newRow("S0 of 24000") << 24000.0 << "M3 S0" << QStringList{};
    QTest::newRow("S30000 of 24000")
        << 24000.0 << "G0 X1\nN20 M3 S30000"
        << QStringList{"2:8: controller \"table\": S30000 is above the spindle's maxRpm 24000 "
                       "(the machine file's spindle scale)"};
    QTest::newRow("S before M3") << 10000.0 << "S10001 M3"
                                 << QStringList{"1:1: controller \"table\": S10001 is above the "
                                                "spindle's maxRpm 10000 (the machine file's "
                                                "spindle scale)"};
    // S on any line (LightBurn, pcb2gcode): the same rules.
    QTest::newRow("S on G1") << 24000.0 << "M3 S1000\nG1 X1 S30000 F100"
                             << QStringList{"2:7: controller \"table\": S30000 is above the "
                                            "spindle's maxRpm 24000 (the machine file's "
                                            "spindle scale)"};
    QTest::newRow("S alone") << 24000.0 << "S30000"
                             << QStringList{"1:1: controller \"table\": S30000 is above the "
                                            "spindle's maxRpm 24000 (the machine file's "
                                            "spindle scale)"};
    QTest::newRow("G1 S0") << 24000.0 << "M3\nG1 X1 S20000 F100\nG1 S0\nM5" << QStringList{};
    QTest::newRow("no scale: S12000 beyond the E-LAB's 1000")
        << 0.0 << "M3 S12000"
        << QStringList{"1:4: controller \"table\": Spindle speed: value '12000' is out of range "
                       "(allowed: 0..1000 rpm)"};
}

void TestProgramCheckDialect::check_spindleAboveMaxRpm_refusedAtS()
{
    QFETCH(double, maxRpm);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    MachineFacts facts = machineFacts("millRefuse");
    if (maxRpm > 0)
        facts.description.spindle.maxRpm = maxRpm;
    facts.knownPositions = positions("X=0");
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors), errors);
    QVERIFY(result.notes.isEmpty());
}

// Issue 50: by default an S above maxRpm runs at maxRpm, as GRBL clamps S at $30: a note at the
// S word (programmed S, the S that runs), once per S value, and no error. The controller's own
// range without a scale stays an error (the E-LAB's 0..1000). Issue 50 item 5: on a laser, M4
// runs as M3 (one note) and S is the beam's power.
void TestProgramCheckDialect::check_spindleAboveMaxRpm_runsAtMaxRpmWithNote_data()
{
    QTest::addColumn<double>("maxRpm"); // 0: none; < 0: a laser's, -maxRpm
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("notes");
    QTest::addColumn<QStringList>("errors");
    const QString at24000 = "S30000 runs at S24000, the spindle's maxRpm (the machine file's "
                            "spindle scale)";
    QTest::newRow("M3 S30000 of 24000")
        << 24000.0 << "G0 X1\nN20 M3 S30000" << QStringList{"2:8: " + at24000} << QStringList{};
    QTest::newRow("S on G1, twice")
        << 24000.0 << "M3 S1000\nG1 X1 S30000 F100\nG1 X2 S30000"
        << QStringList{"2:7: " + at24000 + " (also on 1 more line(s))"} << QStringList{};
    QTest::newRow("S24000 of 24000: none")
        << 24000.0 << "M3 S24000" << QStringList{} << QStringList{};
    QTest::newRow("no scale: S12000 beyond the E-LAB's 1000")
        << 0.0 << "M3 S12000" << QStringList{}
        << QStringList{"1:4: controller \"table\": Spindle speed: value '12000' is out of range "
                       "(allowed: 0..1000 rpm)"};
    const QString asM3 = "M4 runs as M3 on this laser: the beam's power is S, constant (GRBL's M4 "
                         "lowers the power where the feed slows; StepDeck's controllers have no "
                         "such power)";
    QTest::newRow("a laser: M4 as M3, S as power")
        << -1000.0 << "M4 S500\nG1 X1 F100\nM5\nM4 S2000"
        << QStringList{"1:1: " + asM3 + " (also on 1 more line(s))",
                       "4:4: S2000 runs at S1000, the laser's full power (the machine file's "
                       "spindle scale)"}
        << QStringList{};
}

void TestProgramCheckDialect::check_spindleAboveMaxRpm_runsAtMaxRpmWithNote()
{
    QFETCH(double, maxRpm);
    QFETCH(QString, program);
    QFETCH(QStringList, notes);
    QFETCH(QStringList, errors);
    MachineFacts facts = machineFacts("mill");
    if (maxRpm != 0)
        facts.description.spindle.maxRpm = std::abs(maxRpm);
    facts.description.spindle.laser = maxRpm < 0;
    facts.knownPositions = positions("X=0");
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors), errors);
    QCOMPARE(texts(result.notes), notes);
}

// G93 (docs/programs.md "Inverse time"): a G1 takes 1/F minutes, each axis at its distance times
// F; the rates checked like G1's, from where each block starts (the mill: 100 steps/mm, the
// E-LAB's feed speed 0..65535 steps/s).
void TestProgramCheckDialect::check_inverseTime_eachAxisItsRate_data()
{
    QTest::addColumn<QString>("known");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<double>("seconds"); // the estimate, when no errors
    QTest::newRow("one move, two axes: 10 s") << "X=0 Y=0"
                                              << "G93 G1 X10 Y5 F6" << QStringList{} << 10.0;
    // A half circle of 31.4 mm at its path speed: the chords' axes each at 188 mm/min, so the
    // estimate is the chords' longer sides (2 sqrt 2 / pi of the curve) at that speed, 9.0 s.
    QTest::newRow("arc: its length in 1/F minutes")
        << "X=0 Y=0"
        << "G93 G2 X20 Y0 I10 J0 F6" << QStringList{} << 10.0 * 2 * std::sqrt(2.0) / M_PI;
    QTest::newRow("from where the block before ended")
        << "X=0 Y=0"
        << "G93\nG1 X10 F60\nG1 X40 F30" << QStringList{} << 3.0; // 1 s, then 30 mm in 2 s
    QTest::newRow("relative from an unknown position")
        << ""
        << "G91 G93 G1 X-5 F60" << QStringList{} << 1.0;
    QTest::newRow("the same F, other distances")
        << "X=0"
        << "G93 G1 X1 F60\nG1 X3 F60" << QStringList{} << 2.0;
    // Issue 50: X would need 166 667 steps/s; it runs below the start speed 2401 (feed mode has
    // no ramp), at 2400 steps/s = 24 mm/s, and the move takes longer (a note says so).
    QTest::newRow("too fast for the board: runs at the highest")
        << "X=0"
        << "G93 G1 X100 F1000" << QStringList{} << 100.0 / 24;
    QTest::newRow("back to G94 and its own F")
        << "X=0"
        << "G93 G1 X1 F60\nG94 G1 X2 F60" << QStringList{} << 2.0;
}

void TestProgramCheckDialect::check_inverseTime_eachAxisItsRate()
{
    QFETCH(QString, known);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    QFETCH(double, seconds);
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions(known);
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors).join(QLatin1Char('|')), errors.join(QLatin1Char('|')));
    if (errors.isEmpty())
        QVERIFY2(std::abs(result.preview.estimatedSeconds - seconds) < 0.01,
                 qPrintable(QString::number(result.preview.estimatedSeconds)));
}

// G94 G1 over several axes of a controller that coordinates (issue 30, CoordinatedFeed): each
// axis at its share of F, so the move takes its length / F; a share below the model's lowest
// rate runs at that rate instead of being refused. The machines count in steps.
void TestProgramCheckDialect::check_coordinatedFeed_alongThePathAtF_data()
{
    QTest::addColumn<QString>("machine");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<double>("seconds");
    // 500 steps at 10 steps/s (before issue 30: 40 s, each axis at F).
    QTest::newRow("EMIS: a 3-4-5 diagonal in length / F")
        << "emisKnown"
        << "G1 X300 Y400 F600" << QStringList{} << 50.0;
    QTest::newRow("EMIS: an arc's chords at F along each")
        << "emisKnown"
        << "G2 X200 Y0 I100 J0 F600" << QStringList{} << 100 * M_PI / 10;
    // Y's share is about 1 step/s, below the drive's lowest o (60, 6.9): it runs at 60 and
    // arrives early; X's 100 steps/s take 60 s.
    QTest::newRow("Nanotec: a share below the lowest rate runs at it")
        << "nanotec"
        << "G1 X6000 Y60 F6000" << QStringList{} << 60.0;
    // 26 667 steps/s would exceed o's 25 000 on one axis; along the diagonal each drive runs
    // 18 856.
    QTest::newRow("Nanotec: a diagonal within the range on each drive")
        << "nanotec"
        << "G1 X1000 Y1000 F1600000" << QStringList{} << std::sqrt(2.0) * 1000 / (1600000.0 / 60);
}

void TestProgramCheckDialect::check_coordinatedFeed_alongThePathAtF()
{
    QFETCH(QString, machine);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    QFETCH(double, seconds);
    MachineFacts facts = machineFacts(machine);
    facts.knownPositions = positions("X=0 Y=0");
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors).join(QLatin1Char('|')), errors.join(QLatin1Char('|')));
    QVERIFY2(std::abs(result.preview.estimatedSeconds - seconds) < 0.02 * seconds + 0.01,
             qPrintable(QString::number(result.preview.estimatedSeconds)));
}

// A feed move over axes of several controllers (issue 30): the preview says that its path is
// approximate and by how much (the fastest axis over the gap between the controllers' set-up
// times); a machine file with "crossControllerFeed": false refuses it. "mixed": E-LAB X (mm),
// Nanotec A (deg, set-up 0.06 s against the E-LAB's 0.005 s).
void TestProgramCheckDialect::check_acrossControllers_approximateOrForbidden_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<bool>("allowed");
    QTest::addColumn<QString>("note"); // the part of the motion note about it; empty: none
    QTest::addColumn<QString>("errors");
    // X at 10 mm/s for 0.055 s: 0.55 mm.
    QTest::newRow("approximate, with its estimate")
        << "G1 X10 A90 F600" << true
        << "feed moves across controllers (1 in all, the first on line 1) follow their path only "
           "approximately: up to about 0.550 mm off"
        << "";
    QTest::newRow("the largest of several, counted")
        << "G1 X10 A90 F600\nG1 X20 A0 F1200\nG1 X30 F1200" << true
        << "feed moves across controllers (2 in all, the first on line 1) follow their path only "
           "approximately: up to about 1.100 mm off"
        << "";
    QTest::newRow("one controller's axes only: nothing to say")
        << "G1 X10 F600\nG0 A5" << true << ""
        << "";
    QTest::newRow("forbidden by the machine file")
        << "G1 X10 A90 F600" << false << ""
        << "1:4: this feed move drives axes of controllers table, rotary together; the machine "
           "file forbids that (\"crossControllerFeed\": false), since their path between the "
           "ends is only approximate";
}

void TestProgramCheckDialect::check_acrossControllers_approximateOrForbidden()
{
    QFETCH(QString, program);
    QFETCH(bool, allowed);
    QFETCH(QString, note);
    QFETCH(QString, errors);
    MachineFacts facts = machineFacts("mixed");
    facts.description.crossControllerFeed = allowed;
    facts.knownPositions = positions("X=0 A=0");
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors).join(QLatin1Char('|')), errors);
    if (!errors.isEmpty())
        return;
    const QString motion = result.preview.motionNote;
    QVERIFY2(note.isEmpty() ? !motion.contains("across controllers") : motion.endsWith(note),
             qPrintable(motion));
    // The note names how each kind of controller follows F.
    QVERIFY2(motion.contains("rotary: each axis of a feed move runs at its share of F"),
             qPrintable(motion));
    QVERIFY2(motion.contains("table: contours (G64)"), qPrintable(motion));
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramCheckDialect)
#include "tst_programcheckdialect.moc"
