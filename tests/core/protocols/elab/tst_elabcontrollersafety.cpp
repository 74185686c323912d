// The E-LAB adapter's safety paths (ElabControllerStop.cpp, docs/architecture.md "Safety
// contract") against the real ElabSimulator. Every test asserts what the DEVICE saw (frames at
// the simulator) and that the simulated axes stand still, not only the host's own variables.
#include "ElabControllerRig.h"
#include "KernelBufferTransport.h"
#include "TestMain.h"
#include <QRandomGenerator>

namespace {
const QByteArray kZeroJog = encode::jogSpeed({0, 0, 0});

bool deviceStill(Rig& rig)
{
    return rig.sim->standingStill();
}
} // namespace

class TestElabControllerSafety : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void stop_whileJogging_sendsZeroJog_deviceStops();
    void close_whileJogging_zeroJogReachesDevice_beforeClose();
    void close_duringVelocityMove_deviceBrakes();
    void pollLoss_whileJogging_stopReachesDevice_portStaysOpenForPanic();
    void peerVanish_whileJogging_saysItMayStillMove();
    void lostJogAck_stopsAndRereadsStatus();
    void untrackedMotion_atConnect_isStopped();
    void untrackedMotion_statusReadQueuedBehindTheRead_notCancelledByTheStop();
    void limitSwitch_duringJog_stopsAxis_andOnlyAwayIsAllowed();
    void limitSwitch_duringStream_endsStream();
    void velocityReversal_waitsForStandstill();
    void setupWrite_whileMoving_refusedAndNotSent();
    void stream_kernelBuffer_pacedByWire_noOverflowAfterXoff();
    void stream_adapterFifoTheDriverDoesNotCount_pacedByWireBudget();
    void stream_stop_discardsBacklog_deviceStopsPromptly();
    void lineNoise_statusReads_survive();
    void resetLine_dtrOption_reachesTransport();
};

void TestElabControllerSafety::stop_whileJogging_sendsZeroJog_deviceStops()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.jogUntil({{Axis::X, 800}}, [&] { return rig.sim->isMoving(Axis::X); }));
    rig.sim->clearReceivedFrames();
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->stop(id); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    // The manual lists only SetJogSpeed and ForcePanicStop in jog mode: <XOFF> alone would
    // leave the simulated board jogging.
    QVERIFY(rig.sim->countReceived(kZeroJog) >= 1);
    QVERIFY(rig.sim->countReceived(encode::stopMove()) >= 1);
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 2000);
    QVERIFY(!rig.ctl->status().motionUnconfirmed);
}

void TestElabControllerSafety::close_whileJogging_zeroJogReachesDevice_beforeClose()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.jogUntil({{Axis::Y, -900}}, [&] { return rig.sim->isMoving(Axis::Y); }));
    rig.sim->clearReceivedFrames();
    QVERIFY(rig.close());
    QCOMPARE(rig.ctl->linkState(), LinkState::Disconnected);
    QVERIFY(!rig.hostEnd->isOpen());
    QVERIFY(rig.sim->countReceived(kZeroJog) >= 1);
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 2000);
    QVERIFY(!rig.ctl->status().motionUnconfirmed); // the board acknowledged it
}

void TestElabControllerSafety::close_duringVelocityMove_deviceBrakes()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::Z, 4000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::Z), 5000);
    rig.sim->clearReceivedFrames();
    QVERIFY(rig.close());
    QCOMPARE(rig.sim->receivedFrames(), QList<QByteArray>{encode::stopMove()});
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
}

void TestElabControllerSafety::pollLoss_whileJogging_stopReachesDevice_portStaysOpenForPanic()
{
    ControllerOptions o = defaultOptions();
    o.commandTimeoutMs = 100;
    o.pollIntervalMs = 20;
    Rig rig(o);
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.jogUntil({{Axis::X, 700}}, [&] { return rig.sim->isMoving(Axis::X); }));
    rig.sim->faults().silent = true; // the board still listens, its replies are lost
    rig.sim->clearReceivedFrames();
    // An input that keeps renewing must not keep the axis running across the outage.
    QVERIFY(rig.jogUntil(
        {{Axis::X, 700}}, [&] { return rig.ctl->linkState() == LinkState::Lost; }, 10000));
    QVERIFY(rig.sim->countReceived(kZeroJog) >= 1);
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 2000);
    // No reply came: the host must not claim the stop.
    QVERIFY(rig.ctl->status().motionUnconfirmed);
    QVERIFY(rig.hostEnd->isOpen());
    const CommandResult p = rig.run([&](RequestId id) { rig.ctl->panic(id); }, 2000);
    Q_UNUSED(p) // no reply from a silent board; what counts is that the byte reached it
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->countReceived(encode::panicStop()) >= 1, 2000);
}

