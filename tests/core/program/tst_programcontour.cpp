// Programs whose feed moves run as one <DC2> stream on the E-LAB (issue 30, motion::StreamExecutor)
// on the runner's rig: the E-LAB table (X, Y 400 steps/mm) and a Nanotec rotary axis, each
// simulator on a real pseudo-terminal. The path is rebuilt from the step bytes the board executed
// and compared, tick by tick, with the ideal path worked out here (lines and a circle by their arc
// length at F); the blocks are reported as their ticks pass; a pause holds at a block's end with
// the board still exactly there; STOP and a lost link leave the board still with no step after the
// stop; STOP keeps every axis referenced, the host's count the board's (issue 47); a feed hold
// shows the axes standing at the board's position while it lasts (issue 47 item 8).
#include "ProgramRunnerTestSupport.h"
#include "TestMain.h"
#include "protocols/elab/ElabCodec.h"
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;
using namespace stepdeck::program::runnertest;

class TestProgramContour : public ProgramRunnerFixture
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup() { tearDownRig(); }
    void contour_lineCircleLine_oneStreamWithinHalfAStepAtFTheBoardRan();
    void contour_pause_holdsAtABlockEndBoardStillThereResumeFinishes();
    void contour_feedHold_stopsOnThePathResumeGoesOnNoTickLost();
    void contour_abort_boardStillNoStepAfterTheStop();
    void contour_otherControllersLinkLost_failsLinkDownBoardStops();
    void contour_stop_boardStillEveryAxisStaysReferenced();
    void feedHold_contour_axesShowStanding();
    void contour_camFeedAboveTheStreamsHighest_runsAtItBoardStepsEveryTick();

private:
    QPoint boardPosition() const;
    qsizetype executedSteps() const;
    QList<QPoint> executedPath() const; // after each executed step byte, from the first
    // The board received the stop, stands, and executes no vector over three status polls.
    void stoppedNoStepAfter();
    // The board's last frames ended the stream: an EndOfFeed after its last <DC2> pair.
    bool streamEndedAtBoard() const;
};

namespace {

constexpr double kContourStepsPerMm = 400;
constexpr double kTick = 1999; // below the raised start speed 2000 (raiseElabFeedLimits)

// A zigzag of `segments` moves of 0.5 mm in X and +-0.5 mm in Y at F240 (4 mm/s: 1 600
// steps/s on each axis, within the tick), each 0.177 s.
QByteArray zigzag(int segments)
{
    QByteArray p = "G21 G91 G64\n";
    for (int i = 0; i < segments; ++i)
        p += i % 2 == 0 ? "G1 X0.5 Y0.5 F240\n" : "G1 X0.5 Y-0.5\n";
    return p + "M30\n";
}

} // namespace

void TestProgramContour::init()
{
    setUpRig();
    QVERIFY(test::raiseElabFeedLimits(m_machine->session("table")));
}

QPoint TestProgramContour::boardPosition() const
{
    return m_elab->probe([&] {
        return QPoint(int(m_elab->sim()->position(Axis::X)), int(m_elab->sim()->position(Axis::Y)));
    });
}

qsizetype TestProgramContour::executedSteps() const
{
    return m_elab->probe([&] {
        return qsizetype(
            static_cast<elab::ElabSimulator*>(m_elab->sim())->executedStepRecord().size());
    });
}

bool TestProgramContour::streamEndedAtBoard() const
{
    const QList<QByteArray> frames = m_elab->frames();
    qsizetype lastPair = -1;
    for (qsizetype i = 0; i < frames.size(); ++i)
        lastPair = frames.at(i).startsWith(elab::ctrl::DC2) ? i : lastPair;
    return frames.lastIndexOf(elab::encode::endOfFeed()) > lastPair;
}

void TestProgramContour::stoppedNoStepAfter()
{
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    // The model's stop, or (a STOP during a contour, issue 47) the stream ended after its last
    // pair: the board ran out what it held, as after a feed hold.
    QVERIFY(m_elab->receivedStop() || streamEndedAtBoard());
    const qsizetype executed = executedSteps();
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(executedSteps(), executed);
}

