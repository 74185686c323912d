// The program check (issue 20, docs/programs.md "Check"): every error kind at its line and
// column, positions followed through repeats, G28, rates per model, G20, inputs and outputs
// over several controllers, and the docs' example programs checked clean on their model. The
// whole program's limits, start line, surroundings and repeats: tst_programcheckwhole. The
// preview's figures: tst_programpreview; coordinates, tools and the spindle scale:
// tst_programcheckdialect.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "motion/executors/SwitchExecutor.h"
#include "program/ProgramCheck.h"
#include "program/ProgramParser.h"
#include "protocols/Registry.h"
#include <QDir>
#include <QSignalSpy>
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;

using namespace stepdeck::program::checktest;

class TestProgramCheck : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void check_errors_lineColumnAndMessage_data();
    void check_errors_lineColumnAndMessage();
    void machineIo_numberedOverTheControllers_data();
    void machineIo_numberedOverTheControllers();
    void examples_eachChecksCleanOnItsModel();
    void factsOf_machineReferencedX_onlyXKnownAtZero();
};

void TestProgramCheck::check_errors_lineColumnAndMessage_data()
{
    QTest::addColumn<QString>("machine");
    QTest::addColumn<QString>("known");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");

    const QString unknownX =
        "X: the position is unknown, so an absolute move could go anywhere: reference the axis "
        "first (G28 X) or move it relatively (G91)";
    QTest::newRow("absolute on an unknown axis") << "mill"
                                                 << "Y=0"
                                                 << "G0 Y0 X10" << QStringList{"1:7: " + unknownX};
    QTest::newRow("absolute in a repeat: named once")
        << "mill"
        << ""
        << "O1 repeat [3]\nG0 X1\nO1 endrepeat" << QStringList{"2:4: " + unknownX};
    QTest::newRow("G28 of the axis makes absolute moves legal")
        << "mill"
        << ""
        << "G28 X0\nG0 X10" << QStringList{};
    QTest::newRow("bare G28 references every axis") << "mill"
                                                    << ""
                                                    << "G28\nG0 X10 Y10 Z-1 A5" << QStringList{};
    QTest::newRow("G28 of another axis does not")
        << "mill"
        << ""
        << "G28 Y0\nG0 X10" << QStringList{"2:4: " + unknownX};
    QTest::newRow("known position: absolute moves legal") << "mill"
                                                          << "X=3"
                                                          << "G0 X10" << QStringList{};
    QTest::newRow("relative move from an unknown position") << "mill"
                                                            << ""
                                                            << "G91 G0 X500" << QStringList{};
    QTest::newRow("soft limit, absolute")
        << "mill"
        << "X=0"
        << "G0 X150" << QStringList{"1:4: X reaches 150 mm, outside the soft limits 0..100 mm"};
    QTest::newRow("soft limit, below")
        << "mill"
        << "Z=0"
        << "G0 Z-50.5" << QStringList{"1:4: Z reaches -50.5 mm, outside the soft limits -50..0 mm"};
    QTest::newRow("soft limit reached by relative moves in a repeat")
        << "mill"
        << "X=0"
        << "G91\nO1 repeat [30]\n  G0 X4\nO1 endrepeat"
        << QStringList{"3:6: X reaches 104 mm, outside the soft limits 0..100 mm"};
    QTest::newRow("relative moves in a repeat that stay inside")
        << "mill"
        << "X=0"
        << "G91\nO1 repeat [25]\n  G0 X4\nO1 endrepeat" << QStringList{};
    QTest::newRow("soft limit after G28 (ends at 0)")
        << "mill"
        << ""
        << "G28 Z0\nG91 G0 Z1"
        << QStringList{"2:8: Z reaches 1 mm, outside the soft limits -50..0 mm"};
    QTest::newRow("G20: inch converted on mm axes")
        << "mill"
        << ""
        << "G20 G28 X0\nG0 X5"
        << QStringList{"2:4: X reaches 127 mm, outside the soft limits 0..100 mm"};
    QTest::newRow("G20: rotary axes stay degrees") << "mill"
                                                   << ""
                                                   << "G20 G28 A0\nG0 A80" << QStringList{};
    // G61: each block on its own, its rate written to the board (docs/programs.md "How F maps").
    // Feeds above the highest are refused with "limits": "refuse" ("millRefuse", issue 50); the
    // default runs them at it: check_feedAboveTheHighest_runsAtItWithNote.
    QTest::newRow("G1 rate above the E-LAB feed speed")
        << "millRefuse"
        << ""
        << "G61\nG28 X0\nG1 X10 F40000"
        << QStringList{"3:8: F40000 is 66667 steps/s on X; controller \"table\" takes 0..65535 "
                       "steps/s (Feed speed)"};
    QTest::newRow("a refused rate still moves the axis in the walk")
        << "millRefuse"
        << ""
        << "G61\nG28 X0\nG91 G1 X101 F40000"
        << QStringList{"3:8: X reaches 101 mm, outside the soft limits 0..100 mm",
                       "3:13: F40000 is 66667 steps/s on X; controller \"table\" takes 0..65535 "
                       "steps/s (Feed speed)"};
    QTest::newRow("G1 rate within the E-LAB feed speed")
        << "mill"
        << ""
        << "G61\nG28 X0\nG1 X10 F39000" << QStringList{};
    QTest::newRow("G1 rate from an earlier line: named at G1")
        << "millRefuse"
        << ""
        << "G61\nG28 X0\nF40000\nG1 X10"
        << QStringList{"4:1: F40000 is 66667 steps/s on X; controller \"table\" takes 0..65535 "
                       "steps/s (Feed speed)"};
    QTest::newRow("G20 converts the rate")
        << "millRefuse"
        << ""
        << "G61 G20\nG28 X0\nG1 X1 F1600"
        << QStringList{"3:7: F1600 is 67733 steps/s on X; controller \"table\" takes 0..65535 "
                       "steps/s (Feed speed)"};
    // G64 (the default): the E-LAB runs the feed moves as one stream ticking at 2100/s (the wire's
    // share left after the status polls, issue 47), one step per tick at most: X (100 steps/mm)
    // at most 21 mm/s, Y (200 steps/mm) 10.5 mm/s.
    QTest::newRow("contour: F beyond the tick, named with the highest")
        << "millRefuse"
        << ""
        << "G28 X0\nG1 X10 F40000"
        << QStringList{"2:8: F40000 is too fast for the contour stream of controller \"table\": "
                       "at its 2100 ticks/s (one step per tick at most) this move's highest feed "
                       "is F1259.9"};
    QTest::newRow("contour: G20 converts F")
        << "millRefuse"
        << ""
        << "G20\nG28 Y0\nG1 Y1 F30"
        << QStringList{"3:7: F30 is too fast for the contour stream of controller \"table\": at "
                       "its 2100 ticks/s (one step per tick at most) this move's highest feed is "
                       "F24.8"};
    // F800 along the diagonal: Y (200 steps/mm) alone takes at most F630 at 2100 ticks/s.
    QTest::newRow("contour: the diagonal runs faster than either axis")
        << "mill"
        << ""
        << "G28 X0 Y0\nG1 X10 Y10 F800" << QStringList{};
    QTest::newRow("G1 below the Nanotec max-frequency")
        << "nanotec"
        << "X=0"
        << "G1 X100 F3000"
        << QStringList{"1:9: F3000 is 50 steps/s on X; controller \"nanotec\" takes 60..25000 "
                       "steps/s (Maximum frequency)"};
    QTest::newRow("G1 on a laser axis")
        << "mill"
        << ""
        << "G28\nG1 X1 A10 F100"
        << QStringList{"2:7: A: controller \"tilt\" takes no feed rate, so G1 cannot move it; use "
                       "G0"};
    // Machine::move runs each controller's part at its own rate: the board's X as a feed move,
    // the drive's A as a positioning move at its top speed o.
    QTest::newRow("G1 of a feed-mode axis and a positioning one: each at its rate")
        << "mixed"
        << ""
        << "G28\nG1 X1 A1 F600\nG1 A2\nG1 X2" << QStringList{};
    QTest::newRow("G28 on a controller without reference runs")
        << "noReference"
        << ""
        << "G28 X0 A0" << QStringList{"1:8: A: controller \"tilt\" has no reference run (G28)"};
    QTest::newRow("bare G28 on a controller without reference runs")
        << "noReference"
        << ""
        << "G21 G28" << QStringList{"1:5: A: controller \"tilt\" has no reference run (G28)"};
    // EMIS #E1 is G0's speed too and cannot be read back to be put back after a G1.
    QTest::newRow("G0 and G1 on the EMIS")
        << "emis"
        << ""
        << "G91 G1 X10 F600\nG0 X-10\nG0 Y5"
        << QStringList{"2:4: X: G0 in a program with G1 on controller \"emis\": its fast speed "
                       "(Work speed) cannot be read back to be put back after G1; move X with G1 "
                       "and F only, or with G0 only",
                       "3:4: Y: G0 in a program with G1 on controller \"emis\": its fast speed "
                       "(Work speed) cannot be read back to be put back after G1; move Y with G1 "
                       "and F only, or with G0 only"};
    QTest::newRow("G0 and G1 on the EMIS, its work speed known for X only")
        << "emisKnownX"
        << ""
        << "G91 G1 X10 F600\nG0 X-10\nG0 Y5"
        << QStringList{"2:4: X: G0 in a program with G1 on controller \"emis\": its fast speed "
                       "(Work speed) cannot be read back to be put back after G1; move X with G1 "
                       "and F only, or with G0 only",
                       "3:4: Y: G0 in a program with G1 on controller \"emis\": its fast speed "
                       "(Work speed) cannot be read back to be put back after G1; move Y with G1 "
                       "and F only, or with G0 only"};
    // Issue 29: where the adapter knows the work speed, G1 replaces it and G0 puts it back.
    QTest::newRow("G0 and G1 on the EMIS, its work speed known")
        << "emisKnown"
        << ""
        << "G91 G1 X10 F600\nG0 X-10\nG0 Y5" << QStringList{};
    QTest::newRow("drilling cycle on the EMIS after G1")
        << "emis"
        << "X=0 Y=0 Z=0"
        << "G1 X10 F600\nG81 X5 Z-10 R5"
        << QStringList{"2:5: X: G81 moves it at the fast speed in a program with G1 on controller "
                       "\"emis\", whose fast speed (Work speed) cannot be read back to be put back "
                       "after G1; drill with G1 and F only"};
    QTest::newRow("drilling cycle on the EMIS, its work speed known")
        << "emisKnown"
        << "X=0 Y=0 Z=0"
        << "G1 X10 F600\nG81 X5 Z-10 R5" << QStringList{};
    // Nanotec o is read before the first G1 and put back before the G0.
    QTest::newRow("G0 and G1 on the Nanotec") << "nanotec"
                                              << ""
                                              << "G91 G1 X10 F6000\nG0 X-10" << QStringList{};
    QTest::newRow("M3 without a spindle")
        << "emis"
        << ""
        << "M3 S1000\nM5"
        << QStringList{"1:1: M3: no controller of this machine has a spindle",
                       "2:1: M5: no controller of this machine has a spindle"};
    QTest::newRow("M3 M8 on the E-LAB") << "mill"
                                        << ""
                                        << "M3 S1000\nM8\nM9\nM5" << QStringList{};
    // Issue 29: M4 only where the spindle's controller can reverse; none can (E-LAB: a relay).
    QTest::newRow("M4 on the E-LAB")
        << "mill"
        << ""
        << "M3 S100\nM4 S100\nM5"
        << QStringList{"2:1: M4: controller \"table\" cannot reverse its spindle: use M3"};
    QTest::newRow("M4 without a spindle")
        << "emis"
        << ""
        << "M4 S100" << QStringList{"1:1: M4: no controller of this machine has a spindle"};
    QTest::newRow("M1 checks like M0") << "mill"
                                       << ""
                                       << "M1 (look)\nM0" << QStringList{};
    QTest::newRow("coolant without coolant")
        << "emis"
        << ""
        << "M7\nM8\nM9"
        << QStringList{"1:1: M7: no controller of this machine has coolant",
                       "2:1: M8: no controller of this machine has coolant",
                       "3:1: M9: no controller of this machine has coolant"};
    QTest::newRow("outputs and inputs over two controllers")
        << "io"
        << ""
        << "M64 P14\nM65 P1\nM66 P16 L3 Q1" << QStringList{};
    QTest::newRow("output past the last")
        << "io"
        << ""
        << "M64 P15" << QStringList{"1:5: M64 P15: the machine's outputs are 1..14"};
    QTest::newRow("output 0") << "io"
                              << ""
                              << "M65 P0"
                              << QStringList{"1:5: M65 P0: the machine's outputs are 1..14"};
    QTest::newRow("input past the last")
        << "io"
        << ""
        << "M66 L4 P17 Q1" << QStringList{"1:8: M66 P17: the machine's inputs are 1..16"};
    QTest::newRow("no outputs at all")
        << "mill"
        << ""
        << "M64 P1" << QStringList{"1:5: M64 P1: the machine has no digital outputs"};
    QTest::newRow("no inputs at all")
        << "mill"
        << ""
        << "M66 P1 L3 Q2" << QStringList{"1:5: M66 P1: the machine has no digital inputs"};
    QTest::newRow("every problem, in line order")
        << "mill"
        << "Y=0"
        << "G0 X1\nM64 P1\nG91 G1 A1 F10\nG0 Y300"
        << QStringList{"1:4: " + unknownX, "2:5: M64 P1: the machine has no digital outputs",
                       "3:8: A: controller \"tilt\" takes no feed rate, so G1 cannot move it; use "
                       "G0",
                       "3:8: A: controller \"tilt\" moves to targets only, so a relative move "
                       "(G91) needs the axis' position: home it (G28 A) or move it to an absolute "
                       "target first",
                       "4:4: Y reaches 300 mm, outside the soft limits 0..200 mm"};
    // Arcs (issue 29): the same path as the run, from the current point.
    QTest::newRow("arc within the limits") << "mill"
                                           << "X=0 Y=0"
                                           << "G0 X10 Y50\nG2 X10 Y60 I0 J5 F60" << QStringList{};
    QTest::newRow("arc past a soft limit at its extreme, not at its ends")
        << "mill"
        << "X=0 Y=0"
        << "G0 X1 Y50\nG2 X1 Y60 I0 J5 F60"
        << QStringList{"2:4: X reaches -4 mm, outside the soft limits 0..100 mm"};
    QTest::newRow("arc from an unknown position")
        << "mill"
        << "Y=0"
        << "G2 X10 Y10 I5 J5 F60"
        << QStringList{"1:4: G2: the position of X is unknown, so the arc has no start: "
                       "reference the axis first (G28 X)"};
    QTest::newRow("arc whose end is off its circle")
        << "mill"
        << "X=0 Y=0"
        << "G0 X10 Y10\nG2 X20 Y10 I4 J0 F60"
        << QStringList{"2:1: G2: the end point is not on the arc: radius 4 at the start, 6 at the "
                       "end, 2 apart (at most 0.028 allowed): check the centre and the end point"};
    QTest::newRow("arc in a repeat: named once")
        << "mill"
        << "X=0 Y=0"
        << "O1 repeat [3]\nG0 X10 Y10\nG2 X20 Y10 R4 F60\nO1 endrepeat"
        << QStringList{"3:12: G2: R4 is too short to reach the end point, 10 away"};
    QTest::newRow("G19 arc over the top of Z's travel")
        << "mill"
        << "Y=0 Z=0"
        << "G19 G2 Y10 Z0 J5 F60"
        << QStringList{"1:12: Z reaches 5 mm, outside the soft limits -50..0 mm"};
    // Drilling cycles (issue 29): every move of the cycle from the current point.
    QTest::newRow("cycle within the limits")
        << "mill"
        << "X=0 Y=0 Z=0"
        << "G99 G81 X10 Y10 Z-5 R-1 F60\nX20\nG80" << QStringList{};
    QTest::newRow("cycle's bottom past a soft limit")
        << "mill"
        << "X=0 Y=0 Z=0"
        << "G81 X10 Y10 Z-60 R-1 F60"
        << QStringList{"1:13: Z reaches -60 mm, outside the soft limits -50..0 mm"};
    QTest::newRow("cycle's R above the travel")
        << "mill"
        << "X=0 Y=0 Z=-10"
        << "G81 X10 Y10 Z-20 R5 F60"
        << QStringList{"1:13: Z reaches 5 mm, outside the soft limits -50..0 mm"};
    QTest::newRow("cycle from an unknown Z")
        << "mill"
        << "X=0 Y=0"
        << "G81 X10 Y10 Z-5 R-1 F60"
        << QStringList{"1:13: G81: the position of Z is unknown, so the cycle has no start: "
                       "reference the axis first (G28 Z)"};
    QTest::newRow("cycle's feed beyond Z's rate")
        << "millRefuse"
        << "X=0 Y=0 Z=0"
        << "G81 X10 Y10 Z-5 R-1 F600000"
        << QStringList{"1:21: F600000 is 1000000 steps/s on Z; controller \"table\" takes "
                       "0..65535 steps/s (Feed speed)"};
    QTest::newRow("repeat of count 0: its moves never run")
        << "mill"
        << "X=0"
        << "O1 repeat [0]\nG0 X500\nO1 endrepeat" << QStringList{};
}

