// The Program page while a program runs (issues 20 and 30) on a machine of two simulated
// controllers (ProgramPageFixture): Pause holds after the block that runs, Resume goes on; Hold
// and F2 hold a contour on its path; Abort, STOP and PANIC end the program as aborted with the
// axis standing at the device; M0's prompt shows in the banner; M1's switch reaches the runner;
// a lost link fails naming the line; closing the machine aborts.
#include "../LayoutChecks.h"
#include "ProgramPageFixture.h"
#include "TestMain.h"
#include "machine/MachineDro.h"
#include "machine/SpindleCoolantBar.h"
#include "position/PositionPanel.h"
#include "program/ProgramFiles.h"
#include "window/JobLayout.h"
#include <QScrollBar>

using namespace stepdeck;
using namespace stepdeck::test;
using program::RunState;

class TestProgramPageRun : public ProgramPageFixture
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }
    void pause_duringBlock_holdsAfterItThenResumeFinishes();
    void abort_duringMove_abortedAndAxisStandsStill();
    void stop_duringMove_programEndsAborted_data();
    void stop_duringMove_programEndsAborted();
    void m0_prompt_bannerWithResumeGoesOn();
    void m1_optionalStopsToggle_reachesTheRunner();
    void hold_f2AndHoldButton_contourStopsOnItsPathResumeFinishes();
    void fault_linkLostDuringMove_failedNamingTheLine();
    void stop_duringReferencedProgram_positionsStayKnownAtTheBoard_data();
    void stop_duringReferencedProgram_positionsStayKnownAtTheBoard();
    void closeMachine_whileRunning_programAbortedAndAxisStill_data();
    void closeMachine_whileRunning_programAbortedAndAxisStill();
    void openAnother_afterRun_oldResultCleared();
    void spindleBar_switchesAtTheBoardLockedWhileRunningOffAfterStop();
    void touchOff_zeroXAtM6_restCutsInTheNewZeroAtTheBoard();
    void timeLeft_override50_feedTimeDoublesAtOnce();
    void finished_repeatAndModalLines_countsAsThePreview();
};

void TestProgramPageRun::pause_duringBlock_holdsAfterItThenResumeFinishes()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 X2\nG0 X2\nG0 X2\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    QVERIFY(page()->editor()->isReadOnly());
    // The block running when Pause is pressed (line 2 unless the machine was quicker).
    const int line = page()->editor()->runningLine();
    QVERIFY(line >= 2 && line <= 4);
    page()->controls()->pauseButton()->click();
    // Said while the block runs out.
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Pausing: line %1").arg(line)),
             qPrintable(page()->messageText()));
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Paused), 20000);
    // That block was finished at the device (2 mm at 400 steps/mm each), and nothing more
    // was started.
    QVERIFY(m_rig.elab->still());
    QCOMPARE(m_rig.elab->position(Axis::X), 800 * (line - 1));
    QCOMPARE(runner()->currentLine(), line);
    QVERIFY(!page()->promptBanner()->isShowingPrompt()); // not an M0
    QVERIFY2(page()->controls()->progressText().contains(QStringLiteral("of 5")),
             qPrintable(page()->controls()->progressText()));
    page()->controls()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QCOMPARE(m_rig.elab->position(Axis::X), 2400);
}

void TestProgramPageRun::abort_duringMove_abortedAndAxisStandsStill()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 X100\nG0 X100\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    page()->controls()->abortButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Aborted), 20000);
    QVERIFY(m_rig.elab->receivedStop());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
    QVERIFY(m_rig.elab->position(Axis::X) < 40000);
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Aborted")),
             qPrintable(page()->messageText()));
    QVERIFY(!page()->editor()->isReadOnly());
}

void TestProgramPageRun::stop_duringMove_programEndsAborted_data()
{
    QTest::addColumn<QString>("how");
    QTest::addRow("STOP button") << QStringLiteral("stop");
    QTest::addRow("Esc in the editor") << QStringLiteral("esc");
    QTest::addRow("PANIC button") << QStringLiteral("panic");
}

