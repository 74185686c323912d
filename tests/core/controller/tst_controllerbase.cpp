// The Controller base class's jog machinery (lease, ramp, refusal, link loss) and its safety
// contract (stop before close, flush, link loss keeps the port open, unconfirmed motion),
// through a tiny fake adapter and a transport that record what happens in which order.
#include "TestMain.h"
#include "TestSupport.h"
#include "controller/Controller.h"
#include "transport/LoopbackTransport.h" // complete Transport type first
#include <QtTest>

using namespace stepdeck;

namespace {

// A transport that logs writes, flushes and closes in order ("write STOP", "flush", "close").
class RecordingTransport : public Transport
{
public:
    QStringList log;
    bool open_ = false;
    void open(const LineSettings&) override { open_ = true; }
    void close() override
    {
        log << QStringLiteral("close");
        open_ = false;
    }
    bool isOpen() const override { return open_; }
    qint64 write(const QByteArray& bytes) override
    {
        log << QStringLiteral("write ") + QString::fromLatin1(bytes);
        return bytes.size();
    }
    void discardOutput() override { log << QStringLiteral("discard"); }
    qint64 bytesToWrite() const override { return 0; }
    bool flushOutput(int) override
    {
        log << QStringLiteral("flush");
        return true;
    }
    QString description() const override { return QStringLiteral("recording"); }
    void fail(const QString& why)
    {
        open_ = false;
        Q_EMIT failed(why);
    }
};

struct AppliedJog
{
    qint64 atMs;
    AxisVelocities rates;
};

// Implements only what the base class needs; every protocol operation "succeeds" at once.
class FakeAdapter : public Controller
{
public:
    FakeAdapter(Transport* transport, const ControllerOptions& options)
        : Controller(transport, options)
    {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            mutableStatus().axes.insert(a, AxisStatus{});
    }

    Capabilities capabilities() const override
    {
        Capabilities caps;
        caps.axes = {Axis::X, Axis::Y, Axis::Z};
        caps.motionModes = {MotionMode::Jog};
        caps.maxJogSpeed = 1000;
        caps.defaultJogAcceleration = 2000;
        caps.hostRampedJog = true;
        return caps;
    }
    ParameterSchema schema() const override { return {}; }
    void openLink(RequestId id) override
    {
        setLinkState(LinkState::Connected);
        finishOk(id);
    }
    void readParameters(RequestId id, const QStringList&) override { finishOk(id); }
    void writeParameters(RequestId id, const ParameterSet&, bool) override { finishOk(id); }
    void moveRelative(RequestId id, const AxisVector&) override { finishOk(id); }
    void reference(RequestId id, const QMap<Axis, int>&) override { finishOk(id); }
    void stop(RequestId id) override { finishOk(id); }
    void panic(RequestId id) override { finishOk(id); }
    void refreshStatus(RequestId id) override { finishOk(id); }
    void sendRaw(RequestId id, const QByteArray&) override { finishOk(id); }
    void setPollInterval(int) override {}

    // Test hooks into the protected base.
    void simulatePollLoss() { loseLink(QStringLiteral("test: no replies")); }
    void simulateTransportFailure() { handleTransportFailure(QStringLiteral("test: unplugged")); }
    void confirmStandstill()
    {
        noteStandstillConfirmed();
        publishStatus();
    }
    void markReferenced()
    {
        for (AxisStatus& a : mutableStatus().axes) {
            a.referenced = true;
            a.positionKnown = true;
        }
    }

    QList<AppliedJog> applied;
    bool moving = false; // motionMayBeRunning()
    bool ackStop = true; // sendSafetyStop() answers at once; false: never
    int safetyStops = 0;
    QStringList aborted; // abortHostSide() messages

protected:
    void sendSafetyStop(std::function<void(bool)> done) override
    {
        ++safetyStops;
        transport()->write("STOP");
        if (ackStop)
            done(true);
    }
    void abortHostSide(ErrorKind, const QString& message) override { aborted << message; }
    bool motionMayBeRunning() const override { return moving || jogActive(); }
    int safetyStopTimeoutMs() const override { return 50; }
    void applyJogVelocity(const AxisVelocities& stepsPerS) override
    {
        applied.append({jogTickMs(), stepsPerS});
    }
};

ControllerOptions jogOptions(int leaseMs)
{
    ControllerOptions o;
    o.jogLeaseMs = leaseMs;
    o.jogTickMs = 10;
    o.jogAccelerationStepsPerS2 = 0; // the model default (2000)
    return o;
}

} // namespace

