// EmisController motion against the in-process SMC-IC4 simulator: vector moves, reference runs,
// host-tracked positions, the chunked jog and its lease, lost arrivals and lost links. The
// safety tests assert what the simulated board saw and that its motors stand still.
#include "EmisControllerRig.h"
#include "TestMain.h"
#include "TestSupport.h"

using namespace stepdeck;
using namespace stepdeck::emis;
using stepdeck::test::EmisRig;

namespace {
// Lets the event loop run for ms (timers, the simulator, polls) without waiting for anything.
void letRun(int ms)
{
    QTimer never;
    QSignalSpy quiet(&never, &QTimer::timeout);
    stepdeck::test::staysQuiet(quiet, ms);
}
} // namespace

class TestEmisControllerMotion : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void move_relative_positionsFromArrivals();
    void move_busyAxis_refusedNotSent_otherAxisMayJoin();
    void move_absolute_refusedUntilReferenced_thenUpperCase();
    void reference_sequentialAndSimultaneous();
    void reference_minusOne_invalid();
    void lostArrival_deadline_motionUnconfirmed_untilReferenced();
    void pollRefusedWhileMoving_linkStays_moveArrives();
    void refreshStatus_answeredWithBelWhileMoving_finishesWithTheTrackedMotion();
    void refreshStatus_answeredWithBelAtStandstill_refused();
    void noNakReply_lateArrivalStillCounts();
    void unexpectedArrival_positionUnknown();
    void jog_chunksOfAtMostPointTwoSeconds_nextAfterArrival();
    void jog_leaseExpires_noNewChunk_boardStandsStill();
    void jog_released_noChunkWhileTheHostRampRunsDown();
    void jog_twoAxes_shareOneVector();
    void jog_boardSilent_haltsAndUnconfirmed();
    void linkFailure_whileMoving_unconfirmed_positionsUnknown();
    void closeLink_whileMoving_unconfirmed();
    void externalReset_whileMoving_positionUnknownUntilReferenced();
    void externalReset_whileIdle_silenceSeen_positionsAndOutputsUnknown();

private:
    void fastMotion(); // short ramps, quick speeds: tests stay short
    QList<qint64> chunkSteps(char axisLetter) const;
    EmisRig m_rig;
};

void TestEmisControllerMotion::init()
{
    QVERIFY(m_rig.setUp());
}

void TestEmisControllerMotion::cleanup()
{
    m_rig.tearDown();
}

void TestEmisControllerMotion::fastMotion()
{
    QVERIFY(m_rig.write({"ramp=20", "start-speed=500", "work-speed=4000", "reference-speed=4000"})
                .ok());
    m_rig.sim->clearReceivedCommands();
}

QList<qint64> TestEmisControllerMotion::chunkSteps(char axisLetter) const
{
    QList<qint64> out;
    for (const QByteArray& c : m_rig.commandsStartingWith("L1,")) {
        for (const QByteArray& field : c.mid(3).split(',')) {
            if (field.startsWith(axisLetter))
                out << field.mid(1).toLongLong();
        }
    }
    return out;
}

void TestEmisControllerMotion::move_relative_positionsFromArrivals()
{
    fastMotion();
    const AxisVector steps{{Axis::X, 300}, {Axis::Y, -150}, {Axis::U, 0}};
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, steps); }).ok());
    QCOMPARE(m_rig.commands(), QList<QByteArray>{"L1,x300,y-150"});
    QVERIFY(m_rig.axis(Axis::X).moving); // between <NAK> and <DC1>
    QTRY_VERIFY(!m_rig.anyMoving());
    QCOMPARE(m_rig.axis(Axis::X).position, 300);
    QCOMPARE(m_rig.axis(Axis::Y).position, -150);
    QCOMPARE(m_rig.sim->position(Axis::X), 300);
    QVERIFY(!m_rig.axis(Axis::X).positionKnown); // relative bookkeeping, not referenced
    QVERIFY(!m_rig.axis(Axis::X).positionEstimated);
    QVERIFY(!m_rig.ctl->status().motionUnconfirmed);
}

