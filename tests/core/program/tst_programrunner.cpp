// ProgramRunner (issue 20): programs on a machine of an E-LAB table (X, Y, Z in mm) and a
// Nanotec rotary axis (A in degrees), each simulator on a real pseudo-terminal. What matters
// is asserted at the devices: the moves they accepted and in which order, the frames they
// received, whether they stand still.
#include "MachineTestSupport.h"
#include "PtyDevice.h"
#include "machine/Machine.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include "protocols/elab/ElabSimulator.h"
#include <QSignalSpy>
#include <QtTest>
#include <algorithm>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;

namespace {

using Device = test::PtyDevice;

QList<qint64> acceptedSteps(Device& d, Axis axis)
{
    return d.probe([&] {
        QList<qint64> steps;
        for (const SimulatedMove& m : d.sim()->acceptedMoves())
            if (m.axis == axis)
                steps << m.steps;
        return steps;
    });
}

int acceptedCount(Device& d)
{
    return d.probe([&] { return int(d.sim()->acceptedMoves().size()); });
}

bool still(Device& d)
{
    return d.probe([&] { return d.sim()->standingStill(); });
}

bool moving(Device& d)
{
    return d.probe([&] { return !d.sim()->standingStill(); });
}

// The index of the first frame the device received that contains `part` after `from`; -1: none.
int frameIndex(Device& d, const QByteArray& part, int from = 0)
{
    const QList<QByteArray> frames = d.frames();
    for (int i = from; i < frames.size(); ++i)
        if (frames.at(i).contains(part))
            return i;
    return -1;
}

} // namespace

class TestProgramRunner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void run_homeMovesRepeatDwell_devicesGetTheBlocksInOrder();
    void start_absoluteMoveOnUnknownAxis_refusedNothingSent();
    void pause_duringMove_holdsAfterTheBlockResumeGoesOn();
    void step_oneBlockThenPaused();
    void pause_m0_pausedWithItsPrompt();
    void toolChange_m6_pausedToLoadTheToolThenOn();
    void optionalStop_m1_pausesOnlyWithTheSwitchOn_data();
    void optionalStop_m1_pausesOnlyWithTheSwitchOn();
    void spindle_maxRpm_boardGetsSMappedOntoItsFullScale();
    void spindle_m4_refusedNothingSent();
    void spindle_sOnAnyLine_runningSpindleChangesOffOneWaits();
    void msg_reached_saidBeforeTheNextMoveGoesOut();
    void abort_duringMove_deviceStandsStillNextBlockNeverArrives();
    void fault_moveEndsAtLimitSwitch_failsAtThatLineLaterBlocksNeverArrive();
    void runFromLine_afterFault_startsThereWithItsModalState();
    void fault_boardNaksTheMove_failedAsNakAtThatLine();
    void g1_nanotec_rateWrittenBeforeTheMoveFastSpeedPutBackBeforeG0();
    void g1_elab_feedMoveAtItsFeedSpeed();
    void g93_elab_eachAxisItsRateFromItsDistance();
    void g93_elab_arcAtThePathSpeedOfItsLength();
    void linkLost_duringDwell_failsLinkDownAndTheTableStops();
    void abort_emisWithoutStopCommand_moveRunsOutSaidSoNextBlockNeverArrives();
    void run_workOffsets_absoluteTargetsShiftedRelativeNot();
    void run_coordinateSystems_boardGetsTheTargetsOfG55G10G92G53();
    void arc_fullCircle_boardGetsChordsOnTheCircleBackAtTheStart();
    void pause_duringArc_holdsBetweenChordsResumeFinishesTheArc();

private:
    MachineDescription description() const;
    void recreateMachine(const MachineDescription& d);
    void writeElabSetup();
    bool run(const QByteArray& text, int fromLine = 1, bool stepOnly = false);
    quint32 boardRpm() const; // the E-LAB simulator's spindle value (SetSpindleRPM)

    std::unique_ptr<Device> m_elab;
    std::unique_ptr<Device> m_nanotec;
    std::unique_ptr<Machine> m_machine;
    std::unique_ptr<ProgramRunner> m_runner;
};