void TestProgramPageRun::stop_duringMove_programEndsAborted()
{
    QFETCH(QString, how);
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 X100\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    stopBy(how);
    QTRY_VERIFY2_WITH_TIMEOUT(runState(RunState::Aborted), qPrintable(page()->messageText()),
                              20000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
    QVERIFY(m_rig.elab->position(Axis::X) < 40000);
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Aborted")),
             qPrintable(page()->messageText()));
}

// Issue 28, item 4: STOP and Esc during a program brake the E-LAB with its ramp (ForceStopMove
// "ohne Schrittverluste"; RequestRelPosition gives the steps not run): X and Y stay referenced
// at the board's count. Only PANIC makes them unknown (the safety contract).
void TestProgramPageRun::stop_duringReferencedProgram_positionsStayKnownAtTheBoard_data()
{
    QTest::addColumn<QString>("how");
    QTest::addColumn<bool>("known");
    QTest::newRow("STOP button") << "stop" << true;
    QTest::newRow("Esc in the editor") << "esc" << true;
    QTest::newRow("PANIC button") << "panic" << false;
}

void TestProgramPageRun::stop_duringReferencedProgram_positionsStayKnownAtTheBoard()
{
    QFETCH(QString, how);
    QFETCH(bool, known);
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable());
    const qint64 xHome = m_rig.elab->position(Axis::X); // the board counts from power-on
    const qint64 yHome = m_rig.elab->position(Axis::Y);
    setProgram(QStringLiteral("G90\nG0 X100 Y50\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    stopBy(how);
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Aborted), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
    machine::Machine* m = m_rig.machine();
    const machine::MachineAxis& x = *m->description().axis(QStringLiteral("X"));
    const machine::MachineAxis& y = *m->description().axis(QStringLiteral("Y"));
    if (!known) {
        QTRY_VERIFY(m->axisStatus(x).known == machine::PositionKnowledge::Unknown);
        return;
    }
    QTRY_COMPARE_WITH_TIMEOUT(m->axisStatus(x).steps, m_rig.elab->position(Axis::X) - xHome, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(m->axisStatus(y).steps, m_rig.elab->position(Axis::Y) - yHome, 10000);
    QCOMPARE(m->axisStatus(x).known, machine::PositionKnowledge::Referenced);
    QCOMPARE(m->axisStatus(y).known, machine::PositionKnowledge::Referenced);
}

void TestProgramPageRun::m0_prompt_bannerWithResumeGoesOn()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("M0 (Clamp it)\nG91\nG0 X0.25\n"
                              "M0 (Load the part; a long prompt that does not fit on one line of "
                              "the banner however wide the window is, since it goes on and on "
                              "and on and on and on and on and on and on and on and on)\n"
                              "G0 X0.25\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    // The window settled first: the Run workspace fits the program's dock to its page on a
    // queued call after the program opened (before that, the page scrolls by a few pixels).
    const QAbstractScrollArea* scroll = enclosingScrollArea(page());
    QVERIFY(scroll);
    QTRY_VERIFY(!scroll->verticalScrollBar()->isVisible());
    const int bannerHeight = page()->promptBanner()->height();
    page()->controls()->runButton()->click();
    // M0 on the first line: the program's first block runs too (it was skipped once).
    QTRY_VERIFY2_WITH_TIMEOUT(page()->promptBanner()->isShowingPrompt(),
                              qPrintable(page()->messageText()), 10000);
    QVERIFY2(page()->promptBanner()->text().contains(QStringLiteral("Clamp it")),
             qPrintable(page()->promptBanner()->text()));
    QCOMPARE(page()->promptBanner()->height(), bannerHeight); // room reserved
    // Nothing the operator may reach for moves when a prompt appears, however long it is. (The
    // job's start gave the Program dock the jog pad's room, issue 47 item 15: compared from the
    // first prompt on.)
    auto place = [this](QWidget* w) { return QRect(w->mapTo(window(), QPoint()), w->size()); };
    QTRY_VERIFY(page()->editor()->isReadOnly());
    // The job's layout sizes the Program dock on a queued call (JobLayout::give), its layout
    // requests follow as posted events: the places are taken after them. (A sanitized build
    // reached the first prompt before the queued call ran, and the dock grew after it.)
    QTRY_VERIFY(window()->jobLayout()->isJobLayout());
    for (int i = 0; i < 4; ++i) {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
    }
    const QRect abort = place(page()->controls()->abortButton());
    const QRect editor = place(page()->editor());
    QCOMPARE(m_rig.elab->position(Axis::X), 0);
    page()->promptBanner()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(
        page()->promptBanner()->isShowingPrompt() &&
            page()->promptBanner()->text().contains(QStringLiteral("Load the part")),
        10000);
    QCOMPARE(page()->promptBanner()->height(), bannerHeight);
    QCOMPARE(place(page()->controls()->abortButton()), abort);
    QCOMPARE(place(page()->editor()), editor);
    QCOMPARE(m_rig.elab->position(Axis::X), 100);
    page()->promptBanner()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QCOMPARE(m_rig.elab->position(Axis::X), 200);
    QVERIFY(!page()->promptBanner()->isShowingPrompt());
}

// Issue 29: the window's "Optional stops (M1)" switch reaches the runner: off, the program
// runs past M1 without a prompt; on (also switched while nothing runs), M1 holds with its
// comment in the banner and the board gets the next move only after Resume.
// Issue 30: the feed override box reaches the runner; F2 (from the editor: a window-wide key)
// and the Hold button hold a contour on its path (the board's X stands still over several
// polls, short of the end); Resume goes on and the contour ends exactly at its end.
void TestProgramPageRun::hold_f2AndHoldButton_contourStopsOnItsPathResumeFinishes()
{
    QVERIFY(m_rig.openAndConnect());
    QSpinBox* override = page()->controls()->feedOverrideBox();
    override->setValue(50);
    QCOMPARE(runner()->feedOverride(), 50.0);
    override->setValue(100);
    QCOMPARE(runner()->feedOverride(), 100.0);
    // Eight moves of 0.05 mm (20 steps) at 0.2 mm/s (80 steps/s, below the stream's 99 ticks/s).
    QString program = QStringLiteral("G91 G64\n");
    for (int i = 0; i < 8; ++i)
        program += QStringLiteral("G1 X0.05 F12\n");
    setProgram(program + QStringLiteral("M2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    const auto holdsStill = [&] {
        QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Paused), 10000);
        QVERIFY(runner()->feedHeld());
        QVERIFY(!page()->controls()->holdButton()->isEnabled());
        // The board runs what it holds, then stands: its buffer empty, X the same twice.
        qint64 stood = -1;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                const qint64 now = m_rig.elab->position(Axis::X);
                const int buffered = m_rig.elab->probe([&] {
                    return static_cast<elab::ElabSimulator*>(m_rig.elab->sim())->streamBuffered();
                });
                return std::exchange(stood, now) == now && buffered == 0;
            }(),
            5000);
        QSignalSpy polls(m_rig.machine()->session(QStringLiteral("table")),
                         &ControllerSession::statusChanged);
        QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 3, 10000);
        QCOMPARE(m_rig.elab->position(Axis::X), stood);
        QVERIFY(stood < 160);
    };
    QTRY_VERIFY_WITH_TIMEOUT(runner()->currentLine() >= 3, 20000);
    QTest::keyClick(page()->editor(), Qt::Key_F2);
    holdsStill();
    page()->controls()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runner()->currentLine() >= 6, 20000);
    QTRY_VERIFY(page()->controls()->holdButton()->isEnabled());
    page()->controls()->holdButton()->click();
    holdsStill();
    page()->controls()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QCOMPARE(m_rig.elab->position(Axis::X), 160);
}

