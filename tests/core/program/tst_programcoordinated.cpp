// G1 and G2 over two axes on controllers that coordinate (issue 30, CoordinatedFeed), run end
// to end on an EMIS SMC-IC4 and on a Nanotec bus of two drives, each simulator on a real
// pseudo-terminal. Asserted at the device: the EMIS got interpolation on (IP1, 9.12) before the
// program's first such move and its old value back at the end, every move of both axes ran at
// speeds whose path speed is F (within 2 %, the steps/s being whole) and its axes' <DCn> went
// out on the same tick; the Nanotec drives ran at top speeds 'o' in proportion to their
// distances, started by consecutive 'A's; both boards end where the program ends. On the EMIS
// also: a feed hold ends at a chord's end and resumes, a feed override scales the shares, an
// abort lets the running chord end and sends no chord after it. On the Nanotec: STOP and
// PANIC mid-arc leave both drives standing with no start after; on both, a link pulled mid-arc
// fails the run LinkDown.
#include "MachineTestSupport.h"
#include "PtyDevice.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "program/ArcPath.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include "protocols/emis/EmisSimulator.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include <QSignalSpy>
#include <QtTest>
#include <cmath>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;

namespace {
constexpr double kCoordinatedStepsPerMm = 100;
} // namespace

class TestProgramCoordinated : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void cleanup();
    void emis_lineAndArc_interpolatedAtFArriveTogether();
    void nanotec_line_drivesAtTheirSharesStartedTogether();
    void nanotec_cutterComp_drivesFollowTheToolsPath();
    void emis_feedHoldInAnArc_holdsAtAChordEndResumeFinishes();
    void emis_feedOverride_movesAtItsShareOfF();
    void emis_abortMidArc_runningChordEndsNoChordAfter();
    void nanotec_stopOrPanicMidArc_drivesStillNoStartAfter_data();
    void nanotec_stopOrPanicMidArc_drivesStillNoStartAfter();
    void linkLostMidArc_runFailsLinkDownNoChordAfter_data();
    void linkLostMidArc_runFailsLinkDownNoChordAfter();

private:
    bool setUp(const QString& model);
    bool run(const QByteArray& text);
    // A full circle of radius 5 around (5, 0) at F300 (6.3 s), started and under way (the
    // board left its start by a millimetre); empty if not.
    std::optional<Program> startCircle();
    QPointF boardMm(); // X, Y in mm from the reference
    // Frames the simulator received that start with prefix.
    qsizetype countFrames(const QByteArray& prefix);

    std::unique_ptr<test::PtyDevice> m_device;
    std::unique_ptr<Machine> m_machine;
    std::unique_ptr<ProgramRunner> m_runner;
    qint64 m_origin[2] = {0, 0};
};

void TestProgramCoordinated::cleanup()
{
    m_runner.reset();
    m_machine.reset();
    m_device.reset();
}

// X and Y in mm at 100 steps/mm, referenced. The EMIS gets its work speed written (the fast
// speed G0 runs at) and interpolation off, so that the run must turn it on.
bool TestProgramCoordinated::setUp(const QString& model)
{
    const bool emis = model == QLatin1String("emis");
    // The Nanotec adapter greets the model's default drives 1, 2, 3 (X, Y, Z).
    m_device = std::make_unique<test::PtyDevice>(model, emis ? QList<int>{1} : QList<int>{1, 2, 3});
    MachineDescription d;
    d.name = QStringLiteral("coordinated");
    d.controllers = {{"table", model, m_device->path(), {}, {}, {}, {}, {}}};
    d.axes = {
        test::machineAxis("X", "table", Axis::X, AxisUnit::Millimetre, kCoordinatedStepsPerMm),
        test::machineAxis("Y", "table", Axis::Y, AxisUnit::Millimetre, kCoordinatedStepsPerMm)};
    m_machine = std::make_unique<Machine>();
    QString error;
    if (!m_machine->create(d, &error))
        return false;
    m_machine->open();
    if (!QTest::qWaitFor([&] { return m_machine->state() == MachineState::Idle; }, 10000))
        return false;
    ControllerSession* table = m_machine->session("table");
    if (emis) {
        ParameterValue work;
        for (Axis a : {Axis::X, Axis::Y})
            work.perAxis.insert(a, 4000);
        if (!test::writeParametersAndWait(
                table, {{QStringLiteral("work-speed"), work},
                        {QStringLiteral("interpolation"), ParameterValue{QVariant(false), {}}}}))
            return false;
    }
    QSignalSpy referenced(m_machine.get(), &Machine::referenceFinished);
    if (m_machine->reference({}, &error) == 0 || !referenced.wait(60000) ||
        !referenced.first().at(1).toBool())
        return false;
    m_runner = std::make_unique<ProgramRunner>(m_machine.get());
    return m_device->probe([&] {
        m_device->sim()->clearReceivedFrames();
        if (auto* sim = qobject_cast<emis::EmisSimulator*>(m_device->sim()))
            sim->clearReceivedCommands();
        m_origin[0] = m_device->sim()->position(Axis::X);
        m_origin[1] = m_device->sim()->position(Axis::Y);
        return true;
    });
}

