// The machine owns execution (issue 49 item 4): a run holds the machine's motion
// (Machine::claimMotion) from its start to its end, so that a second runner (an MDI line, Go
// to) is refused while it holds it, and the machine's own STOP and PANIC -- not the runner's
// abort() -- end the run that holds it. The operator's jog and reference run hold it too. Asserted
// at the devices: the E-LAB simulator on a pseudo-terminal stands, and the blocks after the stop
// never arrive.
#include "ProgramRunnerTestSupport.h"
#include "TestMain.h"
#include "protocols/elab/ElabCodec.h"

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;
using namespace stepdeck::program::runnertest;

class TestProgramRunnerOwner : public ProgramRunnerFixture
{
    Q_OBJECT
private Q_SLOTS:
    void init() { setUpRig(); }
    void cleanup() { tearDownRig(); }
    void machineStop_duringMove_runAbortedDeviceStandsNextBlockNeverArrives_data();
    void machineStop_duringMove_runAbortedDeviceStandsNextBlockNeverArrives();
    void machineStop_whilePausedAtM0_runAborted();
    void secondRunner_whileOneRuns_refusedNamingTheHolderNothingSent();
    void fault_runnersOwnStop_failedNotAborted();
    void manualMotion_whileRunning_refusedPausedBetweenBlocksAdmitted();
    void start_duringTheOperatorsReferenceRun_refusedNothingSent();
    void start_whileTheOperatorJogs_refusedUntilTheJogEnds();
    void jogAndReference_excludeEachOther_namingTheHolder();
    void resume_whileJoggingAtM0_refusedUntilTheJogEnds();

private:
    static std::optional<Program> parsed(const QByteArray& text);
};

std::optional<Program> TestProgramRunnerOwner::parsed(const QByteArray& text)
{
    QList<ProgramError> errors;
    return ProgramParser::parse(
        text, {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("A")}, &errors);
}

void TestProgramRunnerOwner::
    machineStop_duringMove_runAbortedDeviceStandsNextBlockNeverArrives_data()
{
    QTest::addColumn<bool>("panic");
    QTest::newRow("stop") << false;
    QTest::newRow("panic") << true;
}

// The window's STOP and PANIC reach the machine only (MainWindow has no list of what moves).
void TestProgramRunnerOwner::machineStop_duringMove_runAbortedDeviceStandsNextBlockNeverArrives()
{
    QFETCH(bool, panic);
    QVERIFY(run("G91\nG0 X200\nG0 X-1\n"));
    QCOMPARE(m_machine->motionHolder(), ProgramRunner::tr("a program runs"));
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    panic ? m_machine->panic() : m_machine->stop();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Aborted);
    QVERIFY2(m_runner->endMessage().contains("line 2"), qPrintable(m_runner->endMessage()));
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    if (panic) { // the run's own stop (its abort) never goes ahead of the panic
        const int panicAt = frameIndex(*m_elab, elab::encode::panicStop());
        const int stopAt = frameIndex(*m_elab, elab::encode::stopMove());
        QVERIFY2(panicAt >= 0 && (stopAt < 0 || stopAt > panicAt),
                 qPrintable(QStringLiteral("%1 %2").arg(panicAt).arg(stopAt)));
    } else {
        QVERIFY(m_elab->receivedStop());
    }
    QVERIFY(m_machine->motionHolder().isEmpty()); // given back at the run's end
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{80000})); // line 3 never came
}

void TestProgramRunnerOwner::machineStop_whilePausedAtM0_runAborted()
{
    QVERIFY(run("G91\nG0 X1\nM0\nG0 X2\n"));
    QTRY_VERIFY_WITH_TIMEOUT(m_runner->state() == RunState::Paused, 20000);
    m_machine->stop();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Aborted);
    QVERIFY(m_machine->motionHolder().isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->receivedStop(), 10000); // posted: it arrives in its time
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400})); // line 4 never came
}

