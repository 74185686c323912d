// LaserAxisController against the in-process LaserAxisSimulator over a LoopbackTransport
// pair. Every motion test asserts what the simulated axes received and where they stand.
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/laser/LaserAxisController.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "protocols/laser/LaserModel.h"
#include "transport/LoopbackTransport.h"
#include <QtTest>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::laser;

namespace {
struct Rig
{
    explicit Rig(int arrivalTimeoutMs = 60000)
    {
        auto [host, device] = LoopbackTransport::createPair();
        hostEnd.reset(host);
        deviceEnd.reset(device);
        sim = std::make_unique<LaserAxisSimulator>(SimulatorOptions{});
        sim->setSpeed(20000);
        sim->attach(deviceEnd.get());
        deviceEnd->open(lineSettings());
        ControllerOptions options;
        options.arrivalTimeoutMs = arrivalTimeoutMs;
        controller = std::make_unique<LaserAxisController>(hostEnd.get(), options);
        QObject::connect(controller.get(), &Controller::requestFinished, controller.get(),
                         [this](const CommandResult& r) { results.insert(r.id, r); });
        QObject::connect(controller.get(), &Controller::errorOccurred, controller.get(),
                         [this](const QString& e) { errors << e; });
    }
    ~Rig() { controller.reset(); }

    bool open()
    {
        controller->openLink(nextId);
        return waitFor(nextId++) && controller->linkState() == LinkState::Connected;
    }
    bool waitFor(RequestId id, int timeoutMs = 5000)
    {
        QElapsedTimer t;
        t.start();
        while (!results.contains(id) && t.elapsed() < timeoutMs)
            QTest::qWait(5);
        return results.contains(id);
    }
    RequestId id() { return nextId++; }
    const AxisStatus& axis(Axis a) const { return controller->status().axes.find(a).value(); }

    std::unique_ptr<LoopbackTransport> hostEnd;
    std::unique_ptr<LoopbackTransport> deviceEnd;
    std::unique_ptr<LaserAxisSimulator> sim;
    std::unique_ptr<LaserAxisController> controller;
    QHash<RequestId, CommandResult> results;
    QStringList errors;
    RequestId nextId = 1;
};
} // namespace

class TestLaserAxisController : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void capabilities_honest();
    void open_connectsWithoutSending();
    void home_sendsFrame_succeedsOnHomeSwitch();
    void moveAbsolute_sendsFrame_finishesOnTargetReached();
    void moveAbsolute_outOfRange_refusedNothingSent_data();
    void moveAbsolute_outOfRange_refusedNothingSent();
    void moveRelative_unknownPosition_refusedNothingSent();
    void moveRelative_afterStatus_fromReportedPosition();
    void moveAbsolute_endSwitch_finishesNamingIt();
    void moveAbsolute_newTarget_replacesOldRequest();
    void moveAbsolute_silentAxis_timesOutUnconfirmed();
    void arrivalTimeout_positionUnknown_relativeRefused();
    void stopAndPanic_unsupported_nothingSent();
    void jog_refusedNoStream();
    void unsolicitedFrames_doorAndSwitchAndPosition();
    void garbage_ignoredFramesStillRead();
    void close_duringMove_cancelsAndLeavesUnconfirmed();
    void linkLost_duringMove_failsRequestUnconfirmed();
    void sendRaw_commandFrame_closeWhileMoving_warnsMayStillMove_data();
    void sendRaw_commandFrame_closeWhileMoving_warnsMayStillMove();
    void sendRaw_moveFrame_arrivalConfirmsStandstill();
    void parameters_unsupported();
    void refreshStatus_noQuery_returnsLastReport();
    void newTarget_afterLostTrack_staysUnconfirmedUntilReport();
    void jogStep_commandedVelocity_untilEndOrLease();
};