bool TestProgramCoordinated::run(const QByteArray& text)
{
    QList<ProgramError> errors;
    const std::optional<Program> program = ProgramParser::parse(text, {"X", "Y"}, &errors);
    if (!program || !m_runner->start(*program, 1, &errors)) {
        qWarning() << (errors.isEmpty() ? QString() : errors.first().text());
        return false;
    }
    if (!QTest::qWaitFor([&] { return isEnded(m_runner->state()); }, 60000) ||
        m_runner->state() != RunState::Finished) {
        qWarning() << m_runner->endMessage();
        return false;
    }
    return QTest::qWaitFor(
        [&] { return m_device->probe([&] { return m_device->sim()->standingStill(); }); }, 5000);
}

std::optional<Program> TestProgramCoordinated::startCircle()
{
    QList<ProgramError> errors;
    std::optional<Program> program =
        ProgramParser::parse("G21 G90 G2 X0 Y0 I5 J0 F300\nM2\n", {"X", "Y"}, &errors);
    if (!program || !m_runner->start(*program, 1, &errors) ||
        !QTest::qWaitFor([&] { return boardMm().manhattanLength() > 1; }, 10000))
        return std::nullopt;
    return program;
}

qsizetype TestProgramCoordinated::countFrames(const QByteArray& prefix)
{
    return m_device->probe([&] {
        const QList<QByteArray> frames = m_device->sim()->receivedFrames();
        return qsizetype(std::count_if(frames.cbegin(), frames.cend(),
                                       [&](const QByteArray& f) { return f.startsWith(prefix); }));
    });
}

QPointF TestProgramCoordinated::boardMm()
{
    return m_device->probe([&] {
        return QPointF(
            double(m_device->sim()->position(Axis::X) - m_origin[0]) / kCoordinatedStepsPerMm,
            double(m_device->sim()->position(Axis::Y) - m_origin[1]) / kCoordinatedStepsPerMm);
    });
}