class TestControllerBase : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void jogLease_notRenewed_rampsToZero();
    void jogLease_renewed_keepsRate();
    void jog_appliedSteps_boundedByAcceleration_data();
    void jog_appliedSteps_boundedByAcceleration();
    void jog_notConnected_refused();
    void linkLost_marksUnreferencedAndZeroesVelocity();
    void jogAccelerationOption_reachesRamp();
    void slowJog_estimateAdvancesByFractions();
    void closeLink_writesStopThenFlushesThenCloses();
    void closeLink_stopUnanswered_marksMotionUnconfirmed();
    void closeLink_notOpen_sendsNothing();
    void pollLoss_sendsStopAndKeepsPortOpen();
    void transportFailure_whileMoving_marksMotionUnconfirmed();
    void motionUnconfirmed_clearedOnlyByDeviceStandstill();

private:
    LoopbackTransport m_transport;
};

void TestControllerBase::jogLease_notRenewed_rampsToZero()
{
    FakeAdapter c(&m_transport, jogOptions(100));
    c.openLink(1);
    c.setJogVelocity({{Axis::X, 400}});
    QVERIFY(!c.jogRamp().isIdle());
    // Never renewed: after the lease the axis ramps down by itself and the timer stops.
    QTRY_VERIFY_WITH_TIMEOUT(c.jogRamp().isIdle(), 5000);
    QVERIFY(!c.applied.isEmpty());
    QCOMPARE(c.applied.last().rates.value(Axis::X), 0.0);
    QCOMPARE(c.status().axes.value(Axis::X).commandedVelocity, 0.0);
    bool moved = false;
    for (const AppliedJog& a : c.applied)
        moved = moved || a.rates.value(Axis::X) > 0;
    QVERIFY(moved); // it did start before the lease ran out
}

void TestControllerBase::jogLease_renewed_keepsRate()
{
    FakeAdapter c(&m_transport, jogOptions(300));
    c.openLink(1);
    // An input that renews every 30 ms, well inside the 300 ms lease.
    QTimer renew;
    renew.setInterval(30);
    connect(&renew, &QTimer::timeout, &c, [&c] { c.setJogVelocity({{Axis::Y, -200}}); });
    c.setJogVelocity({{Axis::Y, -200}});
    renew.start();
    QTRY_COMPARE_WITH_TIMEOUT(c.jogRamp().current(Axis::Y), -200.0, 5000);
    QCOMPARE(c.jogRamp().target(Axis::Y), -200.0);

    renew.stop();
    QTRY_VERIFY_WITH_TIMEOUT(c.jogRamp().isIdle(), 5000);
    QCOMPARE(c.applied.last().rates.value(Axis::Y), 0.0);
}

void TestControllerBase::jog_appliedSteps_boundedByAcceleration_data()
{
    QTest::addColumn<double>("acceleration");
    QTest::addColumn<double>("target");

    QTest::newRow("default 2000, +600") << 0.0 << 600.0;
    QTest::newRow("5000, -900") << 5000.0 << -900.0;
    QTest::newRow("800, +250") << 800.0 << 250.0;
}

void TestControllerBase::jog_appliedSteps_boundedByAcceleration()
{
    QFETCH(double, acceleration);
    QFETCH(double, target);

    FakeAdapter c(&m_transport, jogOptions(300));
    c.openLink(1);
    if (acceleration > 0)
        c.setJogAcceleration(acceleration);
    const double a = acceleration > 0 ? acceleration : 2000.0;

    QTimer renew;
    renew.setInterval(30);
    connect(&renew, &QTimer::timeout, &c, [&c, target] { c.setJogVelocity({{Axis::Z, target}}); });
    c.setJogVelocity({{Axis::Z, target}});
    renew.start();
    QTRY_COMPARE_WITH_TIMEOUT(c.jogRamp().current(Axis::Z), target, 10000);
    renew.stop();
    c.endJog();
    QTRY_VERIFY_WITH_TIMEOUT(c.jogRamp().isIdle(), 10000);

    // Every change the adapter was asked to send is one the motor can follow: bounded by
    // acceleration * ramp time between the ticks that computed them (+2 ms: a tick within the
    // same millisecond still advances 1 ms, +1 step/s: integer rounding). The ramp's own clock,
    // not the time of the call: a tick preempted between reading the clock and the send (seen
    // under ASan on a loaded CI machine) would otherwise look like a jump.
    double previous = 0;
    qint64 previousMs = c.applied.isEmpty() ? 0 : c.applied.first().atMs;
    for (const AppliedJog& j : c.applied) {
        const double v = j.rates.value(Axis::Z);
        const double bound = a * (j.atMs - previousMs + 2) / 1000.0 + 1.0;
        QVERIFY2(qAbs(v - previous) <= bound,
                 qPrintable(QStringLiteral("%1 -> %2 in %3 ms exceeds %4")
                                .arg(previous)
                                .arg(v)
                                .arg(j.atMs - previousMs)
                                .arg(bound)));
        previous = v;
        previousMs = j.atMs;
    }
    QCOMPARE(previous, 0.0);
}

