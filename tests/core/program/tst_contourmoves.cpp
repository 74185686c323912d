// Which program blocks run as one step stream and the moves they become (issue 30,
// ContourMoves), and the check's refusal of a feed the stream's tick cannot carry. The
// expected figures are worked out here by hand from the machine's steps per unit.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "motion/ContourSteps.h"
#include "program/ContourMoves.h"
#include "program/FeedLimit.h"
#include "program/ProgramReader.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

class TestContourMoves : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void streamOf_whichBlocksJoin_data();
    void streamOf_whichBlocksJoin();
    void lineMove_absoluteAndRelative_machineUnitsInvertedScale();
    void arcMove_fullCircle_pointsOnTheCircle();
    void check_feedAboveTheTick_refusedNamingTheHighest_data();
    void check_feedAboveTheTick_refusedNamingTheHighest();
    void check_startSpeedNotKnown_refusedWithReason();
    void contourFeed_aboveTheTick_theHighestTheStreamTakes_data();
    void contourFeed_aboveTheTick_theHighestTheStreamTakes();
    void check_feedAboveTheTick_runsAtTheHighestWithNote_data();
    void check_feedAboveTheTick_runsAtTheHighestWithNote();
};

namespace {

ParameterSet startSpeeds(qint64 x, qint64 y, qint64 z)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}};
    return {{QStringLiteral("start-speed"), v}};
}

// The "contourMill" of the check's tests (E-LAB X 100, Y 200, Z 100 steps/mm; laser axis A) with
// the board's start speed known.
MachineFacts contourMill(qint64 startSpeed = 2000)
{
    MachineFacts f = machineFacts(QStringLiteral("contourMill"));
    f.knownParameters[QStringLiteral("table")] = startSpeeds(startSpeed, startSpeed, startSpeed);
    f.knownPositions = positions(QStringLiteral("X=10 Y=10 Z=-1"));
    return f;
}

ProgramBlock block(const QString& text, const MachineFacts& facts)
{
    const Program p = parsed(text, facts);
    const QList<ProgramBlock> blocks = p.allBlocks();
    return blocks.isEmpty() ? ProgramBlock{} : blocks.last();
}

} // namespace

void TestContourMoves::streamOf_whichBlocksJoin_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<bool>("joins");
    QTest::newRow("G1 X Y in G64 (the default)") << "G91 G1 X1 Y1 F100" << true;
    QTest::newRow("G1 X Y Z") << "G91 G1 X1 Y1 Z-1 F100" << true;
    QTest::newRow("G2 in XY") << "G91 G2 X2 I1 F100" << true;
    QTest::newRow("G61: exact path, a stop at each point") << "G61 G91 G1 X1 F100" << false;
    QTest::newRow("G61.1: exact stop") << "G61.1 G91 G1 X1 F100" << false;
    QTest::newRow("G0") << "G91 G0 X1" << false;
    QTest::newRow("G93 inverse time") << "G93 G91 G1 X1 F10" << false;
    QTest::newRow("an axis on another controller") << "G91 G1 X1 A1 F100" << false;
    QTest::newRow("only the laser axis") << "G91 G1 A1 F100" << false;
}

void TestContourMoves::streamOf_whichBlocksJoin()
{
    QFETCH(QString, line);
    QFETCH(bool, joins);
    const MachineFacts facts = contourMill();
    const ContourMoves contours(facts);
    const ProgramBlock b = block(line, facts);
    const ContourMoves::Stream* s = contours.streamOf(b);
    QCOMPARE(s != nullptr, joins);
    if (s) {
        QCOMPARE(s->controller, QStringLiteral("table"));
        QCOMPARE(s->tickRate, 1999.0);
        QCOMPARE(s->scale.axisCount, 3);
    }
}

// X 100 steps/mm inverted: its slot counts -100 per mm. An absolute target is work + offset,
// a relative one a distance from where the contour stands; F is per minute.
void TestContourMoves::lineMove_absoluteAndRelative_machineUnitsInvertedScale()
{
    MachineFacts facts = contourMill();
    facts.description.axes[0].invert = true;
    const ContourMoves contours(facts);
    const ProgramBlock absolute = block(QStringLiteral("G1 X10 Y5 F600"), facts);
    const ContourMoves::Stream* s = contours.streamOf(absolute);
    QVERIFY(s);
    QCOMPARE(s->scale.stepsPerUnit[0], -100.0);
    QCOMPARE(s->scale.stepsPerUnit[1], 200.0);
    const motion::Position from{1, 2, -3};
    const auto offset = [](const QString& axis) { return axis == QLatin1String("X") ? 20.0 : 0.0; };
    const motion::CanonicalMove a = contours.lineMove(*s, absolute, from, offset);
    QCOMPARE(a.start, from);
    QCOMPARE(a.end[0], 30.0);
    QCOMPARE(a.end[1], 5.0);
    QCOMPARE(a.end[2], -3.0); // Z stays
    QCOMPARE(a.feed, 10.0);   // 600 mm/min
    QCOMPARE(a.line, 1);
    const ProgramBlock relative = block(QStringLiteral("G91 G1 X-1 Z2 F60"), facts);
    const motion::CanonicalMove r = contours.lineMove(*s, relative, from, offset);
    QCOMPARE(r.end[0], 0.0);
    QCOMPARE(r.end[1], 2.0);
    QCOMPARE(r.end[2], -1.0);
    QCOMPARE(r.feed, 1.0);
}

