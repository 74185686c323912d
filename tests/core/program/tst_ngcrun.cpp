// Programs in LinuxCNC's language (issue 33), our own in tests/core/program/ngc/, run end to end
// on an E-LAB table and on an EMIS SMC-IC4 (X, Y, Z in mm, 100 steps/mm, G54 at machine X5 Y5
// Z-20), each its simulator on a real pseudo-terminal. As the window runs them: checked over the
// file (worked out, parsed, checked), then the checked program given to the runner. Asserted at
// the device, against moves worked out in the test (NgcProgramsTestSupport.h): the EMIS's
// journal of vector moves, one point per move, is every target of the program in order; the
// E-LAB's trace (every stream vector, every move's rest) passes every target in order within a
// step and never leaves the program's box. The runner names the source lines: its blocks' lines
// are the loops' and subroutine's bodies, its messages the (DEBUG, …)/(PRINT, …) lines with their
// values. A copy beyond the soft limits, worked out and parsed as the CLI does, is refused by
// the runner's check at the source line, and the device saw no move.
#include "MachineTestSupport.h"
#include "NgcProgramsTestSupport.h"
#include "PathTestSupport.h"
#include "PtyDevice.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "program/ProgramCheck.h"
#include "program/ProgramReader.h"
#include "program/ProgramRunner.h"
#include "program/language/ProgramExpansion.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/emis/EmisSimulator.h"
#include <QSet>
#include <QSignalSpy>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;
using namespace stepdeck::program::ngctest;

namespace {

using Device = test::PtyDevice;
constexpr double kNgcStepsPerMm = 100;
constexpr double kStep = 1 / kNgcStepsPerMm + 1e-9;
const Point kG54{5, 5, -20}; // machine position of the work zero

using test::near;
using test::pointText;

// The first of `points` that `path` does not pass within `tolerance`, in order (empty: all).
QString firstPointNotPassed(const QList<Point>& path, const QList<Point>& points, double tolerance)
{
    const qsizetype i = test::firstNotPassed(path, points, tolerance);
    return i < 0 ? QString()
                 : QStringLiteral("target %1 %2 not passed").arg(i).arg(pointText(points.at(i)));
}

// The targets a program's moves reach from `start` (work coordinates), a move that goes
// nowhere left out: the device journals no move there.
QList<Point> targets(const QList<Move>& moves, const Point& start)
{
    QList<Point> out;
    Point last = start;
    for (const Point& p : positionsAfter(moves, start)) {
        if (!near(p, last, 1e-9))
            out << p;
        last = p;
    }
    return out;
}

} // namespace

class TestNgcRun : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void cleanup();
    void run_ngcProgram_deviceSawEveryTargetInOrder_data();
    void run_ngcProgram_deviceSawEveryTargetInOrder();
    void run_branchOnM66_emisTakesThePathOfItsInput();
    void run_ngcProgramBeyondTheLimits_refusedBeforeAnythingMoved_data();
    void run_ngcProgramBeyondTheLimits_refusedBeforeAnythingMoved();

private:
    bool setUp(const QString& model);
    bool prepare();
    Point boardWork(); // where the board stands, work coordinates
    qsizetype journalSize();
    // What the device took for motion: E-LAB its positioning moves and stream bytes, EMIS the
    // vector moves (L1, 9.11) it received, accepted or not.
    QList<qint64> motionReceived();
    // EMIS: one point per vector move it accepted from entry `from` on, the board at `start`.
    QList<Point> deviceTargets(qsizetype from, const Point& start);
    QList<Point> boardTrace(qsizetype from); // E-LAB: its trace, work coordinates
    void comparePath(const QList<Point>& expected, qsizetype from, const Point& start);

    std::unique_ptr<Device> m_device;
    std::unique_ptr<Machine> m_machine;
    std::unique_ptr<ProgramRunner> m_runner;
    bool m_elab = false;
    qint64 m_origin[3] = {0, 0, 0}; // the simulator's count at the reference
};