void TestControllerBase::jog_notConnected_refused()
{
    FakeAdapter c(&m_transport, jogOptions(300));
    QSignalSpy refused(&c, &Controller::jogRefused);
    c.setJogVelocity({{Axis::X, 100}});
    QCOMPARE(refused.count(), 1);
    QVERIFY(refused.first().at(0).toString().contains(QLatin1String("not connected")));
    QVERIFY(c.jogRamp().isIdle());
    QVERIFY(test::staysQuiet(refused, 50));
    QVERIFY(c.applied.isEmpty());
}

void TestControllerBase::linkLost_marksUnreferencedAndZeroesVelocity()
{
    FakeAdapter c(&m_transport, jogOptions(300));
    c.openLink(1);
    c.markReferenced();
    QSignalSpy link(&c, &Controller::linkStateChanged);
    QSignalSpy status(&c, &Controller::statusChanged);

    QTimer renew;
    renew.setInterval(30);
    connect(&renew, &QTimer::timeout, &c, [&c] { c.setJogVelocity({{Axis::X, 500}}); });
    c.setJogVelocity({{Axis::X, 500}});
    renew.start();
    QTRY_VERIFY_WITH_TIMEOUT(c.status().axes.value(Axis::X).commandedVelocity > 0, 5000);

    c.simulatePollLoss();
    QCOMPARE(c.linkState(), LinkState::Lost);
    QCOMPARE(link.count(), 1);
    QCOMPARE(link.first().at(0).value<LinkState>(), LinkState::Lost);
    QVERIFY(!status.isEmpty());
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        const AxisStatus s = c.status().axes.value(a);
        QVERIFY(!s.referenced);
        QVERIFY(!s.positionKnown);
        QCOMPARE(s.commandedVelocity, 0.0);
        QVERIFY(!s.jogging);
    }
    QVERIFY(c.status().commFault);
    QVERIFY(c.jogRamp().isIdle());

    // The input keeps renewing, but a lost link refuses jogging: nothing more is applied.
    QSignalSpy refused(&c, &Controller::jogRefused);
    const qsizetype appliedBefore = c.applied.size();
    QTRY_VERIFY_WITH_TIMEOUT(!refused.isEmpty(), 2000);
    renew.stop();
    QCOMPARE(c.applied.size(), appliedBefore);
    QVERIFY(c.jogRamp().isIdle());
}

void TestControllerBase::jogAccelerationOption_reachesRamp()
{
    ControllerOptions o = jogOptions(300);
    o.jogAccelerationStepsPerS2 = 500;
    FakeAdapter c(&m_transport, o);
    c.openLink(1);
    c.setJogVelocity({{Axis::X, 100}});
    QCOMPARE(c.jogRamp().acceleration(), 500.0);
}

void TestControllerBase::slowJog_estimateAdvancesByFractions()
{
    // 20 steps/s at 10 ms ticks is 0.2 steps a tick: rounding each tick would never move.
    FakeAdapter c(&m_transport, jogOptions(300));
    c.openLink(1);
    QTimer renew;
    renew.setInterval(30);
    connect(&renew, &QTimer::timeout, &c, [&c] { c.setJogVelocity({{Axis::Z, 20}}); });
    c.setJogVelocity({{Axis::Z, 20}});
    renew.start();
    QTRY_VERIFY_WITH_TIMEOUT(c.status().axes.value(Axis::Z).position >= 3, 5000);
    QVERIFY(c.status().axes.value(Axis::Z).positionEstimated);
    renew.stop();
}

