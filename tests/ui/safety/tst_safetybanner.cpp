// The safety bar's banner as a pure function: a machine that may still be moving is said
// first and never called stopped; "Release the emergency stop" only when there is one to
// release; setup before referencing; "Ready" only while connected and referenced.
#include "TestMain.h"
#include "safety/SafetyBanner.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::ui;

namespace {
// A status of axes X, Y, Z referenced or not (nothing else set), and the knowledge of the
// positions that goes with it.
void setAxes(SafetyBannerInput* in, bool referenced)
{
    in->status = MachineStatus{}; // the whole status, as a new status word
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        AxisStatus axis;
        axis.referenced = axis.positionKnown = referenced;
        in->status.axes.insert(a, axis);
    }
    in->positions =
        referenced ? machine::PositionKnowledge::Referenced : machine::PositionKnowledge::Unknown;
}
} // namespace

class TestSafetyBanner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void compute_data();
    void compute();
    void neverClaimsAStop();
};

void TestSafetyBanner::compute_data()
{
    QTest::addColumn<SafetyBannerInput>("in");
    QTest::addColumn<QString>("contains");
    QTest::addColumn<QString>("absent");
    QTest::addColumn<QString>("severity");

    SafetyBannerInput in;
    setAxes(&in, true); // stale: the last status before the disconnect said referenced
    QTest::newRow("disconnected, stale referenced") << in << "Not connected"
                                                    << "Ready"
                                                    << "idle";

    in.link = LinkState::Lost;
    setAxes(&in, false);
    QTest::newRow("lost, idle") << in << "Link lost"
                                << "may still be moving"
                                << "fault";
    in.movingWhenLinkEnded = true;
    QTest::newRow("lost while moving") << in << "may still be moving: use the machine's emergency"
                                       << "stopped"
                                       << "fault";
    in.link = LinkState::Disconnected;
    QTest::newRow("disconnected while moving") << in << "may still be moving"
                                               << "Not connected"
                                               << "fault";
    in.movingWhenLinkEnded = false;
    in.status.motionUnconfirmed = true;
    QTest::newRow("disconnected, unconfirmed") << in << "may still be moving"
                                               << "Ready"
                                               << "fault";

    in = SafetyBannerInput{};
    in.link = LinkState::Connected;
    setAxes(&in, true);
    in.status.motionUnconfirmed = true;
    QTest::newRow("connected, unconfirmed") << in << "No standstill confirmed"
                                            << "Ready"
                                            << "fault";
    in.status.motionUnconfirmed = false;
    in.status.panic = true;
    in.hostPanicSent = true;
    QTest::newRow("host panic") << in << "PANIC STOP sent"
                                << "Release"
                                << "fault";
    in.hostPanicSent = false;
    QTest::newRow("machine emergency stop") << in << "Release the emergency stop"
                                            << "Ready"
                                            << "fault";
    setAxes(&in, false);
    in.status.setupIncomplete = true;
    in.positionsLost = true;
    QTest::newRow("setup first") << in << "write the setup (start speed, max speed, acceleration)"
                                 << "Reference"
                                 << "warning";
    in.status.setupIncomplete = false;
    QTest::newRow("positions lost") << in << "Positions are lost"
                                    << "Ready"
                                    << "fault";
    in.positionsLost = false;
    QTest::newRow("not referenced") << in << "Not referenced"
                                    << "Ready"
                                    << "warning";
    setAxes(&in, true);
    QTest::newRow("ready") << in << "Ready: all axes referenced"
                           << "lost"
                           << "ok";
    // Issue 28, item 4: an axis referenced once whose position is now estimated (a jog without
    // read-back) is not "ready": Go to and the check refuse absolute moves on it.
    in.positions = machine::PositionKnowledge::Estimated;
    QTest::newRow("estimated") << in << "Positions estimated"
                               << "Ready"
                               << "warning";
    // Issue 47 item 15: while a program runs or holds the banner says so, not "Ready"; a fault
    // or a panic still comes first.
    in.positions = machine::PositionKnowledge::Referenced;
    in.job = program::RunState::Running;
    in.jobLine = 12;
    QTest::newRow("program running") << in << "Program running, line 12"
                                     << "Ready"
                                     << "job";
    in.job = program::RunState::Paused;
    QTest::newRow("program held") << in << "Program held at line 12"
                                  << "Ready"
                                  << "job";
    in.job = program::RunState::Finished;
    QTest::newRow("program finished") << in << "Ready: all axes referenced"
                                      << "Program"
                                      << "ok";
    in.job = program::RunState::Running;
    in.status.motionUnconfirmed = true;
    QTest::newRow("program running, stop unconfirmed") << in << "No standstill confirmed"
                                                       << "Program running"
                                                       << "fault";
}

void TestSafetyBanner::compute()
{
    QFETCH(SafetyBannerInput, in);
    QFETCH(QString, contains);
    QFETCH(QString, absent);
    QFETCH(QString, severity);
    const SafetyBannerText out = SafetyBanner::compute(in);
    QVERIFY2(out.text.contains(contains), qPrintable(out.text));
    QVERIFY2(!out.text.contains(absent), qPrintable(out.text));
    QCOMPARE(out.severity, severity);
}

void TestSafetyBanner::neverClaimsAStop()
{
    // Every combination: the host never says motion stopped, it cannot know.
    for (LinkState link :
         {LinkState::Disconnected, LinkState::Connecting, LinkState::Connected, LinkState::Lost}) {
        for (int bits = 0; bits < 64; ++bits) {
            SafetyBannerInput in;
            in.link = link;
            setAxes(&in, bits & 1);
            in.status.panic = bits & 2;
            in.status.motionUnconfirmed = bits & 4;
            in.status.setupIncomplete = bits & 8;
            in.movingWhenLinkEnded = bits & 16;
            in.hostPanicSent = bits & 32;
            const QString text = SafetyBanner::compute(in).text;
            QVERIFY2(!text.contains(QStringLiteral("stopped by")), qPrintable(text));
            QVERIFY2(!text.contains(QStringLiteral("motion stopped")), qPrintable(text));
            if (link != LinkState::Connected)
                QVERIFY2(!text.startsWith(QStringLiteral("Ready")), qPrintable(text));
            if (in.status.motionUnconfirmed ||
                (link != LinkState::Connected && in.movingWhenLinkEnded))
                QVERIFY2(text.contains(SafetyBanner::mayStillMoveText()), qPrintable(text));
        }
    }
}

STEPDECK_TEST_MAIN(TestSafetyBanner)
#include "tst_safetybanner.moc"