void TestProgramPageRun::m1_optionalStopsToggle_reachesTheRunner()
{
    QVERIFY(m_rig.openAndConnect());
    QCheckBox* optionalStops = page()->controls()->optionalStopsBox();
    QVERIFY(optionalStops->isChecked()); // the default
    QVERIFY(runner()->optionalStops());
    optionalStops->click();
    QVERIFY(!runner()->optionalStops());
    setProgram(QStringLiteral("G91\nM1 (Look at the clamps)\nG0 X0.25\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QCOMPARE(m_rig.elab->position(Axis::X), 100);
    QVERIFY(!page()->promptBanner()->isShowingPrompt());

    optionalStops->click();
    QVERIFY(runner()->optionalStops());
    // Run comes back once the finished run's state reached the page (a disabled button takes
    // no click: under the sanitizers this took longer than the click).
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY2_WITH_TIMEOUT(page()->promptBanner()->isShowingPrompt(),
                              qPrintable(page()->messageText()), 10000);
    QVERIFY2(page()->promptBanner()->text().contains(QStringLiteral("Look at the clamps")),
             qPrintable(page()->promptBanner()->text()));
    QCOMPARE(m_rig.elab->position(Axis::X), 100); // the second pass holds before its move
    page()->promptBanner()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QCOMPARE(m_rig.elab->position(Axis::X), 200);
}

void TestProgramPageRun::fault_linkLostDuringMove_failedNamingTheLine()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 A3600\nG0 X1\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.nanotec->moving(Axis::X), 10000);
    m_rig.nanotec->vanish(); // the rotary's USB adapter pulled
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Failed), 20000);
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Failed: line 2")),
             qPrintable(page()->messageText()));
    QVERIFY(!page()->editor()->isReadOnly());
    QCOMPARE(page()->editor()->runningLine(), 0);
    QVERIFY(m_rig.elab->still()); // line 3 never started
    QCOMPARE(m_rig.elab->position(Axis::X), 0);
}

