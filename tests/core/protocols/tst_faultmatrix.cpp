// The fault-injection matrix of the safety contract (docs/architecture.md), over every model
// with a stop command, through the generic Controller interface: each fault x each motion, and
// each cell asserts what the DEVICE saw -- the model's stop frames at the simulator and the
// simulated axes standing still -- or, where nothing can reach the device (the port vanished),
// that the host says the motion is unconfirmed instead of claiming a stop.
#include "ModelBench.h"
#include "TestMain.h"
#include "TestSupport.h"
#include "controller/Controller.h"
#include "protocols/Registry.h"
#include "sim/Simulator.h"
#include "transport/LoopbackTransport.h"
#include <QDeadlineTimer>
#include <QtTest>
#include <memory>

using namespace stepdeck;

namespace {
enum class Fault { Stop, Panic, Close, RepliesLost, PortVanished };
enum class Motion { Jog, Velocity, Move, FeedStream };

const char* faultName(Fault f)
{
    static const char* names[] = {"STOP", "PANIC", "close", "replies lost", "port vanished"};
    return names[int(f)];
}
const char* motionName(Motion m)
{
    static const char* names[] = {"jog", "velocity", "move", "feed stream"};
    return names[int(m)];
}

// One model's adapter against its simulator over an in-memory link.
struct FaultBench : test::ModelBench
{
    explicit FaultBench(const ModelInfo* model) : ModelBench(model, 150) {}

    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs = 5000)
    {
        return ModelBench::run(call, timeoutMs);
    }
    // Schema defaults where the device needs a setup before it moves
    // (ModelInfo::setupBeforeMotion, E-LAB tmInvSetup).
    bool prepare()
    {
        if (!run([this](RequestId id) { ctl->openLink(id); }).ok())
            return false;
        if (info->setupBeforeMotion.isEmpty())
            return true;
        const ParameterSet set = test::setupBeforeMotionDefaults(*info);
        return run([&](RequestId id) { ctl->writeParameters(id, set, false); }).ok() &&
               run([this](RequestId id) { ctl->refreshStatus(id); }).ok();
    }
    // Starts the motion and returns once the device moves (false: it never did).
    bool start(Motion m)
    {
        bool ok = true;
        switch (m) {
        case Motion::Jog:
            ctl->setJogVelocity({{Axis::X, 800}});
            break;
        case Motion::Velocity:
            ok = run([this](RequestId id) { ctl->velocityMove(id, {{Axis::X, 1500}}); }).ok();
            break;
        case Motion::Move:
            ok = run([this](RequestId id) { ctl->moveRelative(id, {{Axis::X, 2500}}); }).ok();
            break;
        case Motion::FeedStream:
            stream = ++nextId;
            ctl->feedStream(stream, QVector<AxisVector>(20000, AxisVector{{Axis::X, 1}}));
            break;
        }
        QDeadlineTimer deadline(5000);
        while (ok && sim->standingStill() && !deadline.hasExpired()) {
            if (m == Motion::Jog)
                ctl->setJogVelocity({{Axis::X, 800}});
            results->wait(20);
        }
        return ok && !sim->standingStill();
    }
    bool stopFrameReceived() const
    {
        for (const QByteArray& f : sim->receivedFrames()) {
            if (sim->isStopFrame(f)) // the manual's stop commands (Simulator::isStopFrame)
                return true;
        }
        return false;
    }

    RequestId stream = 0;
};
} // namespace

Q_DECLARE_METATYPE(Fault)
Q_DECLARE_METATYPE(Motion)

class TestFaultMatrix : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void fault_duringMotion_deviceEndsStillOrHostSaysUnconfirmed_data();
    void fault_duringMotion_deviceEndsStillOrHostSaysUnconfirmed();
};

void TestFaultMatrix::fault_duringMotion_deviceEndsStillOrHostSaysUnconfirmed_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<Fault>("fault");
    QTest::addColumn<Motion>("motion");
    for (const ModelInfo& m : models()) {
        if (!m.capabilities.stopCommand)
            continue; // models without a stop: their own tests (every chunk ends by itself)
        for (Fault f :
             {Fault::Stop, Fault::Panic, Fault::Close, Fault::RepliesLost, Fault::PortVanished}) {
            for (Motion mo : {Motion::Jog, Motion::Velocity, Motion::Move, Motion::FeedStream}) {
                if (mo == Motion::FeedStream && !m.capabilities.has(MotionMode::FeedStream))
                    continue;
                QTest::addRow("%s %s during %s", qPrintable(m.id), faultName(f), motionName(mo))
                    << m.id << f << mo;
            }
        }
    }
}

void TestFaultMatrix::fault_duringMotion_deviceEndsStillOrHostSaysUnconfirmed()
{
    QFETCH(QString, model);
    QFETCH(Fault, fault);
    QFETCH(Motion, motion);
    FaultBench b(findModel(model));
    QVERIFY(b.prepare());
    QVERIFY(b.start(motion));
    b.sim->clearReceivedFrames();
    QSignalSpy closed(b.ctl.get(), &Controller::closeFinished);
    switch (fault) {
    case Fault::Stop:
        b.ctl->endJog();
        b.run([&](RequestId id) { b.ctl->stop(id); });
        break;
    case Fault::Panic:
        b.run([&](RequestId id) { b.ctl->panic(id); });
        break;
    case Fault::Close:
        b.ctl->closeLink();
        QVERIFY(closed.count() == 1 || closed.wait(5000));
        QVERIFY(!b.host->isOpen());
        break;
    case Fault::RepliesLost:
        b.sim->faults().silent = true; // the device still listens
        QTRY_COMPARE_WITH_TIMEOUT(b.ctl->linkState(), LinkState::Lost, 10000);
        QVERIFY(b.host->isOpen());                  // STOP and PANIC can still be written
        QVERIFY(b.ctl->status().motionUnconfirmed); // no reply: not claimed
        break;
    case Fault::PortVanished:
        b.host->simulateFailure(QStringLiteral("test: unplugged"));
        QTRY_COMPARE(b.ctl->linkState(), LinkState::Lost);
        // Nothing can reach the device: the truth is that it may still move.
        QVERIFY(b.ctl->status().motionUnconfirmed);
        QVERIFY(b.ctl->jogRamp().isIdle());
        return;
    }
    QVERIFY2(b.stopFrameReceived(), "the device received no stop frame");
    QTRY_VERIFY_WITH_TIMEOUT(b.sim->standingStill(), 5000);
}

STEPDECK_TEST_GUILESS_MAIN(TestFaultMatrix)
#include "tst_faultmatrix.moc"
