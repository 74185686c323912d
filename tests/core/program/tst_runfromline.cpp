// Run from line N (issue 47 item 5): where the lines before it leave the tool, and the rapids
// that bring it there first (RunFromState: Z up first or down last, as gSender and UGS do), as
// the confirmation names them; and the check of such a run, which judges those rapids and the
// restored spindle as the run will send them (RunFromState::prelude, one function for both).
// The run itself, asserted at the device: tst_programrunner's runFromLine_ tests.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/ProgramReader.h"
#include "program/RunFromLine.h"

using namespace stepdeck;
using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

namespace {

// The test machines by name: checktest's, and "mill" with a work offset or a spindle scale.
MachineFacts factsNamed(const QString& name)
{
    if (name.endsWith(QLatin1String("Refuse"))) { // issue 50: "limits": "refuse"
        MachineFacts f = factsNamed(name.chopped(6));
        f.description.limits = machine::LimitPolicy::Refuse;
        return f;
    }
    if (name == QLatin1String("millOffset")) {
        MachineFacts f = machineFacts(QStringLiteral("mill"));
        f.coordinateSystems[0] = {{QStringLiteral("X"), 20.0}, {QStringLiteral("Z"), -30.0}};
        return f;
    }
    if (name == QLatin1String("millSpindle")) {
        MachineFacts f = machineFacts(QStringLiteral("mill"));
        f.description.spindle.maxRpm = 24000;
        return f;
    }
    return machineFacts(name);
}

// What a run from `fromLine` of `text` starts with (*line: its first block's line).
RunFromState stateAt(const QString& text, const MachineFacts& facts, int fromLine, int* line)
{
    const Program program = parsed(text, facts);
    ProgramReader reader(program);
    const int first = reader.firstBlockAtLine(fromLine);
    const ProgramBlock* block = reader.at(first);
    *line = block ? block->line : 0;
    return RunFromState::before(reader, first, facts);
}

QStringList blockTexts(const QList<ProgramBlock>& blocks)
{
    QStringList out;
    for (const ProgramBlock& b : blocks)
        out << b.text;
    return out;
}

} // namespace

class TestRunFromLine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void approach_zUpFirstOrDownLast_namedInItsOrder_data();
    void approach_zUpFirstOrDownLast_namedInItsOrder();
    void check_approachOrRestoredSpindleRefused_namedAtTheStartLine_data();
    void check_approachOrRestoredSpindleRefused_namedAtTheStartLine();
    void check_fromLine_previewWalksTheApproachNotCountedAsBlocks();
};