void TestEmisControllerMotion::move_busyAxis_refusedNotSent_otherAxisMayJoin()
{
    QVERIFY(m_rig.write({"work-speed=300", "start-speed=100"}).ok());
    m_rig.sim->clearReceivedCommands();
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::X, 600}}); }).ok());
    const CommandResult busy = m_rig.run([&](RequestId id) {
        m_rig.ctl->moveRelative(id, {{Axis::X, 10}});
    });
    QCOMPARE(busy.error, ErrorKind::Refused);
    const CommandResult home = m_rig.run([&](RequestId id) {
        m_rig.ctl->reference(id, {{Axis::X, 1}});
    });
    QCOMPARE(home.error, ErrorKind::Refused);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::U, 5}}); }).ok());
    QCOMPARE(m_rig.commands(), (QList<QByteArray>{"L1,x600", "L1,u5"}));
    QCOMPARE(m_rig.sim->busyRefusals(), 0);
}

void TestEmisControllerMotion::move_absolute_refusedUntilReferenced_thenUpperCase()
{
    fastMotion();
    CommandResult r = m_rig.run([&](RequestId id) {
        m_rig.ctl->moveAbsolute(id, {{Axis::Z, 50}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY(m_rig.commands().isEmpty());
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->reference(id, {{Axis::Z, 1}}); }).ok());
    QCOMPARE(m_rig.commands(), QList<QByteArray>{"$Hz"});
    QTRY_VERIFY(m_rig.axis(Axis::Z).referenced);
    QVERIFY(m_rig.axis(Axis::Z).positionKnown);
    QCOMPARE(m_rig.axis(Axis::Z).position, 0);
    r = m_rig.run([&](RequestId id) { m_rig.ctl->moveAbsolute(id, {{Axis::Z, 50}}); });
    QVERIFY(r.ok());
    QCOMPARE(m_rig.commands().last(), QByteArray("L1,Z50"));
    QTRY_VERIFY(!m_rig.anyMoving());
    QCOMPARE(m_rig.axis(Axis::Z).position, 50);
    QVERIFY(m_rig.axis(Axis::Z).positionKnown);
    QCOMPARE(m_rig.sim->position(Axis::Z), 50);
    // Where it stands already: nothing to move, nothing sent (9.11 leaves open how the board
    // answers a move of no length).
    const qsizetype sent = m_rig.commandsStartingWith("L1").size();
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveAbsolute(id, {{Axis::Z, 50}}); }).ok());
    QCOMPARE(m_rig.commandsStartingWith("L1").size(), sent);
    QVERIFY(!m_rig.anyMoving());
    QCOMPARE(m_rig.axis(Axis::Z).position, 50);
}

void TestEmisControllerMotion::reference_sequentialAndSimultaneous()
{
    fastMotion();
    QVERIFY(m_rig
                .run([&](RequestId id) {
                    m_rig.ctl->reference(id, {{Axis::U, 1}, {Axis::X, 1}, {Axis::Y, 0}});
                })
                .ok());
    QCOMPARE(m_rig.commands(), QList<QByteArray>{"$Hxu"});
    QTRY_VERIFY(m_rig.axis(Axis::X).referenced && m_rig.axis(Axis::U).referenced);
    QVERIFY(!m_rig.axis(Axis::Y).referenced);
    QVERIFY(m_rig.operation("reference", {{"axes", "YZ"}, {"simultaneous", true}}).ok());
    QCOMPARE(m_rig.commands().last(), QByteArray("$Hyz,a"));
    QTRY_VERIFY(m_rig.axis(Axis::Y).referenced && m_rig.axis(Axis::Z).referenced);
    QVERIFY(m_rig.sim->isReferenced(Axis::Z));
}

void TestEmisControllerMotion::reference_minusOne_invalid()
{
    const CommandResult r = m_rig.run([&](RequestId id) {
        m_rig.ctl->reference(id, {{Axis::X, -1}});
    });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY(m_rig.commandsStartingWith("$H").isEmpty());
}

