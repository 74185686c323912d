// The rules both the check and the run go by (issue 28, ProgramRules): the feed-rate write a
// G1 makes, the model's parameter rules judged against what the device holds and an incomplete
// setup, and the check refusing with them what the run would refuse (the spindle's range:
// tst_switchexecutor);
// the limits both take a feed or S above the machine's highest by (issue 50, FeedLimit).
#include "TestMain.h"
#include "program/FeedLimit.h"
#include "program/ProgramCheck.h"
#include "program/ProgramParser.h"
#include "program/ProgramRules.h"
#include "protocols/Registry.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;

using AxisWords = QMap<QString, double>;

namespace {

// An E-LAB board in its own steps (MachineDescription::singleController: X, Y, Z), with its
// model's rules, and `known` the values the host knows it holds.
MachineFacts elabFacts(const ParameterSet& known)
{
    const ModelInfo* info = findModel(QStringLiteral("elab"));
    MachineFacts f;
    f.description = MachineDescription::singleController(*info, QStringLiteral("sim"));
    f.capabilities.insert("elab", info->capabilities);
    f.schemas.insert("elab", info->schema);
    f.models.insert("elab", info);
    f.knownParameters.insert("elab", known);
    return f;
}

ParameterValue perAxis(qint64 x, qint64 y, qint64 z)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}};
    return v;
}

// "start=100,100,100 feed=50,50,50": the known parameter values.
ParameterSet known(const QString& text)
{
    ParameterSet out;
    for (const QString& pair : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QStringList kv = pair.split(QLatin1Char('='));
        const QStringList v = kv.at(1).split(QLatin1Char(','));
        const QString name = kv.at(0) == QLatin1String("start") ? QStringLiteral("start-speed")
                                                                : QStringLiteral("feed-speed");
        out.insert(name, perAxis(v.at(0).toLongLong(), v.at(1).toLongLong(), v.at(2).toLongLong()));
    }
    return out;
}

QStringList checked(const QString& text, const MachineFacts& facts)
{
    QStringList names;
    for (const MachineAxis& a : facts.description.axes)
        names << a.name;
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(text.toUtf8(), names, &errors);
    QStringList out;
    for (const ProgramError& e : errors)
        out << e.text();
    if (!p)
        return out;
    for (const ProgramError& e : ProgramCheck::check(*p, facts).errors)
        out << e.text();
    return out;
}

ProgramBlock feedBlock(const QMap<QString, double>& axes, double feed)
{
    ProgramBlock b;
    b.kind = BlockKind::Feed;
    for (auto it = axes.cbegin(); it != axes.cend(); ++it)
        b.axes.insert(it.key(), it.value());
    b.feed = feed;
    return b;
}

} // namespace

class TestProgramRules : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void feedRateWrite_wholeSetModel_everyAxisGetsAValue_data();
    void feedRateWrite_wholeSetModel_everyAxisGetsAValue();
    void feedRateWrite_perAxisModel_onlyTheBlocksAxes();
    void parameterWrite_elabRules_sameAsTheAdapter_data();
    void parameterWrite_elabRules_sameAsTheAdapter();
    void check_elab_refusesWhatTheRunWould_data();
    void check_elab_refusesWhatTheRunWould();
    void feedLimit_axisAtF_runsAtTheHighest_data();
    void feedLimit_axisAtF_runsAtTheHighest();
    void feedLimit_coordinatedShares_slowedByOneFactor();
    void check_elab_feedAboveTheHighest_runsAtItWithNote_data();
    void check_elab_feedAboveTheHighest_runsAtItWithNote();
};

void TestProgramRules::feedRateWrite_wholeSetModel_everyAxisGetsAValue_data()
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

void TestProgramRules::feedRateWrite_wholeSetModel_everyAxisGetsAValue()
{
    QFETCH(QString, held);
    QFETCH(AxisWords, axes);
    QFETCH(ParameterValue, expected);
    const MachineFacts f = elabFacts(known(held));
    const ParameterSet set = ProgramRules::feedRateWrite(
        f.description, "elab", f.capabilities["elab"], feedBlock(axes, 6000), known(held), nullptr);
    QCOMPARE(set.keys(), QStringList{"feed-speed"});
    QCOMPARE(set.value("feed-speed"), expected);
}