// A 3-4-5 line and a half circle of radius 5 at F600 (10 mm/s: 1 000 steps/s along the path).
void TestProgramCoordinated::emis_lineAndArc_interpolatedAtFArriveTogether()
{
    QVERIFY(setUp("emis"));
    QVERIFY(run("G21 G90 G1 X3 Y4 F600\nG2 X13 Y4 I5 J0\nM2\n"));
    QCOMPARE(boardMm(), QPointF(13, 4));
    using Accepted = emis::EmisSimulator::AcceptedMove;
    const auto [commands, moves, interpolation] = m_device->probe([&] {
        auto* sim = static_cast<emis::EmisSimulator*>(m_device->sim());
        return std::make_tuple(sim->receivedCommands(), sim->acceptedMovesWithSpeed(),
                               sim->working().interpolation);
    });
    // IP1 before the first vector move of the program, IP0 (what the setup wrote) at its end.
    const qsizetype on = commands.indexOf("IP1");
    QVERIFY2(on >= 0, commands.join(' ').constData());
    const auto firstMove = std::find_if(commands.cbegin(), commands.cend(),
                                        [](const QByteArray& c) { return c.startsWith("L1,"); });
    QVERIFY(firstMove != commands.cend());
    QVERIFY(on < firstMove - commands.cbegin());
    qsizetype lastMove = -1;
    for (qsizetype i = 0; i < commands.size(); ++i)
        if (commands.at(i).startsWith("L1,"))
            lastMove = i;
    QVERIFY2(commands.lastIndexOf("IP0") > lastMove, commands.join(' ').constData());
    QVERIFY(!interpolation);
    // Every move of both axes: the path speed of the speeds the board ran, and one tick.
    int pairs = 0;
    for (qsizetype i = 0; i + 1 < moves.size(); ++i) {
        const Accepted& a = moves.at(i);
        const Accepted& b = moves.at(i + 1);
        if (a.acceptedUs != b.acceptedUs || a.axis == b.axis)
            continue;
        ++pairs;
        // Along the whole steps the board runs: F within 2 % (the rates are whole steps/s).
        const double speed =
            std::hypot(a.runSpeed, b.runSpeed) / kCoordinatedStepsPerMm * 60; // mm/min
        QVERIFY2(std::abs(speed - 600) <= 12,
                 qPrintable(QStringLiteral("%1 mm/min over %2, %3 steps")
                                .arg(speed)
                                .arg(a.steps)
                                .arg(b.steps)));
        QCOMPARE(a.arrivedUs, b.arrivedUs);
        ++i;
    }
    // The line and most of the arc's chords move both axes.
    QVERIFY2(pairs > 10, qPrintable(QString::number(pairs)));
}

// A 3-4-5 line at F600: X's drive at 3/5 of 1 000 steps/s, Y's at 4/5.
void TestProgramCoordinated::nanotec_line_drivesAtTheirSharesStartedTogether()
{
    QVERIFY(setUp("nanotec"));
    QVERIFY(run("G21 G90 G1 X3 Y4 F600\nM2\n"));
    QCOMPARE(boardMm(), QPointF(3, 4));
    const auto [started, frames] = m_device->probe([&] {
        auto* sim = static_cast<nanotec::NanotecSimulator*>(m_device->sim());
        return std::make_pair(sim->startedMoves(), sim->receivedFrames());
    });
    QVERIFY(started.size() >= 2);
    const auto x = started.at(started.size() - 2);
    const auto y = started.at(started.size() - 1);
    QCOMPARE(QSet<int>({x.address, y.address}), QSet<int>({1, 2}));
    const auto& onX = x.address == 1 ? x : y;
    const auto& onY = x.address == 1 ? y : x;
    QCOMPARE(onX.maxFrequency, qint64(600));
    QCOMPARE(onY.maxFrequency, qint64(800));
    // The two 'A's one right after the other: nothing between them on the bus.
    const qsizetype a1 = frames.indexOf("#1A\r");
    const qsizetype a2 = frames.indexOf("#2A\r");
    QVERIFY2(a1 >= 0 && a2 >= 0, frames.join(' ').constData());
    QCOMPARE(std::abs(a2 - a1), qsizetype(1));
}

// Issue 50 item 7 on the Nanotec family: G41.1 D2 round (10,10) (10,20) (20,20), entered from
// (0,10), worked out by hand: the entry touches the circle of 1 about (10,10) at (9.9, 10.995)
// and is cut back to the line X9 at Y10.9045 (inside corner); up X9 to Y20; round (10,20)
// clockwise to (10,21) (outside corner, as chords); along Y21 to X20; G40 leaves to (25,20).
// Each drive's position when each move ended, in order, within a step.
void TestProgramCoordinated::nanotec_cutterComp_drivesFollowTheToolsPath()
{
    QVERIFY(setUp("nanotec"));
    QList<QPointF> arrived;
    connect(m_machine.get(), &Machine::moveFinished, this, [&](quint64, bool ok) {
        if (ok)
            arrived << boardMm();
    });
    QVERIFY(run("G21 G90 G0 X0 Y10\nG41.1 D2\nG1 X10 Y10 F600\nG1 X10 Y20\nG1 X20 Y20\n"
                "G40 G1 X25 Y20\nM2\n"));
    const QList<QPointF> spots{{0, 10}, {9, 10.90}, {9, 20}, {10, 21}, {20, 21}, {25, 20}};
    qsizetype next = 0;
    for (const QPointF& a : std::as_const(arrived))
        if (next < spots.size() && std::abs(a.x() - spots.at(next).x()) <= 0.011 &&
            std::abs(a.y() - spots.at(next).y()) <= 0.011)
            ++next;
    QStringList path;
    for (const QPointF& a : std::as_const(arrived))
        path << QStringLiteral("(%1, %2)").arg(a.x()).arg(a.y());
    QVERIFY2(next == spots.size(), qPrintable(path.join(' ')));
    QCOMPARE(boardMm(), QPointF(25, 20));
}