MachineDescription TestProgramRunner::description() const
{
    MachineDescription d;
    d.name = QStringLiteral("Table with rotary axis");
    d.controllers = {{"table", "elab", m_elab->path(), {}, {}, {}, {}},
                     {"rotary", "nanotec", m_nanotec->path(), {{Axis::X, 1}}, {}, {}, {}}};
    d.axes = {test::machineAxis("X", "table", Axis::X, AxisUnit::Millimetre, 400),
              test::machineAxis("Y", "table", Axis::Y, AxisUnit::Millimetre, 400),
              test::machineAxis("A", "rotary", Axis::X, AxisUnit::Degree, 100)};
    return d;
}

void TestProgramRunner::init()
{
    m_elab = std::make_unique<Device>("elab");
    m_nanotec = std::make_unique<Device>("nanotec");
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(description(), &error), qPrintable(error));
    m_machine->open();
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    writeElabSetup();
    m_runner = std::make_unique<ProgramRunner>(m_machine.get());
}

// The same devices as a machine of another description (a spindle scale).
void TestProgramRunner::recreateMachine(const MachineDescription& d)
{
    m_runner.reset();
    m_machine.reset();
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(d, &error), qPrintable(error));
    m_machine->open();
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    writeElabSetup();
    m_runner = std::make_unique<ProgramRunner>(m_machine.get());
}

void TestProgramRunner::cleanup()
{
    m_runner.reset();
    m_machine.reset();
    m_elab.reset();
    m_nanotec.reset();
}

// The board moves only after its ramp setup was written (ModelInfo::setupBeforeMotion).
void TestProgramRunner::writeElabSetup()
{
    QVERIFY(test::writeSetupBeforeMotion(m_machine->session("table")));
}

bool TestProgramRunner::run(const QByteArray& text, int fromLine, bool stepOnly)
{
    QList<ProgramError> errors;
    const std::optional<Program> program = ProgramParser::parse(
        text, {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("A")}, &errors);
    if (!program) {
        qWarning() << "parse:" << (errors.isEmpty() ? QString() : errors.first().text());
        return false;
    }
    if (!m_runner->start(*program, fromLine, &errors, stepOnly)) {
        for (const ProgramError& e : std::as_const(errors))
            qWarning() << "check:" << e.text();
        return false;
    }
    return true;
}

quint32 TestProgramRunner::boardRpm() const
{
    return m_elab->probe(
        [&] { return static_cast<elab::ElabSimulator*>(m_elab->sim())->spindleRpm(); });
}

#define WAIT_ENDED() QTRY_VERIFY_WITH_TIMEOUT(isEnded(m_runner->state()), 60000)
#define VERIFY_STATE(expected)                                                                     \
    QVERIFY2(m_runner->state() == (expected), qPrintable(m_runner->endMessage()))

// Reference, moves on both controllers, a 3x repeat of a relative move and a dwell: each
// device accepted exactly these moves, in this order (a block starts only after the previous
// one arrived, so no two moves overlap on an axis).
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

// Issue 29: with "spindle": {"maxRpm": 24000} a program's S is in rpm: the board receives
// S / 24000 of its full scale 1000 (SetSpindleRPM, "einen Wert zwischen 0 und 1000").
void TestProgramRunner::spindle_maxRpm_boardGetsSMappedOntoItsFullScale()
{
    MachineDescription d = description();
    d.spindle.maxRpm = 24000;
    recreateMachine(d);
    QVERIFY(run("M3 S12000\nM0\nM3 S24000\nM0\nM3 S6000\nM0\nM5\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(boardRpm(), quint32(500));
    QVERIFY(frameIndex(*m_elab, QByteArray("\x01"
                                           "000001F4#")) >= 0);
    m_runner->resume();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 4, 30000);
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(boardRpm(), quint32(1000));
    m_runner->resume();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 6, 30000);
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(boardRpm(), quint32(250));
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(boardRpm(), quint32(0));
}