void TestProgramRules::feedRateWrite_perAxisModel_onlyTheBlocksAxes()
{
    const ModelInfo* info = findModel(QStringLiteral("nanotec"));
    const MachineDescription d = MachineDescription::singleController(*info, "sim");
    const ParameterSet set = ProgramRules::feedRateWrite(d, "nanotec", info->capabilities,
                                                         feedBlock({{"Y", 5}}, 60000), {}, nullptr);
    QCOMPARE(set.keys(), QStringList{"max-frequency"});
    QCOMPARE(set.value("max-frequency").perAxis.keys(), QList<Axis>{Axis::Y});
    QCOMPARE(set.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 1000);
    // G0 writes no rate; G1 without F neither.
    ProgramBlock rapid = feedBlock({{"Y", 5}}, 60000);
    rapid.kind = BlockKind::Rapid;
    QVERIFY(ProgramRules::feedRateWrite(d, "nanotec", info->capabilities, rapid, {}, nullptr)
                .isEmpty());
    // Issue 30: a coordinated G1's shares (ProgramBlock::axisRates, per minute); a share below
    // the parameter's minimum (o: 60 steps/s) runs at it.
    ProgramBlock shares = feedBlock({{"X", 6000}, {"Y", 60}}, 6000);
    shares.axisRates = {{"X", 5999.7}, {"Y", 59.997}};
    const ParameterSet coordinated = ProgramRules::feedRateWrite(
        d, "nanotec", info->capabilities, shares, {}, info->schema.find("max-frequency"));
    QCOMPARE(coordinated.value("max-frequency").perAxis.value(Axis::X).toLongLong(), 100);
    QCOMPARE(coordinated.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 60);
    // Above the maximum (a feed override of 200 %): o's 25 000, and (issue 50, as LinuxCNC
    // slows the whole move) Y slowed by the same factor, 25 000 / 33 333, so both still arrive
    // together.
    shares.axisRates = {{"X", 2000000.0}, {"Y", 6000.0}};
    const ParameterSet fast = ProgramRules::feedRateWrite(d, "nanotec", info->capabilities, shares,
                                                          {}, info->schema.find("max-frequency"));
    QCOMPARE(fast.value("max-frequency").perAxis.value(Axis::X).toLongLong(), 25000);
    QCOMPARE(fast.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 75);
    shares.axisRates = {{"X", 5999.7}, {"Y", 59.997}};
    // Without the spec (not known) the share stands as it is.
    QCOMPARE(ProgramRules::feedRateWrite(d, "nanotec", info->capabilities, shares, {}, nullptr)
                 .value("max-frequency")
                 .perAxis.value(Axis::Y)
                 .toLongLong(),
             1);
}

void TestProgramRules::parameterWrite_elabRules_sameAsTheAdapter_data()
{
    QTest::addColumn<QString>("held");
    QTest::addColumn<ParameterValue>("feed");
    QTest::addColumn<QString>("refusal");
    QTest::newRow("below the start speed") << "start=100,100,100" << perAxis(99, 50, 1) << "";
    QTest::newRow("equal to the start speed")
        << "start=100,100,100" << perAxis(100, 50, 1)
        << "Feed speed 100 on axis X must be below Start speed 100 (feed mode has no ramp)";
    QTest::newRow("start speed unknown")
        << "" << perAxis(10, 10, 10)
        << "Feed speed must be below Start speed (feed mode has no ramp), but Start speed is "
           "not known: write Start speed in the same set";
    QTest::newRow("out of the schema range")
        << "start=100,100,100" << perAxis(70000, 50, 1)
        << "Feed speed: value '70000' is out of range (allowed: 0..65535 steps/s) (X)";
}

void TestProgramRules::parameterWrite_elabRules_sameAsTheAdapter()
{
    QFETCH(QString, held);
    QFETCH(ParameterValue, feed);
    QFETCH(QString, refusal);
    const ModelInfo* info = findModel(QStringLiteral("elab"));
    QVERIFY(info->parameterRules);
    QCOMPARE(ProgramRules::parameterWrite(info->schema, info->capabilities, info->parameterRules,
                                          {{"feed-speed", feed}}, known(held)),
             refusal);
}