void TestEmisControllerMotion::lostArrival_deadline_motionUnconfirmed_untilReferenced()
{
    fastMotion();
    QSignalSpy errors(m_rig.ctl, &Controller::errorOccurred);
    m_rig.sim->dropArrivals(1);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::X, 40}}); }).ok());
    QTRY_VERIFY(m_rig.ctl->status().motionUnconfirmed);
    QVERIFY(!errors.isEmpty());
    QVERIFY(errors.last().at(0).toString().contains("DC1"));
    QVERIFY(m_rig.axis(Axis::X).positionEstimated);
    QVERIFY(!m_rig.axis(Axis::X).positionKnown);
    QVERIFY(!m_rig.axis(Axis::X).moving); // not claimed either way: motionUnconfirmed says it
    const CommandResult again = m_rig.run([&](RequestId id) {
        m_rig.ctl->moveRelative(id, {{Axis::X, 5}});
    });
    QCOMPARE(again.error, ErrorKind::Refused);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->reference(id, {{Axis::X, 1}}); }).ok());
    QTRY_VERIFY(!m_rig.ctl->status().motionUnconfirmed);
    QVERIFY(m_rig.axis(Axis::X).positionKnown);
}

void TestEmisControllerMotion::pollRefusedWhileMoving_linkStays_moveArrives()
{
    // The board answers every @IG with <BEL> while a motor moves: a refusal, not silence.
    QVERIFY(m_rig.write({"ramp=20", "start-speed=500", "work-speed=500"}).ok());
    m_rig.sim->clearReceivedCommands();
    m_rig.sim->setBellOnPollWhileMoving(true);
    QSignalSpy link(m_rig.ctl, &Controller::linkStateChanged);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::X, 300}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig.sim->anyMoving(), 5000); // 0.6 s at 500 steps/s
    QTRY_VERIFY(!m_rig.anyMoving());
    QVERIFY(link.isEmpty()); // never Lost
    QCOMPARE(m_rig.ctl->linkState(), LinkState::Connected);
    QVERIFY2(m_rig.sim->receivedCommands().count("@IG") > 5, "polled while moving");
    QVERIFY(!m_rig.ctl->status().motionUnconfirmed);
    QCOMPARE(m_rig.axis(Axis::X).position, 300);
    QCOMPARE(m_rig.sim->position(Axis::X), 300);
    QVERIFY(!m_rig.axis(Axis::X).positionEstimated);
}

// A status read during a move (what Machine asks for once a move was accepted): the board
// answers @IG with <BEL> while its motor moves (chapter 9). The read is answered by the motion
// the host tracks; the move still arrives and nothing counts as lost.
void TestEmisControllerMotion::
    refreshStatus_answeredWithBelWhileMoving_finishesWithTheTrackedMotion()
{
    QVERIFY(m_rig.write({"ramp=20", "start-speed=500", "work-speed=500"}).ok());
    m_rig.sim->setBellOnPollWhileMoving(true);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::X, 300}}); }).ok());
    QVERIFY(m_rig.sim->anyMoving()); // 0.6 s at 500 steps/s
    m_rig.sim->clearReceivedCommands();
    const CommandResult read = m_rig.run([&](RequestId id) { m_rig.ctl->refreshStatus(id); });
    QVERIFY2(read.ok(), qPrintable(read.message));
    QCOMPARE(m_rig.sim->receivedCommands().value(0), QByteArray("@IG")); // it was asked
    QVERIFY(m_rig.sim->anyMoving());                                     // and refused with <BEL>
    const MachineStatus status = read.value.value<MachineStatus>();
    QVERIFY(status.axes.value(Axis::X).moving);
    QVERIFY(!status.motionUnconfirmed);
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig.sim->anyMoving(), 5000);
    QTRY_VERIFY(!m_rig.anyMoving());
    QCOMPARE(m_rig.axis(Axis::X).position, 300);
    QCOMPARE(m_rig.sim->position(Axis::X), 300);
    QVERIFY(!m_rig.ctl->status().motionUnconfirmed);
}

// Without a motion of the host's under way a <BEL> to @IG stays a refusal: the host could not
// say which motor the board is busy with.
void TestEmisControllerMotion::refreshStatus_answeredWithBelAtStandstill_refused()
{
    m_rig.ctl->setPollInterval(60000); // no poll takes the <BEL> meant for the read
    QTRY_VERIFY(m_rig.ctl->link().isIdle());
    m_rig.sim->bellOn("@IG");
    const CommandResult read = m_rig.run([&](RequestId id) { m_rig.ctl->refreshStatus(id); });
    QCOMPARE(read.error, ErrorKind::Nak);
    QVERIFY2(read.message.contains("@IG"), qPrintable(read.message));
}