// One holder at a time, in core: the second runner is refused with the first's name for it and
// sends nothing; once the first ended, the second runs.
void TestProgramRunnerOwner::secondRunner_whileOneRuns_refusedNamingTheHolderNothingSent()
{
    ProgramRunner mdi(m_machine.get());
    mdi.setOwnerName(QStringLiteral("an MDI line runs"));
    QVERIFY(run("G91\nG0 X20\n"));
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    const std::optional<Program> line = parsed("G91 G0 A1\n");
    QVERIFY(line);
    QList<ProgramError> errors;
    QVERIFY(!mdi.start(*line, 1, &errors));
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.first().message, ProgramRunner::tr("a program runs"));
    QVERIFY(!mdi.claimMotion(nullptr));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedCount(*m_nanotec), 0); // the refused line's A never went out
    // Now free: the second runs, and holds it under its own name meanwhile.
    QVERIFY(mdi.start(*line, 1, &errors));
    QCOMPARE(m_machine->motionHolder(), QStringLiteral("an MDI line runs"));
    errors.clear();
    QVERIFY(!m_runner->start(*parsed("G0 X1\n"), 1, &errors));
    QCOMPARE(errors.first().message, QStringLiteral("an MDI line runs"));
    QTRY_VERIFY_WITH_TIMEOUT(isEnded(mdi.state()), 60000);
    QCOMPARE(mdi.state(), RunState::Finished);
    QCOMPARE(acceptedSteps(*m_nanotec, Axis::X), (QList<qint64>{100}));
    QVERIFY(m_machine->motionHolder().isEmpty());
}

// A fault stops the machine from inside the run: that stop is the run's own, so the run fails
// at its line (not aborted), and gives the motion back.
void TestProgramRunnerOwner::fault_runnersOwnStop_failedNotAborted()
{
    QVERIFY(run("G91 G0 A10\nG0 A40\nG0 X1 A-5\n")); // the drive's limit switch at 30 deg
    WAIT_ENDED();
    VERIFY_STATE(RunState::Failed);
    QVERIFY2(m_runner->endMessage().startsWith("line 2:"), qPrintable(m_runner->endMessage()));
    QVERIFY(m_machine->motionHolder().isEmpty());
    QCOMPARE(acceptedCount(*m_elab), 0);
}

// While the run moves the machine nobody else does (a jog, a move by hand: the device never
// hears them); held between blocks (M0) it lends the machine to the operator's hands, as the
// touch-off at M6 needs, and takes it back when it goes on.
void TestProgramRunnerOwner::manualMotion_whileRunning_refusedPausedBetweenBlocksAdmitted()
{
    QVERIFY(run("G91\nG0 X20\nM0\nG0 X1\n"));
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    QString why;
    QVERIFY(!m_machine->jog({{QStringLiteral("A"), 5.0}}, &why));
    QVERIFY2(why.startsWith(ProgramRunner::tr("a program runs")), qPrintable(why));
    QCOMPARE(m_machine->move({{QStringLiteral("A"), 1.0}}, false, &why), quint64(0));
    QVERIFY2(why.startsWith(ProgramRunner::tr("a program runs")), qPrintable(why));
    QCOMPARE(m_machine->reference({QStringLiteral("A")}, &why), quint64(0));
    QTRY_VERIFY_WITH_TIMEOUT(m_runner->state() == RunState::Paused, 20000);
    QCOMPARE(acceptedCount(*m_nanotec), 0); // nothing by hand reached the drive
    // Held at M0: a move by hand goes, and arrives.
    QSignalSpy finished(m_machine.get(), &Machine::moveFinished);
    const quint64 byHand = m_machine->move({{QStringLiteral("A"), 1.0}}, false, &why);
    QVERIFY2(byHand != 0, qPrintable(why));
    QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 10000);
    QCOMPARE(acceptedSteps(*m_nanotec, Axis::X), (QList<qint64>{100}));
    m_runner->resume();
    QTRY_VERIFY_WITH_TIMEOUT(m_runner->state() != RunState::Paused, 10000);
    QVERIFY(!m_machine->jog({{QStringLiteral("A"), 5.0}}, &why) || isEnded(m_runner->state()));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{8000, 400}));
}

// The operator's reference run moves the axes: a program does not start beside it.
void TestProgramRunnerOwner::start_duringTheOperatorsReferenceRun_refusedNothingSent()
{
    QString why;
    QVERIFY2(m_machine->reference({QStringLiteral("A")}, &why) != 0, qPrintable(why));
    QVERIFY(m_machine->isReferencing());
    const int before = acceptedCount(*m_elab);
    QList<ProgramError> errors;
    QVERIFY(!m_runner->start(*parsed("G91 G0 X1\n"), 1, &errors));
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.first().message, Machine::tr("a reference run is under way"));
    QCOMPARE(m_machine->motionHolder(), Machine::tr("a reference run is under way"));
    QCOMPARE(acceptedCount(*m_elab), before);
    QCOMPARE(m_runner->state(), RunState::Idle);
}