// Issue 29: S on any line, as LightBurn and pcb2gcode write it (LinuxCNC's meaning). M3
// without S starts at the S in effect; S on a move line changes a running spindle's speed
// before the move; while the spindle is off, S only sets the speed the next M3 starts at.
void TestProgramRunner::spindle_sOnAnyLine_runningSpindleChangesOffOneWaits()
{
    MachineDescription d = description();
    d.spindle.maxRpm = 24000;
    recreateMachine(d);
    const auto pausedAt = [this](int line) {
        return QTest::qWaitFor(
            [&] {
                return m_runner->state() == RunState::Paused && m_runner->currentLine() == line;
            },
            30000);
    };
    QVERIFY(run("G00 S6000\nM3\nM0\nG91 G0 X1 S12000\nM0\nM5\nG0 X2 S24000\nM0\nG0 X1 M3\nM0\n"
                "M5\n"));
    QVERIFY(pausedAt(3));
    QCOMPARE(boardRpm(), quint32(250));
    m_runner->resume();
    QVERIFY(pausedAt(5));
    QCOMPARE(boardRpm(), quint32(500));
    m_runner->resume();
    QVERIFY(pausedAt(8));
    QCOMPARE(boardRpm(), quint32(0)); // off: S24000 waits for the next M3
    m_runner->resume();
    QVERIFY(pausedAt(10));
    QCOMPARE(boardRpm(), quint32(1000)); // M3 beside a move (Vectric) switched it on
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(boardRpm(), quint32(0));
}

// No controller can reverse its spindle (the E-LAB switches a relay): M4 is refused before
// anything is sent, and the board's spindle stays off.
void TestProgramRunner::spindle_m4_refusedNothingSent()
{
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse("M4 S500\n", {"X", "Y", "A"}, &errors);
    QVERIFY(p);
    QVERIFY(!m_runner->start(*p, 1, &errors));
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.first().text(),
             QStringLiteral("1:1: M4: controller \"table\" cannot reverse its spindle: use M3"));
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QVERIFY(frameIndex(*m_elab, QByteArray("\x01")) < 0);
    QCOMPARE(boardRpm(), quint32(0));
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