void TestLaserAxisController::capabilities_honest()
{
    const Capabilities caps = laser::capabilities();
    QVERIFY(!caps.stopCommand);
    QVERIFY(!caps.panic);
    QVERIFY(!caps.statusQuery);
    QVERIFY(caps.reportsArrival);
    QVERIFY(caps.jogByTargets);
    QVERIFY(!caps.has(MotionMode::Jog));
    QVERIFY(caps.has(MotionMode::AbsoluteMove));
    QVERIFY(caps.has(MotionMode::Reference));
    QVERIFY(laser::modelInfo().schema.specs().isEmpty());
    // Positions are the protocol's plain numbers, not steps (issue 16).
    QCOMPARE(QString::fromLatin1(caps.positionUnit), QStringLiteral("units"));
    QCOMPARE(QString::fromLatin1(Capabilities{}.positionUnit), QStringLiteral("steps"));
    QCOMPARE(laser::lineSettings().baudRate, 9600);
    QCOMPARE(laser::lineSettings().stopBits, 1);
}

void TestLaserAxisController::open_connectsWithoutSending()
{
    Rig rig;
    QVERIFY(rig.open());
    QVERIFY(rig.sim->receivedCommands().isEmpty());
    QVERIFY(!rig.axis(Axis::X).positionKnown);
}

void TestLaserAxisController::home_sendsFrame_succeedsOnHomeSwitch()
{
    Rig rig;
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->reference(id, {{Axis::X, 1}, {Axis::Y, 0}});
    QVERIFY(rig.controller->status().busy);
    QVERIFY(rig.axis(Axis::X).moving);
    // Tracked, awaiting its report: motion, not "unconfirmed" (issue 16: red on every jog).
    QVERIFY(!rig.controller->status().motionUnconfirmed);
    QVERIFY(rig.waitFor(id));
    QVERIFY(rig.results[id].ok());
    QCOMPARE(rig.sim->receivedCommands(), (QList<CommandFrame>{{Command::Home, Axis::X, 0}}));
    QVERIFY(rig.sim->isHomed(Axis::X));
    QVERIFY(!rig.sim->isHomed(Axis::Y));
    QVERIFY(rig.axis(Axis::X).referenced);
    QVERIFY(rig.axis(Axis::X).positionKnown);
    QCOMPARE(rig.axis(Axis::X).position, qint64(0));
    QCOMPARE(rig.axis(Axis::X).lastSwitch, SwitchEvent::Reference);
    QVERIFY(!rig.controller->status().motionUnconfirmed);
}

void TestLaserAxisController::moveAbsolute_sendsFrame_finishesOnTargetReached()
{
    Rig rig;
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::Y, 150}});
    QVERIFY(rig.axis(Axis::Y).moving);
    QVERIFY(rig.waitFor(id));
    QVERIFY(rig.results[id].ok());
    QCOMPARE(rig.sim->receivedCommands(), (QList<CommandFrame>{{Command::Move, Axis::Y, 150}}));
    QCOMPARE(rig.sim->position(Axis::Y), qint64(150));
    QVERIFY(!rig.sim->isMoving(Axis::Y));
    QCOMPARE(rig.axis(Axis::Y).position, qint64(150));
    QVERIFY(rig.axis(Axis::Y).positionKnown);
    QVERIFY(!rig.axis(Axis::Y).moving);
    QVERIFY(!rig.controller->status().busy);
}

void TestLaserAxisController::moveAbsolute_outOfRange_refusedNothingSent_data()
{
    QTest::addColumn<qint64>("target");
    QTest::newRow("negative") << qint64(-1);
    QTest::newRow("six digits") << qint64(100000);
    QTest::newRow("huge") << (qint64(1) << 40);
}

void TestLaserAxisController::moveAbsolute_outOfRange_refusedNothingSent()
{
    QFETCH(qint64, target);
    Rig rig;
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::X, 5}, {Axis::Z, target}});
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::InvalidValue);
    QVERIFY(rig.results[id].message.contains("0..99999"));
    QTest::qWait(20);
    QVERIFY(rig.sim->receivedCommands().isEmpty());
    QVERIFY(!rig.controller->status().motionUnconfirmed);
}

void TestLaserAxisController::moveRelative_unknownPosition_refusedNothingSent()
{
    Rig rig;
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveRelative(id, {{Axis::X, 10}});
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::Refused);
    QVERIFY(rig.results[id].message.contains("unknown"));
    QTest::qWait(20);
    QVERIFY(rig.sim->receivedCommands().isEmpty());
}