void TestEmisControllerMotion::noNakReply_lateArrivalStillCounts()
{
    fastMotion();
    m_rig.sim->faults().dropReplies = 1; // the <NAK> is lost, the move runs
    const CommandResult r = m_rig.run([&](RequestId id) {
        m_rig.ctl->moveRelative(id, {{Axis::Y, 30}});
    });
    QCOMPARE(r.error, ErrorKind::Timeout);
    QVERIFY(m_rig.ctl->status().motionUnconfirmed || m_rig.sim->position(Axis::Y) == 30);
    QTRY_VERIFY(!m_rig.ctl->status().motionUnconfirmed); // its <DC2> proves the arrival
    QCOMPARE(m_rig.axis(Axis::Y).position, 30);
    QVERIFY(!m_rig.axis(Axis::Y).positionEstimated); // <DC2> proves the whole move ran
}

void TestEmisControllerMotion::unexpectedArrival_positionUnknown()
{
    fastMotion();
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->reference(id, {{Axis::U, 1}}); }).ok());
    QTRY_VERIFY(m_rig.axis(Axis::U).positionKnown);
    m_rig.sim->receive("L1,u7\r"); // moved by something else (an input program)
    QTRY_VERIFY(!m_rig.axis(Axis::U).positionKnown);
    QVERIFY(m_rig.axis(Axis::U).positionEstimated);
}

void TestEmisControllerMotion::jog_chunksOfAtMostPointTwoSeconds_nextAfterArrival()
{
    fastMotion();
    QVERIFY(m_rig.write({"work-speed=4000"}).ok()); // known, so the jog can give it back
    m_rig.sim->clearReceivedCommands();
    QTimer renew; // the input renews the lease every 50 ms
    connect(&renew, &QTimer::timeout, this, [this] {
        m_rig.ctl->setJogVelocity({{Axis::X, 600}});
    });
    renew.start(50);
    m_rig.ctl->setJogVelocity({{Axis::X, 600}});
    QTRY_VERIFY(chunkSteps('x').size() >= 4);
    renew.stop();
    m_rig.ctl->endJog();
    QTRY_VERIFY(!m_rig.anyMoving() && !m_rig.sim->anyMoving());
    const QList<qint64> chunks = chunkSteps('x');
    QVERIFY2(chunks.size() >= 3, qPrintable(QString::number(chunks.size())));
    for (qint64 n : chunks)
        QVERIFY(n > 0 && n <= 120);         // 600 steps/s for at most 0.2 s
    QCOMPARE(m_rig.sim->busyRefusals(), 0); // never a move for a motor still moving
    QCOMPARE(m_rig.commands().first(), QByteArray("#E1,x600"));
    QTRY_COMPARE(m_rig.commands().last(), QByteArray("#E1,x4000")); // work speed given back
    qint64 sum = 0;
    for (qint64 n : chunks)
        sum += n;
    QCOMPARE(m_rig.axis(Axis::X).position, sum);
    QCOMPARE(m_rig.sim->position(Axis::X), sum); // host bookkeeping = the board's own
    QVERIFY(!m_rig.axis(Axis::X).positionEstimated);
}

void TestEmisControllerMotion::jog_leaseExpires_noNewChunk_boardStandsStill()
{
    fastMotion();
    m_rig.ctl->setJogVelocity({{Axis::Y, -500}}); // once; never renewed (a frozen input)
    QTRY_VERIFY(!chunkSteps('y').isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.ctl->jogRamp().isIdle(), 2000);
    QTRY_VERIFY(!m_rig.sim->anyMoving());
    const qsizetype chunks = chunkSteps('y').size();
    QVERIFY2(chunks <= 3, qPrintable(QString::number(chunks))); // 300 ms lease, ~0.2 s chunks
    for (qint64 n : chunkSteps('y'))
        QVERIFY(n >= -100 && n < 0);
    // No chunk after the lease: the board stays still.
    letRun(400);
    QCOMPARE(chunkSteps('y').size(), chunks);
    QVERIFY(!m_rig.sim->anyMoving());
    QCOMPARE(m_rig.axis(Axis::Y).position, m_rig.sim->position(Axis::Y));
}

