// ProgramRunner (issue 20): the run's walk on a machine of an E-LAB table and a Nanotec rotary
// axis (ProgramRunnerTestSupport.h): blocks in order, refusals, pauses, steps, M0/M6/M1, (MSG),
// abort, faults, run from line and a lost link. What matters is asserted at the devices: the
// moves they accepted and in which order, the frames they received, whether they stand still.
// What each block sends (spindle, rates, G93, coordinates, arcs): tst_programrunnermotion.
#include "ProgramRunnerTestSupport.h"
#include "TestMain.h"

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;
using namespace stepdeck::program::runnertest;

class TestProgramRunner : public ProgramRunnerFixture
{
    Q_OBJECT
private Q_SLOTS:
    void init() { setUpRig(); }
    void cleanup() { tearDownRig(); }
    void run_homeMovesRepeatDwell_devicesGetTheBlocksInOrder();
    void polar_boltCircle_boardGetsThePointsOfTheCircle();
    void start_absoluteMoveOnUnknownAxis_refusedNothingSent();
    void startChecked_machineChangedSinceTheCheck_refusedNothingSent_data();
    void startChecked_machineChangedSinceTheCheck_refusedNothingSent();
    void pause_duringMove_holdsAfterTheBlockResumeGoesOn();
    void step_oneBlockThenPaused();
    void pause_m0_pausedWithItsPrompt();
    void toolChange_m6_pausedToLoadTheToolThenOn();
    void optionalStop_m1_pausesOnlyWithTheSwitchOn_data();
    void optionalStop_m1_pausesOnlyWithTheSwitchOn();
    void msg_reached_saidBeforeTheNextMoveGoesOut();
    void abort_duringMove_deviceStandsStillNextBlockNeverArrives();
    void fault_moveEndsAtLimitSwitch_failsAtThatLineLaterBlocksNeverArrive();
    void fault_boardNaksTheMove_failedAsNakAtThatLine();
    void runFromLine_afterFault_startsThereWithItsModalState();
    void runFromLine_afterM3M8_spindleAndCoolantOnBeforeTheFirstMove();
    void runFromLine_toTheStartPoint_zUpFirstOrXYFirst_data();
    void runFromLine_toTheStartPoint_zUpFirstOrXYFirst();
    void runFromLine_restoredSpindleOutOfRange_refusedByTheCheckNothingSent();
    void linkLost_duringDwell_failsLinkDownAndTheTableStops();
    void abort_emisWithoutStopCommand_moveRunsOutSaidSoNextBlockNeverArrives();
};

