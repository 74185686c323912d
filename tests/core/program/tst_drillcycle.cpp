// Drilling cycles (issue 29, docs/programs.md "Drilling cycles"): the words G81, G82, G83, G73,
// G80, G98, G99 as the parser reads them (sticky numbers, LinuxCNC's errors), and the moves
// DrillCycle expands them into from the current point: retract planes, pecks, dwell, repeats in
// G90 and G91, work offsets and inches, unknown positions and the bound on moves.
#include "MillTestSupport.h"
#include "TestMain.h"
#include "program/DrillCycle.h"
#include "program/ProgramParser.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::program;

namespace {

using pathtest::mill;

const QStringList kDrillAxes{QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z"),
                             QStringLiteral("A")};

std::optional<Program> parse(const QString& text, QList<ProgramError>* errors)
{
    return ProgramParser::parse(text.toUtf8(), kDrillAxes, errors);
}

// The moves of the last block of `program` from (x, y, z): "R Z5 | F Z-2 | D0.5 | R X10 Y5".
QString movesOf(const QString& program, const AxisPositions& start,
                const QMap<QString, double>& offsets = {})
{
    QList<ProgramError> errors;
    const std::optional<Program> p = parse(program, &errors);
    if (!p)
        return QStringLiteral("parse: ") + errors.first().text();
    const std::variant<DrillCycle, DrillCycle::Error> planned =
        DrillCycle::plan(p->allBlocks().last(), mill(), start, offsets);
    if (const DrillCycle::Error* e = std::get_if<DrillCycle::Error>(&planned))
        return QStringLiteral("error: ") + e->message;
    QStringList out;
    const char* names[] = {"X", "Y", "Z"};
    for (const DrillCycle::Segment& s : std::get<DrillCycle>(planned).segments()) {
        if (s.kind == DrillCycle::Kind::Dwell) {
            out << QStringLiteral("D%1").arg(s.seconds);
            continue;
        }
        QStringList words{s.kind == DrillCycle::Kind::Rapid ? QStringLiteral("R")
                                                            : QStringLiteral("F")};
        for (const auto& [axis, value] : s.targets)
            words << QStringLiteral("%1%2").arg(QLatin1String(names[axis])).arg(value);
        out << words.join(QLatin1Char(' '));
    }
    return out.join(QStringLiteral(" | "));
}

} // namespace

class DrillCycleTest : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_cycleWords_data();
    void parse_cycleWords();
    void parse_badCycle_namesWord_data();
    void parse_badCycle_namesWord();
    void plan_moves_data();
    void plan_moves();
    void plan_manyPecks_refusedBeforeAnyMove();
    void plan_peckBelowTheResolutionOfR_oneFeedToTheBottom();
};

void DrillCycleTest::parse_cycleWords_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("code");
    QTest::addColumn<double>("r");
    QTest::addColumn<double>("bottom");
    QTest::addColumn<double>("peck");
    QTest::addColumn<double>("dwell");
    QTest::addColumn<int>("repeats");
    QTest::addColumn<bool>("retractToR");
    QTest::addColumn<QString>("axes");
    QTest::newRow("G81") << "F100\nG81 X1 Y2 Z-3 R1" << 81 << 1.0 << -3.0 << 0.0 << 0.0 << 1
                         << false << "X1 Y2";
    QTest::newRow("G99 G82 P") << "F100\nG99 G82 X1 Z-3 R1 P0.5" << 82 << 1.0 << -3.0 << 0.0 << 0.5
                               << 1 << true << "X1";
    QTest::newRow("G83 Q") << "F100\nG83 Z-10 R2 Q2.5" << 83 << 2.0 << -10.0 << 2.5 << 0.0 << 1
                           << false << "";
    QTest::newRow("G73 L") << "F100\nG91\nG73 X5 Z-4 R-1 Q1 L3" << 73 << -1.0 << -4.0 << 1.0 << 0.0
                           << 3 << false << "X5";
    // LinuxCNC's sticky numbers: a line of axis words drills again with the same R, Z, Q.
    QTest::newRow("sticky") << "F100\nG83 X1 Z-10 R2 Q2.5\nX4 Y4" << 83 << 2.0 << -10.0 << 2.5
                            << 0.0 << 1 << false << "X4 Y4";
    QTest::newRow("sticky, new Z")
        << "F100\nG81 X1 Z-10 R2\nX4 Z-6" << 81 << 2.0 << -6.0 << 0.0 << 0.0 << 1 << false << "X4";
    QTest::newRow("G98 after G99") << "F100\nG99\nG81 X1 Z-1 R1\nG98 X2" << 81 << 1.0 << -1.0 << 0.0
                                   << 0.0 << 1 << false << "X2";
}

