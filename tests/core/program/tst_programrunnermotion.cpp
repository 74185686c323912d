// ProgramRunner (issues 20, 29): what the blocks send, on the machine of
// ProgramRunnerTestSupport.h: the spindle's S, G1's rates on each model, G93's per-axis rates,
// work offsets and coordinate systems, and arcs as chords, asserted at the devices (the frames
// they received, where they stand, whether they stand still).
#include "ProgramRunnerTestSupport.h"
#include "TestMain.h"

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;
using namespace stepdeck::program::runnertest;

class TestProgramRunnerMotion : public ProgramRunnerFixture
{
    Q_OBJECT
private Q_SLOTS:
    void init() { setUpRig(); }
    void cleanup() { tearDownRig(); }
    void spindle_maxRpm_boardGetsSMappedOntoItsFullScale();
    void spindle_sOnAnyLine_runningSpindleChangesOffOneWaits();
    void spindle_m4_refusedUnlessALaser_data();
    void spindle_m4_refusedUnlessALaser();
    void g1_nanotec_rateWrittenBeforeTheMoveFastSpeedPutBackBeforeG0();
    void g1_elab_feedMoveAtItsFeedSpeed();
    void g93_elab_eachAxisItsRateFromItsDistance();
    void g93_elab_arcAtThePathSpeedOfItsLength();
    void run_workOffsets_absoluteTargetsShiftedRelativeNot();
    void run_coordinateSystems_boardGetsTheTargetsOfG55G10G92G53();
    void arc_fullCircle_boardGetsChordsOnTheCircleBackAtTheStart();
    void pause_duringArc_holdsBetweenChordsResumeFinishesTheArc();
    void end_spindleAndCoolantOn_boardSwitchesThemOffAtM2M30Only_data();
    void end_spindleAndCoolantOn_boardSwitchesThemOffAtM2M30Only();
    void abort_duringMove_boardSwitchesSpindleOffOnceStanding();
    void toolChange_zeroSetWhileHeld_restRunsInTheNewZero();
    void toolChange_zeroFailsTheRestsCheck_resumeRefusedUntilPutBack();
    void cutterComp_offsetsChangedAtM0_resumeRefusedUntilPutBack();
    void touchOff_m6_holdsUntilZeroZRestCutsAtTheNewZ();
    void touchOff_tableMode_g43WithAnEmptyTableRefusedNothingSent();

private:
    // The rig's machine with a Z on the table (400 steps/mm) and tool lengths as given.
    void recreateWithZ(ToolLength toolLength);
};

// Issue 29: with "spindle": {"maxRpm": 24000} a program's S is in rpm: the board receives
// S / 24000 of its full scale 1000 (SetSpindleRPM, "einen Wert zwischen 0 und 1000"); S30000
// runs at 24000 (issue 50).
void TestProgramRunnerMotion::spindle_maxRpm_boardGetsSMappedOntoItsFullScale()
{
    MachineDescription d = description();
    d.spindle.maxRpm = 24000;
    recreateMachine(d);
    QVERIFY(run("M3 S12000\nM0\nM3 S24000\nM0\nM3 S6000\nM0\nM3 S30000\nM0\nM5\n"));
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
    // Issue 50 item 1: S above maxRpm runs at maxRpm (GRBL's $30), the board at its full scale,
    // and the run's check said so in a note.
    m_runner->resume();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 8, 30000);
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(boardRpm(), quint32(1000));
    const QList<ProgramError> notes = m_runner->checkNotes();
    QVERIFY(std::any_of(notes.cbegin(), notes.cend(), [](const ProgramError& n) {
        return n.line == 7 && n.message.contains(QStringLiteral("S30000"));
    }));
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(boardRpm(), quint32(0));
}

// Issue 29: S on any line, as LightBurn and pcb2gcode write it (LinuxCNC's meaning). M3
// without S starts at the S in effect; S on a move line changes a running spindle's speed
// before the move; while the spindle is off, S only sets the speed the next M3 starts at.
void TestProgramRunnerMotion::spindle_sOnAnyLine_runningSpindleChangesOffOneWaits()
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
// anything is sent, and the board's spindle stays off. On a machine whose spindle output drives
// a laser (issue 50 item 5), M4 (GRBL's dynamic power) runs as M3: the board's spindle output
// at S (500 of the E-LAB's 0..1000, no scale), and M5 switches the beam off.
void TestProgramRunnerMotion::spindle_m4_refusedUnlessALaser_data()
{
    QTest::addColumn<bool>("laser");
    QTest::newRow("a spindle") << false;
    QTest::newRow("a laser") << true;
}

