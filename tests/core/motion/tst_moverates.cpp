// The rates a move of its own writes (issue 49 item 3, motion::MoveRates; issue 50's limits):
// the feed-rate write of a G1 on each model, an axis at F limited at the highest its controller
// runs, coordinated shares slowed by one factor. The check (ProgramPlan) and the run
// (MoveExecutor) take a move's rates from these; the blocks here go through the lowering's
// ProgramLowering::ratedMove as theirs do.
#include "../program/ElabBoardTestSupport.h"
#include "TestMain.h"
#include "machine/MachineDescription.h"
#include "motion/executors/MoveRates.h"
#include "program/ProgramBlock.h"
#include "program/ProgramCheck.h"
#include "program/ProgramLowering.h"
#include "protocols/Registry.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::motion;
using namespace stepdeck::program;
using namespace stepdeck::program::elabboard;

using AxisWords = QMap<QString, double>;

namespace {

ProgramBlock feedBlock(const QMap<QString, double>& axes, double feed)
{
    ProgramBlock b;
    b.kind = BlockKind::Feed;
    for (auto it = axes.cbegin(); it != axes.cend(); ++it)
        b.axes.insert(it.key(), it.value());
    b.feed = feed;
    return b;
}

// The block's speeds as the check and the run hand them to MoveRates.
RatedMove g1(const ProgramBlock& block, const MachineDescription& d)
{
    return ProgramLowering::ratedMove(block, d);
}

} // namespace

class TestMoveRates : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void feedRateWrite_wholeSetModel_everyAxisGetsAValue_data();
    void feedRateWrite_wholeSetModel_everyAxisGetsAValue();
    void feedRateWrite_perAxisModel_onlyTheBlocksAxes();
    void feedLimit_axisAtF_runsAtTheHighest_data();
    void feedLimit_axisAtF_runsAtTheHighest();
    void feedLimit_coordinatedShares_slowedByOneFactor();
    void ratedMove_inchesAndG93_speedsInAxisUnitsPerSecond();
};

void TestMoveRates::feedRateWrite_wholeSetModel_everyAxisGetsAValue_data()
{
    QTest::addColumn<QString>("held");
    QTest::addColumn<AxisWords>("axes");
    QTest::addColumn<ParameterValue>("expected");
    // F6000 = 100 mm/min... in steps: 100 steps/s on an axis of 1 step per unit.
    QTest::newRow("nothing known: the others at the same F")
        << "" << AxisWords{{"X", 10}} << perAxis(100, 100, 100);
    QTest::newRow("known values kept for the axes that do not move")
        << "start=200,200,200 feed=40,30,20" << AxisWords{{"Y", 5}} << perAxis(40, 100, 20);
    QTest::newRow("two axes at F") << "start=200,200,200 feed=40,30,20"
                                   << AxisWords{{"X", 1}, {"Z", 2}} << perAxis(100, 30, 100);
}

void TestMoveRates::feedRateWrite_wholeSetModel_everyAxisGetsAValue()
{
    QFETCH(QString, held);
    QFETCH(AxisWords, axes);
    QFETCH(ParameterValue, expected);
    const MachineFacts f = elabFacts(known(held));
    const ParameterSet set =
        MoveRates::feedRateWrite(f.description, "elab", f.capabilities["elab"],
                                 g1(feedBlock(axes, 6000), f.description), known(held), nullptr);
    QCOMPARE(set.keys(), QStringList{"feed-speed"});
    QCOMPARE(set.value("feed-speed"), expected);
}