// Reference, moves on both controllers, a 3x repeat of a relative move and a dwell: each
// device accepted exactly these moves, in this order (a block starts only after the previous
// one arrived, so no two moves overlap on an axis).
// Issue 50 item 6: LinuxCNC's polar coordinates, "@r ^a" from the work zero (X's at machine
// 2 mm): three holes of a bolt circle of radius 1 mm at 0, 90 and 180 degrees. At the board
// (400 steps/mm) from the reference: X to machine 3 (1200); X to 2 and Y to 1 (-400, +400);
// X to 1 and Y back to 0 (-400, -400).
void TestProgramRunner::polar_boltCircle_boardGetsThePointsOfTheCircle()
{
    m_runner->setWorkOffsets({{QStringLiteral("X"), 2.0}});
    QVERIFY(run("G28 X0 Y0\nG90 G0 @1 ^0\nG0 @1 ^90\nG0 ^180 @1\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{1200, -400, -400}));
    QCOMPARE(acceptedSteps(*m_elab, Axis::Y), (QList<qint64>{400, -400}));
    QVERIFY(still(*m_elab));
}

void TestProgramRunner::run_homeMovesRepeatDwell_devicesGetTheBlocksInOrder()
{
    QSignalSpy started(m_runner.get(), &ProgramRunner::blockStarted);
    QVERIFY(run("G28\n"
                "G0 X1 A10\n"
                "O1 repeat [3]\n"
                "  G91 G0 X0.5\n"
                "O1 endrepeat\n"
                "G4 P0.2\n"
                "G90 G0 X0 A0\n"
                "M30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    // At the board: 1 mm, three times 0.5 mm, back by 2.5 mm (x 400 steps/mm).
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400, 200, 200, 200, -1000}));
    // At the drive: 10 deg = 1000 steps, then back.
    QCOMPARE(acceptedSteps(*m_nanotec, Axis::X), (QList<qint64>{1000, -1000}));
    QVERIFY(still(*m_elab) && still(*m_nanotec));
    QList<int> lines;
    for (const QList<QVariant>& args : std::as_const(started))
        lines << args.at(0).toInt();
    QCOMPARE(lines, (QList<int>{1, 2, 4, 4, 4, 6, 7, 8}));
    QCOMPARE(m_runner->blocksDone(), qint64(8));
}

// The check refuses the whole program: nothing reaches a device.
void TestProgramRunner::start_absoluteMoveOnUnknownAxis_refusedNothingSent()
{
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse("G91 G0 X1\nG90 G0 A10\n", {"X", "Y", "A"}, &errors);
    QVERIFY(p);
    QVERIFY(!m_runner->start(*p, 1, &errors));
    QVERIFY(!errors.isEmpty());
    QCOMPARE(errors.first().line, 2);
    QCOMPARE(m_runner->state(), RunState::Idle);
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(acceptedCount(*m_elab), 0);
    QCOMPARE(acceptedCount(*m_nanotec), 0);
}

void TestProgramRunner::startChecked_machineChangedSinceTheCheck_refusedNothingSent_data()
{
    QTest::addColumn<QString>("change");
    QTest::newRow("nothing") << QString();
    QTest::newRow("work offset") << "offset";
    QTest::newRow("tool table") << "tool";
}

// start() in two halves (the window checks off the GUI thread): a check of facts the machine no
// longer has is refused, nothing sent; with the facts unchanged the run starts from it.
void TestProgramRunner::startChecked_machineChangedSinceTheCheck_refusedNothingSent()
{
    QFETCH(QString, change);
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse("G91 G0 X1\nM2\n", {"X", "Y", "A"}, &errors);
    QVERIFY(p);
    const MachineFacts facts = m_runner->startFacts();
    const ProgramCheckResult checked = ProgramRunner::checkForStart(*p, facts, 1);
    QVERIFY(checked.ok());
    if (change == QLatin1String("offset")) {
        m_runner->setWorkOffsets({{QStringLiteral("X"), 5.0}});
    } else if (change == QLatin1String("tool")) {
        ToolTable tools;
        tools.insert(Tool{1, 10.0, 3.0, QStringLiteral("end mill")});
        m_runner->setToolTable(tools);
    }
    const bool started = m_runner->startChecked(*p, 1, facts, checked, &errors);
    if (change.isEmpty()) {
        QVERIFY2(started, qPrintable(errors.value(0).text()));
        WAIT_ENDED();
        VERIFY_STATE(RunState::Finished);
        QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400}));
        return;
    }
    QVERIFY(!started);
    QVERIFY2(errors.value(0).message.contains(QStringLiteral("the machine changed")),
             qPrintable(errors.value(0).text()));
    QCOMPARE(m_runner->state(), RunState::Idle);
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(acceptedCount(*m_elab), 0);
    QVERIFY(still(*m_elab));
}

void TestProgramRunner::pause_duringMove_holdsAfterTheBlockResumeGoesOn()
{
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    QVERIFY(run("G91\nG0 X5\nG0 X-5\nG0 X1\n"));
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    m_runner->pause();
    QVERIFY(m_runner->pausePending()); // "pausing after this block" while it runs out
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(paused.size(), 1);
    QCOMPARE(paused.at(0).at(0).toInt(), 2);
    // Held: more status polls pass and the board got the first move only.
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{2000}));
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{2000, -2000, 400}));
}

void TestProgramRunner::step_oneBlockThenPaused()
{
    QVERIFY(run("G91\nG0 X1\nG0 X1\n", 1, true));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400}));
    m_runner->step();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400, 400}));
    m_runner->step(); // nothing left: the program finishes
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
}

void TestProgramRunner::pause_m0_pausedWithItsPrompt()
{
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    QVERIFY(run("G91 G0 X1\nM0 (Load the part, then Resume)\nG0 X1\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(paused.at(0).at(1).toString(), QStringLiteral("Load the part, then Resume"));
    QCOMPARE(m_runner->prompt(), QStringLiteral("Load the part, then Resume"));
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400}));
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400, 400}));
}