// Feed hold on the EMIS (issue 30): the running chord ends, the board stands at its end (a
// point of the arc, within a step, the chords' tolerance added), no move is sent until resume,
// and resume goes on to the arc's end.
void TestProgramCoordinated::emis_feedHoldInAnArc_holdsAtAChordEndResumeFinishes()
{
    QVERIFY(setUp("emis"));
    const std::optional<Program> program = startCircle();
    QVERIFY(program);
    QVERIFY(m_runner->holdFeed());
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_device->probe([&] { return m_device->sim()->standingStill(); }),
                             5000);
    // At the end of one of the arc's chords, as ArcPath plans them from (0, 0), to the step.
    const QPointF held = boardMm();
    const auto planned = ArcPath::plan(program->allBlocks().first(), m_machine->description(),
                                       AxisPositions{0.0, 0.0}, {});
    const ArcPath* arc = std::get_if<ArcPath>(&planned);
    QVERIFY(arc);
    bool atChordEnd = false;
    for (qint64 k = 1; k < arc->chords() && !atChordEnd; ++k) {
        double end[2] = {};
        for (const auto& [axis, value] : arc->pointAt(k))
            end[axis] = value;
        atChordEnd = qRound64(end[0] * kCoordinatedStepsPerMm) ==
                         qRound64(held.x() * kCoordinatedStepsPerMm) &&
                     qRound64(end[1] * kCoordinatedStepsPerMm) ==
                         qRound64(held.y() * kCoordinatedStepsPerMm);
    }
    QVERIFY2(atChordEnd, qPrintable(QStringLiteral("%1, %2").arg(held.x()).arg(held.y())));
    const qsizetype accepted =
        m_device->probe([&] { return qsizetype(m_device->sim()->acceptedMoves().size()); });
    m_runner->resume();
    // The next chord starts where the board held (its move was accepted after the resume).
    QTRY_VERIFY_WITH_TIMEOUT(m_device->probe([&] {
        return qsizetype(m_device->sim()->acceptedMoves().size());
    }) > accepted,
                             5000);
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Finished, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(m_device->probe([&] { return m_device->sim()->standingStill(); }),
                             5000);
    QCOMPARE(boardMm(), QPointF(0, 0));
}

// Feed override 50 % (issue 30): the line's axes and a move of one axis run at half their
// shares of F at the device.
void TestProgramCoordinated::emis_feedOverride_movesAtItsShareOfF()
{
    QVERIFY(setUp("emis"));
    m_runner->setFeedOverride(50);
    QVERIFY(run("G21 G90 G1 X3 Y4 F600\nG1 X6\nM2\n"));
    QCOMPARE(boardMm(), QPointF(6, 4));
    const auto moves = m_device->probe([&] {
        return static_cast<emis::EmisSimulator*>(m_device->sim())->acceptedMovesWithSpeed();
    });
    QCOMPARE(moves.size(), qsizetype(3)); // X and Y of the line, then X alone
    // F600 is 1 000 steps/s along the path; at 50 % 500 steps/s.
    QCOMPARE(moves.at(0).runSpeed, 300.0); // 3/5 of it
    QCOMPARE(moves.at(1).runSpeed, 400.0); // 4/5
    QCOMPARE(moves.at(2).runSpeed, 500.0); // X alone
}