void TestProgramRules::check_elab_refusesWhatTheRunWould_data()
{
    QTest::addColumn<QString>("held");
    QTest::addColumn<bool>("setupIncomplete");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    QTest::newRow("S12000 M3") << "start=100,100,100" << false << "S12000 M3"
                               << QStringList{"1:1: controller \"elab\": Spindle speed: value "
                                              "'12000' is out of range (allowed: 0..1000 rpm)"};
    QTest::newRow("M3 S800") << "start=100,100,100" << false << "M3 S800" << QStringList{};
    // 6000 steps/min = 100 steps/s, not below the start speed 100; F5994 (99.9) is.
    // G61: the block on its own, its rate written to the board as feed speed.
    QTest::newRow("feed not below the start speed")
        << "start=100,100,100" << false << "G61 G91 G1 Z-1 F6000"
        << QStringList{"1:16: F6000: controller \"elab\" would refuse its rate: Feed speed 100 "
                       "on axis X must be below Start speed 100 (feed mode has no ramp); F5969.9 "
                       "or less is taken, or change the setup on the Setup page"};
    // G64 (the default): a contour stream ticks below the start speed, at 99/s: one step a tick
    // at most is 5940 steps/min.
    QTest::newRow("contour: feed beyond the tick below the start speed")
        << "start=100,100,100" << false << "G91 G1 Z-1 F6000"
        << QStringList{"1:12: F6000 is too fast for the contour stream of controller \"elab\": at "
                       "its 99 ticks/s (one step per tick at most) this move's highest feed is "
                       "F5939.9"};
    // G93: X's rate is its distance times F, 100 steps in 1 s; the highest F taken scales it.
    QTest::newRow("G93: X's rate not below the start speed")
        << "start=100,100,100" << false << "G91 G93 G1 X100 Y50 F60"
        << QStringList{"1:21: F60: controller \"elab\" would refuse its rate: Feed speed 100 "
                       "on axis X must be below Start speed 100 (feed mode has no ramp); F59.6 "
                       "or less is taken, or change the setup on the Setup page"};
    QTest::newRow("G93: below it")
        << "start=100,100,100" << false << "G91 G93 G1 X100 Y50 F59" << QStringList{};
    QTest::newRow("start speed never written")
        << "" << false << "G61 G91 G1 X10 F600"
        << QStringList{"1:16: F600: controller \"elab\" would refuse its rate: Feed speed must be "
                       "below Start speed (feed mode has no ramp), but Start speed is not known: "
                       "write Start speed in the same set; set it on the Setup page first"};
    QTest::newRow("contour: start speed never written")
        << "" << false << "G91 G1 X10 F600"
        << QStringList{"1:12: the move runs in the contour stream of controller \"elab\", but a "
                       "contour's steps run at one tick rate below Start speed on every axis, "
                       "and Start speed is not known: write the controller's setup first"};
    // A fresh session: no feed speed written for Y and Z; the run writes X's rate for all.
    QTest::newRow("G0 then G1 of one axis, nothing written before")
        << "start=100,100,100" << false << "G91 G0 X100\nG1 X100 F5400" << QStringList{};
    QTest::newRow("bare G1 and G1 F are legal") << "" << false << "G1\nG1 F12\nG0" << QStringList{};
    QTest::newRow("setup incomplete: named once at the first move")
        << "start=100,100,100" << true << "G91 G0 X1\nG0 Y1"
        << QStringList{"1:8: X: controller \"elab\": its setup is incomplete, so it refuses "
                       "every move: write Start speed, Max speed, Acceleration, Feed speed on "
                       "the Setup page first"};
}

void TestProgramRules::check_elab_refusesWhatTheRunWould()
{
    QFETCH(QString, held);
    QFETCH(bool, setupIncomplete);
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    MachineFacts f = elabFacts(known(held));
    f.description.limits = LimitPolicy::Refuse; // issue 50: the refusals of "limits": "refuse"
    if (setupIncomplete)
        f.setupIncomplete.insert("elab");
    QCOMPARE(checked(program, f), errors);
}

// Issue 50, FeedLimit::axisRate: an axis at F (an E-LAB block of its own, in steps) runs at most
// one below the start speed the device holds (feed mode has no ramp), else at most its
// feed-rate parameter's top (65 535); with "limits": "refuse" as programmed. The rate
// feedRateWrite writes is the same.
void TestProgramRules::feedLimit_axisAtF_runsAtTheHighest_data()
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

void TestProgramRules::feedLimit_axisAtF_runsAtTheHighest()
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
    const FeedLimit::AxisRate rate =
        FeedLimit::axisRate(f.description, *f.description.axis("X"), caps, spec, known(held), b);
    QCOMPARE(rate.programmed, qint64(std::llround(feed / 60)));
    QCOMPARE(rate.runs, runs);
    QCOMPARE(rate.limited, limited);
    if (limited)
        QCOMPARE(rate.ceiling.belowParameter, belowParameter);
    const ParameterSet write =
        ProgramRules::feedRateWrite(f.description, "elab", caps, b, known(held), spec);
    QCOMPARE(write.value("feed-speed").perAxis.value(Axis::X).toLongLong(), runs);
}

