// The Nanotec adapter's safety paths (NanotecStop.cpp, docs/architecture.md "Safety
// contract") against the simulated bus: what every drive RECEIVED and whether its motor stands,
// not only the host's own state.
#include "NanotecRig.h"
#include "TestMain.h"

using namespace stepdeck;
using namespace stepdeck::nanotec;
using nanotectest::NanotecRig;

class TestNanotecSafety : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void close_duringJog_movingDriveGetsS_thenBroadcast();
    void close_duringVelocity_driveThatStoppedAnswering_stillStopped();
    void pollLoss_duringVelocity_stopReachesDrives_portStaysOpen();
    void silentDrive_axisMotionUnknown_stopStillSentAndNotClaimed();
    void startRecord_afterJog_positioningModeRestoredAndReadBack();
    void move_driveIgnoredASetting_notStarted();
    void velocity_belowStartFrequency_refusedNotRaised();
    void jog_belowStartFrequency_refused();
    void powerCycle_betweenMoves_modeWrittenAgain_targetReached();
    void silentDrive_answersAgain_positionUnknown_absoluteMoveRefused();

private:
    std::unique_ptr<NanotecRig> m_rig;
};

void TestNanotecSafety::init()
{
    m_rig = std::make_unique<NanotecRig>();
    QVERIFY(m_rig->connect());
}

void TestNanotecSafety::cleanup()
{
    m_rig.reset();
}

void TestNanotecSafety::close_duringJog_movingDriveGetsS_thenBroadcast()
{
    NanotecDrive* d = m_rig->sim->drive(2);
    m_rig->ctl->setJogVelocity({{Axis::Y, 2000}});
    QTRY_VERIFY_WITH_TIMEOUT(d->speed() >= 1999, 3000);
    m_rig->sim->clearReceivedFrames();
    QVERIFY(m_rig->close());
    // 6.2: 'S' is the only way out of speed mode; '#*S' follows for anyone who missed it.
    const QList<QByteArray> f = m_rig->sim->receivedFrames();
    QVERIFY(f.contains("#2S\r"));
    QVERIFY(f.indexOf("#*S\r") > f.indexOf("#2S\r"));
    QTRY_VERIFY_WITH_TIMEOUT(m_rig->sim->standingStill(), 2000);
    QVERIFY(!m_rig->host->isOpen());
    QVERIFY(!m_rig->ctl->status().motionUnconfirmed); // drive 2 echoed its 'S'
}

void TestNanotecSafety::close_duringVelocity_driveThatStoppedAnswering_stillStopped()
{
    QVERIFY(m_rig->run([&](RequestId id) {
                     m_rig->ctl->velocityMove(id, {{Axis::X, 3000}});
                 })
                .ok());
    NanotecDrive* d = m_rig->sim->drive(1);
    QTRY_VERIFY_WITH_TIMEOUT(d->speed() >= 2999, 3000);
    d->handle("|0"); // 6.4: still listens and executes, answers nothing any more
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig->ctl->status().drives[0].responding, 3000);
    QVERIFY(m_rig->ctl->status().axes[Axis::X].motionUnknown);
    m_rig->sim->clearReceivedFrames();
    QVERIFY(m_rig->close());
    QVERIFY(m_rig->sim->receivedFrames().contains("#1S\r")); // written anyway
    QTRY_VERIFY_WITH_TIMEOUT(m_rig->sim->standingStill(), 2000);
    // No echo came from drive 1: the host does not claim that it stopped.
    QVERIFY(m_rig->ctl->status().motionUnconfirmed);
}