void TestLaserAxisController::moveRelative_afterStatus_fromReportedPosition()
{
    Rig rig;
    QVERIFY(rig.open());
    RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::Z, 500}});
    QVERIFY(rig.waitFor(id));
    id = rig.id();
    rig.controller->moveRelative(id, {{Axis::Z, -120}});
    QVERIFY(rig.waitFor(id));
    QVERIFY(rig.results[id].ok());
    QCOMPARE(rig.sim->receivedCommands().last(), (CommandFrame{Command::Move, Axis::Z, 380}));
    QCOMPARE(rig.sim->position(Axis::Z), qint64(380));
    // Below 0 is out of the protocol's range: refused, not clamped.
    id = rig.id();
    rig.controller->moveRelative(id, {{Axis::Z, -381}});
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::InvalidValue);
    QCOMPARE(rig.sim->receivedCommands().size(), 2);
}

void TestLaserAxisController::moveAbsolute_endSwitch_finishesNamingIt()
{
    Rig rig;
    rig.sim->config(Axis::Y).endSwitch = 300;
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::Y, 500}, {Axis::X, 40}});
    QVERIFY(rig.waitFor(id));
    QVERIFY(rig.results[id].ok());
    QCOMPARE(rig.results[id].value.toMap().value("endSwitch").toStringList(), QStringList{"Y"});
    QVERIFY(rig.axis(Axis::Y).limitSwitch);
    QCOMPARE(rig.axis(Axis::Y).lastSwitch, SwitchEvent::Limit);
    QCOMPARE(rig.axis(Axis::Y).position, qint64(300));
    QVERIFY(!rig.axis(Axis::X).limitSwitch);
    QCOMPARE(rig.sim->position(Axis::X), qint64(40));
    QVERIFY(!rig.errors.isEmpty());
    QVERIFY(rig.errors.last().contains("end switch"));
}

void TestLaserAxisController::moveAbsolute_newTarget_replacesOldRequest()
{
    Rig rig;
    rig.sim->setSpeed(1000);
    rig.sim->powerOn(Axis::X, 0);
    QVERIFY(rig.open());
    const RequestId first = rig.id();
    rig.controller->moveAbsolute(first, {{Axis::X, 90000}});
    QTRY_VERIFY(rig.sim->position(Axis::X) > 0);
    const RequestId second = rig.id();
    rig.controller->moveAbsolute(second, {{Axis::X, 30}});
    QVERIFY(rig.waitFor(first));
    QCOMPARE(rig.results[first].error, ErrorKind::Cancelled);
    QVERIFY(rig.waitFor(second));
    QVERIFY(rig.results[second].ok());
    QCOMPARE(rig.sim->position(Axis::X), qint64(30));
    QVERIFY(!rig.sim->isMoving(Axis::X));
}

void TestLaserAxisController::moveAbsolute_silentAxis_timesOutUnconfirmed()
{
    Rig rig(150); // the 60 s of the laser, shortened for the test
    rig.sim->faults().silent = true;
    rig.sim->setSpeed(2000);
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::Z, 400}});
    QVERIFY(!rig.controller->status().motionUnconfirmed); // tracked until the deadline
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::Timeout);
    QVERIFY(rig.results[id].message.contains("Z"));
    QVERIFY(rig.controller->status().motionUnconfirmed);
    QVERIFY(rig.sim->isMoving(Axis::Z)); // the device really is still on its way
    // A late status frame proves it stopped.
    rig.sim->faults().silent = false;
    QTRY_VERIFY_WITH_TIMEOUT(!rig.controller->status().motionUnconfirmed, 10000);
    QCOMPARE(rig.axis(Axis::Z).position, qint64(400));
}