// Issue 29: T selects, M6 changes by hand: the program holds with "Load tool n (comment)"
// and the board receives nothing more until the operator resumes.
void TestProgramRunner::toolChange_m6_pausedToLoadTheToolThenOn()
{
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    QVERIFY(run("G91 G0 X1\nT3 M6 (6 mm end mill)\nG0 X1\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(paused.at(0).at(0).toInt(), 2);
    QCOMPARE(m_runner->prompt(), QStringLiteral("Load tool 3 (6 mm end mill)"));
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400}));
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400, 400}));
}

// Issue 29: M1 holds like M0 (with its comment as the prompt) while the optional-stop switch
// is on -- the default -- and the run passes it when it is off.
void TestProgramRunner::optionalStop_m1_pausesOnlyWithTheSwitchOn_data()
{
    QTest::addColumn<int>("optionalStops"); // -1: left at the default
    QTest::addColumn<bool>("holds");
    QTest::newRow("default") << -1 << true;
    QTest::newRow("on") << 1 << true;
    QTest::newRow("off") << 0 << false;
}

void TestProgramRunner::optionalStop_m1_pausesOnlyWithTheSwitchOn()
{
    QFETCH(int, optionalStops);
    QFETCH(bool, holds);
    if (optionalStops >= 0)
        m_runner->setOptionalStops(optionalStops == 1);
    QCOMPARE(m_runner->optionalStops(), holds);
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    QVERIFY(run("G91 G0 X1\nM1 (Look at the first pass)\nG0 X1\n"));
    if (holds) {
        QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
        QCOMPARE(paused.size(), 1);
        QCOMPARE(paused.at(0).at(0).toInt(), 2);
        QCOMPARE(m_runner->prompt(), QStringLiteral("Look at the first pass"));
        // Held: more status polls pass and the board got the first move only.
        QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
        QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
        QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400}));
        m_runner->resume();
    }
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(paused.size(), holds ? 1 : 0);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400, 400}));
}

// Issue 29: "(MSG, text)" is said when the run reaches its line (in a repeat: each time),
// before the next block's move goes out.
void TestProgramRunner::msg_reached_saidBeforeTheNextMoveGoesOut()
{
    QList<QPair<int, int>> said; // line, moves the board had accepted then
    connect(m_runner.get(), &ProgramRunner::operatorMessage, this,
            [&](int line, const QString& text) {
                QCOMPARE(text, QStringLiteral("Second pass"));
                said << qMakePair(line, int(acceptedSteps(*m_elab, Axis::X).size()));
            });
    QVERIFY(run("G91 G0 X1\nO1 repeat [2]\n(MSG, Second pass)\nG0 X1\nO1 endrepeat\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(said.size(), 2);
    QCOMPARE(said.at(0).first, 3);
    QCOMPARE(said.at(0).second, 1); // only line 1's move: line 4's comes after it
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400, 400, 400}));
}

void TestProgramRunner::abort_duringMove_deviceStandsStillNextBlockNeverArrives()
{
    QVERIFY(run("G91\nG0 X200\nG0 X-1\n"));
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    m_runner->abort();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Aborted);
    QVERIFY(m_runner->endMessage().contains("line 2"));
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QVERIFY(m_elab->receivedStop());
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{80000})); // line 3 never came
}