// Shares of F on a coordinating controller (a Nanotec bus in steps, o at most 25 000): a
// diagonal whose Y share would be 40 000 steps/s slows X and Y by one factor (0.625), so they
// still arrive together, as LinuxCNC slows the whole move; refused, each share is clamped at o
// on its own as before (a feed override's case).
void TestProgramRules::feedLimit_coordinatedShares_slowedByOneFactor()
{
    const ModelInfo* info = findModel(QStringLiteral("nanotec"));
    MachineDescription d = MachineDescription::singleController(*info, "sim");
    const ParameterSpec* spec = info->schema.find("max-frequency");
    QVERIFY(spec);
    ProgramBlock shares = feedBlock({{"X", 30000}, {"Y", 40000}}, 3000000);
    shares.axisRates = {{"X", 1800000.0}, {"Y", 2400000.0}}; // per minute: 30 000, 40 000 /s
    const FeedLimit::AxisRate x =
        FeedLimit::axisRate(d, *d.axis("X"), info->capabilities, spec, {}, shares);
    const FeedLimit::AxisRate y =
        FeedLimit::axisRate(d, *d.axis("Y"), info->capabilities, spec, {}, shares);
    QCOMPARE(x.programmed, qint64(30000));
    QCOMPARE(x.runs, qint64(18750));
    QCOMPARE(y.runs, qint64(25000));
    QCOMPARE(x.feedFactor, 0.625);
    QVERIFY(x.limited && y.limited);
    const ParameterSet write =
        ProgramRules::feedRateWrite(d, "nanotec", info->capabilities, shares, {}, spec);
    QCOMPARE(write.value("max-frequency").perAxis.value(Axis::X).toLongLong(), 18750);
    QCOMPARE(write.value("max-frequency").perAxis.value(Axis::Y).toLongLong(), 25000);
    d.limits = LimitPolicy::Refuse;
    QCOMPARE(FeedLimit::axisRate(d, *d.axis("X"), info->capabilities, spec, {}, shares).runs,
             qint64(25000));
    QVERIFY(!FeedLimit::axisRate(d, *d.axis("X"), info->capabilities, spec, {}, shares).limited);
}

// The rows of check_elab_refusesWhatTheRunWould that were too fast, by default (issue 50): no
// error, a note naming the F (or G93's time) that runs. The board in its own steps, start speed
// 100: a rate of its own at most 99 steps/s, a contour's tick 99/s.
void TestProgramRules::check_elab_feedAboveTheHighest_runsAtItWithNote_data()
{
    QTest::addColumn<QString>("held");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("notes");
    QTest::addColumn<QStringList>("errors");
    QTest::newRow("G61: Z at the start speed runs one below")
        << "start=100,100,100"
        << "G61 G91 G1 Z-1 F6000"
        << QStringList{"1:16: F6000 is 100 steps/s on Z, above the 99 steps/s controller "
                       "\"elab\" takes (below its Start speed: feed mode has no ramp): Z runs at "
                       "F5940"}
        << QStringList{};
    QTest::newRow("contour: beyond the tick")
        << "start=100,100,100"
        << "G91 G1 Z-1 F6000"
        << QStringList{"1:12: F6000 runs at F5940, the highest this move can run at in the "
                       "contour stream of controller \"elab\" (99 ticks/s, one step per tick at "
                       "most)"}
        << QStringList{};
    QTest::newRow("G93: the move takes longer")
        << "start=100,100,100"
        << "G91 G93 G1 X100 Y50 F60"
        << QStringList{"1:21: G93 F60 (the move in 1 s) moves X at 100 steps/s, above the 99 "
                       "steps/s controller \"elab\" takes (below its Start speed: feed mode has "
                       "no ramp): the move takes 1.01 s"}
        << QStringList{};
    // What it cannot do otherwise stays an error: the start speed must be known.
    QTest::newRow("start speed never written")
        << ""
        << "G61 G91 G1 X10 F600" << QStringList{}
        << QStringList{"1:16: F600: controller \"elab\" would refuse its rate: Feed speed must be "
                       "below Start speed (feed mode has no ramp), but Start speed is not known: "
                       "write Start speed in the same set; set it on the Setup page first"};
}

void TestProgramRules::check_elab_feedAboveTheHighest_runsAtItWithNote()
{
    QFETCH(QString, held);
    QFETCH(QString, program);
    QFETCH(QStringList, notes);
    QFETCH(QStringList, errors);
    const MachineFacts f = elabFacts(known(held));
    QStringList names;
    for (const MachineAxis& a : f.description.axes)
        names << a.name;
    QList<ProgramError> parseErrors;
    const std::optional<Program> p = ProgramParser::parse(program.toUtf8(), names, &parseErrors);
    QVERIFY(p);
    const ProgramCheckResult r = ProgramCheck::check(*p, f);
    QStringList errorTexts, noteTexts;
    for (const ProgramError& e : r.errors)
        errorTexts << e.text();
    for (const ProgramError& n : r.notes)
        noteTexts << n.text();
    QCOMPARE(errorTexts, errors);
    QCOMPARE(noteTexts, notes);
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramRules)
#include "tst_programrules.moc"