void TestRunFromLine::approach_zUpFirstOrDownLast_namedInItsOrder_data()
{
    QTest::addColumn<QString>("machine");
    QTest::addColumn<QString>("known");
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("fromLine");
    QTest::addColumn<QStringList>("prelude"); // RunFromState::prelude's blocks
    QTest::addColumn<QString>("text");        // approachText, for the confirmation

    // The mill: X, Y, Z in mm (Z -50..0), A in degrees. Line 4 starts at X10 Y5 Z-10.
    const QString cut = "G0 Z-5\nG0 X10 Y5\nG1 Z-10 F100\nG1 X20 F100\n";
    QTest::newRow("start above: Z up first, then X Y")
        << "mill"
        << "X=0 Y=0 Z=-20 A=0" << cut << 4 << QStringList{"G53 G0 Z-10", "G53 G0 X10 Y5"}
        << "Z up to -10.000 mm, then X 10.000 mm Y 5.000 mm at rapid";
    QTest::newRow("start below: X Y first at the tool's height, then Z down")
        << "mill"
        << "X=0 Y=0 Z=-2 A=0" << cut << 4 << QStringList{"G53 G0 X10 Y5", "G53 G0 Z-10"}
        << "X 10.000 mm Y 5.000 mm, then Z down to -10.000 mm at rapid";
    QTest::newRow("Z there already: X Y only")
        << "mill"
        << "X=0 Y=0 Z=-10" << cut << 4 << QStringList{"G53 G0 X10 Y5"}
        << "X 10.000 mm Y 5.000 mm at rapid";
    QTest::newRow("all there already: nothing moves first")
        << "mill"
        << "X=10 Y=5 Z=-10 A=0" << cut << 4 << QStringList{} << QString();
    QTest::newRow("switches first, then the approach")
        << "mill"
        << "X=0 Y=0 Z=-20"
        << "M3 S500\nM8\nG0 X10 Z-5\nG0 X20\n"
        << 4 << QStringList{"M3 S500", "M8", "G53 G0 Z-5", "G53 G0 X10"}
        << "Z up to -5.000 mm, then X 10.000 mm at rapid";
    // G54 X20 Z-30: the program's X10 Z5 is machine X30 Z-25.
    QTest::newRow("work offsets: machine positions")
        << "millOffset"
        << "X=0 Z=-40"
        << "G0 X10 Z5\nG0 X11\n"
        << 2 << QStringList{"G53 G0 Z-25", "G53 G0 X30"}
        << "Z up to -25.000 mm, then X 30.000 mm at rapid";
    QTest::newRow("no Z: one rapid")
        << "mixed"
        << "X=0 A=0"
        << "G0 X10 A90\nG0 X20\n"
        << 2 << QStringList{"G53 G0 X10 A90"} << "X 10.000 mm A 90.000 deg at rapid";
    QTest::newRow("relative from the program's start: left where it stands")
        << "mill"
        << "X=0 Y=0 Z=0"
        << "G91 G0 X5\nG0 X1\n"
        << 2 << QStringList{} << QString();
    QTest::newRow("relative after an absolute move: followed")
        << "mill"
        << "X=0 Y=0 Z=0"
        << "G0 X5\nG91 G0 X1\nG0 X1\n"
        << 3 << QStringList{"G53 G0 X6"} << "X 6.000 mm at rapid";
    QTest::newRow("an arc ends at its words")
        << "mill"
        << "X=0 Y=0 Z=-1"
        << "G0 X0 Y0 Z-1\nG2 X10 Y0 I5 J0 F100\nG0 X20\n"
        << 3 << QStringList{"G53 G0 X10"} << "X 10.000 mm at rapid";
    QTest::newRow("G28: at the reference")
        << "mill"
        << "X=5 Y=0 Z=0"
        << "G28 X0\nG0 X20\n"
        << 2 << QStringList{"G53 G0 X0"} << "X 0.000 mm at rapid";
    // G98: out to the higher of R and the Z the cycle began at.
    QTest::newRow("a drilling cycle ends at its clearance level")
        << "mill"
        << "X=0 Y=0 Z=-2"
        << "G0 X0 Y0 Z-2\nF100\nG81 X10 Y10 Z-8 R-1\nG80\nG0 X20\n"
        << 5 << QStringList{"G53 G0 Z-1", "G53 G0 X10 Y10"}
        << "Z up to -1.000 mm, then X 10.000 mm Y 10.000 mm at rapid";
    QTest::newRow("relative moves repeated: left where they stand")
        << "mill"
        << "X=0 Y=0 Z=0"
        << "G0 X1\nO1 repeat [3]\nG91 G0 X1\nO1 endrepeat\nG90 G0 X20\n"
        << 5 << QStringList{} << QString();
    QTest::newRow("a repeat of no passes does not run")
        << "mill"
        << "X=0 Y=0 Z=0"
        << "G0 X1\nO1 repeat [0]\nG0 X50\nO1 endrepeat\nG0 X20\n"
        << 5 << QStringList{"G53 G0 X1"} << "X 1.000 mm at rapid";
}

void TestRunFromLine::approach_zUpFirstOrDownLast_namedInItsOrder()
{
    QFETCH(QString, machine);
    QFETCH(QString, known);
    QFETCH(QString, program);
    QFETCH(int, fromLine);
    QFETCH(QStringList, prelude);
    QFETCH(QString, text);
    MachineFacts facts = factsNamed(machine);
    facts.knownPositions = positions(known);
    int line = 0;
    const RunFromState state = stateAt(program, facts, fromLine, &line);
    QCOMPARE(line, fromLine);
    const QList<ProgramBlock> blocks = state.prelude(facts, line);
    QCOMPARE(blockTexts(blocks), prelude);
    for (const ProgramBlock& b : blocks)
        QCOMPARE(b.line, fromLine); // named at the line the run starts from
    QCOMPARE(state.approachText(facts), text);
}