void TestMoveRates::feedRateWrite_perAxisModel_onlyTheBlocksAxes()
{
    const ModelInfo* info = findModel(QStringLiteral("nanotec"));
    const MachineDescription d = MachineDescription::singleController(*info, "sim");
    const ParameterSet set = MoveRates::feedRateWrite(
        d, "nanotec", info->capabilities, g1(feedBlock({{"Y", 5}}, 60000), d), {}, nullptr);
    QCOMPARE(set.keys(), QStringList{"max-frequency"});
    QCOMPARE(set.value("max-frequency").perAxis.keys(), QList<Axis>{Axis::Y});
    QCOMPARE(set.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 1000);
    // G0 writes no rate; G1 without F neither.
    ProgramBlock rapid = feedBlock({{"Y", 5}}, 60000);
    rapid.kind = BlockKind::Rapid;
    QVERIFY(MoveRates::feedRateWrite(d, "nanotec", info->capabilities, g1(rapid, d), {}, nullptr)
                .isEmpty());
    // Issue 30: a coordinated G1's shares (ProgramBlock::axisRates, per minute); a share below
    // the parameter's minimum (o: 60 steps/s) runs at it.
    ProgramBlock shares = feedBlock({{"X", 6000}, {"Y", 60}}, 6000);
    shares.axisRates = {{"X", 5999.7}, {"Y", 59.997}};
    const ParameterSet coordinated = MoveRates::feedRateWrite(
        d, "nanotec", info->capabilities, g1(shares, d), {}, info->schema.find("max-frequency"));
    QCOMPARE(coordinated.value("max-frequency").perAxis.value(Axis::X).toLongLong(), 100);
    QCOMPARE(coordinated.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 60);
    // Above the maximum (a feed override of 200 %): o's 25 000, and (issue 50, as LinuxCNC
    // slows the whole move) Y slowed by the same factor, 25 000 / 33 333, so both still arrive
    // together.
    shares.axisRates = {{"X", 2000000.0}, {"Y", 6000.0}};
    const ParameterSet fast = MoveRates::feedRateWrite(
        d, "nanotec", info->capabilities, g1(shares, d), {}, info->schema.find("max-frequency"));
    QCOMPARE(fast.value("max-frequency").perAxis.value(Axis::X).toLongLong(), 25000);
    QCOMPARE(fast.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 75);
    shares.axisRates = {{"X", 5999.7}, {"Y", 59.997}};
    // Without the spec (not known) the share stands as it is.
    QCOMPARE(MoveRates::feedRateWrite(d, "nanotec", info->capabilities, g1(shares, d), {}, nullptr)
                 .value("max-frequency")
                 .perAxis.value(Axis::Y)
                 .toLongLong(),
             1);
}

// Issue 50, MoveRates::axisRate: an axis at F (an E-LAB block of its own, in steps) runs at most
// one below the start speed the device holds (feed mode has no ramp), else at most its
// feed-rate parameter's top (65 535); with "limits": "refuse" as programmed. The rate
// feedRateWrite writes is the same.
void TestMoveRates::feedLimit_axisAtF_runsAtTheHighest_data()
{
    QTest::addColumn<QString>("held");
    QTest::addColumn<double>("feed"); // steps/min
    QTest::addColumn<bool>("refuse");
    QTest::addColumn<qint64>("runs");
    QTest::addColumn<bool>("limited");
    QTest::addColumn<bool>("belowParameter");
    QTest::newRow("within") << "start=100,100,100" << 5000.0 << false << qint64(83) << false
                            << true;
    QTest::newRow("at the start speed: one below")
        << "start=100,100,100" << 6000.0 << false << qint64(99) << true << true;
    QTest::newRow("start speed unknown: the range's top")
        << "" << 6000000.0 << false << qint64(65535) << true << false;
    QTest::newRow("start speed above the range: the range's top")
        << "start=70000,70000,70000" << 6000000.0 << false << qint64(65535) << true << false;
    QTest::newRow("refuse: as programmed")
        << "start=100,100,100" << 6000.0 << true << qint64(100) << false << false;
}

void TestMoveRates::feedLimit_axisAtF_runsAtTheHighest()
{
    QFETCH(QString, held);
    QFETCH(double, feed);
    QFETCH(bool, refuse);
    QFETCH(qint64, runs);
    QFETCH(bool, limited);
    QFETCH(bool, belowParameter);
    MachineFacts f = elabFacts(known(held));
    if (refuse)
        f.description.limits = LimitPolicy::Refuse;
    const Capabilities& caps = f.capabilities["elab"];
    const ParameterSpec* spec = f.schemas["elab"].find("feed-speed");
    QVERIFY(spec);
    const ProgramBlock b = feedBlock({{"X", 10}}, feed);
    const MoveRates::AxisRate rate = MoveRates::axisRate(
        f.description, f.description.axisIndex("X"), caps, spec, known(held), g1(b, f.description));
    QCOMPARE(rate.programmed, qint64(std::llround(feed / 60)));
    QCOMPARE(rate.runs, runs);
    QCOMPARE(rate.limited, limited);
    if (limited)
        QCOMPARE(rate.ceiling.belowParameter, belowParameter);
    const ParameterSet write = MoveRates::feedRateWrite(f.description, "elab", caps,
                                                        g1(b, f.description), known(held), spec);
    QCOMPARE(write.value("feed-speed").perAxis.value(Axis::X).toLongLong(), runs);
}