void TestNanotecSafety::pollLoss_duringVelocity_stopReachesDrives_portStaysOpen()
{
    QVERIFY(m_rig
                ->run([&](RequestId id) {
                    m_rig->ctl->velocityMove(id, {{Axis::X, 2000}, {Axis::Z, -2000}});
                })
                .ok());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig->sim->drive(3)->speed() <= -1999, 3000);
    m_rig->sim->faults().silent = true; // every reply lost on the way back; drives still listen
    m_rig->sim->clearReceivedFrames();
    QTRY_COMPARE_WITH_TIMEOUT(m_rig->ctl->linkState(), LinkState::Lost, 10000);
    const QList<QByteArray> f = m_rig->sim->receivedFrames();
    QVERIFY(f.contains("#1S\r"));
    QVERIFY(f.contains("#3S\r"));
    QVERIFY(f.contains("#*S\r"));
    QTRY_VERIFY_WITH_TIMEOUT(m_rig->sim->standingStill(), 2000);
    QVERIFY(m_rig->host->isOpen()); // PANIC can still be written
    QVERIFY(m_rig->ctl->status().motionUnconfirmed);
}

void TestNanotecSafety::silentDrive_axisMotionUnknown_stopStillSentAndNotClaimed()
{
    m_rig->sim->setDriveSilent(2, true);
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig->ctl->status().drives[1].responding, 3000);
    const MachineStatus st = m_rig->ctl->status();
    QVERIFY(st.axes[Axis::Y].motionUnknown);
    QVERIFY(st.anyMoving()); // never shown as idle
    QVERIFY(!st.axes[Axis::X].motionUnknown);
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = m_rig->run([&](RequestId id) { m_rig->ctl->stop(id); });
    QVERIFY(m_rig->sim->receivedFrames().contains("#2S\r"));
    QCOMPARE(r.error, ErrorKind::Timeout);
    QVERIFY2(r.message.contains("drive 2"), qPrintable(r.message));
    QVERIFY(m_rig->ctl->status().motionUnconfirmed);
}

void TestNanotecSafety::startRecord_afterJog_positioningModeRestoredAndReadBack()
{
    NanotecDrive* d = m_rig->sim->drive(1);
    m_rig->ctl->setJogVelocity({{Axis::X, 1500}});
    QTRY_VERIFY_WITH_TIMEOUT(d->speed() >= 1499, 3000);
    QCOMPARE(d->value('!'), qint64(2)); // speed mode
    m_rig->ctl->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(d->ready() && !m_rig->ctl->status().axes[Axis::X].jogging, 5000);
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = m_rig->run([&](RequestId id) {
        m_rig->ctl->modelOperation(
            id, QStringLiteral("start-record"),
            {{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("record"), 0}});
    });
    QVERIFY2(r.ok(), qPrintable(r.message));
    const QList<QByteArray> f = m_rig->sim->receivedFrames();
    const int mode = f.indexOf("#1!1\r");
    const int readBack = f.indexOf("#1Z!\r");
    const int start = f.indexOf("#1A\r");
    QVERIFY(mode >= 0 && readBack > mode && start > readBack);
    QCOMPARE(d->value('!'), qint64(1));
}

void TestNanotecSafety::move_driveIgnoredASetting_notStarted()
{
    NanotecDrive* d = m_rig->sim->drive(3);
    d->handle("o2500"); // changed behind StepDeck's back (another tool, a stored record)
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = m_rig->run([&](RequestId id) {
        m_rig->ctl->moveRelative(id, {{Axis::Z, 500}});
    });
    QCOMPARE(r.error, ErrorKind::VerifyFailed);
    QVERIFY2(r.message.contains("o=2500"), qPrintable(r.message));
    QVERIFY(!m_rig->sim->receivedFrames().contains("#3A\r"));
    QCOMPARE(d->position(), qint64(0));
}