// Soft limits (machine) X and Y 0..60 mm, Z -30..0 mm.
bool TestNgcRun::setUp(const QString& model)
{
    m_elab = model == QLatin1String("elab");
    m_device = std::make_unique<Device>(model);
    MachineDescription d;
    d.name = QStringLiteral("ngc table");
    d.controllers = {{"table", model, m_device->path(), {}, {}, {}, {}, {}}};
    for (const auto& [name, axis, low, high] : {std::tuple{"X", Axis::X, 0.0, 60.0},
                                                {"Y", Axis::Y, 0.0, 60.0},
                                                {"Z", Axis::Z, -30.0, 0.0}}) {
        MachineAxis a =
            test::machineAxis(name, "table", axis, AxisUnit::Millimetre, kNgcStepsPerMm);
        a.softMinimum = low;
        a.softMaximum = high;
        d.axes << a;
    }
    m_machine = std::make_unique<Machine>();
    QString error;
    if (!m_machine->create(d, &error)) {
        qWarning() << error;
        return false;
    }
    m_machine->open();
    if (!QTest::qWaitFor([&] { return m_machine->state() == MachineState::Idle; }, 10000) ||
        !prepare())
        return false;
    m_runner = std::make_unique<ProgramRunner>(m_machine.get());
    CoordinateSystems systems;
    systems[0] = {{"X", kG54.x}, {"Y", kG54.y}, {"Z", kG54.z}};
    m_runner->setCoordinateSystems(systems, 0);
    return true;
}

void TestNgcRun::cleanup()
{
    m_runner.reset();
    m_machine.reset();
    m_device.reset();
}

// The setup and reference run (test::prepareTableForPrograms), then the board's count at the
// reference.
bool TestNgcRun::prepare()
{
    if (!test::prepareTableForPrograms(m_machine.get(), QStringLiteral("table")))
        return false;
    return m_device->probe([&] {
        for (int i = 0; i < 3; ++i)
            m_origin[i] = m_device->sim()->position(Axis::at(i));
        return true;
    });
}

Point TestNgcRun::boardWork()
{
    return m_device->probe([&] {
        Simulator* sim = m_device->sim();
        return Point{double(sim->position(Axis::X) - m_origin[0]) / kNgcStepsPerMm - kG54.x,
                     double(sim->position(Axis::Y) - m_origin[1]) / kNgcStepsPerMm - kG54.y,
                     double(sim->position(Axis::Z) - m_origin[2]) / kNgcStepsPerMm - kG54.z};
    });
}

// E-LAB: the trace's length (rests and stream vectors); EMIS: the vector moves' entries.
qsizetype TestNgcRun::journalSize()
{
    return m_device->probe([&] {
        if (m_elab)
            return qsizetype(
                static_cast<elab::ElabSimulator*>(m_device->sim())->positionTrace().size());
        return qsizetype(m_device->sim()->acceptedMoves().size());
    });
}

QList<qint64> TestNgcRun::motionReceived()
{
    return m_device->probe([&] {
        if (m_elab) {
            auto* sim = static_cast<elab::ElabSimulator*>(m_device->sim());
            return QList<qint64>{sim->acceptedMoves().size(), sim->executedStepBytes()};
        }
        const QList<QByteArray> commands =
            static_cast<emis::EmisSimulator*>(m_device->sim())->receivedCommands();
        return QList<qint64>{
            qint64(std::count_if(commands.cbegin(), commands.cend(),
                                 [](const QByteArray& c) { return c.startsWith("L1,"); }))};
    });
}

// The entries of one vector move share the time it was accepted: each group is one target.
QList<Point> TestNgcRun::deviceTargets(qsizetype from, const Point& start)
{
    const QList<emis::EmisSimulator::AcceptedMove> moves = m_device->probe([&] {
        return static_cast<emis::EmisSimulator*>(m_device->sim())->acceptedMovesWithSpeed();
    });
    qint64 steps[3] = {std::llround((start.x + kG54.x) * kNgcStepsPerMm),
                       std::llround((start.y + kG54.y) * kNgcStepsPerMm),
                       std::llround((start.z + kG54.z) * kNgcStepsPerMm)};
    QList<Point> out;
    for (qsizetype i = from; i < moves.size(); ++i) {
        const int axis = moves.at(i).axis.index(); // X, Y, Z: 0, 1, 2
        if (axis < 3)
            steps[axis] += moves.at(i).steps;
        if (i + 1 == moves.size() || moves.at(i + 1).acceptedUs != moves.at(i).acceptedUs)
            out << Point{double(steps[0]) / kNgcStepsPerMm - kG54.x,
                         double(steps[1]) / kNgcStepsPerMm - kG54.y,
                         double(steps[2]) / kNgcStepsPerMm - kG54.z};
    }
    return out;
}