void TestProgramRunnerMotion::spindle_m4_refusedUnlessALaser()
{
    QFETCH(bool, laser);
    if (laser) {
        MachineDescription d = description();
        d.spindle.laser = true;
        recreateMachine(d);
        QVERIFY(run("M4 S500\nG91 G0 X1\n"));
        WAIT_ENDED();
        VERIFY_STATE(RunState::Finished);
        QCOMPARE(boardRpm(), quint32(500)); // no M2: the beam stays on, as after an MDI line
        QCOMPARE(acceptedSteps(*m_elab, Axis::X), QList<qint64>{400});
        QVERIFY(run("M5\n"));
        WAIT_ENDED();
        VERIFY_STATE(RunState::Finished);
        QCOMPARE(boardRpm(), quint32(0));
        return;
    }
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

// G1 on the Nanotec drive: its top speed o carries F (1200 deg/min = 20 deg/s = 2000 steps/s)
// before the move is sent; the fast speed it had is read first and written back before G0.
void TestProgramRunnerMotion::g1_nanotec_rateWrittenBeforeTheMoveFastSpeedPutBackBeforeG0()
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

// G1 in G61 (a block of its own, not a contour: issue 30) on the board: a feed move (no ramp)
// at its feed speed, F 6 mm/min = 40 steps/s.
void TestProgramRunnerMotion::g1_elab_feedMoveAtItsFeedSpeed()
{
    QVERIFY(run("G61 G91 G1 X0.1 F6\n"));
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
void TestProgramRunnerMotion::g93_elab_eachAxisItsRateFromItsDistance()
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
void TestProgramRunnerMotion::g93_elab_arcAtThePathSpeedOfItsLength()
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

// Issue 28, item 3: a program's absolute targets are work coordinates. With X's work zero at
// machine 2 mm and A's at 25 deg, "G0 X1 A0" goes to machine 3 mm and 25 deg; a relative move
// is not offset; G28 goes to the machine's reference (0), not the work zero.
void TestProgramRunnerMotion::run_workOffsets_absoluteTargetsShiftedRelativeNot()
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
void TestProgramRunnerMotion::run_coordinateSystems_boardGetsTheTargetsOfG55G10G92G53()
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

// G3 full circle of radius 1 mm about X11 Y10 (400 steps/mm) in G61 (on its own, not a
// contour): ceil(2 pi / (2 acos(1 - 0.01))) = 23 chords, each arriving on the circle to within a
// step at the board, the last back at the start; counter-clockwise.
void TestProgramRunnerMotion::arc_fullCircle_boardGetsChordsOnTheCircleBackAtTheStart()
{
    QVERIFY(test::raiseElabFeedLimits(m_machine->session("table")));
    ArrivalLog log;
    logArrivals(m_machine.get(), *m_elab, &log);
    QVERIFY(run("G28 X0 Y0\nG0 X10 Y10\nG61 G3 I1 F150\nM30\n"));
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

// A pause during an arc in G61 holds between two chords, at the arc's line; resume sends the
// rest.
void TestProgramRunnerMotion::pause_duringArc_holdsBetweenChordsResumeFinishesTheArc()
{
    QVERIFY(test::raiseElabFeedLimits(m_machine->session("table")));
    ArrivalLog log;
    logArrivals(m_machine.get(), *m_elab, &log);
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    QVERIFY(run("G28 X0 Y0\nG0 X10 Y10\nG61 G2 I1 F150\nG0 X0\n"));
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

// Issue 47, item 1: M2/M30 end with spindle and coolant off, as in LinuxCNC (a Fusion 360
// post ends "G0 Z15 / M30" with no M5), and the run says "finished" only after the board
// acknowledged both; a program that just runs out (an MDI line) leaves them as they are.
// "M5 M9" switch off as the program's end does; without any, the board keeps both on.
void TestProgramRunnerMotion::end_spindleAndCoolantOn_boardSwitchesThemOffAtM2M30Only_data()
{
    QTest::addColumn<QByteArray>("program");
    QTest::addColumn<bool>("switchedOff");
    QTest::newRow("M30 without M5") << QByteArray("M3 S1000\nM8\nG91 G0 X1\nM30\n") << true;
    QTest::newRow("M2 without M5 and M9") << QByteArray("M3 S1000\nM8\nG91 G0 X1\nM2\n") << true;
    QTest::newRow("no program end (an MDI line)") << QByteArray("M3 S1000\nM8\n") << false;
    // Issue 50: LinuxCNC's whole line: several switches, and M2 after the line's move.
    QTest::newRow("on one line, M2 after the move")
        << QByteArray("M8 M3 S1000\nG91 G0 X1 M2\n") << true;
    QTest::newRow("on one line, then M5 M9")
        << QByteArray("M3 M8 S1000\nG91 G0 X1\nM5 M9\n") << true;
    QTest::newRow("on one line (an MDI line)") << QByteArray("M3 M8 S1000\n") << false;
}

void TestProgramRunnerMotion::end_spindleAndCoolantOn_boardSwitchesThemOffAtM2M30Only()
{
    QFETCH(QByteArray, program);
    QFETCH(bool, switchedOff);
    const auto coolant = [this] {
        return m_elab->probe(
            [&] { return static_cast<elab::ElabSimulator*>(m_elab->sim())->coolant(); });
    };
    QVERIFY(run(program));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    // Finished is said after the acknowledgements: the relays are off at the board by then.
    QCOMPARE(boardRpm(), switchedOff ? quint32(0) : quint32(1000));
    QCOMPARE(coolant(), !switchedOff);
    QCOMPARE(frameIndex(*m_elab, elab::encode::spindleRpm(0)) >= 0, switchedOff);
    // The move ran (M2 on its line comes after it) with the spindle on.
    QCOMPARE(acceptedSteps(*m_elab, Axis::X),
             program.contains("X1") ? QList<qint64>{400} : QList<qint64>{});
}

// Issue 47, item 1: STOP during a program's move: the board brakes, then its spindle relay goes
// off (SetSpindleRPM is taken only at standstill).
void TestProgramRunnerMotion::abort_duringMove_boardSwitchesSpindleOffOnceStanding()
{
    QVERIFY(run("M3 S1000\nG91 G0 X200\n"));
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    QCOMPARE(boardRpm(), quint32(1000));
    m_runner->abort();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Aborted);
    QTRY_COMPARE_WITH_TIMEOUT(boardRpm(), quint32(0), 20000);
    QVERIFY(still(*m_elab));
    const int stopAt = frameIndex(*m_elab, elab::encode::stopMove());
    QVERIFY(stopAt >= 0);
    QVERIFY(frameIndex(*m_elab, elab::encode::spindleRpm(0), stopAt) > stopAt);
}

// Issue 47, item 2: a touch-off at M6. The run holds; the operator moves X by 0.5 mm and sets
// the work zero there (the DRO's Zero X: G54's X = where X stands); Resume checks the rest with
// it and the rest runs in it. At the board (400 steps/mm): X1 in the old zero (machine 3 mm),
// the operator's 0.5 mm, then X1 in the new zero (machine 4.5 mm): 1 mm on.
void TestProgramRunnerMotion::toolChange_zeroSetWhileHeld_restRunsInTheNewZero()
{
    CoordinateSystems systems;
    systems[0] = {{QStringLiteral("X"), 2.0}};
    m_runner->setCoordinateSystems(systems, 0);
    QSignalSpy checked(m_runner.get(), &ProgramRunner::restChecked);
    QVERIFY(run("G28 X0 Y0\nG90 G0 X1\nT2 M6\nG0 X1\nM30\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QVERIFY(m_runner->pausedAtOperatorStop());
    QString error;
    QSignalSpy moved(m_machine.get(), &Machine::moveFinished);
    QVERIFY2(m_machine->move({{QStringLiteral("X"), 0.5}}, false, &error) != 0, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(!moved.isEmpty(), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    systems[0] = {{QStringLiteral("X"), 3.5}};
    m_runner->setCoordinateSystems(systems, 0);
    QVERIFY(m_runner->restNeedsCheck());
    m_runner->resume();
    QCOMPARE(checked.size(), 1);
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{1200, 200, 400}));
    QCOMPARE(m_runner->workOffsets().value(QStringLiteral("X")), 3.5);
}

// The same with a zero that puts the rest beyond X's soft limit (10 mm): Resume refuses with
// the check's reason and nothing more reaches the board; with the zero put back it goes on
// (X2: machine 4 mm).
void TestProgramRunnerMotion::toolChange_zeroFailsTheRestsCheck_resumeRefusedUntilPutBack()
{
    MachineDescription d = description();
    d.axes[0].softMinimum = 0.0;
    d.axes[0].softMaximum = 10.0;
    recreateMachine(d);
    CoordinateSystems systems;
    systems[0] = {{QStringLiteral("X"), 2.0}};
    m_runner->setCoordinateSystems(systems, 0);
    QSignalSpy refused(m_runner.get(), &ProgramRunner::resumeRefused);
    QVERIFY(run("G28 X0 Y0\nG90 G0 X1\nM0\nG0 X2\nM30\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    CoordinateSystems moved = systems;
    moved[0] = {{QStringLiteral("X"), 9.8}};
    m_runner->setCoordinateSystems(moved, 0);
    m_runner->resume();
    QCOMPARE(refused.size(), 1);
    QVERIFY2(refused.first().at(0).toString().contains(QStringLiteral("line 4")),
             qPrintable(refused.first().at(0).toString()));
    QCOMPARE(m_runner->state(), RunState::Paused);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{1200}));
    m_runner->setCoordinateSystems(systems, 0);
    QVERIFY(!m_runner->restNeedsCheck());
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), (QList<qint64>{1200, 400}));
}

// Issue 50 item 7: held at an M0 under cutter compensation, the tool's path was laid from the
// offsets and the moves after it; new offsets cannot be checked into it. Resume is refused and
// the board gets nothing more; with the offsets put back the run finishes.
void TestProgramRunnerMotion::cutterComp_offsetsChangedAtM0_resumeRefusedUntilPutBack()
{
    QSignalSpy refused(m_runner.get(), &ProgramRunner::resumeRefused);
    QVERIFY(run("G28 X0 Y0\nG0 X1 Y1\nG41.1 D0.5\nG0 X3 Y1\nM0\nG0 X3 Y3\n"
                "G40 G0 X1 Y3\nM30\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(m_runner->currentLine(), 5);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    const QList<qint64> before = acceptedSteps(*m_elab, Axis::Y);
    CoordinateSystems moved;
    moved[0] = {{QStringLiteral("X"), 0.5}};
    m_runner->setCoordinateSystems(moved, 0);
    m_runner->resume();
    QCOMPARE(refused.size(), 1);
    QVERIFY2(refused.first().at(0).toString().contains(QStringLiteral("cutter compensation")),
             qPrintable(refused.first().at(0).toString()));
    QCOMPARE(m_runner->state(), RunState::Paused);
    QVERIFY(still(*m_elab));
    QCOMPARE(acceptedSteps(*m_elab, Axis::Y), before);
    m_runner->setCoordinateSystems(CoordinateSystems{}, 0);
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
}

void TestProgramRunnerMotion::recreateWithZ(ToolLength toolLength)
{
    MachineDescription d = description();
    d.axes.insert(2, test::machineAxis("Z", "table", Axis::Z, AxisUnit::Millimetre, 400));
    d.toolLength = toolLength;
    recreateMachine(d);
}

// Issue 50 item 4: tool lengths by touch-off ("toolLength": "touchOff"), no tool table. The run
// holds at each M6 with the tool and its comment; Resume is refused until the work Z was set
// for it. At the first M6 the operator says the tool is the one Z was set for before the run
// (resumeSameTool); at T2 that is refused (another tool), so the operator jogs Z 1.5 mm up and
// zeroes Z there (G54's Z = machine 3.5 mm); G43 H2 adds nothing, and the rest cuts in the new
// zero. At the board (400 steps/mm): Z2 in the old zero (+800), the jog (+600), then Z1 in the
// new zero, machine 4.5 mm (+400; the old zero would have gone down 1000 steps).
void TestProgramRunnerMotion::touchOff_m6_holdsUntilZeroZRestCutsAtTheNewZ()
{
    recreateWithZ(ToolLength::TouchOff);
    QSignalSpy refused(m_runner.get(), &ProgramRunner::resumeRefused);
    QVERIFY(run("G28 X0 Y0 Z0\nT1 M6 (3 mm drill)\nG0 Z2\nT2 M6 (6 mm end mill)\nG43 H2\n"
                "G0 Z1\nM30\n"));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(m_runner->currentLine(), 2);
    QVERIFY(m_runner->awaitsTouchOff());
    m_runner->resume();
    QCOMPARE(refused.size(), 1);
    QCOMPARE(m_runner->state(), RunState::Paused);
    QVERIFY(m_runner->sameToolResumable()); // the run's first M6
    QVERIFY(m_runner->resumeSameTool());
    QTRY_VERIFY_WITH_TIMEOUT(m_runner->state() == RunState::Paused && m_runner->currentLine() == 4,
                             30000);
    QVERIFY2(m_runner->prompt().startsWith(QStringLiteral("Load tool 2 (6 mm end mill)")),
             qPrintable(m_runner->prompt()));
    QVERIFY(m_runner->pausedAtOperatorStop());
    QVERIFY(m_runner->awaitsTouchOff());
    QVERIFY(!m_runner->sameToolResumable()); // tool 1 was in
    m_runner->resume();
    QVERIFY(!m_runner->resumeSameTool());
    m_runner->step();
    QCOMPARE(refused.size(), 4);
    QVERIFY2(refused.at(1).at(0).toString().contains(QStringLiteral("tool 2")),
             qPrintable(refused.at(1).at(0).toString()));
    QCOMPARE(m_runner->state(), RunState::Paused);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QCOMPARE(acceptedSteps(*m_elab, Axis::Z), (QList<qint64>{800}));
    QString error;
    QSignalSpy moved(m_machine.get(), &Machine::moveFinished);
    QVERIFY2(m_machine->move({{QStringLiteral("Z"), 1.5}}, false, &error) != 0, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(!moved.isEmpty(), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    CoordinateSystems systems;
    systems[0] = {{QStringLiteral("X"), 0.5}}; // another axis' zero is no touch-off of Z
    m_runner->setCoordinateSystems(systems, 0);
    QVERIFY(m_runner->awaitsTouchOff());
    systems[0] = {{QStringLiteral("Z"), 3.5}}; // the DRO's Zero Z where Z stands
    m_runner->setCoordinateSystems(systems, 0);
    QVERIFY(!m_runner->awaitsTouchOff());
    QVERIFY(m_runner->restNeedsCheck());
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(refused.size(), 4);
    QCOMPARE(acceptedSteps(*m_elab, Axis::Z), (QList<qint64>{800, 600, 400}));
    QVERIFY2(m_runner->preview().toolNote.contains(QStringLiteral("touch-off")),
             qPrintable(m_runner->preview().toolNote));
}

// The same program on a machine that keeps a tool table (the default): G43 H2 with the table
// empty is refused before the run, as before issue 50; nothing reaches the board.
void TestProgramRunnerMotion::touchOff_tableMode_g43WithAnEmptyTableRefusedNothingSent()
{
    recreateWithZ(ToolLength::Table);
    QStringList axes;
    for (const MachineAxis& a : m_machine->description().axes)
        axes << a.name;
    QList<ProgramError> errors;
    const std::optional<Program> program = ProgramParser::parse(
        "G28 X0 Y0 Z0\nT1 M6 (3 mm drill)\nG0 Z2\nT2 M6 (6 mm end mill)\nG43 H2\nG0 Z1\nM30\n",
        axes, &errors);
    QVERIFY(program);
    QVERIFY(!m_runner->start(*program, 1, &errors));
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.first().text(),
             QStringLiteral("5:5: G43: the machine's tool table is empty: enter tool 2's length "
                            "first"));
    QCOMPARE(m_runner->state(), RunState::Idle);
    QCOMPARE(acceptedCount(*m_elab), 0);
    QVERIFY(still(*m_elab));
}

STEPDECK_TEST_MAIN(TestProgramRunnerMotion)
#include "tst_programrunnermotion.moc"