// Shares of F on a coordinating controller (a Nanotec bus in steps, o at most 25 000): a
// diagonal whose Y share would be 40 000 steps/s slows X and Y by one factor (0.625), so they
// still arrive together, as LinuxCNC slows the whole move; refused, each share is clamped at o
// on its own as before (a feed override's case).
void TestMoveRates::feedLimit_coordinatedShares_slowedByOneFactor()
{
    const ModelInfo* info = findModel(QStringLiteral("nanotec"));
    MachineDescription d = MachineDescription::singleController(*info, "sim");
    const ParameterSpec* spec = info->schema.find("max-frequency");
    QVERIFY(spec);
    ProgramBlock shares = feedBlock({{"X", 30000}, {"Y", 40000}}, 3000000);
    shares.axisRates = {{"X", 1800000.0}, {"Y", 2400000.0}}; // per minute: 30 000, 40 000 /s
    const MoveRates::AxisRate x =
        MoveRates::axisRate(d, d.axisIndex("X"), info->capabilities, spec, {}, g1(shares, d));
    const MoveRates::AxisRate y =
        MoveRates::axisRate(d, d.axisIndex("Y"), info->capabilities, spec, {}, g1(shares, d));
    QCOMPARE(x.programmed, qint64(30000));
    QCOMPARE(x.runs, qint64(18750));
    QCOMPARE(y.runs, qint64(25000));
    QCOMPARE(x.feedFactor, 0.625);
    QVERIFY(x.limited && y.limited);
    const ParameterSet write =
        MoveRates::feedRateWrite(d, "nanotec", info->capabilities, g1(shares, d), {}, spec);
    QCOMPARE(write.value("max-frequency").perAxis.value(Axis::X).toLongLong(), 18750);
    QCOMPARE(write.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 25000);
    d.limits = LimitPolicy::Refuse;
    QCOMPARE(
        MoveRates::axisRate(d, d.axisIndex("X"), info->capabilities, spec, {}, g1(shares, d)).runs,
        qint64(25000));
    QVERIFY(!MoveRates::axisRate(d, d.axisIndex("X"), info->capabilities, spec, {}, g1(shares, d))
                 .limited);
}

// The lowering's speeds: F per minute in the program's unit becomes the axis' unit per second
// (G20 on a millimetre axis: 25.4 mm per inch); G93's resolved rates go together, and an axis
// without one does not move; a rapid gets none.
void TestMoveRates::ratedMove_inchesAndG93_speedsInAxisUnitsPerSecond()
{
    const ModelInfo* info = findModel(QStringLiteral("nanotec"));
    MachineDescription d = MachineDescription::singleController(*info, "sim");
    d.axes[0].unit = AxisUnit::Millimetre;
    ProgramBlock b = feedBlock({{"X", 1}, {"Y", 2}}, 60);
    b.inches = true;
    RatedMove m = g1(b, d);
    QVERIFY(m.feed && !m.inverseTime);
    QCOMPARE(int(m.speeds.size()), 2);
    QCOMPARE(m.speeds[0].axis, 0);
    QCOMPARE(m.speeds[0].perSecond, 25.4); // 60 in/min on a mm axis
    QCOMPARE(m.speeds[1].perSecond, 1.0);  // Y in steps: not converted
    QVERIFY(!m.speeds[0].together);
    b.inches = false;
    b.inverseTime = true;
    b.axisRates = {{"Y", 120.0}};
    m = g1(b, d);
    QVERIFY(m.inverseTime);
    QCOMPARE(int(m.speeds.size()), 1);
    QCOMPARE(m.speeds[0].axis, 1);
    QCOMPARE(m.speeds[0].perSecond, 2.0);
    QVERIFY(m.speeds[0].together);
    b.kind = BlockKind::Rapid;
    QVERIFY(g1(b, d).speeds.empty());
    QVERIFY(!g1(b, d).feed);
}

STEPDECK_TEST_GUILESS_MAIN(TestMoveRates)
#include "tst_moverates.moc"