void TestProgramPageRun::closeMachine_whileRunning_programAbortedAndAxisStill_data()
{
    QTest::addColumn<bool>("throughWindow");
    QTest::addRow("window") << true;
    QTest::addRow("context (another machine opened)") << false;
}

void TestProgramPageRun::closeMachine_whileRunning_programAbortedAndAxisStill()
{
    QFETCH(bool, throughWindow);
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 X100\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    if (throughWindow)
        window()->closeMachine();
    else
        window()->context()->closeMachine();
    // The runner of the closed machine is gone; the connection bar's machine has its own.
    QVERIFY(window()->context()->isConnectionMachine());
    QVERIFY(!page()->isRunning());
    QVERIFY(!page()->editor()->isReadOnly());
    // Either way the machine's close aborts the run that holds its motion (issue 49 item 4:
    // Machine::abortRequested; the window keeps no list of what moves).
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Aborted")),
             qPrintable(page()->messageText()));
    QVERIFY(m_rig.elab->receivedStop());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
}

// Issue 31 finding: how the last program's run ended ("Finished: ...", "line n of m") is not
// said of another program opened after it, which has not run.
void TestProgramPageRun::openAnother_afterRun_oldResultCleared()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 X0.5\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Finished")),
             qPrintable(page()->messageText()));
    QVERIFY2(page()->controls()->progressText().startsWith(QStringLiteral("line ")),
             qPrintable(page()->controls()->progressText()));
    QVERIFY(!page()->controls()->timeLeftText().isEmpty());

    const QString other =
        m_rig.writeFile(QByteArrayLiteral("G91\nG0 Y0.25\nG0 Y0.25\nM2\n"), "other.ngc");
    QVERIFY(page()->files()->load(other));
    QTRY_VERIFY(!page()->isChecking());
    QVERIFY2(page()->messageText().isEmpty(), qPrintable(page()->messageText()));
    QCOMPARE(page()->controls()->progressText(), QStringLiteral("not running"));
    QVERIFY2(page()->controls()->timeLeftText().isEmpty(),
             qPrintable(page()->controls()->timeLeftText()));
    QVERIFY(page()->controls()->runButton()->isEnabled()); // the new one is checked, not run
}

