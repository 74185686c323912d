// The program check over a whole program (issue 20, 50; docs/programs.md "Check"): feeds above
// the machine's highest run at it with a note, a run from a line, what stands around the program
// (block delete, program numbers, text after the end), an axis the machine lacks, repeats and
// the number of errors listed. Errors line by line: tst_programcheck.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "machine/Machine.h"
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

class TestProgramCheckWhole : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void check_feedAboveTheHighest_runsAtItWithNote_data();
    void check_feedAboveTheHighest_runsAtItWithNote();
    void check_fromLine_startOrRefusal_data();
    void check_fromLine_startOrRefusal();
    void check_axisTheMachineLacks_named();
    void check_relativeFromUnknown_refusedWhereTheModelMovesToTargetsOnly();
    void check_nestedEmptyRepeats_endQuickly();
    void check_tooManyBlocks_namedAtTheOutermostRepeat();
    void check_manyErrors_listedUpToTheParsersLimit();
    void check_aroundTheProgram_blockDeleteAndNotes_data();
    void check_aroundTheProgram_blockDeleteAndNotes();
};

// Issue 50: a feed above the highest a move can run at runs at that highest, as LinuxCNC and
// GRBL limit it: a note (line, column of F, programmed F, the F that runs), no error, and the
// estimate at the feed that runs. The mill's E-LAB holds start speed 2401: its contour ticks at
// 2100/s (X 100 steps/mm: at most 21 mm/s, F1260; Y 200: F630, in inches F24.803), a G61 block
// runs below the start speed (2400 steps/s: X at F1440). The Nanotec in steps slows both shares
// of a diagonal by one factor (o at most 25 000), so they still arrive together.
void TestProgramCheckWhole::check_feedAboveTheHighest_runsAtItWithNote_data()
{
    QTest::addColumn<QString>("machine");
    QTest::addColumn<QString>("known");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("notes");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<double>("seconds"); // the estimate; < 0: not asserted
    const QString contour = "F40000 runs at F1260, the highest this move can run at in the "
                            "contour stream of controller \"table\" (2100 ticks/s, one step per "
                            "tick at most)";
    QTest::newRow("contour: F above the tick runs at the highest")
        << "mill"
        << ""
        << "G28 X0\nG1 X10 F40000" << QStringList{"2:8: " + contour} << QStringList{} << 10.0 / 21;
    QTest::newRow("contour: one note for the F, the further lines counted")
        << "mill"
        << ""
        << "G28 X0\nG1 X10 F40000\nG1 X0\nG1 X10"
        << QStringList{"2:8: " + contour + " (also on 2 more line(s))"} << QStringList{}
        << 30.0 / 21;
    QTest::newRow("contour: G20 converts F")
        << "mill"
        << ""
        << "G20\nG28 Y0\nG1 Y1 F30"
        << QStringList{"3:7: F30 runs at F24.803, the highest this move can run at in the "
                       "contour stream of controller \"table\" (2100 ticks/s, one step per tick "
                       "at most)"}
        << QStringList{} << 25.4 / 10.5;
    QTest::newRow("G61: below the start speed")
        << "mill"
        << ""
        << "G61\nG28 X0\nG1 X10 F40000"
        << QStringList{"3:8: F40000 is 66667 steps/s on X, above the 2400 steps/s controller "
                       "\"table\" takes (below its Start speed: feed mode has no ramp): X runs "
                       "at F1440"}
        << QStringList{} << 10.0 / 24;
    QTest::newRow("Nanotec: both shares slowed by one factor")
        << "nanotec"
        << "X=0 Y=0"
        << "G1 X30000 Y40000 F3000000"
        << QStringList{"1:18: F3000000 moves X at 30000 steps/s, above the 25000 steps/s "
                       "controller \"nanotec\" takes (Maximum frequency at most): the move runs "
                       "at F1875000"}
        << QStringList{} << 1.6;
    QTest::newRow("within the highest: no note")
        << "mill"
        << ""
        << "G28 X0\nG1 X10 F1200" << QStringList{} << QStringList{} << 0.5;
    // What the device cannot do more slowly stays an error (o at least 60 steps/s).
    QTest::newRow("below the lowest: still refused")
        << "nanotec"
        << "X=0"
        << "G1 X100 F3000" << QStringList{}
        << QStringList{"1:9: F3000 is 50 steps/s on X; controller \"nanotec\" takes 60..25000 "
                       "steps/s (Maximum frequency)"}
        << -1.0;
    QTest::newRow("\"limits\": \"refuse\": the error of before, no note")
        << "millRefuse"
        << ""
        << "G28 X0\nG1 X10 F40000" << QStringList{}
        << QStringList{"2:8: F40000 is too fast for the contour stream of controller \"table\": "
                       "at its 2100 ticks/s (one step per tick at most) this move's highest feed "
                       "is F1259.9"}
        << -1.0;
}