void DrillCycleTest::parse_cycleWords()
{
    QFETCH(QString, program);
    QList<ProgramError> errors;
    const std::optional<Program> p = parse(program, &errors);
    QVERIFY2(p, qPrintable(errors.isEmpty() ? QString() : errors.first().text()));
    const ProgramBlock b = p->allBlocks().last();
    QCOMPARE(b.kind, BlockKind::DrillCycle);
    QTEST(b.cycle.code, "code");
    QTEST(b.cycle.r, "r");
    QTEST(b.cycle.bottom, "bottom");
    QTEST(b.cycle.peck, "peck");
    QTEST(b.cycle.dwell, "dwell");
    QTEST(b.cycle.repeats, "repeats");
    QTEST(b.cycle.retractToR, "retractToR");
    QStringList axes;
    for (auto it = b.axes.cbegin(); it != b.axes.cend(); ++it)
        axes << QStringLiteral("%1%2").arg(it.key()).arg(it.value());
    QTEST(axes.join(QLatin1Char(' ')), "axes");
    QCOMPARE(blockWord(b), QStringLiteral("G%1").arg(b.cycle.code));
}

void DrillCycleTest::parse_badCycle_namesWord_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("error");
    QTest::newRow("no R") << "F100\nG81 X1 Z-1"
                          << "2:1: G81 needs R: the retract plane";
    QTest::newRow("no Z") << "F100\nG81 X1 R1"
                          << "2:1: G81 needs Z: the hole's bottom";
    QTest::newRow("G83 without Q") << "F100\nG83 Z-1 R1"
                                   << "2:1: G83 needs Q: the depth of each peck";
    QTest::newRow("Q zero") << "F100\nG73 Z-1 R1 Q0"
                            << "2:12: G73: Q, the depth of each peck, must be greater than 0";
    QTest::newRow("Q on G81") << "F100\nG81 Z-1 R1 Q1"
                              << "2:12: Q1 is not used by G81";
    QTest::newRow("G82 without P") << "F100\nG82 Z-1 R1"
                                   << "2:1: G82 needs P: the dwell at the bottom in seconds";
    QTest::newRow("Z above R") << "F100\nG81 Z2 R1"
                               << "2:1: G81: Z2 lies above R1: the hole's bottom must lie below "
                                  "the retract plane";
    QTest::newRow("G91 Z up") << "F100\nG91 G81 Z2 R1"
                              << "2:5: G81: in G91, Z is measured down from R: not above 0";
    QTest::newRow("L0") << "F100\nG81 Z-1 R1 L0"
                        << "2:12: L0: L, the repeats, takes a whole "
                           "number 1..10000";
    QTest::newRow("G18") << "F100\nG18 G81 Z-1 R1"
                         << "2:5: G81: drilling cycles run in the XY plane (G17) only";
    QTest::newRow("A axis") << "F100\nG81 A5 Z-1 R1"
                            << "2:5: G81: a drilling cycle moves X, Y and Z only, not A";
    QTest::newRow("no F") << "G81 Z-1 R1"
                          << "1:1: G81 needs a feed rate: F on this line or an earlier one";
    // Numbers are sticky only within the same cycle (LinuxCNC).
    QTest::newRow("other cycle") << "F100\nG81 Z-1 R1\nG83 X2 Q1"
                                 << "3:1: G83 needs Z: the hole's bottom";
    QTest::newRow("after G80") << "F100\nG81 Z-1 R1\nG80\nX2"
                               << "4:1: axis words need G0, G1, G2 or G3 before them";
    QTest::newRow("with G1") << "F100\nG1 G81 Z-1 R1"
                             << "2:4: G1 and G81 on one line: they are of one modal group";
    QTest::newRow("G53") << "F100\nG53 G81 Z-1 R1"
                         << "2:1: G53 moves in machine coordinates with G0 or G1 only";
}

void DrillCycleTest::parse_badCycle_namesWord()
{
    QFETCH(QString, program);
    QList<ProgramError> errors;
    QVERIFY(!parse(program, &errors));
    QVERIFY(!errors.isEmpty());
    QTEST(errors.first().text(), "error");
}