void TestProgramCheck::check_errors_lineColumnAndMessage()
{
    QFETCH(QString, machine);
    QFETCH(QString, known);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    MachineFacts facts = machineFacts(machine);
    facts.knownPositions = positions(known);
    const Program p = parsed(program, facts);
    QVERIFY(!p.allBlocks().isEmpty());
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QCOMPARE(texts(result.errors), errors);
    QCOMPARE(result.ok(), errors.isEmpty());
}

void TestProgramCheck::machineIo_numberedOverTheControllers_data()
{
    QTest::addColumn<bool>("output");
    QTest::addColumn<int>("n");
    QTest::addColumn<QString>("controller"); // empty: none
    QTest::addColumn<int>("number");
    QTest::newRow("output 0") << true << 0 << "" << 0;
    QTest::newRow("output 1") << true << 1 << "io1" << 1;
    QTest::newRow("output 7") << true << 7 << "io1" << 7;
    QTest::newRow("output 8") << true << 8 << "io2" << 1;
    QTest::newRow("output 14") << true << 14 << "io2" << 7;
    QTest::newRow("output 15") << true << 15 << "" << 0;
    QTest::newRow("input 8") << false << 8 << "io1" << 8;
    QTest::newRow("input 9") << false << 9 << "io2" << 1;
    QTest::newRow("input 16") << false << 16 << "io2" << 8;
    QTest::newRow("input 17") << false << 17 << "" << 0;
    QTest::newRow("input -1") << false << -1 << "" << 0;
}