void TestLaserAxisController::arrivalTimeout_positionUnknown_relativeRefused()
{
    // stepdeck-bench --soak: after a lost status frame a relative move went from the last
    // reported position, i.e. to the wrong target.
    Rig rig(150);
    QVERIFY(rig.open());
    RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::X, 100}});
    QVERIFY(rig.waitFor(id));
    QVERIFY(rig.axis(Axis::X).positionKnown);
    rig.sim->faults().silent = true;
    id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::X, 400}});
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::Timeout);
    QVERIFY(!rig.axis(Axis::X).positionKnown);
    id = rig.id();
    rig.controller->moveRelative(id, {{Axis::X, 50}});
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::Refused);
    QCOMPARE(rig.sim->receivedCommands().size(), 2); // nothing sent for the relative move
}

void TestLaserAxisController::stopAndPanic_unsupported_nothingSent()
{
    Rig rig;
    QVERIFY(rig.open());
    const RequestId stop = rig.id();
    rig.controller->stop(stop);
    const RequestId panic = rig.id();
    rig.controller->panic(panic);
    QVERIFY(rig.waitFor(stop) && rig.waitFor(panic));
    for (RequestId id : {stop, panic}) {
        QCOMPARE(rig.results[id].error, ErrorKind::Unsupported);
        QCOMPARE(rig.results[id].message, Controller::noStopCommandText());
    }
    QTest::qWait(20);
    QVERIFY(rig.sim->receivedCommands().isEmpty());
    QCOMPARE(rig.sim->rejectedFrames(), 0);
}

void TestLaserAxisController::jog_refusedNoStream()
{
    Rig rig;
    QVERIFY(rig.open());
    QSignalSpy refused(rig.controller.get(), &Controller::jogRefused);
    rig.controller->setJogVelocity({{Axis::X, 100}});
    QCOMPARE(refused.count(), 1);
    QVERIFY(refused.first().first().toString().contains("short targets"));
    QTest::qWait(20);
    QVERIFY(rig.sim->receivedCommands().isEmpty());
}

void TestLaserAxisController::unsolicitedFrames_doorAndSwitchAndPosition()
{
    Rig rig;
    QVERIFY(rig.open());
    QVERIFY(!rig.controller->status().doorOpen.has_value());
    rig.sim->setDoorOpen(true);
    QTRY_VERIFY(rig.controller->status().doorOpen.value_or(false));
    QVERIFY(rig.axis(Axis::X).positionKnown); // the door frame carried X's position
    rig.sim->setDoorOpen(false);
    QTRY_VERIFY(!rig.controller->status().doorOpen.value_or(true));
    rig.sim->reportStatus(Axis::Z, Status::EndSwitch);
    QTRY_COMPARE(rig.axis(Axis::Z).lastSwitch, SwitchEvent::Limit);
    QVERIFY(rig.axis(Axis::Z).limitSwitch);
    const QJsonObject json = rig.controller->status().toJson("laser-axis");
    QCOMPARE(json["machine"].toObject()["doorOpen"].toBool(true), false);
    QCOMPARE(json["axes"].toObject()["Z"].toObject()["lastSwitch"].toString(), QString("limit"));
    QVERIFY(!json["axes"].toObject()["Y"].toObject().contains("lastSwitch"));
}

void TestLaserAxisController::garbage_ignoredFramesStillRead()
{
    Rig rig;
    rig.sim->setGarbageBeforeStatus(true);
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::X, 77}});
    QVERIFY(rig.waitFor(id));
    QVERIFY(rig.results[id].ok());
    QCOMPARE(rig.controller->status().resyncCount, quint64(1));
    QVERIFY(rig.errors.join("\n").contains("malformed"));
}

void TestLaserAxisController::close_duringMove_cancelsAndLeavesUnconfirmed()
{
    Rig rig;
    rig.sim->setSpeed(500);
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::X, 5000}});
    QTRY_VERIFY(rig.sim->isMoving(Axis::X));
    rig.controller->closeLink();
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::Cancelled);
    QVERIFY(rig.controller->status().motionUnconfirmed);
    QCOMPARE(rig.controller->linkState(), LinkState::Disconnected);
    QVERIFY(rig.errors.join("\n").contains("no stop command"));
    // Nothing could stop it: the device goes on (the truth the flag stands for).
    QVERIFY(rig.sim->isMoving(Axis::X));
}