void DrillCycleTest::plan_moves_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<AxisPositions>("start");
    QTest::addColumn<QString>("moves");
    const AxisPositions above{0.0, 0.0, 10.0};
    QTest::newRow("G81 G98: back to the initial level")
        << "F100\nG81 X10 Y5 Z-2 R1" << above << "R X10 Y5 | R Z1 | F Z-2 | R Z10";
    QTest::newRow("G81 G99: back to R")
        << "F100\nG99 G81 X10 Y5 Z-2 R1" << above << "R X10 Y5 | R Z1 | F Z-2 | R Z1";
    QTest::newRow("below R: up to R first")
        << "F100\nG81 X10 Z-2 R5" << AxisPositions{0.0, 0.0, 2.0} << "R Z5 | R X10 | F Z-2 | R Z5";
    QTest::newRow("G82 dwells at the bottom")
        << "F100\nG82 X1 Z-2 R1 P0.5" << above << "R X1 | R Z1 | F Z-2 | D0.5 | R Z10";
    // Pecks of 2 from R1 to -4.5: out to R after each and back down to 0.254 above the depth.
    QTest::newRow("G83 pecks")
        << "F100\nG83 Z-4.5 R1 Q2" << above
        << "R Z1 | F Z-1 | R Z1 | R Z-0.746 | F Z-3 | R Z1 | R Z-2.746 | F Z-4.5 | R Z10";
    QTest::newRow("G73 breaks the chip")
        << "F100\nG99 G73 Z-4 R1 Q2" << above
        << "R Z1 | F Z-1 | R Z-0.746 | F Z-3 | R Z-2.746 | F Z-4 | R Z1";
    // G91: R from the current Z, Z from R, X Y increments per repeat.
    QTest::newRow("G91 L3")
        << "F100\nG91 G81 X5 Z-3 R-8 L3" << above
        << "R X5 | R Z2 | F Z-1 | R Z10 | R X10 | R Z2 | F Z-1 | R Z10 | R X15 | R Z2 | F Z-1 | "
           "R Z10";
    QTest::newRow("G90 L2: the same hole twice")
        << "F100\nG99 G81 X1 Z-1 R1 L2" << above << "R X1 | R Z1 | F Z-1 | R Z1 | F Z-1 | R Z1";
    QTest::newRow("inch") << "F10\nG20 G99 G81 X1 Z-0.1 R0.1" << above
                          << "R X25.4 | R Z2.54 | F Z-2.54 | R Z2.54";
    QTest::newRow("no position of Z")
        << "F100\nG81 X1 Z-1 R1" << AxisPositions{0.0, 0.0, std::nullopt}
        << "error: G81: the position of Z is unknown, so the cycle has no start: reference the "
           "axis first (G28 Z)";
}

void DrillCycleTest::plan_moves()
{
    QFETCH(QString, program);
    QFETCH(AxisPositions, start);
    QTEST(movesOf(program, start), "moves");
}

void DrillCycleTest::plan_manyPecks_refusedBeforeAnyMove()
{
    // Work offsets move R and the bottom; a Q of 1 µm over 1 m is 10^6 pecks: refused.
    QCOMPARE(movesOf("F100\nG99 G81 X1 Z-1 R1", {0.0, 0.0, 50.0},
                     {{QStringLiteral("X"), 100.0}, {QStringLiteral("Z"), 20.0}}),
             QStringLiteral("R X101 | R Z21 | F Z19 | R Z21"));
    QCOMPARE(movesOf("F100\nG83 Z-1000 R1 Q0.001", {0.0, 0.0, 50.0}),
             QStringLiteral("error: G83 takes more than 100000 moves: make Q larger or L smaller"));
}

// Found by fuzzing (issue 33): in G91, R 10^18 above Z puts the bottom 200 below it, where a
// peck of 1 is below a double's resolution (depth - Q == depth): the cycle feeds to the bottom
// once instead of pecking for ever.
void DrillCycleTest::plan_peckBelowTheResolutionOfR_oneFeedToTheBottom()
{
    const QString moves = movesOf("F100\nG91 G83 Z-200 R1000000000000000000 Q1", {0.0, 0.0, 10.0});
    QCOMPARE(moves.count(QStringLiteral("F Z")), 1);
    QVERIFY2(moves.startsWith(QStringLiteral("R Z1e+18 | F Z")), qPrintable(moves));
}

STEPDECK_TEST_GUILESS_MAIN(DrillCycleTest)
#include "tst_drillcycle.moc"