void TestProgramCheck::machineIo_numberedOverTheControllers()
{
    QFETCH(bool, output);
    QFETCH(int, n);
    QFETCH(QString, controller);
    QFETCH(int, number);
    const MachineFacts facts = machineFacts("io");
    const motion::SwitchExecutor switches(facts.description, facts.capabilities, facts.schemas);
    const std::optional<motion::SwitchExecutor::Io> io =
        output ? switches.output(n) : switches.input(n);
    QCOMPARE(io.has_value(), !controller.isEmpty());
    if (io) {
        QCOMPARE(io->controller, controller);
        QCOMPARE(io->number, number);
    }
}

void TestProgramCheck::examples_eachChecksCleanOnItsModel()
{
    const QDir dir(QStringLiteral(STEPDECK_SOURCE_DIR "/docs/examples"));
    const QStringList files = dir.entryList({QStringLiteral("*.ngc")}, QDir::Files, QDir::Name);
    QCOMPARE(files, (QStringList{"elab.ngc", "emis.ngc", "laser.ngc", "nanotec.ngc"}));
    for (const QString& name : files) {
        const QString base = name.chopped(4); // the model's id, "laser" for "laser-axis"
        const QString model = base == QLatin1String("laser") ? QStringLiteral("laser-axis") : base;
        MachineFacts single;
        const ModelInfo* info = findModel(model);
        QVERIFY2(info, qPrintable(name));
        single.description = MachineDescription::singleController(*info, QStringLiteral("sim"));
        single.capabilities.insert(model, info->capabilities);
        single.schemas.insert(model, info->schema);
        single.knownParameters.insert(model, setupDefaults(*info)); // as --setup-defaults
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QStringList names;
        for (const MachineAxis& a : single.description.axes)
            names << a.name;
        QList<ProgramError> errors;
        const std::optional<Program> p = ProgramParser::parse(file.readAll(), names, &errors);
        QVERIFY2(p, qPrintable(name + ": " + texts(errors).join('\n')));
        const ProgramCheckResult result = ProgramCheck::check(*p, single);
        QVERIFY2(result.ok(), qPrintable(name + ": " + texts(result.errors).join('\n')));
        QVERIFY2(result.preview.blocksRun > 3, qPrintable(name));
    }
}