void TestElabControllerSafety::peerVanish_whileJogging_saysItMayStillMove()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.jogUntil({{Axis::X, 500}}, [&] { return rig.sim->isMoving(Axis::X); }));
    rig.errors->clear();
    rig.hostEnd->simulateFailure(QStringLiteral("test: unplugged"));
    QTRY_COMPARE(rig.ctl->linkState(), LinkState::Lost);
    // Nothing can reach a vanished port: the truth is that the board may still jog.
    QVERIFY(rig.ctl->status().motionUnconfirmed);
    QCOMPARE(rig.errors->count(), 1);
    const QString said = rig.errors->first().at(0).toString();
    QVERIFY2(said.contains(Controller::mayStillBeMovingText()), qPrintable(said));
    QVERIFY(rig.ctl->jogRamp().isIdle());
}

void TestElabControllerSafety::lostJogAck_stopsAndRereadsStatus()
{
    ControllerOptions o = defaultOptions();
    o.commandTimeoutMs = 150;
    Rig rig(o);
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.jogUntil({{Axis::X, 600}}, [&] { return rig.sim->isMoving(Axis::X); }));
    // The ACK of the next <DC4> is lost: whether the board took the new rate is unknown.
    rig.sim->clearReceivedFrames();
    rig.sim->dropNextReplyTo(ctrl::DC4);
    rig.errors->clear();
    QVERIFY(rig.jogUntil({{Axis::X, 900}}, [&] { return rig.sim->countReceived(kZeroJog) >= 1; }));
    // The host stopped it (zero rates, ForceStopMove) and read the status again.
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
    QVERIFY(rig.sim->countReceived(encode::stopMove()) >= 1);
    bool said = false;
    for (const QList<QVariant>& e : *rig.errors)
        said = said || e.at(0).toString().contains(QLatin1String("may still be jogging"));
    QVERIFY(said);
    rig.ctl->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->jogRamp().isIdle(), 3000);
}

void TestElabControllerSafety::untrackedMotion_atConnect_isStopped()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::Y, 4000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::Y), 5000);
    // A host that crashed: its adapter vanishes without any close; the board runs on.
    {
        QSignalBlocker quiet(rig.hostEnd.get());
        rig.ctl.reset();
    }
    QVERIFY(rig.sim->isMoving(Axis::Y));
    rig.sim->clearReceivedFrames();
    rig.replaceController(defaultOptions());
    QVERIFY(rig.connect());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->countReceived(encode::stopMove()) >= 1, 3000);
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
    bool said = false;
    for (const QList<QVariant>& e : *rig.errors)
        said = said || e.at(0).toString().contains(QLatin1String("did not command"));
    QVERIFY(said);
}

// Issue 28: two status reads queued together (a CLI's read behind a poll); the first one shows
// move bits the host did not command and the host stops that motion. The stop overtakes the
// second read but does not drop it: a read only observes, it returns what the board reports
// (never "cancelled by stop"). The board got the stop and stands.
void TestElabControllerSafety::untrackedMotion_statusReadQueuedBehindTheRead_notCancelledByTheStop()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    // A FastMove X, Y of an earlier host: the board runs it, its ACK went nowhere.
    rig.sim->faults().silent = true;
    rig.sim->receive(encode::fastMoveXY(100000, 100000));
    rig.sim->faults().silent = false;
    QVERIFY(rig.sim->isMoving(Axis::X) && rig.sim->isMoving(Axis::Y));
    rig.sim->clearReceivedFrames();
    rig.errors->clear();

    const RequestId first = rig.nextId++;
    const RequestId second = rig.nextId++;
    rig.ctl->refreshStatus(first);
    rig.ctl->refreshStatus(second);
    const CommandResult read = rig.wait(first);
    QVERIFY2(read.ok(), qPrintable(read.message));
    const MachineStatus seen = read.value.value<MachineStatus>();
    QVERIFY(seen.axes.value(Axis::X).moving && seen.axes.value(Axis::Y).moving);
    const CommandResult behind = rig.wait(second);
    QVERIFY2(behind.ok(), qPrintable(behind.message));

    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->countReceived(encode::stopMove()) >= 1, 3000);
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
    QVERIFY(rig.sim->position(Axis::X) < 100000);
    bool said = false;
    for (const QList<QVariant>& e : *rig.errors)
        said = said || e.at(0).toString().contains(QLatin1String("did not command"));
    QVERIFY(said);
}