// The drive's limit switch sits at 3000 steps (30 deg): the move of line 2 ends there, the
// program fails at line 2, and line 3 never reaches either device.
void TestProgramRunner::fault_moveEndsAtLimitSwitch_failsAtThatLineLaterBlocksNeverArrive()
{
    QVERIFY(run("G91 G0 A10\nG0 A40\nG0 X1 A-5\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Failed);
    QVERIFY2(m_runner->endMessage().startsWith("line 2:"), qPrintable(m_runner->endMessage()));
    QSignalSpy rotary(m_machine->session("rotary"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(rotary.size() >= 3, 10000);
    QCOMPARE(acceptedSteps(*m_nanotec, Axis::X), (QList<qint64>{1000, 4000}));
    QCOMPARE(acceptedCount(*m_elab), 0);
    QVERIFY(still(*m_nanotec));
}

// The board refuses the move with NAK: the program fails at that line as refused by the device
// (Nak), not as a move that ended short, and the next block never arrives.
void TestProgramRunner::fault_boardNaksTheMove_failedAsNakAtThatLine()
{
    m_elab->probe([&] {
        static_cast<elab::ElabSimulator*>(m_elab->sim())->forceNak(1);
        return true;
    });
    QVERIFY(run("G91 G0 X1\nG0 X2\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Failed);
    QCOMPARE(m_runner->failureKind(), ErrorKind::Nak);
    QVERIFY2(m_runner->endMessage().startsWith("line 1:"), qPrintable(m_runner->endMessage()));
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(acceptedCount(*m_elab), 0);
}

// Run from line N: the blocks before it are not run; line 3's G91 comes from line 1.
void TestProgramRunner::runFromLine_afterFault_startsThereWithItsModalState()
{
    QVERIFY(run("G91 G0 X1\nG0 X2\nG0 X-3\n", 3));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{-1200}));
}

void TestProgramRunner::linkLost_duringDwell_failsLinkDownAndTheTableStops()
{
    QVERIFY(run("G91 G0 X1\nG4 P30\nG0 X1\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 2, 30000);
    m_nanotec->vanish();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Failed);
    QCOMPARE(m_runner->failureKind(), ErrorKind::LinkDown);
    QVERIFY2(m_runner->endMessage().startsWith("line 2:"), qPrintable(m_runner->endMessage()));
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400}));
}

// The SMC-IC4 has no stop command: abort lets the move under way finish, says so, and ends
// the program once the board reports it done; the next block is never sent.
void TestProgramRunner::abort_emisWithoutStopCommand_moveRunsOutSaidSoNextBlockNeverArrives()
{
    m_runner.reset();
    m_machine.reset();
    Device emis("emis");
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(
                 MachineDescription::singleController(*findModel("emis"), emis.path()), &error),
             qPrintable(error));
    m_machine->open();
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    m_runner = std::make_unique<ProgramRunner>(m_machine.get());
    QSignalSpy stopping(m_runner.get(), &ProgramRunner::stopping);
    QList<ProgramError> errors;
    // 2000 steps at the board's work speed (1000 steps/s unless set): about 2 s.
    const std::optional<Program> p =
        ProgramParser::parse("G91 G0 X2000\nG0 X-100\n", {"X", "Y", "Z", "U"}, &errors);
    QVERIFY(p);
    QVERIFY(m_runner->start(*p, 1, &errors));
    QTRY_VERIFY_WITH_TIMEOUT(moving(emis), 10000);
    m_runner->abort();
    QCOMPARE(m_runner->state(), RunState::Stopping);
    QCOMPARE(stopping.size(), 1);
    QVERIFY2(stopping.at(0).at(0).toString().contains("finishes by itself"),
             qPrintable(stopping.at(0).at(0).toString()));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Aborted);
    QVERIFY(still(emis));
    QCOMPARE(emis.probe([&] { return emis.sim()->position(Axis::X); }), qint64(2000));
    QSignalSpy polls(m_machine->session("emis"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 3, 10000);
    QCOMPARE(acceptedSteps(emis, Axis::X), (QList<qint64>{2000}));
    m_runner.reset();
    m_machine.reset(); // before the device goes
}

// Issue 47 item 5: from a line after "M3 S500" and "M8" the cut runs with the spindle and the
// coolant on: both are switched at the board before the first move of the run.
void TestProgramRunner::runFromLine_afterM3M8_spindleAndCoolantOnBeforeTheFirstMove()
{
    const int before = int(m_elab->frames().size());
    QVERIFY(run("M3 S500\nM8\nG91 G0 X1\nG0 X1\nM5\nM9\n", 4));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{400})); // line 4 only
    const int spindleOn = frameIndex(*m_elab, elab::encode::spindleRpm(500), before);
    const int coolantOn = frameIndex(*m_elab, elab::encode::coolant(true), before);
    const int move = frameIndex(*m_elab, QByteArray(1, '\x0c'), before); // <FF>: SetFastMoveXY
    QVERIFY2(spindleOn >= 0 && coolantOn > spindleOn && move > coolantOn,
             qPrintable(QStringLiteral("%1 %2 %3").arg(spindleOn).arg(coolantOn).arg(move)));
    QCOMPARE(boardRpm(), quint32(0)); // line 5's M5
}