void TestControllerBase::closeLink_writesStopThenFlushesThenCloses()
{
    RecordingTransport t;
    t.open({});
    FakeAdapter c(&t, jogOptions(300));
    c.openLink(1);
    c.moving = true;
    QSignalSpy finished(&c, &Controller::closeFinished);
    c.closeLink();
    QCOMPARE(finished.count(), 1);
    // The stop left the process before the port was closed.
    QCOMPARE(t.log, (QStringList{"write STOP", "flush", "close"}));
    QCOMPARE(c.linkState(), LinkState::Disconnected);
    QVERIFY(!c.status().motionUnconfirmed);
    QCOMPARE(c.aborted.size(), 1);
}

void TestControllerBase::closeLink_stopUnanswered_marksMotionUnconfirmed()
{
    RecordingTransport t;
    t.open({});
    FakeAdapter c(&t, jogOptions(300));
    c.openLink(1);
    c.moving = true;
    c.ackStop = false;
    QSignalSpy finished(&c, &Controller::closeFinished);
    QSignalSpy errors(&c, &Controller::errorOccurred);
    c.closeLink();
    QCOMPARE(finished.count(), 0); // waits (bounded) for the stop's reply
    QVERIFY(finished.wait(2000));
    QCOMPARE(t.log, (QStringList{"write STOP", "flush", "close"}));
    QVERIFY(c.status().motionUnconfirmed);
    bool said = false;
    for (const QList<QVariant>& e : errors)
        said = said || e.at(0).toString() == Controller::mayStillBeMovingText();
    QVERIFY(said);
    c.closeLink(); // a second close is harmless and finishes at once
    QCOMPARE(finished.count(), 2);
}

void TestControllerBase::closeLink_notOpen_sendsNothing()
{
    RecordingTransport t;
    FakeAdapter c(&t, jogOptions(300));
    QSignalSpy finished(&c, &Controller::closeFinished);
    c.moving = true;
    c.closeLink();
    QCOMPARE(finished.count(), 1);
    QCOMPARE(c.safetyStops, 0);
    QVERIFY(!t.log.contains(QStringLiteral("write STOP")));
}

void TestControllerBase::pollLoss_sendsStopAndKeepsPortOpen()
{
    RecordingTransport t;
    t.open({});
    FakeAdapter c(&t, jogOptions(300));
    c.openLink(1);
    c.moving = true;
    c.ackStop = false;
    QSignalSpy link(&c, &Controller::linkStateChanged);
    c.simulatePollLoss();
    QCOMPARE(c.linkState(), LinkState::Connected); // the stop goes out first
    QTRY_COMPARE_WITH_TIMEOUT(c.linkState(), LinkState::Lost, 2000);
    QCOMPARE(t.log, (QStringList{"write STOP"}));
    QVERIFY(t.isOpen()); // PANIC and STOP can still be written
    QVERIFY(c.status().motionUnconfirmed);
    QCOMPARE(c.aborted.size(), 1);
}

void TestControllerBase::transportFailure_whileMoving_marksMotionUnconfirmed()
{
    RecordingTransport t;
    t.open({});
    FakeAdapter c(&t, jogOptions(300));
    c.openLink(1);
    c.moving = true;
    c.simulateTransportFailure();
    QCOMPARE(c.linkState(), LinkState::Lost);
    QVERIFY(c.status().motionUnconfirmed);
    QCOMPARE(c.safetyStops, 0); // nothing can be written to a vanished port
    QVERIFY(t.log.isEmpty());
}

void TestControllerBase::motionUnconfirmed_clearedOnlyByDeviceStandstill()
{
    RecordingTransport t;
    t.open({});
    FakeAdapter c(&t, jogOptions(300));
    c.openLink(1);
    c.moving = true;
    c.simulateTransportFailure();
    QVERIFY(c.status().motionUnconfirmed);
    c.openLink(2); // reconnecting alone proves nothing
    QVERIFY(c.status().motionUnconfirmed);
    c.confirmStandstill();
    QVERIFY(!c.status().motionUnconfirmed);
}

STEPDECK_TEST_GUILESS_MAIN(TestControllerBase)
#include "tst_controllerbase.moc"