void TestNanotecSafety::velocity_belowStartFrequency_refusedNotRaised()
{
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = m_rig->run([&](RequestId id) {
        m_rig->ctl->velocityMove(id, {{Axis::Y, 100}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("start frequency"), qPrintable(r.message));
    QVERIFY(!m_rig->sim->receivedFrames().contains("#2A\r"));
    QVERIFY(m_rig->sim->standingStill());
}

void TestNanotecSafety::jog_belowStartFrequency_refused()
{
    QSignalSpy refused(m_rig->ctl, &Controller::jogRefused);
    m_rig->sim->clearReceivedFrames();
    m_rig->ctl->setJogVelocity({{Axis::Z, 150}});
    QCOMPARE(refused.count(), 1);
    QVERIFY(refused.first().at(0).toString().contains("start frequency"));
    QTRY_VERIFY(m_rig->ctl->jogRamp().isIdle());
    QVERIFY(!m_rig->sim->receivedFrames().contains("#3A\r"));
    QVERIFY(m_rig->sim->standingStill());
}

// Issue 30 holds '!1' and 'p2' over a chain of moves (NanotecHeldSettings). A drive switched
// off and on between two moves is back in relative positioning (p1) with position 0: the next
// absolute move must set its mode again, or the drive would run the target as a distance. With
// idle polls 2 s apart the host may see no unanswered poll at all; the half second the drive
// was silent (5.32) is what tells.
void TestNanotecSafety::powerCycle_betweenMoves_modeWrittenAgain_targetReached()
{
    ControllerOptions co = nanotectest::fastOptions();
    co.pollIntervalMs = 2000;
    m_rig = std::make_unique<NanotecRig>(co);
    QVERIFY(m_rig->connect());
    NanotecController* ctl = m_rig->ctl;
    QVERIFY(
        m_rig->run([&](RequestId id) {
                 ctl->modelOperation(id, "reset-position", {{"axis", "Y"}});
             })
            .ok());
    QVERIFY(m_rig->run([&](RequestId id) { ctl->moveAbsolute(id, {{Axis::Y, 100}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!ctl->status().axes[Axis::Y].moving, 5000);
    QCOMPARE(m_rig->sim->drive(2)->position(), qint64(100));
    m_rig->sim->powerCycle(2, 450);
    QCOMPARE(m_rig->sim->drive(2)->value('p'), qint64(1)); // power-on: relative positioning
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig->sim->drive(2)->faults.silent, 2000);
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = m_rig->run([&](RequestId id) {
        ctl->moveAbsolute(id, {{Axis::Y, 200}});
    });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY(m_rig->sim->receivedFrames().contains("#2p2\r"));
    QVERIFY(m_rig->sim->receivedFrames().contains("#2Zp\r"));
    QTRY_COMPARE_WITH_TIMEOUT(m_rig->sim->drive(2)->position(), qint64(200), 5000);
    QCOMPARE(m_rig->sim->drive(2)->value('p'), qint64(2));
}

// Safety contract: after a reconnect positions are unknown until referenced. A drive that fell
// silent (switched off, cable pulled) and answers again may have lost or changed its position.
void TestNanotecSafety::silentDrive_answersAgain_positionUnknown_absoluteMoveRefused()
{
    NanotecController* ctl = m_rig->ctl;
    QVERIFY(
        m_rig->run([&](RequestId id) {
                 ctl->modelOperation(id, "reset-position", {{"axis", "Y"}});
             })
            .ok());
    QVERIFY(ctl->status().axes[Axis::Y].positionKnown);
    QSignalSpy errors(ctl, &Controller::errorOccurred);
    m_rig->sim->setDriveSilent(2, true);
    QTRY_VERIFY_WITH_TIMEOUT(!ctl->status().drives[1].responding, 5000);
    m_rig->sim->setDriveSilent(2, false);
    QTRY_VERIFY_WITH_TIMEOUT(ctl->status().drives[1].responding, 5000);
    QVERIFY(!ctl->status().axes[Axis::Y].positionKnown);
    QVERIFY(!ctl->status().axes[Axis::Y].referenced);
    QVERIFY(ctl->status().axes[Axis::X].positionKnown == false); // never referenced here
    bool told = false;
    for (const QList<QVariant>& e : errors)
        told = told || e.at(0).toString().contains(QStringLiteral("answers again"));
    QVERIFY(told);
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = m_rig->run([&](RequestId id) {
        ctl->moveAbsolute(id, {{Axis::Y, 50}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY(r.message.contains(QStringLiteral("reference")));
    QCOMPARE(m_rig->countFrames("#2A\r"), 0);
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecSafety)
#include "tst_nanotecsafety.moc"