// G2 full circle of radius 1 about X11 Y10 from X10 Y10, clockwise: a quarter of the way it is
// at X11 Y11 (clockwise from the left goes up), half way at X12 Y10.
void TestContourMoves::arcMove_fullCircle_pointsOnTheCircle()
{
    MachineFacts facts = contourMill();
    const ContourMoves contours(facts);
    const ProgramBlock b = block(QStringLiteral("G2 X10 Y10 I1 F60"), facts);
    const ContourMoves::Stream* s = contours.streamOf(b);
    QVERIFY(s);
    AxisPositions at{10.0, 10.0, 0.0, std::nullopt};
    const auto planning = ArcPath::plan(b, facts.description, at, {});
    QVERIFY(std::holds_alternative<ArcPath>(planning));
    const motion::CanonicalMove m =
        contours.arcMove(*s, b, std::get<ArcPath>(planning), contours.positionOf(*s, at));
    QCOMPARE(m.kind, motion::CanonicalMove::Kind::Arc);
    QVERIFY(std::fabs(m.length() - 2 * M_PI) < 1e-9);
    const motion::Position quarter = m.at(m.length() / 4);
    QVERIFY(std::fabs(quarter[0] - 11) < 1e-9 && std::fabs(quarter[1] - 11) < 1e-9);
    const motion::Position half = m.at(m.length() / 2);
    QVERIFY(std::fabs(half[0] - 12) < 1e-9 && std::fabs(half[1] - 10) < 1e-9);
    QCOMPARE(m.end[0], 10.0);
    QCOMPARE(m.end[1], 10.0);
}

// Start speed 500: the tick is 499/s. X has 100 steps/mm, Y 200: along X the highest feed is
// 4.99 mm/s = F299.4, along Y F149.7; a diagonal of X and Y at 45 degrees needs Y's 200
// steps/mm times F/sqrt(2), so F211.71 still runs there. A circle moves Y at the full path
// speed at its top and bottom: F149.7 again. The figure named is rounded down to 0.1 (a step
// per tick exactly is just beyond: ContourSteps keeps a hair below it), so that F runs.
void TestContourMoves::check_feedAboveTheTick_refusedNamingTheHighest_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("error");
    QTest::newRow("along X, within") << "G91 G1 X1 F299"
                                     << "";
    QTest::newRow("along X, beyond") << "G91 G1 X1 F300"
                                     << "highest feed is F299.3";
    QTest::newRow("along Y, beyond") << "G91 G1 Y1 F150"
                                     << "highest feed is F149.6";
    QTest::newRow("the diagonal, within") << "G91 G1 X1 Y1 F211"
                                          << "";
    QTest::newRow("the diagonal, beyond") << "G91 G1 X1 Y1 F212"
                                          << "highest feed is F211.7";
    QTest::newRow("a circle, beyond") << "G91 G2 X0 Y0 I1 F150"
                                      << "highest feed is F149.6";
    QTest::newRow("G61 moves alone: the board's feed-speed rule instead") << "G61 G91 G1 X1 F300"
                                                                          << "";
}

void TestContourMoves::check_feedAboveTheTick_refusedNamingTheHighest()
{
    QFETCH(QString, program);
    QFETCH(QString, error);
    MachineFacts facts = contourMill(500);
    facts.description.limits = machine::LimitPolicy::Refuse; // issue 50: refused as before
    const ProgramCheckResult r = ProgramCheck::check(parsed(program, facts), facts);
    const QStringList errors = texts(r.errors);
    if (error.isEmpty()) {
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
        return;
    }
    QCOMPARE(errors.size(), 1);
    QVERIFY2(errors.first().contains(error), qPrintable(errors.first()));
    QVERIFY2(errors.first().contains("contour stream of controller \"table\""),
             qPrintable(errors.first()));
    QVERIFY2(errors.first().contains("499 ticks/s"), qPrintable(errors.first()));
}