void TestLaserAxisController::linkLost_duringMove_failsRequestUnconfirmed()
{
    Rig rig;
    rig.sim->setSpeed(500);
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->moveAbsolute(id, {{Axis::Y, 5000}});
    rig.hostEnd->simulateFailure("unplugged");
    QVERIFY(rig.waitFor(id));
    QCOMPARE(rig.results[id].error, ErrorKind::LinkDown);
    QCOMPARE(rig.controller->linkState(), LinkState::Lost);
    QVERIFY(rig.controller->status().motionUnconfirmed);
    QVERIFY(!rig.axis(Axis::Y).positionKnown);
    QVERIFY(rig.errors.join("\n").contains(Controller::mayStillBeMovingText())); // said once
    QCOMPARE(rig.errors.filter("link lost").size(), 1);
}

// A frame typed in the traffic console moves the axis like a move request: the host tracks it
// (moving, motion unconfirmed), and closing while it runs says it may still be moving.
void TestLaserAxisController::sendRaw_commandFrame_closeWhileMoving_warnsMayStillMove_data()
{
    QTest::addColumn<QList<QByteArray>>("pieces");
    QTest::addColumn<QString>("axisLetter");
    QTest::newRow("move") << QList<QByteArray>{"2105000\r"} << "X";
    QTest::newRow("home") << QList<QByteArray>{"1200000\r"} << "Y";
    QTest::newRow("move in two pieces") << QList<QByteArray>{"230", "5000\r"} << "Z";
}

void TestLaserAxisController::sendRaw_commandFrame_closeWhileMoving_warnsMayStillMove()
{
    QFETCH(QList<QByteArray>, pieces);
    QFETCH(QString, axisLetter);
    const Axis axis = axisFromName(axisLetter).value();
    Rig rig;
    rig.sim->setSpeed(500);
    rig.sim->powerOn(axis, 3000); // a home run has 3000 units to go
    QVERIFY(rig.open());
    for (const QByteArray& piece : pieces) {
        const RequestId id = rig.id();
        rig.controller->sendRaw(id, piece);
        QVERIFY(rig.waitFor(id));
        QVERIFY(rig.results[id].ok());
    }
    QTRY_VERIFY(rig.sim->isMoving(axis)); // the device took the frame
    QVERIFY(rig.axis(axis).moving);
    QVERIFY(rig.controller->status().motionUnconfirmed);
    rig.controller->closeLink();
    QCOMPARE(rig.controller->linkState(), LinkState::Disconnected);
    QVERIFY(rig.controller->status().motionUnconfirmed);
    const QString errors = rig.errors.join("\n");
    QVERIFY2(errors.contains(QStringLiteral("no longer tracking axis %1").arg(axisName(axis))),
             qPrintable(errors));
    QVERIFY(errors.contains("no stop command"));
    QVERIFY(rig.sim->isMoving(axis)); // nothing stopped it: the warning is the truth
}

void TestLaserAxisController::sendRaw_moveFrame_arrivalConfirmsStandstill()
{
    Rig rig;
    QVERIFY(rig.open());
    const RequestId waiting = rig.id();
    rig.sim->setSpeed(500);
    rig.controller->moveAbsolute(waiting, {{Axis::X, 5000}});
    const RequestId raw = rig.id();
    rig.controller->sendRaw(raw, "2100040\r"); // replaces the target, as on the axes
    QVERIFY(rig.waitFor(waiting));
    QCOMPARE(rig.results[waiting].error, ErrorKind::Cancelled);
    QTRY_VERIFY(!rig.axis(Axis::X).moving);
    QCOMPARE(rig.axis(Axis::X).position, qint64(40));
    QCOMPARE(rig.sim->position(Axis::X), qint64(40));
    QVERIFY(!rig.sim->isMoving(Axis::X));
    QVERIFY(!rig.controller->status().motionUnconfirmed);
    QVERIFY(!rig.controller->status().busy);
}

void TestLaserAxisController::parameters_unsupported()
{
    Rig rig;
    QVERIFY(rig.open());
    const RequestId read = rig.id();
    rig.controller->readParameters(read, {"speed"});
    QVERIFY(rig.waitFor(read));
    QCOMPARE(rig.results[read].error, ErrorKind::Unsupported);
    const RequestId empty = rig.id();
    rig.controller->writeParameters(empty, {}, true);
    QVERIFY(rig.waitFor(empty));
    QVERIFY(rig.results[empty].ok());
}