QList<QPoint> TestProgramContour::executedPath() const
{
    const std::vector<quint8> record = m_elab->probe(
        [&] { return static_cast<elab::ElabSimulator*>(m_elab->sim())->executedStepRecord(); });
    QList<QPoint> out;
    QPoint at;
    for (const quint8 byte : record) {
        const elab::Triple<int> s = elab::decodeStepByte(byte);
        at += QPoint(s[0], s[1]);
        out << at;
    }
    return out;
}

// After a reference run and a G0: G1 X1, a clockwise full circle of radius 0.5 mm about +0.5
// X, G1 X-1 Y1, all at F240 (4 mm/s), then a G0 that ends the stream. The board executed one vector
// per tick: tick k stands at path distance 4k/1999 mm, and each is within half a step of that
// point; the number of ticks is the path's length over 4 mm/s (the path speed is F); the stream
// ended exactly at the last move's end, and the G0 started from there.
void TestProgramContour::contour_lineCircleLine_oneStreamWithinHalfAStepAtFTheBoardRan()
{
    QSignalSpy started(m_runner.get(), &ProgramRunner::blockStarted);
    QSignalSpy finished(m_runner.get(), &ProgramRunner::blockFinished);
    // Where the board stands when the contour's first block starts (the G0 arrived).
    QPoint start;
    connect(m_runner.get(), &ProgramRunner::blockStarted, this, [&](int line) {
        if (line == 4)
            start = boardPosition();
    });
    QVERIFY(run("G28 X0 Y0\n"
                "G0 X10 Y10\n"
                "G21 G91 G64\n"
                "G1 X1 F240\n"
                "G2 X0 Y0 I0.5\n"
                "G1 X-1 Y1\n"
                "G0 X0.5\n"
                "M30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    const double r = 0.5;
    const double lengths[3] = {1.0, 2 * M_PI * r, std::sqrt(2.0)};
    const auto ideal = [&](double s) -> std::pair<double, double> { // mm from the start
        if (s <= lengths[0])
            return {s, 0};
        s -= lengths[0];
        if (s <= lengths[1]) {
            const double angle = M_PI - s / r; // clockwise from the circle's left
            return {1 + r + r * std::cos(angle), r * std::sin(angle)};
        }
        s = std::min(s - lengths[1], lengths[2]);
        return {1 - s / std::sqrt(2.0), s / std::sqrt(2.0)};
    };
    const double total = lengths[0] + lengths[1] + lengths[2];
    const QList<QPoint> path = executedPath();
    const double feed = 4.0; // mm/s
    QCOMPARE(path.size(), qsizetype(std::ceil(total / feed * kTick - 1e-9)));
    double worst = 0;
    for (qsizetype k = 0; k < path.size(); ++k) {
        const auto [x, y] = ideal(std::min(double(k + 1) * feed / kTick, total));
        worst = std::max({worst, std::fabs(path.at(k).x() - x * kContourStepsPerMm),
                          std::fabs(path.at(k).y() - y * kContourStepsPerMm)});
    }
    QVERIFY2(worst <= 0.5 + 1e-6, qPrintable(QString::number(worst)));
    QCOMPARE(path.last(), QPoint(0, 400));               // X-1 Y1 after X1 and the circle
    QCOMPARE(boardPosition() - start, QPoint(200, 400)); // then the G0 X0.5
    QList<int> lines, ends;
    for (const QList<QVariant>& a : std::as_const(started))
        lines << a.at(0).toInt();
    for (const QList<QVariant>& a : std::as_const(finished))
        ends << a.at(0).toInt();
    QCOMPARE(lines, (QList<int>{1, 2, 4, 5, 6, 7, 8}));
    QCOMPARE(ends, (QList<int>{1, 2, 4, 5, 6, 7, 8}));
    QCOMPARE(m_runner->blocksDone(), qint64(7));
    QVERIFY(still(*m_elab));
}

// A pause asked while the zigzag runs: the stream ends at the end of a block within the moves
// appended ahead, the runner holds there, and the board stands exactly at that block's end;
// resume runs the rest from there to the zigzag's end.
void TestProgramContour::contour_pause_holdsAtABlockEndBoardStillThereResumeFinishes()
{
    const int segments = 20;
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    const QPoint start = boardPosition();
    QVERIFY(run(zigzag(segments)));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 4, 20000);
    m_runner->pause();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 20000);
    QCOMPARE(paused.size(), 1);
    const int line = paused.at(0).at(0).toInt();
    QVERIFY2(line >= 4 && line < segments + 1, qPrintable(QString::number(line)));
    // Block n (line n + 1) ends at X 200n, Y 200 after an odd number of blocks.
    const int blocks = line - 1;
    const QPoint end(200 * blocks, blocks % 2 == 1 ? 200 : 0);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QCOMPARE(boardPosition() - start, end);
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(boardPosition() - start, end); // held: nothing more ran
    m_runner->resume();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(boardPosition() - start, QPoint(200 * segments, 0));
    QVERIFY(still(*m_elab));
}

