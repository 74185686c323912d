// Jog on controllers without a jog command (laser-axis): the jog inputs become short targets,
// each sent only after the previous one arrived; releasing stops sending. Asserted at the
// simulated axes: what they received and that they stand still afterwards.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "controller/TargetJogger.h"
#include "jog/IncrementalJogWidget.h"
#include "jog/JogController.h"
#include "jog/JogInputSource.h"
#include "jog/JogPanel.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "safety/SafetyBar.h"
#include <QLabel>

using namespace stepdeck;
using namespace stepdeck::test;
using laser::LaserAxisSimulator;

namespace {
// A jog input that proves exactly what the test holds (the real sources prove it by key
// auto-repeat, pointer buttons or fresh gamepad samples).
class HeldStick : public ui::JogInputSource
{
public:
    QString sourceName() const override { return QStringLiteral("test stick"); }
    ui::SlotVelocities heldDeflection() override { return m_held; }
    void latch() override { m_held.clear(); }
    void hold(const ui::SlotVelocities& deflection)
    {
        m_held = deflection;
        Q_EMIT changed();
    }

private:
    ui::SlotVelocities m_held;
};
} // namespace

class TestTargetJogger : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void chunkSteps_shortAndNeverZero();
    void note_shownForLaserAxesOnly();
    void deflect_shortTargetsOneAfterTheOther_releaseStops();
    void deflect_positionUnknown_refusedWithReason();
    void incremental_movesByStepSize();

private:
    bool connectLaser();
    bool homeX();
    QList<laser::CommandFrame> received();
    bool simMoving();

    std::unique_ptr<UiFixture> m_f;
};

void TestTargetJogger::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
}

bool TestTargetJogger::connectLaser()
{
    ConnectionSpec spec{QStringLiteral("sim"), {}, {}};
    QString error;
    if (!m_f->window->context()->connectTo(*findModel(QStringLiteral("laser-axis")), spec, &error))
        return false;
    if (!m_f->waitConnected())
        return false;
    return m_f->withSimulatorAs<LaserAxisSimulator>(
        [](LaserAxisSimulator* s) { s->setSpeed(2000); });
}

bool TestTargetJogger::homeX()
{
    QSignalSpy finished(m_f->session, &ControllerSession::requestFinished);
    const RequestId id = m_f->session->reference({{Axis::X, -1}});
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 5000) {
        for (const QList<QVariant>& args : finished) {
            const CommandResult r = args.first().value<CommandResult>();
            if (r.id == id)
                return r.ok();
        }
        finished.wait(20);
    }
    return false;
}

QList<laser::CommandFrame> TestTargetJogger::received()
{
    QList<laser::CommandFrame> out;
    m_f->withSimulatorAs<LaserAxisSimulator>(
        [&](LaserAxisSimulator* s) { out = s->receivedCommands(); });
    return out;
}

bool TestTargetJogger::simMoving()
{
    bool moving = false;
    m_f->withSimulatorAs<LaserAxisSimulator>([&](LaserAxisSimulator* s) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            moving = moving || s->isMoving(a);
    });
    return moving;
}

void TestTargetJogger::chunkSteps_shortAndNeverZero()
{
    QCOMPARE(TargetJogger::chunkSteps(1000), qint64(200));
    QCOMPARE(TargetJogger::chunkSteps(-1000), qint64(-200));
    QCOMPARE(TargetJogger::chunkSteps(1), qint64(1));
    QCOMPARE(TargetJogger::chunkSteps(-0.1), qint64(-1));
    QCOMPARE(TargetJogger::chunkSteps(0), qint64(0));
    QCOMPARE(TargetJogger::chunkSteps(qQNaN()), qint64(0));
}