void TestLaserAxisController::refreshStatus_noQuery_returnsLastReport()
{
    Rig rig;
    QVERIFY(rig.open());
    const RequestId id = rig.id();
    rig.controller->refreshStatus(id);
    QVERIFY(rig.waitFor(id));
    QVERIFY(rig.results[id].ok());
    QTest::qWait(20);
    QVERIFY(rig.sim->receivedCommands().isEmpty());
    QCOMPARE(rig.sim->rejectedFrames(), 0); // nothing at all went to the axes
}

void TestLaserAxisController::newTarget_afterLostTrack_staysUnconfirmedUntilReport()
{
    Rig rig(150);
    rig.sim->faults().silent = true;
    rig.sim->setSpeed(2000);
    QVERIFY(rig.open());
    const RequestId lost = rig.id();
    rig.controller->moveAbsolute(lost, {{Axis::Y, 300}});
    QVERIFY(rig.waitFor(lost));
    QVERIFY(rig.controller->status().motionUnconfirmed);
    // A new target does not prove the old motion ended: still unconfirmed ...
    const RequestId next = rig.id();
    rig.controller->moveAbsolute(next, {{Axis::Y, 350}});
    QVERIFY(rig.controller->status().motionUnconfirmed);
    // ... until the axis itself reports.
    rig.sim->faults().silent = false;
    QTRY_VERIFY_WITH_TIMEOUT(!rig.controller->status().motionUnconfirmed, 10000);
    QVERIFY(!rig.sim->isMoving(Axis::Y));
    QCOMPARE(rig.sim->position(Axis::Y), qint64(350));
}

void TestLaserAxisController::jogStep_commandedVelocity_untilEndOrLease()
{
    // Jog by targets: the rate each short target stands for is the commanded velocity (the
    // jog panel showed +0 while the axes moved, issue 16).
    Rig rig;
    rig.sim->setSpeed(1000);
    QVERIFY(rig.open());
    const RequestId home = rig.id();
    rig.controller->reference(home, {{Axis::X, 1}});
    QVERIFY(rig.waitFor(home));
    const RequestId step = rig.id();
    rig.controller->jogStep(step, {{Axis::X, 100}}, {{Axis::X, 500.0}});
    QCOMPARE(rig.axis(Axis::X).commandedVelocity, 500.0);
    QCOMPARE(rig.axis(Axis::Y).commandedVelocity, 0.0);
    QVERIFY(!rig.controller->status().motionUnconfirmed);
    QTRY_VERIFY(rig.sim->isMoving(Axis::X));
    QVERIFY(rig.waitFor(step));
    QVERIFY(rig.results[step].ok());
    QCOMPARE(rig.axis(Axis::X).commandedVelocity, 500.0); // the next step may follow at once
    const RequestId again = rig.id();
    rig.controller->jogStep(again, {{Axis::X, 100}}, {{Axis::X, 400.0}});
    QCOMPARE(rig.axis(Axis::X).commandedVelocity, 400.0);
    rig.controller->endJog(); // released: nothing more commanded, the step ends by itself
    QCOMPARE(rig.axis(Axis::X).commandedVelocity, 0.0);
    QVERIFY(rig.waitFor(again));
    QCOMPARE(rig.sim->position(Axis::X), qint64(200));
    // No next step within the lease after one ended: zero again without endJog().
    const RequestId last = rig.id();
    rig.controller->jogStep(last, {{Axis::X, -50}}, {{Axis::X, -250.0}});
    QCOMPARE(rig.axis(Axis::X).commandedVelocity, -250.0);
    QVERIFY(rig.waitFor(last));
    QTRY_COMPARE(rig.axis(Axis::X).commandedVelocity, 0.0);
    QVERIFY(!rig.sim->isMoving(Axis::X));
}

STEPDECK_TEST_GUILESS_MAIN(TestLaserAxisController)
#include "tst_laseraxiscontroller.moc"