void TestContourMoves::check_startSpeedNotKnown_refusedWithReason()
{
    MachineFacts facts = machineFacts(QStringLiteral("contourMill"));
    facts.knownParameters.remove(QStringLiteral("table")); // this session wrote no setup
    const ProgramCheckResult r =
        ProgramCheck::check(parsed(QStringLiteral("G91 G1 X1 F60"), facts), facts);
    const QStringList errors = texts(r.errors);
    QCOMPARE(errors.size(), 1);
    QVERIFY2(errors.first().contains("Start speed is not known"), qPrintable(errors.first()));
}

// Issue 50, FeedLimit::contourFeed: a move's feed where its tick carries it, else the highest
// feed (mm/s) its tick allows, which the stream then takes (no slot steps more than once a
// tick); with "limits": "refuse" the feed as programmed (the check refuses it). Tick 499/s:
// along X (100 steps/mm) 4.99 mm/s, along Y (200) 2.495, the diagonal 2.495 x sqrt 2.
void TestContourMoves::contourFeed_aboveTheTick_theHighestTheStreamTakes_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<bool>("refuse");
    QTest::addColumn<double>("feed"); // mm/s the move runs at
    QTest::newRow("within: as programmed") << "G91 G1 X1 F240" << false << 4.0;
    QTest::newRow("along X") << "G91 G1 X1 F600" << false << 4.99;
    QTest::newRow("along Y") << "G91 G1 Y1 F600" << false << 2.495;
    QTest::newRow("the diagonal") << "G91 G1 X1 Y1 F600" << false << 2.495 * std::sqrt(2.0);
    QTest::newRow("refuse: as programmed") << "G91 G1 X1 F600" << true << 10.0;
}

void TestContourMoves::contourFeed_aboveTheTick_theHighestTheStreamTakes()
{
    QFETCH(QString, program);
    QFETCH(bool, refuse);
    QFETCH(double, feed);
    const MachineFacts facts = contourMill(500);
    const ContourMoves contours(facts);
    const ProgramBlock b = block(program, facts);
    const ContourMoves::Stream* s = contours.streamOf(b);
    QVERIFY(s);
    QCOMPARE(s->tickRate, 499.0);
    motion::CanonicalMove move =
        contours.lineMove(*s, b, motion::Position{}, [](const QString&) { return 0.0; });
    const double runs = FeedLimit::contourFeed(
        *s, move, refuse ? machine::LimitPolicy::Refuse : machine::LimitPolicy::Clamp);
    QVERIFY2(std::abs(runs - feed) < 1e-6, qPrintable(QString::number(runs, 'g', 12)));
    move.feed = runs;
    if (!refuse) // the stream takes it: within the tick
        QVERIFY(motion::ContourSteps::neededTickRate(move, s->scale) <= s->tickRate);
}

// The same moves as check_feedAboveTheTick_refusedNamingTheHighest, by default: no error, a
// note naming the F that runs (unrounded: the F the stream runs at, 3 decimals at most).
void TestContourMoves::check_feedAboveTheTick_runsAtTheHighestWithNote_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("runsAt"); // empty: no note
    QTest::newRow("along X, within") << "G91 G1 X1 F299"
                                     << "";
    QTest::newRow("along X, beyond") << "G91 G1 X1 F300"
                                     << "F300 runs at F299.4,";
    QTest::newRow("along Y, beyond") << "G91 G1 Y1 F150"
                                     << "F150 runs at F149.7,";
    QTest::newRow("the diagonal, beyond") << "G91 G1 X1 Y1 F212"
                                          << "F212 runs at F211.708,";
    QTest::newRow("a circle, beyond") << "G91 G2 X0 Y0 I1 F150"
                                      << "F150 runs at F149.7,";
}

void TestContourMoves::check_feedAboveTheTick_runsAtTheHighestWithNote()
{
    QFETCH(QString, program);
    QFETCH(QString, runsAt);
    const MachineFacts facts = contourMill(500);
    const ProgramCheckResult r = ProgramCheck::check(parsed(program, facts), facts);
    QVERIFY2(r.ok(), qPrintable(texts(r.errors).join('\n')));
    const QStringList notes = texts(r.notes);
    if (runsAt.isEmpty()) {
        QVERIFY2(notes.isEmpty(), qPrintable(notes.join('\n')));
        return;
    }
    QCOMPARE(notes.size(), 1);
    QVERIFY2(notes.first().contains(runsAt), qPrintable(notes.first()));
    QVERIFY2(notes.first().contains("contour stream of controller \"table\" (499 ticks/s"),
             qPrintable(notes.first()));
}

STEPDECK_TEST_MAIN(TestContourMoves)
#include "tst_contourmoves.moc"