// G1 on the Nanotec drive: its top speed o carries F (1200 deg/min = 20 deg/s = 2000 steps/s)
// before the move is sent; the fast speed it had is read first and written back before G0.
void TestProgramRunner::g1_nanotec_rateWrittenBeforeTheMoveFastSpeedPutBackBeforeG0()
{
    QVERIFY(run("G91 G1 A5 F1200\nG0 A-5\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_nanotec, Axis::X), (QList<qint64>{500, -500}));
    // Read (Zo) before the first write, written before the move's start (A), put back
    // before the G0's start.
    const int read = frameIndex(*m_nanotec, "#1Zo");
    const int rate = frameIndex(*m_nanotec, "#1o2000");
    QVERIFY(read >= 0 && rate > read);
    const int firstStart = frameIndex(*m_nanotec, "#1A\r", rate);
    QVERIFY2(firstStart > rate, "the rate goes before the move");
    // The drive's top speed before the program (the simulator's power-on value).
    const int putBack = frameIndex(*m_nanotec, "#1o1000", firstStart);
    QVERIFY2(putBack > firstStart, "the fast speed goes back after the G1");
    QVERIFY(frameIndex(*m_nanotec, "#1A\r", putBack) > putBack);
}

// G1 on the board: a feed move (no ramp) at its feed speed, F 6 mm/min = 40 steps/s.
void TestProgramRunner::g1_elab_feedMoveAtItsFeedSpeed()
{
    QVERIFY(run("G91 G1 X0.1 F6\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    // SetFeedSpeed <FS> with X at 40 (0x28), then the feed move of 40 steps (0x19 ...);
    // the simulator journals positioning moves only, so the board's count says where it went.
    QVERIFY(frameIndex(*m_elab, QByteArray::fromHex("1c303032382c")) >= 0);
    QVERIFY(frameIndex(*m_elab, QByteArray::fromHex("193030303030303238")) >= 0);
    QCOMPARE(m_elab->probe([&] { return m_elab->sim()->position(Axis::X); }), qint64(40));
    QVERIFY(still(*m_elab));
}

// G93 on the board: the move takes 1/F minutes, so each axis gets its distance times F: X 0.1 mm
// and Y 0.05 mm in 1 s are 40 and 20 steps/s (400 steps/mm), written in one <FS>XXXX,YYYY;ZZZZ.
// before the move.
void TestProgramRunner::g93_elab_eachAxisItsRateFromItsDistance()
{
    QVERIFY(run("G91 G93 G1 X0.1 Y0.05 F60\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QVERIFY(frameIndex(*m_elab, QByteArray::fromHex("1c303032382c303031343b")) >= 0);
    QCOMPARE(m_elab->probe([&] { return m_elab->sim()->position(Axis::X); }), qint64(40));
    QCOMPARE(m_elab->probe([&] { return m_elab->sim()->position(Axis::Y); }), qint64(20));
    QVERIFY(still(*m_elab));
}

// A G93 arc: its chords at the path speed that covers it in 1/F minutes. A half circle of radius
// 0.1 mm is 0.314 mm long: in 2 s (F30), 0.157 mm/s = 63 steps/s (0x3F) on X and Y.
void TestProgramRunner::g93_elab_arcAtThePathSpeedOfItsLength()
{
    QVERIFY(run("G28 X0 Y0\n")); // an arc needs known positions
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    const auto board = [&](Axis a) {
        return m_elab->probe([&] { return m_elab->sim()->position(a); });
    };
    const qint64 x0 = board(Axis::X);
    const qint64 y0 = board(Axis::Y);
    QVERIFY(run("G91 G93 G2 X0.2 Y0 I0.1 J0 F30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QVERIFY(frameIndex(*m_elab, QByteArray("\x1c"
                                           "003F,003F;")) >= 0);
    QCOMPARE(board(Axis::X) - x0, qint64(80));
    QCOMPARE(board(Axis::Y) - y0, qint64(0));
    QVERIFY(still(*m_elab));
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

// Issue 28, item 3: a program's absolute targets are work coordinates. With X's work zero at
// machine 2 mm and A's at 25 deg, "G0 X1 A0" goes to machine 3 mm and 25 deg; a relative move
// is not offset; G28 goes to the machine's reference (0), not the work zero.
void TestProgramRunner::run_workOffsets_absoluteTargetsShiftedRelativeNot()
{
    m_runner->setWorkOffsets({{QStringLiteral("X"), 2.0}, {QStringLiteral("A"), 25.0}});
    QVERIFY(run("G28\n"
                "G90 G0 X1 A0\n"
                "G91 G0 X0.5\n"
                "G90 G0 X0\n"
                "M30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(m_runner->workOffsets().value(QStringLiteral("X")), 2.0);
    // At the board: to machine 3 mm (1200 steps), 0.5 mm on, back to machine 2 mm.
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{1200, 200, -600}));
    // At the drive: to 25 deg = 2500 steps (within its 6000-step travel).
    QCOMPARE(acceptedSteps(*m_nanotec, Axis::X), (QList<qint64>{2500}));
    QVERIFY(still(*m_elab) && still(*m_nanotec));
}

// G54..G59, G10 L20, G92 and G53 (issue 29): each absolute word reaches the board as the
// machine position LinuxCNC would go to (400 steps/mm); the G10 is reported for the window.
void TestProgramRunner::run_coordinateSystems_boardGetsTheTargetsOfG55G10G92G53()
{
    CoordinateSystems systems;
    systems[0] = {{QStringLiteral("X"), 2.0}};
    systems[1] = {{QStringLiteral("X"), 5.0}};
    m_runner->setCoordinateSystems(systems, 0);
    QSignalSpy set(m_runner.get(), &ProgramRunner::coordinateSystemSet);
    QVERIFY(run("G28 X0 Y0\n"
                "G55 G0 X1\n"     // machine 6
                "G10 L20 P3 X0\n" // G56's X zero where X stands: 6
                "G56 G0 X1\n"     // machine 7
                "G92 X0\n"        // X reads 0 here: G92 adds 1
                "G0 X1\n"         // machine 8
                "G53 G0 X0.5\n"   // machine 0.5
                "G92.1\n"
                "G54 G0 X0\n" // machine 2
                "M30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{2400, 400, 400, -3000, 600}));
    QCOMPARE(set.size(), 1);
    QCOMPARE(set.at(0).at(0).toInt(), 2);
    using Offsets = QMap<QString, double>;
    QCOMPARE(set.at(0).at(1).value<Offsets>(), (Offsets{{QStringLiteral("X"), 6.0}}));
    QVERIFY(still(*m_elab));
}

// Where the board stands (steps, X and Y) each time the machine reports a move arrived: read
// from the simulator inside that signal, before the runner (connected later) sends the next
// chord.
struct ArrivalLog
{
    QList<QPoint> points;
    QMetaObject::Connection connection;
};

void logArrivals(Machine* machine, Device& board, ArrivalLog* log)
{
    log->connection = QObject::connect(machine, &Machine::moveFinished, machine, [&board, log] {
        log->points << board.probe([&] {
            return QPoint(int(board.sim()->position(Axis::X)), int(board.sim()->position(Axis::Y)));
        });
    });
}

// G3 full circle of radius 1 mm about X11 Y10 (400 steps/mm): ceil(2 pi / (2 acos(1 - 0.01)))
// = 23 chords, each arriving on the circle to within a step at the board, the last back at
// the start; counter-clockwise.
void TestProgramRunner::arc_fullCircle_boardGetsChordsOnTheCircleBackAtTheStart()
{
    QVERIFY(test::raiseElabFeedLimits(m_machine->session("table")));
    ArrivalLog log;
    logArrivals(m_machine.get(), *m_elab, &log);
    QVERIFY(run("G28 X0 Y0\nG0 X10 Y10\nG3 I1 F150\nM30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(m_runner->preview().path.size(), 3 + 23); // start, G28, G0, the chords
    QCOMPARE(log.points.size(), 1 + 23);               // the G0, then the chords
    // The simulator counts from its power-up place: positions relative to the G0's end.
    const QPoint start = log.points.first();
    for (const QPoint& p : log.points.mid(1))
        QVERIFY2(std::abs(std::hypot(p.x() - start.x() - 400, p.y() - start.y()) - 400) <= 1.0,
                 qPrintable(QStringLiteral("%1 %2").arg(p.x()).arg(p.y())));
    QCOMPARE(log.points.last(), start);
    const QPoint first = log.points.at(1) - start;
    QVERIFY(first.x() > 0 && first.y() < 0); // counter-clockwise from the circle's left: down
    QVERIFY(still(*m_elab));
}

// A pause during an arc holds between two chords, at the arc's line; resume sends the rest.
void TestProgramRunner::pause_duringArc_holdsBetweenChordsResumeFinishesTheArc()
{
    QVERIFY(test::raiseElabFeedLimits(m_machine->session("table")));
    ArrivalLog log;
    logArrivals(m_machine.get(), *m_elab, &log);
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    QVERIFY(run("G28 X0 Y0\nG0 X10 Y10\nG2 I1 F150\nG0 X0\n"));
    QTRY_VERIFY_WITH_TIMEOUT(log.points.size() >= 4, 30000); // the G0 and three chords
    m_runner->pause();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(paused.size(), 1);
    QCOMPARE(paused.at(0).at(0).toInt(), 3);
    QCOMPARE(m_runner->currentLine(), 3);
    const qsizetype held = log.points.size();
    QVERIFY2(held < 1 + 23, qPrintable(QString::number(held))); // mid-arc
    // Held: more status polls pass, the board stands where the last chord ended.
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QVERIFY(still(*m_elab));
    QCOMPARE(m_elab->probe([&] {
        return QPoint(int(m_elab->sim()->position(Axis::X)), int(m_elab->sim()->position(Axis::Y)));
    }),
             log.points.last());
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(log.points.size(), 1 + 23 + 1);
    QCOMPARE(log.points.at(23), log.points.first());                   // the circle closed
    QCOMPARE(log.points.last(), log.points.first() - QPoint(4000, 0)); // then the G0 X0
}

QTEST_MAIN(TestProgramRunner)
#include "tst_programrunner.moc"