// The operator's jog holds the motion from its first rate to endJog(): a program does not
// start beside it (LinuxCNC runs no program while jogging), and starts once the jog ended.
void TestProgramRunnerOwner::start_whileTheOperatorJogs_refusedUntilTheJogEnds()
{
    QString why;
    // The input held (renewed, as the jog pad does) until the board jogs.
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->jog({{QStringLiteral("X"), 5.0}}, &why) && moving(*m_elab),
                             20000);
    QVERIFY(m_machine->isJogging());
    QCOMPARE(m_machine->motionHolder(), Machine::tr("the axes are being jogged"));
    QList<ProgramError> errors;
    QVERIFY(!m_runner->start(*parsed("G91 G0 X1\n"), 1, &errors));
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.first().message, Machine::tr("the axes are being jogged"));
    QCOMPARE(m_runner->state(), RunState::Idle);
    m_machine->endJog();
    QVERIFY(m_machine->motionHolder().isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 20000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), QList<qint64>{}); // the program's move never came
    QVERIFY(run("G91 G0 X1\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400}));
}

// The operator's reference run and jog exclude each other in core, each refused with what holds
// the machine; the drive never got a move by hand during the reference run.
void TestProgramRunnerOwner::jogAndReference_excludeEachOther_namingTheHolder()
{
    QString why;
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->jog({{QStringLiteral("X"), 5.0}}, &why) && moving(*m_elab),
                             20000);
    QCOMPARE(m_machine->reference({QStringLiteral("A")}, &why), quint64(0));
    QVERIFY2(why.startsWith(Machine::tr("the axes are being jogged")), qPrintable(why));
    QVERIFY(!m_machine->isReferencing());
    m_machine->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 20000);
    QSignalSpy referenced(m_machine.get(), &Machine::referenceFinished);
    QVERIFY2(m_machine->reference({QStringLiteral("A")}, &why) != 0, qPrintable(why));
    QCOMPARE(m_machine->motionHolder(), Machine::tr("a reference run is under way"));
    QVERIFY(!m_machine->jog({{QStringLiteral("X"), 5.0}}, &why));
    QVERIFY2(why.startsWith(Machine::tr("a reference run is under way")), qPrintable(why));
    QVERIFY(!m_machine->isJogging());
    QVERIFY(still(*m_elab)); // the jog was never sent
    QTRY_VERIFY_WITH_TIMEOUT(!referenced.isEmpty(), 30000);
    QVERIFY(m_machine->motionHolder().isEmpty()); // given back at its end
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->jog({{QStringLiteral("X"), 5.0}}, &why) && moving(*m_elab),
                             20000);
    m_machine->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 20000);
}

// Held at M0 the run lends the machine, and a jog goes (a touch-off); the run does not go on
// while the jog input is held, since its next move would run beside the jog.
void TestProgramRunnerOwner::resume_whileJoggingAtM0_refusedUntilTheJogEnds()
{
    QVERIFY(run("G91\nG0 X1\nM0\nG0 X2\n"));
    QTRY_VERIFY_WITH_TIMEOUT(m_runner->state() == RunState::Paused, 20000);
    QString why;
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->jog({{QStringLiteral("Y"), 5.0}}, &why) && moving(*m_elab),
                             20000);
    QCOMPARE(m_machine->motionHolder(), ProgramRunner::tr("a program runs")); // still the run's
    QSignalSpy refused(m_runner.get(), &ProgramRunner::resumeRefused);
    m_runner->resume();
    QCOMPARE(refused.size(), 1);
    QVERIFY2(refused.first().first().toString().contains(ProgramRunner::tr("jogged")),
             qPrintable(refused.first().first().toString()));
    QCOMPARE(m_runner->state(), RunState::Paused);
    m_machine->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 20000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400})); // line 4 not sent
    // A state read of the board after Y came to rest (the adapter refuses a move until one
    // shows it out of jog mode).
    QSignalSpy results(m_machine.get(), &Machine::requestFinished);
    const RequestId read = m_machine->session("table")->refreshStatus();
    QTRY_VERIFY_WITH_TIMEOUT(std::any_of(results.cbegin(), results.cend(),
                                         [&](const QList<QVariant>& r) {
                                             return r.at(1).value<CommandResult>().id == read;
                                         }),
                             10000);
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400, 800}));
}

STEPDECK_TEST_MAIN(TestProgramRunnerOwner)
#include "tst_programrunnerowner.moc"