void TestProgramCheck::factsOf_machineReferencedX_onlyXKnownAtZero()
{
    const ModelInfo* info = findModel("nanotec");
    const MachineDescription d = MachineDescription::singleController(*info, "sim");
    Machine machine;
    QString error;
    QVERIFY2(machine.create(d, &error), qPrintable(error));
    const MachineFacts before = factsOf(machine);
    QCOMPARE(before.description, d);
    QCOMPARE(before.capabilities.keys(), QStringList{"nanotec"});
    QCOMPARE(QByteArray(before.capabilities["nanotec"].feedRateParameter),
             QByteArray("max-frequency"));
    QVERIFY(before.schemas["nanotec"].find("max-frequency"));
    QVERIFY(before.knownPositions.isEmpty()); // not even connected

    machine.open();
    QTRY_COMPARE_WITH_TIMEOUT(machine.session("nanotec")->linkState(), LinkState::Connected, 10000);
    QVERIFY(factsOf(machine).knownPositions.isEmpty()); // connected, nothing referenced
    QSignalSpy done(&machine, &Machine::referenceFinished);
    QVERIFY2(machine.reference({"X"}, &error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, 30000);
    QVERIFY2(done.first().at(1).toBool(), qPrintable(done.first().at(2).toString()));
    const MachineFacts after = factsOf(machine);
    // A reference run ends at 0 (docs/programs.md "Check"): what the check assumes after G28.
    QCOMPARE(after.knownPositions, (QMap<QString, double>{{"X", 0.0}}));
    machine.destroy();
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramCheck)
#include "tst_programcheck.moc"
