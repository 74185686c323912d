// The stream executor's layout (issue 49 item 3, issue 30): which controllers of a machine run
// contours as a step stream, how their slots lie on the machine's axes, and the tick rate a
// stream runs at from what the board holds. Its run at the board (tick write, <DC2> stream,
// hold, override, settle) is asserted at the E-LAB simulator over a pty by tst_programcontour.
#include "../program/ElabBoardTestSupport.h"
#include "../program/ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "motion/executors/StreamExecutor.h"

using namespace stepdeck;
using namespace stepdeck::motion;
using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

class TestStreamExecutor : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tickRate_fromTheStartSpeeds_data();
    void tickRate_fromTheStartSpeeds();
    void streamsOf_elabTable_slotsOnTheMachineAxesInvertedNegative();
    void streamsOf_noStreamController_none_data();
    void streamsOf_noStreamController_none();
};

namespace {

// The board's start speeds as the host knows them (ElabBoardTestSupport's text form).
ParameterSet boardStartSpeeds(qint64 x, qint64 y, qint64 z)
{
    return elabboard::known(QStringLiteral("start=%1,%2,%3").arg(x).arg(y).arg(z));
}

} // namespace

void TestStreamExecutor::tickRate_fromTheStartSpeeds_data()
{
    QTest::addColumn<ParameterSet>("known");
    QTest::addColumn<double>("tick");
    QTest::addColumn<QString>("why");
    // Below the lowest start speed (feed mode has no ramp), at most the wire's 2100/s (what the
    // status polls leave of it, issue 47).
    QTest::newRow("500 on every axis") << boardStartSpeeds(500, 500, 500) << 499.0 << "";
    QTest::newRow("the lowest axis counts") << boardStartSpeeds(800, 120, 900) << 119.0 << "";
    QTest::newRow("the wire bounds it") << boardStartSpeeds(5000, 5000, 5000) << 2100.0 << "";
    QTest::newRow("not known") << ParameterSet{} << 0.0 << "not known";
    QTest::newRow("too low") << boardStartSpeeds(1, 500, 500) << 0.0 << "too low";
}

void TestStreamExecutor::tickRate_fromTheStartSpeeds()
{
    QFETCH(ParameterSet, known);
    QFETCH(double, tick);
    QFETCH(QString, why);
    const ModelInfo* elab = findModel(QStringLiteral("elab"));
    QVERIFY(elab);
    QString reason;
    QCOMPARE(StreamExecutor::tickRate(elab->capabilities, elab->schema, known, &reason), tick);
    QVERIFY2(why.isEmpty() ? reason.isEmpty() : reason.contains(why), qPrintable(reason));
}

// The check's mill: E-LAB "table" with X 100, Y 200 (inverted here), Z 100 steps/mm, and a
// laser axis "tilt" (no stream). One stream, its slots the board's X, Y, Z in that order.
void TestStreamExecutor::streamsOf_elabTable_slotsOnTheMachineAxesInvertedNegative()
{
    MachineFacts f = machineFacts(QStringLiteral("mill"));
    f.description.axes[1].invert = true;
    f.knownParameters[QStringLiteral("table")] = boardStartSpeeds(800, 600, 700);
    const std::vector<StepStream> streams =
        StreamExecutor::streamsOf(f.description, f.capabilities, f.schemas, f.knownParameters);
    QCOMPARE(int(streams.size()), 1);
    const StepStream& s = streams.front();
    QCOMPARE(s.controller, QStringLiteral("table"));
    QCOMPARE(s.slotAxes, (QList<Axis>{Axis::X, Axis::Y, Axis::Z}));
    QCOMPARE(s.scale.axisCount, 3);
    QCOMPARE(s.axisOfSlot[0], 0);
    QCOMPARE(s.axisOfSlot[1], 1);
    QCOMPARE(s.axisOfSlot[2], 2);
    QCOMPARE(s.scale.stepsPerUnit[0], 100.0);
    QCOMPARE(s.scale.stepsPerUnit[1], -200.0);
    QCOMPARE(s.scale.stepsPerUnit[2], 100.0);
    QCOMPARE(s.tickRate, 599.0);
    QVERIFY(s.tickRefusal.isEmpty());
}

void TestStreamExecutor::streamsOf_noStreamController_none_data()
{
    QTest::addColumn<QString>("machine");
    QTest::newRow("EMIS") << "emis";
    QTest::newRow("Nanotec") << "nanotec";
}

void TestStreamExecutor::streamsOf_noStreamController_none()
{
    QFETCH(QString, machine);
    const MachineFacts f = machineFacts(machine);
    QVERIFY(StreamExecutor::streamsOf(f.description, f.capabilities, f.schemas, f.knownParameters)
                .empty());
}

STEPDECK_TEST_GUILESS_MAIN(TestStreamExecutor)
#include "tst_streamexecutor.moc"