// Abort (the window's STOP; the SMC-IC4 has no stop command, chapter 9) in the middle of a
// chain of chords (issue 30): the running chord ends by itself, the run ends aborted with the
// board standing, and no vector move reaches the board afterwards, over three of the input
// polls that go on.
void TestProgramCoordinated::emis_abortMidArc_runningChordEndsNoChordAfter()
{
    QVERIFY(setUp("emis"));
    const std::optional<Program> program = startCircle();
    QVERIFY(program);
    m_runner->abort();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Aborted, 10000);
    QVERIFY(m_device->probe([&] { return m_device->sim()->standingStill(); }));
    const qsizetype moves = countFrames("L1,");
    const qsizetype polls = countFrames("@IG");
    QTRY_VERIFY_WITH_TIMEOUT(countFrames("@IG") >= polls + 3, 10000);
    QCOMPARE(countFrames("L1,"), moves);
    // It stopped on the circle, at a chord's end, short of the end.
    const QPointF at = boardMm();
    QVERIFY2(std::abs(std::hypot(at.x() - 5, at.y()) - 5) <= 0.015 && at != QPointF(0, 0),
             qPrintable(QStringLiteral("%1, %2").arg(at.x()).arg(at.y())));
}

void TestProgramCoordinated::nanotec_stopOrPanicMidArc_drivesStillNoStartAfter_data()
{
    QTest::addColumn<bool>("panic");
    QTest::newRow("STOP") << false;
    QTest::newRow("PANIC") << true;
}

// STOP or PANIC in the middle of a chain of chords on the Nanotec (issue 30), as the window
// sends them (the machine's stop first, then the run aborted): both drives get 'S' (6.2, the
// panic '#*S'), stand still, and no drive is started ('A') after it over three status sweeps.
void TestProgramCoordinated::nanotec_stopOrPanicMidArc_drivesStillNoStartAfter()
{
    QFETCH(bool, panic);
    QVERIFY(setUp("nanotec"));
    QVERIFY(startCircle());
    if (panic)
        m_machine->panic();
    else
        m_machine->stop();
    m_runner->abort();
    QTRY_VERIFY_WITH_TIMEOUT(isEnded(m_runner->state()), 10000);
    QVERIFY(m_device->receivedStop());
    if (panic)
        QVERIFY(countFrames("#*S") >= 1);
    QTRY_VERIFY_WITH_TIMEOUT(m_device->probe([&] { return m_device->sim()->standingStill(); }),
                             2000);
    const qsizetype starts = countFrames("#1A") + countFrames("#2A");
    const qsizetype sweeps = countFrames("#1$");
    QTRY_VERIFY_WITH_TIMEOUT(countFrames("#1$") >= sweeps + 3, 10000);
    QCOMPARE(countFrames("#1A") + countFrames("#2A"), starts);
    QVERIFY(m_device->probe([&] { return m_device->sim()->standingStill(); }));
    // Stopped on its way round, not at the end.
    QVERIFY(boardMm() != QPointF(0, 0));
}

void TestProgramCoordinated::linkLostMidArc_runFailsLinkDownNoChordAfter_data()
{
    QTest::addColumn<QString>("model");
    QTest::newRow("emis") << QStringLiteral("emis");
    QTest::newRow("nanotec") << QStringLiteral("nanotec");
}

// The controller's USB adapter is pulled in the middle of a chain of chords (issue 30): the run
// fails LinkDown instead of waiting, and no chord reaches the device after it: the device runs
// out the chord it had (nothing can reach it to stop it) and stands.
void TestProgramCoordinated::linkLostMidArc_runFailsLinkDownNoChordAfter()
{
    QFETCH(QString, model);
    QVERIFY(setUp(model));
    QVERIFY(startCircle());
    m_device->vanish();
    QTRY_VERIFY_WITH_TIMEOUT(isEnded(m_runner->state()), 20000);
    QCOMPARE(m_runner->state(), RunState::Failed);
    QCOMPARE(m_runner->failureKind(), ErrorKind::LinkDown);
    const qsizetype moves =
        m_device->probe([&] { return qsizetype(m_device->sim()->acceptedMoves().size()); });
    QTRY_VERIFY_WITH_TIMEOUT(m_device->probe([&] { return m_device->sim()->standingStill(); }),
                             5000);
    QCOMPARE(m_device->probe([&] { return qsizetype(m_device->sim()->acceptedMoves().size()); }),
             moves);
    QVERIFY(boardMm() != QPointF(0, 0));
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramCoordinated)
#include "tst_programcoordinated.moc"