void TestTargetJogger::note_shownForLaserAxesOnly()
{
    QVERIFY(m_f->connectSim()); // E-LAB: a real jog stream
    QVERIFY(m_f->window->jogPanel()->jogModeNote()->isHidden());
    QVERIFY(connectLaser());
    QTRY_VERIFY(!m_f->window->jogPanel()->jogModeNote()->isHidden());
    QVERIFY(m_f->window->jogPanel()->jogModeNote()->text().contains("short targets"));
    // The protocol has no stop command: the permanent note stands next to STOP/PANIC.
    QLabel* noStop = m_f->window->safetyBar()->noStopNote();
    QVERIFY(!noStop->isHidden());
    QVERIFY2(noStop->text().contains("emergency stop"), qPrintable(noStop->text()));
}

void TestTargetJogger::deflect_shortTargetsOneAfterTheOther_releaseStops()
{
    QVERIFY(connectLaser());
    QVERIFY(homeX());
    ui::JogController* jog = m_f->window->jogController();
    jog->setMaxSpeed(ui::JogSlot::PadHorizontal, 1000);
    HeldStick stick;
    jog->addSource(&stick);
    stick.hold({{ui::JogSlot::PadHorizontal, 1.0}});
    QTRY_VERIFY_WITH_TIMEOUT(received().size() >= 4, 5000); // home + at least three targets
    stick.hold({});
    // The target in flight arrives; none follows it (the machine jogs by targets).
    QTRY_VERIFY_WITH_TIMEOUT(!simMoving(), 3000);
    const QList<laser::CommandFrame> got = received();
    // After the home: targets 200 apart (1000 units/s x 0.2 s), each the previous plus one
    // chunk -- so every one was sent after the previous arrived, never one far ahead.
    for (int i = 1; i < got.size(); ++i) {
        QCOMPARE(got.at(i).command, laser::Command::Move);
        QCOMPARE(got.at(i).position, 200 * i);
    }
    // And each one was reached and reported before the next went out: one status frame per
    // command, at that command's target (a target sent ahead would have replaced the previous
    // one, which then never reports).
    QList<QByteArray> reported;
    m_f->withSimulatorAs<LaserAxisSimulator>(
        [&](LaserAxisSimulator* s) { reported = s->sentStatusFrames(); });
    QCOMPARE(reported.size(), got.size());
    for (int i = 1; i < got.size(); ++i)
        QCOMPARE(reported.at(i),
                 laser::encodeStatus({Axis::X, 200 * i, laser::Status::TargetReached}));
    // Released: nothing more goes out.
    QSignalSpy traffic(m_f->session, &ControllerSession::traffic);
    QTest::qWait(300);
    for (const QList<QVariant>& args : traffic)
        QVERIFY(args.first().value<TrafficRecord>().direction != TrafficRecord::Direction::Out);
    QCOMPARE(received().size(), got.size());
}

void TestTargetJogger::deflect_positionUnknown_refusedWithReason()
{
    QVERIFY(connectLaser());
    QSignalSpy refused(m_f->window->jogController(), &ui::JogController::refused);
    HeldStick stick;
    m_f->window->jogController()->addSource(&stick);
    stick.hold({{ui::JogSlot::PadVertical, -0.5}});
    QTRY_VERIFY(!refused.isEmpty());
    QVERIFY(refused.last().first().toString().contains("unknown"));
    QTest::qWait(100);
    QVERIFY(received().isEmpty()); // nothing reached the axes
    stick.hold({});
}

void TestTargetJogger::incremental_movesByStepSize()
{
    QVERIFY(connectLaser());
    QVERIFY(homeX());
    ui::IncrementalJogWidget* inc = m_f->window->jogPanel()->incremental();
    inc->setUnitStepSize(10); // the connection's laser axes count the protocol's units
    inc->jogMachineAxis(QStringLiteral("X"), +1);
    QTRY_COMPARE(received().size(), 2);
    QCOMPARE(received().last(), (laser::CommandFrame{laser::Command::Move, Axis::X, 10}));
    QTRY_VERIFY(!simMoving());
}

STEPDECK_TEST_MAIN(TestTargetJogger)
#include "tst_targetjogger.moc"