void TestProgramRunner::runFromLine_toTheStartPoint_zUpFirstOrXYFirst_data()
{
    QTest::addColumn<QByteArray>("before"); // run first: where the tool stands at the start
    QTest::addColumn<QByteArray>("program");
    QTest::addColumn<int>("fromLine");
    QTest::addColumn<QStringList>("started");  // the texts of blockStarted
    QTest::addColumn<QStringList>("arrivals"); // the board's X,Y,Z steps as each move arrived
    // The start point is X2 Y1 Z0.5 (800, 400, 200 steps); the line run from goes to X3 (1200).
    QTest::newRow("start above: Z up first, then X Y")
        << QByteArray("G28 X0 Y0 Z0\n") << QByteArray("G0 Z1\nG0 X2 Y1 Z0.5\nG0 X3\n") << 3
        << QStringList{"G53 G0 Z0.5", "G53 G0 X2 Y1", "G0 X3"}
        << QStringList{"0,0,200", "800,400,200", "1200,400,200"};
    QTest::newRow("start below: X Y first at the tool's height, then Z down")
        << QByteArray("G28 X0 Y0 Z0\nG0 Z2\n") << QByteArray("G0 Z3\nG0 X2 Y1\nG0 Z0.5\nG0 X3\n")
        << 4 << QStringList{"G53 G0 X2 Y1", "G53 G0 Z0.5", "G0 X3"}
        << QStringList{"800,400,800", "800,400,200", "1200,400,200"};
    // An axis already there does not move: tst_runfromline (RunFromState::approach).
}

// Issue 47 item 5: a run from line N goes first to where the lines before it leave the tool, as
// gSender and UGS do: Z up first when the start is higher, else X Y at the tool's height and Z
// down last. Asserted at the board (a Z on the table, 400 steps/mm) each time a move arrived;
// the rapids are announced, and they are no blocks of the program.
void TestProgramRunner::runFromLine_toTheStartPoint_zUpFirstOrXYFirst()
{
    QFETCH(QByteArray, before);
    QFETCH(QByteArray, program);
    QFETCH(int, fromLine);
    QFETCH(QStringList, started);
    QFETCH(QStringList, arrivals);
    MachineDescription d = description();
    d.axes.insert(2, test::machineAxis("Z", "table", Axis::Z, AxisUnit::Millimetre, 400));
    recreateMachine(d);
    QVERIFY(run(before)); // referenced: the check counts only on confirmed positions
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    // The board's counts from where its reference run left them (the machine's 0).
    const auto board = [&](Axis a) {
        return m_elab->probe([&] { return m_elab->sim()->position(a); });
    };
    const qint64 x0 = board(Axis::X) - m_machine->axisStatus(d.axes.at(0)).steps;
    const qint64 y0 = board(Axis::Y) - m_machine->axisStatus(d.axes.at(1)).steps;
    const qint64 z0 = board(Axis::Z) - m_machine->axisStatus(d.axes.at(2)).steps;
    QStringList texts;
    QStringList arrived;
    QObject guard; // the connections end before the lists they fill
    connect(m_runner.get(), &ProgramRunner::blockStarted, &guard,
            [&](int, const QString& text) { texts << text; });
    // Read inside the machine's report, before the runner (connected later) sends the next move.
    connect(m_machine.get(), &Machine::moveFinished, &guard, [&] {
        arrived << QStringLiteral("%1,%2,%3")
                       .arg(board(Axis::X) - x0)
                       .arg(board(Axis::Y) - y0)
                       .arg(board(Axis::Z) - z0);
    });
    QVERIFY(run(program, fromLine));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(texts, started);
    QCOMPARE(arrived, arrivals);
    QCOMPARE(m_runner->blocksDone(), qint64(1));
    QVERIFY(still(*m_elab));
}

// The spindle the lines before the start left on is switched on first at their S: beyond the
// board's 0..1000 the check refuses the run, naming it at the start line, before anything is
// sent (the run would refuse it at the switch).
void TestProgramRunner::runFromLine_restoredSpindleOutOfRange_refusedByTheCheckNothingSent()
{
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse("M3 S2000\nG91 G0 X1\nG0 X1\n", {"X", "Y", "A"}, &errors);
    QVERIFY(p);
    QVERIFY(!m_runner->start(*p, 3, &errors));
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.first().line, 3);
    QVERIFY2(errors.first().message.contains("M3 S2000") &&
                 errors.first().message.contains("out of range"),
             qPrintable(errors.first().text()));
    QCOMPARE(m_runner->state(), RunState::Idle);
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(acceptedCount(*m_elab), 0);
    QCOMPARE(boardRpm(), quint32(0));
}

STEPDECK_TEST_MAIN(TestProgramRunner)
#include "tst_programrunner.moc"