void TestRunFromLine::check_approachOrRestoredSpindleRefused_namedAtTheStartLine_data()
{
    QTest::addColumn<QString>("machine");
    QTest::addColumn<QString>("known");
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("fromLine");
    QTest::addColumn<QStringList>("errors");

    QTest::newRow("the approach within the limits: checked clean") << "mill"
                                                                   << "X=0 Y=0 Z=0"
                                                                   << "G0 X10 Y5 Z-5\nG0 X20\n"
                                                                   << 2 << QStringList{};
    // Line 1 is not checked (it does not run), but the run would go there first.
    QTest::newRow("the start point beyond the soft limits")
        << "mill"
        << "X=0 Y=0 Z=0"
        << "G0 X150\nG0 X50\n"
        << 2
        << QStringList{"2:1: run from line 2: the move to its start point first (G53 G0 X150): "
                       "X reaches 150 mm, outside the soft limits 0..100 mm"};
    QTest::newRow("the start point on an axis whose position is unknown")
        << "mill"
        << "X=0 Y=0"
        << "G0 Z-5\nG0 X1\n"
        << 2
        << QStringList{"2:1: run from line 2: the move to its start point first (G53 G0 Z-5): "
                       "Z: the position is unknown, so an absolute move could go anywhere: "
                       "reference the axis first (G28 Z) or move it relatively (G91)"};
    // With "limits": "refuse" (issue 50); clamped, the S runs at maxRpm with a note.
    QTest::newRow("the spindle restored at an S above the spindle's maxRpm")
        << "millSpindleRefuse"
        << "X=0 Y=0 Z=0"
        << "M3 S30000\nG0 X1\nG0 X2\n"
        << 3
        << QStringList{"3:1: run from line 3: M3 S30000 first, as the lines before it left it: "
                       "controller \"table\": S30000 is above the spindle's maxRpm 24000 (the "
                       "machine file's spindle scale)"};
    QTest::newRow("the spindle restored at an S above maxRpm, clamped: no error")
        << "millSpindle"
        << "X=0 Y=0 Z=0"
        << "M3 S30000\nG0 X1\nG0 X2\n"
        << 3 << QStringList{};
    QTest::newRow("from the first line: nothing first") << "mill"
                                                        << "X=0 Y=0 Z=0"
                                                        << "G0 X50\nG0 X60\n"
                                                        << 1 << QStringList{};
}

void TestRunFromLine::check_approachOrRestoredSpindleRefused_namedAtTheStartLine()
{
    QFETCH(QString, machine);
    QFETCH(QString, known);
    QFETCH(QString, program);
    QFETCH(int, fromLine);
    QFETCH(QStringList, errors);
    MachineFacts facts = factsNamed(machine);
    facts.knownPositions = positions(known);
    const Program p = parsed(program, facts);
    const ProgramCheckResult result = ProgramCheck::check(p, facts, fromLine);
    QCOMPARE(texts(result.errors), errors);
    // The one pass over the text (the window's check) judges the same.
    const ProgramCheckResult onePass = ProgramCheck::check(
        ProgramSource::bytes(program.toUtf8()),
        {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z"), QStringLiteral("A")}, facts,
        fromLine);
    QCOMPARE(texts(onePass.errors), errors);
}

// The preview's path goes where the run goes: X Y across at the tool's height, Z down, then
// line 2; the rapids are no blocks of the program (blocksRun counts line 2 only).
void TestRunFromLine::check_fromLine_previewWalksTheApproachNotCountedAsBlocks()
{
    MachineFacts facts = machineFacts(QStringLiteral("mill"));
    facts.knownPositions = positions(QStringLiteral("X=0 Y=0 Z=0"));
    const ProgramCheckResult result =
        ProgramCheck::check(parsed(QStringLiteral("G0 X10 Y5 Z-5\nG0 X20\n"), facts), facts, 2);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join(QLatin1Char('\n'))));
    QCOMPARE(result.preview.blocksRun, qint64(1));
    using Position = QMap<QString, double>;
    const QList<PreviewPoint>& path = result.preview.path;
    QCOMPARE(path.size(), 4);
    QCOMPARE(path.at(0).position, (Position{{"X", 0.0}, {"Y", 0.0}, {"Z", 0.0}}));
    QCOMPARE(path.at(1).position, (Position{{"X", 10.0}, {"Y", 5.0}, {"Z", 0.0}}));
    QCOMPARE(path.at(2).position, (Position{{"X", 10.0}, {"Y", 5.0}, {"Z", -5.0}}));
    QCOMPARE(path.at(3).position, (Position{{"X", 20.0}, {"Y", 5.0}, {"Z", -5.0}}));
    QVERIFY(path.at(1).rapid && path.at(2).rapid);
    QCOMPARE(path.at(1).line, 2);
    QCOMPARE(path.at(1).blocksDone, qint64(0));
    QVERIFY(result.preview.estimatedSeconds > 0);
}

STEPDECK_TEST_MAIN(TestRunFromLine)
#include "tst_runfromline.moc"