void TestProgramCheckWhole::check_feedAboveTheHighest_runsAtItWithNote()
{
    QFETCH(QString, machine);
    QFETCH(QString, known);
    QFETCH(QString, program);
    QFETCH(QStringList, notes);
    QFETCH(QStringList, errors);
    QFETCH(double, seconds);
    MachineFacts facts = machineFacts(machine);
    facts.knownPositions = positions(known);
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts);
    QCOMPARE(texts(result.errors), errors);
    QCOMPARE(texts(result.notes), notes);
    if (seconds >= 0)
        QVERIFY2(std::abs(result.preview.estimatedSeconds - seconds) < 1e-3,
                 qPrintable(QString::number(result.preview.estimatedSeconds)));
}

void TestProgramCheckWhole::check_fromLine_startOrRefusal_data()
{
    QTest::addColumn<QString>("known");
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("fromLine");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<qint64>("blocksRun");

    const QString program = "G28 X0\n"          // 1
                            "O1 repeat [2]\n"   // 2
                            "  G0 X1\n"         // 3
                            "  O2 repeat [3]\n" // 4
                            "    G0 X2\n"       // 5
                            "  O2 endrepeat\n"  // 6
                            "O1 endrepeat\n"    // 7
                            "\n"                // 8
                            "G0 X3\n"           // 9
                            "M30\n";            // 10
    const QString inside =
        "run from line %1 is inside the repeat of line 2: start at line 2 or after its endrepeat";
    QTest::newRow("from 1") << "X=0" << program << 1 << QStringList{}
                            << qint64(1 + 2 * (1 + 3) + 2);
    QTest::newRow("from the repeat's line")
        << "X=0" << program << 2 << QStringList{} << qint64(8 + 2);
    QTest::newRow("inside the repeat")
        << "X=0" << program << 3 << QStringList{"3:1: " + inside.arg(3)} << qint64(0);
    QTest::newRow("at the inner repeat: the outer one is named")
        << "X=0" << program << 4 << QStringList{"4:1: " + inside.arg(4)} << qint64(0);
    QTest::newRow("at the endrepeat")
        << "X=0" << program << 7 << QStringList{"7:1: " + inside.arg(7)} << qint64(0);
    QTest::newRow("a blank line: the next block")
        << "X=0" << program << 8 << QStringList{} << qint64(2);
    QTest::newRow("past the last block")
        << "X=0" << program << 11
        << QStringList{"11:1: run from line 11: the program's last block is on line 10"}
        << qint64(0);
    // Issue 47 item 5: the run goes first to where line 1 leaves X (0), which needs X known.
    QTest::newRow("G28 skipped: the position is the machine's (unknown)")
        << ""
        << "G28 X0\nG0 X10" << 2
        << QStringList{"2:1: run from line 2: the move to its start point first (G53 G0 X0): X: "
                       "the position is unknown, so an absolute move could go anywhere: "
                       "reference the axis first (G28 X) or move it relatively (G91)"}
        << qint64(1);
}

void TestProgramCheckWhole::check_fromLine_startOrRefusal()
{
    QFETCH(QString, known);
    QFETCH(QString, program);
    QFETCH(int, fromLine);
    QFETCH(QStringList, errors);
    QFETCH(qint64, blocksRun);
    MachineFacts facts = machineFacts("mill");
    facts.knownPositions = positions(known);
    const ProgramCheckResult result = ProgramCheck::check(parsed(program, facts), facts, fromLine);
    QCOMPARE(texts(result.errors), errors);
    if (errors.isEmpty() || blocksRun > 0)
        QCOMPARE(result.preview.blocksRun, blocksRun);
}