// Issue 47: the Run workspace's spindle and coolant switches reach the board's relays and
// show the board's state; a running program owns them; STOP switches both off at the board.
void TestProgramPageRun::spindleBar_switchesAtTheBoardLockedWhileRunningOffAfterStop()
{
    QVERIFY(m_rig.openAndConnect());
    ui::SpindleCoolantBar* bar = window()->positionPanel()->spindleCoolant();
    const auto board = [this] {
        return m_rig.elab->probe([&] {
            const auto* sim = static_cast<elab::ElabSimulator*>(m_rig.elab->sim());
            return std::make_pair(sim->spindleRpm(), sim->coolant());
        });
    };
    QTRY_VERIFY(bar->spindleButton()->isEnabled());
    QCOMPARE(bar->coolantText(), QStringLiteral("Coolant: unknown")); // not read back
    bar->spindleButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(board().first > 0, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(bar->spindleText(), QStringLiteral("Spindle: on"), 10000);
    bar->coolantButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(board().second, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(bar->coolantText(), QStringLiteral("Coolant: on"), 10000);

    setProgram(QStringLiteral("G91\nG0 X100\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    QVERIFY(!bar->spindleButton()->isEnabled());
    QVERIFY(!bar->coolantButton()->isEnabled());
    stopBy(QStringLiteral("stop"));
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Aborted), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(board() == std::make_pair(quint32(0), false), 20000);
    QVERIFY(m_rig.elab->still());
    QTRY_COMPARE_WITH_TIMEOUT(bar->spindleText(), QStringLiteral("Spindle: off"), 10000);
    QCOMPARE(bar->coolantText(), QStringLiteral("Coolant: off"));
    QTRY_VERIFY(bar->spindleButton()->isEnabled());
}

// Issue 47, item 11: held after its first block, the run's time left is the G1's; the feed
// override box doubles it at 50 % at once, not at the next block's end (the page's runner gets
// the override too).
void TestProgramPageRun::timeLeft_override50_feedTimeDoublesAtOnce()
{
    QVERIFY(m_rig.openAndConnect());
    QSpinBox* override = page()->controls()->feedOverrideBox();
    override->setValue(100);
    // The G1: 1 mm at 0.2 mm/s (80 steps/s), about 5 s of feed.
    setProgram(QStringLiteral("G91\nG0 X0.25\nG1 X1 F12\nM2\n"));
    QTRY_VERIFY(page()->controls()->stepButton()->isEnabled());
    page()->controls()->stepButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Paused), 20000);
    QCOMPARE(runner()->currentLine(), 2);
    // What is left in the run's estimate: the G1 (feed) and nothing else.
    const program::ProgramPreview& v = runner()->preview();
    const program::PreviewPoint* g0 = nullptr;
    for (const program::PreviewPoint& point : v.path)
        if (point.line == 2)
            g0 = &point;
    QVERIFY(g0);
    const double feedLeft = v.path.last().feedSeconds - g0->feedSeconds;
    const double otherLeft = (v.estimatedSeconds - g0->seconds) - feedLeft;
    QVERIFY2(feedLeft > 4 && feedLeft < 6, qPrintable(QString::number(feedLeft)));
    QVERIFY2(qAbs(otherLeft) < 1e-9, qPrintable(QString::number(otherLeft)));
    QCOMPARE(page()->controls()->timeLeftText(), ui::ProgramTimes::estimatedLeft(feedLeft));
    override->setValue(50);
    QCOMPARE(runner()->feedOverride(), 50.0);
    QCOMPARE(page()->controls()->timeLeftText(), ui::ProgramTimes::estimatedLeft(2 * feedLeft));
    override->setValue(80); // about 6.25 s: away from a rounding edge
    QCOMPARE(page()->controls()->timeLeftText(), ui::ProgramTimes::estimatedLeft(feedLeft / 0.8));
    override->setValue(100);
    QCOMPARE(page()->controls()->timeLeftText(), ui::ProgramTimes::estimatedLeft(feedLeft));
    page()->controls()->abortButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Aborted), 20000);
}