void TestEmisControllerMotion::jog_released_noChunkWhileTheHostRampRunsDown()
{
    fastMotion();
    // A slow host ramp: after the release its rate stays above zero for about a second, long
    // after the chunk under way has arrived. No chunk may start in that time.
    m_rig.ctl->setJogAcceleration(500);
    QTimer renew;
    connect(&renew, &QTimer::timeout, this, [this] {
        m_rig.ctl->setJogVelocity({{Axis::Z, 600}});
    });
    renew.start(50);
    m_rig.ctl->setJogVelocity({{Axis::Z, 600}});
    QTRY_VERIFY_WITH_TIMEOUT(
        m_rig.ctl->jogRamp().current(Axis::Z) > 300.0 && !chunkSteps('z').isEmpty(), 5000);
    renew.stop();
    m_rig.ctl->endJog();
    const qsizetype chunks = chunkSteps('z').size();
    QVERIFY(m_rig.ctl->jogRamp().current(Axis::Z) > 300.0); // the host ramp runs down, ...
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.ctl->jogRamp().isIdle(), 3000);
    QTRY_VERIFY(!m_rig.sim->anyMoving()); // ... the chunk under way arrives ...
    letRun(200);
    QCOMPARE(chunkSteps('z').size(), chunks); // ... and the board got nothing more
    QVERIFY(!m_rig.sim->anyMoving());
    QCOMPARE(m_rig.axis(Axis::Z).position, m_rig.sim->position(Axis::Z));
}

void TestEmisControllerMotion::jog_twoAxes_shareOneVector()
{
    fastMotion();
    m_rig.ctl->setJogVelocity({{Axis::X, 500}, {Axis::U, -250}});
    QTRY_VERIFY(!m_rig.commandsStartingWith("L1,").isEmpty());
    QCOMPARE(m_rig.commandsStartingWith("L1,").first(), QByteArray("L1,x100,u-50"));
    m_rig.ctl->endJog();
    QTRY_VERIFY(!m_rig.anyMoving() && !m_rig.sim->anyMoving());
    QCOMPARE(m_rig.axis(Axis::U).position, m_rig.sim->position(Axis::U));
}

void TestEmisControllerMotion::jog_boardSilent_haltsAndUnconfirmed()
{
    fastMotion();
    QSignalSpy refused(m_rig.ctl, &Controller::jogRefused);
    QTimer renew;
    connect(&renew, &QTimer::timeout, this, [this] {
        m_rig.ctl->setJogVelocity({{Axis::Z, 400}});
    });
    renew.start(50);
    m_rig.ctl->setJogVelocity({{Axis::Z, 400}});
    QTRY_VERIFY(chunkSteps('z').size() >= 2);
    m_rig.sim->faults().silent = true;
    QTRY_VERIFY(m_rig.ctl->status().motionUnconfirmed);
    QTRY_VERIFY(!refused.isEmpty() || m_rig.ctl->linkState() == LinkState::Lost);
    const qsizetype sent = chunkSteps('z').size();
    QTRY_VERIFY(!m_rig.sim->anyMoving()); // the chunk under way ended by itself
    letRun(300);                          // the input keeps asking: nothing more goes out
    QCOMPARE(chunkSteps('z').size(), sent);
    renew.stop();
    QVERIFY(!m_rig.axis(Axis::Z).positionKnown);
}

void TestEmisControllerMotion::linkFailure_whileMoving_unconfirmed_positionsUnknown()
{
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->reference(id, {{Axis::X, 1}}); }).ok());
    QTRY_VERIFY(m_rig.axis(Axis::X).positionKnown);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::X, 500}}); }).ok());
    m_rig.host->simulateFailure("unplugged");
    QTRY_COMPARE(m_rig.ctl->linkState(), LinkState::Lost);
    QVERIFY(m_rig.ctl->status().motionUnconfirmed);
    QVERIFY(!m_rig.axis(Axis::X).positionKnown);
    QVERIFY(m_rig.axis(Axis::X).positionEstimated);
    QVERIFY(!m_rig.axis(Axis::X).moving);
}