// Issue 50 items 3, 6 and 8, through the check of a text (the window's, ProgramCheck::check of
// a source) and the check of the program it read (the run's): the block delete switch of the
// facts decides whether a "/" line is checked and run, plain or in LinuxCNC's language; the
// parser's and the working out's notes reach the result's notes, in line order.
void TestProgramCheckWhole::check_aroundTheProgram_blockDeleteAndNotes_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<bool>("blockDelete");
    QTest::addColumn<QStringList>("errors");
    QTest::addColumn<QStringList>("notes");
    QTest::addColumn<QString>("name");
    const QString plain = "G0 X10\n/G0 X150\nM30\nG0 X200\n(trailer)\n";
    const QString language = "#<x> = 10\nG0 X#<x>\n/G0 X150\nM30\nG0 X200\n";
    const QString beyond = "X reaches 150 mm, outside the soft limits 0..100 mm";
    QTest::newRow("plain, block delete on: the slash line is skipped")
        << plain << true << QStringList{}
        << QStringList{ProgramParser::blockDeleteNote(1, 2).text(),
                       ProgramParser::unreadNote(2, 3).text()}
        << QString();
    QTest::newRow("plain, block delete off: the slash line is checked")
        << plain << false << QStringList{"2:5: " + beyond}
        << QStringList{ProgramParser::unreadNote(2, 3).text()} << QString();
    QTest::newRow("LinuxCNC's language, block delete on")
        << language << true << QStringList{}
        << QStringList{ProgramParser::blockDeleteNote(1, 3).text(),
                       ProgramParser::unreadNote(1, 4).text()}
        << QString();
    QTest::newRow("LinuxCNC's language, block delete off")
        << language << false << QStringList{"3:5: " + beyond}
        << QStringList{ProgramParser::unreadNote(1, 4).text()} << QString();
    QTest::newRow("Fanuc wrapper, GRBL's $ lines, K0 on an arc")
        << "%\nO1001 (BRACKET)\n$H\n$32=1\nG0 X10\nG2 X20 Y0 I5 J0 K0.000 F300\nM30\n%\nG0 X500\n"
        << true << QStringList{}
        << QStringList{"4:1: $32=1 is a GRBL command (a setting, the alarm lock, a report or a "
                       "jog): not run",
                       "6:17: K0.000 on 1 arc(s), this one the first: an offset along the "
                       "plane's normal that is 0 is left out, as GRBL does (LinuxCNC refuses it; "
                       "any other value is refused)",
                       ProgramParser::unreadNote(1, 7).text()}
        << "O1001 (BRACKET)";
    QTest::newRow("LinuxCNC's language with a program number and a $ line")
        << "O1001\n#<x> = 10\n$X\nG0 X#<x>\nM2\n"
        << true << QStringList{}
        << QStringList{"3:1: $X is a GRBL command (a setting, the alarm lock, a report or a jog): "
                       "not run"}
        << "O1001";
}

void TestProgramCheckWhole::check_aroundTheProgram_blockDeleteAndNotes()
{
    QFETCH(QString, program);
    QFETCH(bool, blockDelete);
    QFETCH(QStringList, errors);
    QFETCH(QStringList, notes);
    QFETCH(QString, name);
    MachineFacts facts = machineFacts(QStringLiteral("mill"));
    facts.knownPositions = positions(QStringLiteral("X=0 Y=0 Z=0 A=0"));
    facts.blockDelete = blockDelete;
    QStringList axes;
    for (const MachineAxis& a : facts.description.axes)
        axes << a.name;
    const ProgramCheckResult result =
        ProgramCheck::check(ProgramSource::bytes(program.toUtf8()), axes, facts);
    QCOMPARE(texts(result.errors), errors);
    QCOMPARE(texts(result.notes), notes);
    if (!errors.isEmpty())
        return;
    QVERIFY(result.program);
    QCOMPARE(result.program->name, name);
    // The run's check reads the program as it was read, whatever the switch says now.
    facts.blockDelete = !blockDelete;
    const ProgramCheckResult again = ProgramCheck::check(*result.program, facts);
    QCOMPARE(texts(again.errors), errors);
    QCOMPARE(texts(again.notes), notes);
}