// Feed hold mid-zigzag: the board stops on the path (no more vectors executed, its position
// unchanged over several polls), the runner is Paused with feedHeld(); resume goes on from there,
// and the whole zigzag took exactly the ticks of an uninterrupted one (none lost or repeated),
// every tick within half a step of the zigzag, ending exactly at its end.
void TestProgramContour::contour_feedHold_stopsOnThePathResumeGoesOnNoTickLost()
{
    const int segments = 12;
    const QPoint start = boardPosition();
    QVERIFY(run(zigzag(segments)));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 4, 20000);
    QVERIFY(m_runner->holdFeed());
    QCOMPARE(m_runner->state(), RunState::Paused);
    QVERIFY(m_runner->feedHeld());
    // The board runs what it holds, then nothing more: its buffer empty, the stream open (in
    // feed mode, as the manual has it until EndOfFeed), its axes where the last tick put them.
    QTRY_COMPARE_WITH_TIMEOUT(m_elab->probe([&] {
        return static_cast<elab::ElabSimulator*>(m_elab->sim())->streamBuffered();
    }),
                              0, 10000);
    const qsizetype held = executedSteps();
    const QPoint stood = boardPosition();
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(executedSteps(), held);
    QCOMPARE(boardPosition(), stood);
    QVERIFY(boardPosition().x() - start.x() < 200 * segments); // mid-way
    m_runner->resume();
    QVERIFY(!m_runner->feedHeld());
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(boardPosition() - start, QPoint(200 * segments, 0));
    // Each segment is sqrt(0.5) mm at 4 mm/s.
    const double segment = std::sqrt(0.5);
    const QList<QPoint> path = executedPath();
    QCOMPARE(path.size(), qsizetype(std::ceil(segments * segment / 4.0 * kTick - 1e-9)));
    double worst = 0;
    for (qsizetype k = 0; k < path.size(); ++k) {
        const double s = std::min(double(k + 1) * 4.0 / kTick, segments * segment);
        const int n = std::min(int(s / segment), segments - 1);
        const double t = (s - n * segment) / segment; // 0..1 along segment n
        const double x = 0.5 * (n + t);
        const double y = n % 2 == 0 ? 0.5 * t : 0.5 * (1 - t);
        worst = std::max({worst, std::fabs(path.at(k).x() - x * kContourStepsPerMm),
                          std::fabs(path.at(k).y() - y * kContourStepsPerMm)});
    }
    QVERIFY2(worst <= 0.5 + 1e-6, qPrintable(QString::number(worst)));
}

// STOP (abort) mid-contour: the board received the stop, stands still, and no step byte is
// executed after it (the record stays as it is over further polls); the zigzag's end is never
// reached.
void TestProgramContour::contour_abort_boardStillNoStepAfterTheStop()
{
    const QPoint start = boardPosition();
    QVERIFY(run(zigzag(20)));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 4, 20000);
    m_runner->abort();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Aborted);
    stoppedNoStepAfter();
    if (QTest::currentTestFailed())
        return;
    QVERIFY(still(*m_elab));
    QVERIFY(boardPosition().x() - start.x() < 200 * 20);
}

// The rotary axis' link is lost mid-contour: the run fails LinkDown and the table is stopped
// (the safety contract: a controller lost stops the others), no step after.
void TestProgramContour::contour_otherControllersLinkLost_failsLinkDownBoardStops()
{
    QVERIFY(run(zigzag(20)));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 4, 20000);
    m_nanotec->vanish();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Failed);
    QCOMPARE(m_runner->failureKind(), ErrorKind::LinkDown);
    stoppedNoStepAfter();
    if (QTest::currentTestFailed())
        return;
}