void TestEmisControllerMotion::closeLink_whileMoving_unconfirmed()
{
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::Y, 500}}); }).ok());
    QSignalSpy status(m_rig.ctl, &Controller::statusChanged);
    QSignalSpy closed(m_rig.ctl, &Controller::closeFinished);
    const qsizetype seen = m_rig.sim->receivedCommands().size();
    m_rig.ctl->closeLink(); // no stop command exists: nothing can be sent to stop the move
    QTRY_COMPARE(closed.size(), 1);
    QCOMPARE(m_rig.ctl->linkState(), LinkState::Disconnected);
    QVERIFY(!status.isEmpty());
    QVERIFY(status.last().at(0).value<MachineStatus>().motionUnconfirmed);
    QCOMPARE(m_rig.sim->receivedCommands().size(), seen);
    QVERIFY(m_rig.sim->isMoving(Axis::Y)); // the board goes on until the move arrives
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.sim->standingStill(), 10000);
}

void TestEmisControllerMotion::externalReset_whileMoving_positionUnknownUntilReferenced()
{
    // A button on the reset input (5.8) is the way to stop the board: the move under way ends
    // without its <DC1>, the host says so after the deadline and wants a reference run.
    fastMotion();
    QVERIFY(m_rig.run([&](RequestId id) {
                     m_rig.ctl->reference(id, {{Axis::X, 1}, {Axis::Y, 1}});
                 })
                .ok());
    QTRY_VERIFY(m_rig.axis(Axis::X).positionKnown && m_rig.axis(Axis::Y).positionKnown);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::X, 600}}); }).ok());
    QTRY_VERIFY(m_rig.sim->isMoving(Axis::X));
    m_rig.sim->externalReset(0);
    QVERIFY(m_rig.sim->standingStill());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.ctl->status().motionUnconfirmed, 10000);
    QVERIFY(!m_rig.axis(Axis::X).positionKnown);
    QVERIFY(m_rig.axis(Axis::X).positionEstimated);
    QVERIFY(!m_rig.axis(Axis::Y).positionKnown); // its counter was reset too
    QVERIFY(!m_rig.axis(Axis::Y).positionEstimated);
    QCOMPARE(m_rig.run([&](RequestId id) {
                      m_rig.ctl->moveRelative(id, {{Axis::X, 5}});
                  })
                 .error,
             ErrorKind::Refused);
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->reference(id, {{Axis::X, 1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.axis(Axis::X).positionKnown, 10000);
    QVERIFY(!m_rig.ctl->status().motionUnconfirmed);
    // The reset gave the board its stored working values: the host writes its work speed again.
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->moveRelative(id, {{Axis::X, 50}}); }).ok());
    QTRY_VERIFY(!m_rig.anyMoving());
    QCOMPARE(m_rig.sim->acceptedMovesWithSpeed().last().workSpeed, 4000);
    QCOMPARE(m_rig.sim->position(Axis::X), 50);
    QCOMPARE(m_rig.axis(Axis::X).position, 50);
}

void TestEmisControllerMotion::externalReset_whileIdle_silenceSeen_positionsAndOutputsUnknown()
{
    // While the board restarts it answers nothing: a poll without an answer may be a reset, so
    // the host no longer trusts absolute positions or the outputs it switched.
    QVERIFY(m_rig.run([&](RequestId id) { m_rig.ctl->reference(id, {{Axis::Y, 1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.axis(Axis::Y).positionKnown, 10000);
    QVERIFY(m_rig.operation("set-output", {{"output", 3}, {"on", true}}).ok());
    QCOMPARE(m_rig.ctl->status().outputs.at(2), std::optional<bool>(true));
    m_rig.sim->externalReset(150);
    QVERIFY(!m_rig.sim->output(3));
    QTRY_VERIFY(!m_rig.axis(Axis::Y).positionKnown);
    QVERIFY(!m_rig.ctl->status().outputs.at(2).has_value());
    QCOMPARE(m_rig.ctl->linkState(), LinkState::Connected); // fewer than three missed polls
    const CommandResult absolute = m_rig.run([&](RequestId id) {
        m_rig.ctl->moveAbsolute(id, {{Axis::Y, 10}});
    });
    QCOMPARE(absolute.error, ErrorKind::Refused);
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisControllerMotion)
#include "tst_emiscontrollermotion.moc"