// Issue 47, item 11: "Finished: n block(s) run" names the count the preview names, for a
// program with a repeat and lines of modal words only (ProgramPreview::blocksRun: G91, F600,
// three passes of G91 and G0, M2). The runner passes the modal-only lines by without running
// them: it counts the 3 G0 and M2 it executed.
void TestProgramPageRun::finished_repeatAndModalLines_countsAsThePreview()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nF600\nO1 repeat [3]\nG91\nG0 X0.25\nO1 endrepeat\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    const QString figures = page()->preview()->figuresText();
    QVERIFY2(figures.contains(ui::ProgramPreviewView::tr("%n block(s) run", nullptr, 9)),
             qPrintable(figures));
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QCOMPARE(m_rig.elab->position(Axis::X), 300); // 3 x 0.25 mm at 400 steps/mm
    QCOMPARE(runner()->preview().blocksRun, qint64(9));
    QCOMPARE(page()->messageText(), ui::ProgramPage::tr("Finished: %n block(s) run.", nullptr, 9));
    QCOMPARE(runner()->blocksDone(), qint64(4));
    QCOMPARE(page()->controls()->timeLeftText(), ui::ProgramTimes::estimatedLeft(0));
}

// Issue 47 item 2, through the window: the run holds at M6, the operator moves X by 0.5 mm and
// presses Zero X on the read-out; Resume checks the rest with the new zero and the rest runs in
// it. At the board (400 steps/mm): X2 in the new zero is 2 mm on from where X was zeroed, not
// the 0.5 mm the old zero would have left.
void TestProgramPageRun::touchOff_zeroXAtM6_restCutsInTheNewZeroAtTheBoard()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable());
    setProgram(QStringLiteral("G90 G0 X1\nT2 M6\nG0 X2\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Paused) && runner()->pausedAtOperatorStop(), 20000);
    // The banner names the hold as what it is: a tool change, not an M0.
    QVERIFY2(page()->promptBanner()->text().startsWith(QStringLiteral("Line 2: Load tool 2")),
             qPrintable(page()->promptBanner()->text()));
    QString refusal;
    QSignalSpy moved(m_rig.machine(), &machine::Machine::moveFinished);
    QVERIFY2(m_rig.machine()->move({{QStringLiteral("X"), 0.5}}, false, &refusal) != 0,
             qPrintable(refusal));
    QTRY_VERIFY_WITH_TIMEOUT(!moved.isEmpty(), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
    QTRY_VERIFY(m_rig.machine()->axisStatus(*m_rig.machine()->description().axis("X")).known ==
                machine::PositionKnowledge::Referenced);
    const qint64 zeroedAt = m_rig.elab->position(Axis::X);
    QVERIFY(window()->positionPanel()->machineDro()->zeroAxis(QStringLiteral("X")));
    QTRY_VERIFY2(page()->messageText().contains(QStringLiteral("Resume checks the rest")),
                 qPrintable(page()->messageText()));
    page()->controls()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
    QCOMPARE(m_rig.elab->position(Axis::X) - zeroedAt, qint64(800));
}

STEPDECK_TEST_MAIN_WITH(TestProgramPageRun, runOnLaptopScreen<TestProgramPageRun>)
#include "tst_programpagerun.moc"