// A program parsed for other axes than the machine checked against (the machine file changed
// between reading and running).
void TestProgramCheckWhole::check_axisTheMachineLacks_named()
{
    const MachineFacts facts = machineFacts("mill");
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse("G28 B0\nG91 G0 X1 B2", {"X", "B"}, &errors);
    QVERIFY(p);
    QCOMPARE(texts(ProgramCheck::check(*p, facts).errors),
             (QStringList{"1:5: the machine has no axis B", "2:11: the machine has no axis B"}));
}

// A G91 move from an unknown position: the E-LAB counts it in steps from wherever it stands,
// the laser axis (the mill's A) moves to targets only and its adapter refuses it
// (LaserAxisMotion::moveRelative), so the check refuses it first; once A is referenced, or its
// position known, it passes.
void TestProgramCheckWhole::check_relativeFromUnknown_refusedWhereTheModelMovesToTargetsOnly()
{
    MachineFacts facts = machineFacts("mill");
    QCOMPARE(texts(ProgramCheck::check(parsed("G91 G0 X1 A2\n", facts), facts).errors),
             QStringList{"1:11: A: controller \"tilt\" moves to targets only, so a relative move "
                         "(G91) needs the axis' position: home it (G28 A) or move it to an "
                         "absolute target first"});
    QVERIFY(ProgramCheck::check(parsed("G28 A0\nG91 G0 X1 A2\n", facts), facts).ok());
    facts.knownPositions = positions("A=0");
    QVERIFY(ProgramCheck::check(parsed("G91 G0 X1 A2\n", facts), facts).ok());
}

// 10^6 passes of 10^6 passes of nothing: no block runs, so the walk must not spin 10^12 times.
void TestProgramCheckWhole::check_nestedEmptyRepeats_endQuickly()
{
    const MachineFacts facts = machineFacts("mill");
    const Program p = parsed("O1 repeat [1000000]\n O2 repeat [1000000]\n  O3 repeat [1000000]\n"
                             "  O3 endrepeat\n O2 endrepeat\nO1 endrepeat\nM5",
                             facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QVERIFY(result.ok());
    QCOMPARE(result.preview.blocksRun, qint64(1));
}

void TestProgramCheckWhole::check_tooManyBlocks_namedAtTheOutermostRepeat()
{
    const MachineFacts facts = machineFacts("mill");
    // The program's own blocks run once (M5, G4); the repeats run G4 6 * 10^6 - 1 times more.
    const Program p = parsed("M5\n  O1 repeat [1000000]\nO2 repeat [6]\nG4 P0\nO2 endrepeat\nO1 "
                             "endrepeat",
                             facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts);
    QCOMPARE(texts(result.errors),
             QStringList{"2:3: the repeats run more than 5000000 blocks beyond the program's own"});
    // Just within: the repeats run G4 10^6 * 5 - 1 times more.
    const Program within = parsed("M5\nO1 repeat [1000000]\nO2 repeat [5]\nG4 P0\nO2 "
                                  "endrepeat\nO1 endrepeat",
                                  facts);
    const ProgramCheckResult fits = ProgramCheck::check(within, facts);
    QVERIFY(fits.ok());
    QCOMPARE(fits.preview.blocksRun, qint64(1 + 1000000 * 5));
}

void TestProgramCheckWhole::check_manyErrors_listedUpToTheParsersLimit()
{
    const MachineFacts facts = machineFacts("mill");
    QString text;
    // Errors of the walk (line 1 last, after the walk of a repeat) and of the blocks (every
    // line), more than the list keeps while it collects them.
    text += "G0 X1\n";
    for (int i = 1; i < 1000; ++i)
        text += "M64 P1\n"; // the mill has no outputs
    const ProgramCheckResult result = ProgramCheck::check(parsed(text, facts), facts);
    QCOMPARE(result.errors.size(), ProgramParser::kMaxErrors + 1);
    QCOMPARE(result.errors.first().line, 1);
    QVERIFY(result.errors.first().message.contains("position is unknown"));
    QCOMPARE(result.errors.at(1).line, 2);
    QCOMPARE(result.errors.at(ProgramParser::kMaxErrors - 1).line, ProgramParser::kMaxErrors);
    QCOMPARE(result.errors.last().line, 1000);
    QCOMPARE(result.errors.last().message,
             QString("more errors follow; only the first 100 are listed"));
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramCheckWhole)
#include "tst_programcheckwhole.moc"
