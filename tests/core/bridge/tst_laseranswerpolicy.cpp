// LaserAnswerPolicy (pure): a frame only with a position the controller knows, in the laser's
// range, with the status the controller reported; otherwise nothing and the reason.
#include "TestMain.h"
#include "bridge/LaserAnswerPolicy.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::laser;
using stepdeck::bridge::LaserAnswer;
using stepdeck::bridge::LaserAnswerPolicy;

namespace {
AxisStatus standingAt(qint64 position)
{
    AxisStatus a;
    a.referenced = a.positionKnown = true;
    a.position = position;
    return a;
}

// "2|150" for a frame, "-|<reason>" for none: one string column compares both.
QString describe(const LaserAnswer& answer)
{
    if (!answer.sent())
        return QStringLiteral("-|") + answer.withheld;
    return QStringLiteral("%1|%2").arg(int(answer.frame->status)).arg(answer.frame->position);
}
} // namespace

class TestLaserAnswerPolicy : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void position_onlyWhatIsKnown_data();
    void position_onlyWhatIsKnown();
    void moveEnded_statusAsReported_neverMadeUp_data();
    void moveEnded_statusAsReported_neverMadeUp();
    void referenceAndDoor_needAKnownPosition();
};

void TestLaserAnswerPolicy::position_onlyWhatIsKnown_data()
{
    QTest::addColumn<AxisStatus>("axis");
    QTest::addColumn<double>("scale");
    QTest::addColumn<int>("expected"); // -1: not told
    QTest::addColumn<QString>("why");
    AxisStatus moving = standingAt(10);
    moving.moving = true;
    AxisStatus jogging = standingAt(10);
    jogging.jogging = true;
    AxisStatus silentDrive = standingAt(10);
    silentDrive.motionUnknown = true;
    AxisStatus estimated = standingAt(10);
    estimated.positionEstimated = true;
    AxisStatus unknown;
    unknown.position = 250; // a stale count is not a position
    QTest::newRow("known") << standingAt(150) << 1.0 << 150 << QString();
    QTest::newRow("scaled, rounded") << standingAt(301) << 2.0 << 151 << QString();
    QTest::newRow("zero") << standingAt(0) << 10.0 << 0 << QString();
    QTest::newRow("top of the range") << standingAt(99999) << 1.0 << 99999 << QString();
    QTest::newRow("moving") << moving << 1.0 << -1 << "may still be moving";
    QTest::newRow("jogging") << jogging << 1.0 << -1 << "may still be moving";
    QTest::newRow("motion unknown") << silentDrive << 1.0 << -1 << "may still be moving";
    QTest::newRow("estimated") << estimated << 1.0 << -1 << "position is unknown";
    QTest::newRow("unknown") << unknown << 1.0 << -1 << "position is unknown";
    QTest::newRow("negative: not clamped to 0") << standingAt(-20) << 1.0 << -1 << "outside";
    QTest::newRow("above 99999: not clamped") << standingAt(200000) << 2.0 << -1 << "outside";
}

void TestLaserAnswerPolicy::position_onlyWhatIsKnown()
{
    QFETCH(AxisStatus, axis);
    QFETCH(double, scale);
    QFETCH(int, expected);
    QFETCH(QString, why);
    QString reason;
    const std::optional<int> got = LaserAnswerPolicy(scale).position(axis, &reason);
    QCOMPARE(got.value_or(-1), expected);
    QVERIFY2(got ? reason.isEmpty() : reason.contains(why), qPrintable(reason));
}

void TestLaserAnswerPolicy::moveEnded_statusAsReported_neverMadeUp_data()
{
    QTest::addColumn<AxisStatus>("axis");
    QTest::addColumn<QString>("expected");
    AxisStatus limitKnown = standingAt(480);
    limitKnown.limitSwitch = true;
    AxisStatus limitLost = limitKnown;
    limitLost.positionKnown = limitLost.referenced = false;
    AxisStatus onReference = standingAt(0);
    onReference.referenceSwitch = true;
    AxisStatus switchButLost = onReference; // EMIS: arrival overdue, input 1 high
    switchButLost.positionKnown = switchButLost.referenced = false;
    switchButLost.positionEstimated = true;
    AxisStatus moving = standingAt(200);
    moving.moving = true;
    QTest::newRow("at the target") << standingAt(500) << "0|500";
    QTest::newRow("limit switch, position known") << limitKnown << "1|480";
    QTest::newRow("limit switch, position lost")
        << limitLost << "-|axis X stopped at a limit switch, but its position is unknown";
    QTest::newRow("reference switch") << onReference << "2|0";
    QTest::newRow("reference input, position unknown")
        << switchButLost
        << "-|axis X did not confirm reaching its target 500 steps: its "
           "position is unknown";
    QTest::newRow("short of the target")
        << standingAt(320)
        << "-|axis X stopped at 320 steps, short of its target 500 (stopped by the operator?)";
    QTest::newRow("still moving") << moving
                                  << "-|axis X did not confirm reaching its target 500 steps: it "
                                     "may still be moving";
}

void TestLaserAnswerPolicy::moveEnded_statusAsReported_neverMadeUp()
{
    QFETCH(AxisStatus, axis);
    QFETCH(QString, expected);
    const LaserAnswer answer = LaserAnswerPolicy(1.0).moveEnded(Axis::Y, Axis::X, axis, 500);
    QCOMPARE(describe(answer), expected);
    if (answer.sent())
        QCOMPARE(answer.frame->axis, Axis::Y); // the laser's axis, not the controller's
}

void TestLaserAnswerPolicy::referenceAndDoor_needAKnownPosition()
{
    const LaserAnswerPolicy policy(1.0);
    QCOMPARE(describe(policy.referenced(Axis::X, Axis::Z, standingAt(0))), "2|0");
    AxisStatus lost;
    lost.limitSwitch = true;
    QCOMPARE(describe(policy.referenceFailed(Axis::X, Axis::Z, lost)),
             "-|axis Z stopped at a limit switch before it was referenced, but its position is "
             "unknown");
    QCOMPARE(describe(policy.referenceFailed(Axis::X, Axis::Z, AxisStatus{})),
             "-|axis Z stopped before it was referenced");
    QCOMPARE(describe(policy.refusedAtLimit(Axis::X, Axis::Z, AxisStatus{})),
             "-|axis Z stands at an active limit switch, but its position is unknown");
    QCOMPARE(describe(policy.door(Axis::X, Axis::Z, standingAt(42), true)), "3|42");
    QCOMPARE(describe(policy.door(Axis::X, Axis::Z, standingAt(42), false)), "4|42");
    QCOMPARE(describe(policy.door(Axis::X, Axis::Z, AxisStatus{}, true)),
             "-|the door opened (axis Z), but its position is unknown");
}

STEPDECK_TEST_GUILESS_MAIN(TestLaserAnswerPolicy)
#include "tst_laseranswerpolicy.moc"
