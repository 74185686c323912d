// The rules both the check and the run go by (issue 28, ProgramRules): the model's parameter
// rules judged against what the device holds and an incomplete setup, and the check refusing
// with them what the run would refuse (the spindle's range: tst_switchexecutor; a feed move's
// rates: tst_moverates), or noting a feed above the machine's highest (issue 50).
#include "ElabBoardTestSupport.h"
#include "TestMain.h"
#include "program/ProgramCheck.h"
#include "program/ProgramParser.h"
#include "program/ProgramRules.h"
#include "protocols/Registry.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;
using namespace stepdeck::program::elabboard;

namespace {

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

} // namespace

class TestProgramRules : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parameterWrite_elabRules_sameAsTheAdapter_data();
    void parameterWrite_elabRules_sameAsTheAdapter();
    void check_elab_refusesWhatTheRunWould_data();
    void check_elab_refusesWhatTheRunWould();
    void check_elab_feedAboveTheHighest_runsAtItWithNote_data();
    void check_elab_feedAboveTheHighest_runsAtItWithNote();
};

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