// Issue 47 item 3: STOP (the runner's abort, as the window's STOP does) during a contour on
// referenced axes: the board stands after at most 0.25 s of ticks, no step after, and X and Y
// stay referenced with the host's count where the board stands (before issue 47 every axis of
// the board was unknown after it).
void TestProgramContour::contour_stop_boardStillEveryAxisStaysReferenced()
{
    QVERIFY(run("G28 X0 Y0\nM30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    ControllerSession* table = m_machine->session("table");
    const auto known = [table] {
        bool all = true;
        for (Axis a : {Axis::X, Axis::Y}) {
            const AxisStatus s = table->status().axes.value(a);
            all = all && s.referenced && s.positionKnown && !s.positionEstimated;
        }
        return all;
    };
    const auto host = [table] {
        return QPoint(int(table->status().axes.value(Axis::X).position),
                      int(table->status().axes.value(Axis::Y).position));
    };
    QTRY_VERIFY_WITH_TIMEOUT(known(), 10000);
    const QPoint hostOrigin = host();
    const QPoint boardOrigin = boardPosition();
    QVERIFY(run(zigzag(20)));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 4, 20000);
    const qsizetype atStop = executedSteps();
    m_runner->abort();
    WAIT_ENDED();
    VERIFY_STATE(RunState::Aborted);
    stoppedNoStepAfter();
    if (QTest::currentTestFailed())
        return;
    const qsizetype after = executedSteps() - atStop;
    QVERIFY2(after <= qsizetype(0.25 * kTick),
             qPrintable(QStringLiteral("%1 ticks after the STOP").arg(after)));
    QVERIFY(boardPosition().x() - boardOrigin.x() < 200 * 20); // short of the zigzag's end
    QTRY_VERIFY_WITH_TIMEOUT(known(), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(host() - hostOrigin, boardPosition() - boardOrigin, 10000);
    QVERIFY(known());
}

// Issue 47 item 8: a feed hold on referenced axes showed every axis "≈ ... MOVING" for as long
// as it lasted. Held, (ii) the controller reports every axis of the board not moving (the
// read-out's X and Y: not moving, referenced, not estimated) with the host's count where the
// board stands, and (i) the board stands: its buffer empty, no vector executed and its
// position unchanged over three status polls (its stream still open: feed mode until
// EndOfFeed). Resumed, the axes are reported moving again and the zigzag ends at its end.
void TestProgramContour::feedHold_contour_axesShowStanding()
{
    QVERIFY(run("G28 X0 Y0\nM30\n"));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    ControllerSession* table = m_machine->session("table");
    const QList<Axis> boardAxes = table->capabilities().axes; // X, Y, Z
    const auto host = [table] {
        return QPoint(int(table->status().axes.value(Axis::X).position),
                      int(table->status().axes.value(Axis::Y).position));
    };
    const auto anyReportedMoving = [table, boardAxes] {
        bool any = false;
        for (Axis a : boardAxes)
            any = any || table->status().axes.value(a).moving;
        return any;
    };
    QTRY_VERIFY_WITH_TIMEOUT(table->status().axes.value(Axis::X).referenced, 10000);
    const QPoint hostOrigin = host();
    const QPoint boardOrigin = boardPosition();
    const int segments = 12;
    QVERIFY(run(zigzag(segments)));
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->currentLine(), 4, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(anyReportedMoving(), 10000); // the stream runs
    QVERIFY(m_runner->holdFeed());
    QVERIFY(m_runner->feedHeld());
    // (ii) first: the host says so once the board has run every tick sent.
    QTRY_VERIFY_WITH_TIMEOUT(!anyReportedMoving(), 10000);
    // (i) at the board.
    const auto buffered = [this] {
        return m_elab->probe([&] {
            auto* sim = static_cast<elab::ElabSimulator*>(m_elab->sim());
            sim->position(Axis::X); // brings the board up to now
            return sim->streamBuffered();
        });
    };
    QTRY_COMPARE_WITH_TIMEOUT(buffered(), 0, 10000);
    const qsizetype held = executedSteps();
    const QPoint stood = boardPosition();
    QSignalSpy polls(table, &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 3, 10000);
    QCOMPARE(executedSteps(), held);
    QCOMPARE(boardPosition(), stood);
    QVERIFY(stood.x() - boardOrigin.x() < 200 * segments); // mid-way
    QVERIFY(m_runner->feedHeld());
    // (ii) over those polls: standing, where the board stands, as known as before the run.
    QVERIFY(!anyReportedMoving());
    QCOMPARE(host() - hostOrigin, stood - boardOrigin);
    for (const QString& name : {QStringLiteral("X"), QStringLiteral("Y")}) {
        const machine::MachineAxis* axis = m_machine->description().axis(name);
        QVERIFY(axis);
        const machine::MachineAxisStatus shown = m_machine->axisStatus(*axis);
        QVERIFY2(!shown.moving, qPrintable(name));
        QCOMPARE(shown.known, machine::PositionKnowledge::Referenced);
    }
    // Resumed: moving again, to the zigzag's end.
    bool movingAgain = false;
    QObject watcher;
    connect(table, &ControllerSession::statusChanged, &watcher,
            [&movingAgain](const MachineStatus& s) {
                movingAgain = movingAgain || s.axes.value(Axis::X).moving;
            });
    m_runner->resume();
    QVERIFY(!m_runner->feedHeld());
    QTRY_VERIFY_WITH_TIMEOUT(movingAgain, 10000);
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    QCOMPARE(boardPosition() - boardOrigin, QPoint(200 * segments, 0));
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(host() - hostOrigin, boardPosition() - boardOrigin, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(!anyReportedMoving(), 10000);
}

// Issue 50: a program as a Fusion 360 post writes it, F6000 (100 mm/s) for a generic machine.
// This table's stream ticks at 1999/s (start speed 2000, raiseElabFeedLimits), one step a tick at
// most: along the 2:1 diagonal X (400 steps/mm) allows F335.242, along X alone F299.85. The check
// names the F that runs in a note and refuses nothing; the run streams each move at its highest
// feed, so the board steps X on every tick it executes: as many ticks as X steps (two moves of
// 2 mm, 1600), at the feed speed 1999 the tick was written as. At F6000 the stream could not
// carry the moves; at any lower feed they would take more ticks.
void TestProgramContour::contour_camFeedAboveTheStreamsHighest_runsAtItBoardStepsEveryTick()
{
    QVERIFY(run("(1001)\n"
                "(T1 D=3.175 CR=0. - ZMIN=-1. - flat end mill)\n"
                "G90 G94 G17\n"
                "G21\n"
                "G28 X0 Y0\n"
                "G0 X10. Y10.\n"
                "(2D Contour1)\n"
                "G1 X12. Y11. F6000.\n"
                "X10.\n"
                "G0 X12.\n"
                "M30\n"));
    const QList<ProgramError> notes = m_runner->checkNotes();
    QCOMPARE(notes.size(), 1);
    QCOMPARE(notes.first().line, 8);
    const QString& note = notes.first().message;
    QVERIFY2(note.startsWith("F6000 runs at F335.242,") && note.contains("1999 ticks/s") &&
                 note.endsWith("(also on 1 more line(s))"),
             qPrintable(note));
    WAIT_ENDED();
    VERIFY_STATE(RunState::Finished);
    const std::vector<quint8> record = m_elab->probe(
        [&] { return static_cast<elab::ElabSimulator*>(m_elab->sim())->executedStepRecord(); });
    qint64 xSteps = 0;
    for (const quint8 byte : record)
        xSteps += std::abs(elab::decodeStepByte(byte)[0]);
    QCOMPARE(xSteps, qint64(1600));
    QVERIFY2(record.size() >= 1600 && record.size() <= 1602,
             qPrintable(QString::number(record.size())));
    QCOMPARE(executedPath().last(), QPoint(0, 400)); // X+2 Y+1, then X-2
    const int written = m_elab->probe([&] {
        return int(
            static_cast<elab::ElabSimulator*>(m_elab->sim())->rampParameters(Axis::X).feedSpeed);
    });
    QCOMPARE(written, int(kTick));
    QVERIFY(still(*m_elab));
}

STEPDECK_TEST_MAIN(TestProgramContour)
#include "tst_programcontour.moc"