void TestElabControllerSafety::limitSwitch_duringJog_stopsAxis_andOnlyAwayIsAllowed()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->setLimitPositions(Axis::X, -100000, 150); // the + limit switch sits at X=150
    QVERIFY(rig.jogUntil({{Axis::X, 600}},
                         [&] { return rig.ctl->status().axes.value(Axis::X).limitSwitch; }));
    // The board does not stop a jog at a limit switch; the host does, and the device stands.
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
    QVERIFY(!rig.jogRefusals->isEmpty());
    const qint64 atLimit = rig.sim->position(Axis::X);
    // Further into the switch: refused, nothing moves.
    rig.jogRefusals->clear();
    rig.ctl->setJogVelocity({{Axis::X, 300}});
    QCOMPARE(rig.jogRefusals->count(), 1);
    QVERIFY(rig.jogRefusals->first().at(0).toString().contains("only jogging away"));
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->jogRamp().isIdle(), 2000);
    QCOMPARE(rig.sim->position(Axis::X), atLimit);
    // Away from it: allowed.
    QVERIFY(
        rig.jogUntil({{Axis::X, -300}}, [&] { return rig.sim->position(Axis::X) < atLimit - 20; }));
    rig.ctl->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
}

void TestElabControllerSafety::limitSwitch_duringStream_endsStream()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->setLimitPositions(Axis::X, -100000, 40);
    QVector<AxisVector> steps(3000, AxisVector{{Axis::X, 1}});
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->feedStream(id, steps); }, 20000);
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("limit switch"), qPrintable(r.message));
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
    // The host stopped streaming when the status showed the switch: most of the 3000 step
    // pairs never reached the board.
    int pairs = 0;
    for (const QByteArray& f : rig.sim->receivedFrames())
        pairs += f.startsWith(ctrl::DC2) ? 1 : 0;
    QVERIFY2(pairs < 1000, qPrintable(QString::number(pairs)));
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->countReceived(encode::endOfFeed()) >= 1, 3000);
}

void TestElabControllerSafety::velocityReversal_waitsForStandstill()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, 5000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, 0}}); }).ok());
    // At once the other way: the board would ignore the sign while it still brakes ("wird
    // hier dann das Vorzeichen nicht mehr beachtet") and run on in the old direction.
    const CommandResult r = rig.run(
        [&](RequestId id) {
            rig.ctl->velocityMove(id, {{Axis::X, -5000}});
        },
        15000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    const qint64 turned = rig.sim->position(Axis::X);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->position(Axis::X) < turned - 50, 5000);
    QVERIFY(rig.sim->lastNakReason().isEmpty());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->stop(id); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 5000);
}

void TestElabControllerSafety::setupWrite_whileMoving_refusedAndNotSent()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, 4000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    rig.sim->clearReceivedFrames();
    ParameterSet set;
    set.insert("max-speed", perAxis(6000, 6000, 6000));
    CommandResult r = rig.run([&](RequestId id) { rig.ctl->writeParameters(id, set, false); });
    QCOMPARE(r.error, ErrorKind::Refused);
    r = rig.run([&](RequestId id) { rig.ctl->setCoolant(id, true); });
    QCOMPARE(r.error, ErrorKind::Refused);
    for (const QByteArray& f : rig.sim->receivedFrames()) {
        QVERIFY2(!f.startsWith(ctrl::ESC) && !f.startsWith(ctrl::SI), qPrintable(toMnemonics(f)));
    }
    QVERIFY(!rig.sim->coolant());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->stop(id); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 5000);
}