QList<Point> TestNgcRun::boardTrace(qsizetype from)
{
    return m_device->probe([&] {
        QList<Point> out;
        const auto& trace = static_cast<elab::ElabSimulator*>(m_device->sim())->positionTrace();
        for (size_t i = size_t(from); i < trace.size(); ++i)
            out << Point{double(trace[i][0] - m_origin[0]) / kNgcStepsPerMm - kG54.x,
                         double(trace[i][1] - m_origin[1]) / kNgcStepsPerMm - kG54.y,
                         double(trace[i][2] - m_origin[2]) / kNgcStepsPerMm - kG54.z};
        return out;
    });
}

// EMIS: its journal is the targets, one to one, each within a step. E-LAB: its path passes
// each target in order within a step, stays within the targets' box and ends at the last.
void TestNgcRun::comparePath(const QList<Point>& expected, qsizetype from, const Point& start)
{
    if (!m_elab) {
        const QList<Point> device = deviceTargets(from, start);
        QCOMPARE(device.size(), expected.size());
        for (int i = 0; i < device.size(); ++i)
            QVERIFY2(near(device.at(i), expected.at(i), kStep),
                     qPrintable(QStringLiteral("move %1: device %2, computed %3")
                                    .arg(i)
                                    .arg(pointText(device.at(i)), pointText(expected.at(i)))));
        return;
    }
    const QList<Point> trace = boardTrace(from);
    const QString missed = firstPointNotPassed(trace, expected, kStep);
    QVERIFY2(missed.isEmpty(), qPrintable(missed));
    QVERIFY(!trace.isEmpty());
    QVERIFY2(near(trace.last(), expected.last(), kStep), qPrintable(pointText(trace.last())));
    Point low = expected.first(), high = expected.first();
    for (const Point& p : expected) {
        low = Point{std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = Point{std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    for (const Point& p : trace)
        QVERIFY2(p.x >= low.x - kStep && p.x <= high.x + kStep && p.y >= low.y - kStep &&
                     p.y <= high.y + kStep && p.z >= low.z - kStep && p.z <= high.z + kStep,
                 qPrintable(QStringLiteral("the board strayed to %1").arg(pointText(p))));
}

void TestNgcRun::run_ngcProgram_deviceSawEveryTargetInOrder_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("file");
    for (const char* model : {"elab", "emis"})
        for (const char* file : {"bolt-circle.ngc", "pocket-sub.ngc", "engrave-params.ngc"})
            QTest::newRow(QByteArray(model).append(' ').append(file).constData())
                << QString::fromLatin1(model) << QString::fromLatin1(file);
}

void TestNgcRun::run_ngcProgram_deviceSawEveryTargetInOrder()
{
    QFETCH(QString, model);
    QFETCH(QString, file);
    QVERIFY(setUp(model));
    const Expected expected = expectedOf(file, sourceLines(ngcText(file)));
    QVERIFY(linesFound(expected));
    const ProgramCheckResult checked = ProgramCheck::check(ProgramSource::file(ngcPath(file)),
                                                           {"X", "Y", "Z"}, m_runner->startFacts());
    QVERIFY2(checked.ok(), qPrintable(checked.errors.value(0).text()));
    QList<Message> messages;
    connect(m_runner.get(), &ProgramRunner::operatorMessage, this, [&](int line, const QString& t) {
        messages << Message{line, t};
    });
    QList<int> started;
    connect(m_runner.get(), &ProgramRunner::blockStarted, this,
            [&](int line, const QString&) { started << line; });
    const Point start = boardWork();
    QVERIFY2(near(start, Point{-kG54.x, -kG54.y, -kG54.z}, 1e-9), qPrintable(pointText(start)));
    const qsizetype from = journalSize();
    QList<ProgramError> errors;
    QVERIFY2(m_runner->start(*checked.program, 1, &errors), qPrintable(errors.value(0).text()));
    QTRY_VERIFY_WITH_TIMEOUT(isEnded(m_runner->state()), 120000);
    QVERIFY2(m_runner->state() == RunState::Finished, qPrintable(m_runner->endMessage()));
    comparePath(targets(expected.moves, start), from, start);
    if (QTest::currentTestFailed())
        return;
    // The runner's blocks are the source's: every move started at the line it was written on.
    QSet<int> moveLines;
    QList<int> moveOrder;
    for (const Move& m : expected.moves) {
        moveLines.insert(m.line);
        moveOrder << m.line;
    }
    started.removeIf([&](int line) { return !moveLines.contains(line); });
    QCOMPARE(started, moveOrder);
    QCOMPARE(messages, expected.messages);
}

// A branch on what M66 read (#5399), on the EMIS with its input 5 high: the check followed the
// path past the M66 (StepDeck's M66 stops the run when Q runs out), and the device went there
// and nowhere else.
void TestNgcRun::run_branchOnM66_emisTakesThePathOfItsInput()
{
    QVERIFY(setUp(QStringLiteral("emis")));
    m_device->probe([&] {
        static_cast<emis::EmisSimulator*>(m_device->sim())->setInput(5, true);
        return true;
    });
    const QByteArray program = "G21 G90 G54\nM66 P5 L3 Q5\no1 if [#5399 EQ 1]\n  G0 X12 Y7\n"
                               "o1 else\n  G0 X40 Y40\no1 endif\nM2\n";
    const ProgramCheckResult checked =
        ProgramCheck::check(ProgramSource::bytes(program), {"X", "Y", "Z"}, m_runner->startFacts());
    QVERIFY2(checked.ok(), qPrintable(checked.errors.value(0).text()));
    const Point start = boardWork();
    const qsizetype from = journalSize();
    QList<ProgramError> errors;
    QVERIFY2(m_runner->start(*checked.program, 1, &errors), qPrintable(errors.value(0).text()));
    QTRY_VERIFY_WITH_TIMEOUT(isEnded(m_runner->state()), 60000);
    QVERIFY2(m_runner->state() == RunState::Finished, qPrintable(m_runner->endMessage()));
    comparePath({Point{12, 7, start.z}}, from, start);
}

void TestNgcRun::run_ngcProgramBeyondTheLimits_refusedBeforeAnythingMoved_data()
{
    QTest::addColumn<QString>("model");
    for (const char* model : {"elab", "emis"})
        QTest::newRow(model) << QString::fromLatin1(model);
}

// The bolt circle with a radius of 40: its first hole (15°) at work X 68.637, machine 73.637,
// beyond X 60. Worked out and parsed as `stepdeck-cli run` does, the runner's own check refuses
// it at the loop's line; the device gets no move while the machine goes on polling it.
void TestNgcRun::run_ngcProgramBeyondTheLimits_refusedBeforeAnythingMoved()
{
    QFETCH(QString, model);
    QVERIFY(setUp(model));
    QString source = QString::fromUtf8(ngcText("bolt-circle.ngc"));
    QCOMPARE(source.count("#<radius> = 12\n"), 1);
    source.replace("#<radius> = 12\n", "#<radius> = 40\n");
    const int over = lineOf(sourceLines(source.toUtf8()), "G0 X#<x> Y#<y>");
    QVERIFY(over > 0);
    const MachineFacts facts = m_runner->startFacts();
    NgcContext context;
    context.coordinateSystems = facts.coordinateSystems;
    QList<ProgramError> errors;
    const std::optional<ProgramExpansion::Result> expanded =
        ProgramExpansion::expand(ProgramSource::bytes(source.toUtf8()), context, &errors);
    QVERIFY2(expanded, qPrintable(errors.value(0).text()));
    ProgramReader reader(expanded->source, {"X", "Y", "Z"}, expanded->info->lines);
    std::optional<Program> program = reader.finish(&errors);
    QVERIFY2(program, qPrintable(errors.value(0).text()));
    program->expansion = expanded->info;
    const qsizetype journal = journalSize();
    const QList<qint64> motion = motionReceived();
    const Point before = boardWork();
    QSignalSpy state(m_runner.get(), &ProgramRunner::stateChanged);
    QVERIFY(!m_runner->start(*program, 1, &errors));
    QVERIFY(!errors.isEmpty());
    QCOMPARE(errors.first().text(),
             QStringLiteral("%1:6: X reaches 68.637 mm in work coordinates, 73.637 mm in machine "
                            "coordinates: outside the soft limits 0..60 mm (machine)")
                 .arg(over));
    QCOMPARE(m_runner->state(), RunState::Idle);
    QSignalSpy polled(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polled.size() >= 3, 10000);
    QCOMPARE(journalSize(), journal);
    QCOMPARE(motionReceived(), motion);
    QCOMPARE(pointText(boardWork()), pointText(before));
    QVERIFY(m_device->still());
    QCOMPARE(state.size(), 0);
}

STEPDECK_TEST_MAIN(TestNgcRun)
#include "tst_ngcrun.moc"