void TestElabControllerSafety::stream_kernelBuffer_pacedByWire_noOverflowAfterXoff()
{
    auto* host = new stepdeck::testing::KernelBufferTransport(lineSettings());
    Rig rig(defaultOptions(), false, host);
    QVERIFY(rig.connectAndSetup());
    // The board's buffer: XOFF at 48 bytes, 16 step pairs of slack behind it.
    rig.sim->setStreamBuffer(80, 48, 16);
    QVector<AxisVector> steps(1500, AxisVector{{Axis::X, 1}, {Axis::Y, -1}});
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->feedStream(id, steps); }, 60000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 20000);
    // Paced by the wire: the kernel never held more than about one chunk, so after the
    // board's XOFF at most its slack arrived -- no byte hit a full buffer, none lost.
    QVERIFY2(host->maxQueued() <= 2 * ElabCtlStream::kChunkSteps + 4,
             qPrintable(QString::number(host->maxQueued())));
    QCOMPARE(rig.sim->streamOverflows(), 0);
    QCOMPARE(rig.sim->executedStepBytes(), 1500);
    QCOMPARE(rig.sim->position(Axis::X), 1500);
}

// A USB adapter's own FIFO is not part of TIOCOUTQ: the driver reports nothing pending while
// the bytes still wait for the line. Only the wire budget keeps the stream from filling it.
void TestElabControllerSafety::stream_adapterFifoTheDriverDoesNotCount_pacedByWireBudget()
{
    auto* host = new stepdeck::testing::KernelBufferTransport(lineSettings(), false);
    Rig rig(defaultOptions(), false, host);
    QVERIFY(rig.connectAndSetup());
    rig.sim->setStreamBuffer(80, 48, 16);
    QVector<AxisVector> steps(1500, AxisVector{{Axis::X, 1}, {Axis::Y, -1}});
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->feedStream(id, steps); }, 60000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 20000);
    // About one chunk in the FIFO at a time (its release runs on a 1 ms timer, so it may lag
    // the line by a few bytes); never the stream's kilobytes.
    QVERIFY2(host->maxQueued() <= 4 * ElabCtlStream::kChunkSteps,
             qPrintable(QString::number(host->maxQueued())));
    QCOMPARE(rig.sim->streamOverflows(), 0);
    QCOMPARE(rig.sim->executedStepBytes(), 1500);
    QCOMPARE(rig.sim->position(Axis::X), 1500);
}

void TestElabControllerSafety::stream_stop_discardsBacklog_deviceStopsPromptly()
{
    auto* host = new stepdeck::testing::KernelBufferTransport(lineSettings());
    Rig rig(defaultOptions(), false, host);
    QVERIFY(rig.connectAndSetup());
    QVector<AxisVector> steps(5000, AxisVector{{Axis::Z, 1}});
    const RequestId stream = rig.nextId++;
    rig.ctl->feedStream(stream, steps);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::Z), 5000);
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->stop(id); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QTRY_VERIFY_WITH_TIMEOUT(deviceStill(rig), 3000);
    const qint64 executed = rig.sim->executedStepBytes();
    QVERIFY2(executed < 1000, qPrintable(QString::number(executed)));
    QVERIFY(!rig.wait(stream).ok());
    // Nothing of the discarded backlog arrives later: the board executes no further step.
    QSignalSpy anyTraffic(rig.ctl.get(), &Controller::statusChanged);
    anyTraffic.wait(300); // event loop runs (polls go on); only a window, not an assertion
    QCOMPARE(rig.sim->executedStepBytes(), executed);
}

void TestElabControllerSafety::lineNoise_statusReads_survive()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    // Random bytes between the board's replies, about one per status read.
    QRandomGenerator random(7);
    QTimer noise;
    noise.setInterval(7);
    connect(&noise, &QTimer::timeout, rig.deviceEnd.get(), [&] {
        char b = char(random.bounded(0x20, 0x7F)); // printable: no control byte of the protocol
        rig.deviceEnd->write(QByteArray(1, b));
    });
    noise.start();
    int failures = 0;
    for (int i = 0; i < 40; ++i) {
        const CommandResult r = rig.run([&](RequestId id) { rig.ctl->refreshStatus(id); });
        failures += r.ok() ? 0 : 1;
    }
    noise.stop();
    QCOMPARE(failures, 0);
    QCOMPARE(rig.ctl->linkState(), LinkState::Connected);
}

void TestElabControllerSafety::resetLine_dtrOption_reachesTransport()
{
    ControllerOptions o = defaultOptions();
    o.resetLine = LineSettings::ResetLine::Dtr;
    Rig rig(o);
    QVERIFY(rig.connect());
    QCOMPARE(rig.hostEnd->lineSettings().resetLine, LineSettings::ResetLine::Dtr);
}

STEPDECK_TEST_GUILESS_MAIN(TestElabControllerSafety)
#include "tst_elabcontrollersafety.moc"
