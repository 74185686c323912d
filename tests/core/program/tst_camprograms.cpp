// Programs in the styles CAM posts write (issue 29), run end to end on an E-LAB table and on an
// EMIS SMC-IC4 (X, Y, Z in mm, 100 steps/mm), each its simulator on a pseudo-terminal: their
// headers, tool changes with a tool table, work offsets, G43, G53, arcs of I J and R, drilling
// cycles. The programs are our own, in tests/core/program/cam/. Where the EMIS went is read at
// its simulator each time a move arrived and compared one to one with the path the check
// planned (within a step); the E-LAB runs a contour's feed moves as one <DC2> stream (issue 30),
// so its own trace (every executed vector, every move's rest) must pass within a step of every
// planned point, in order. Both also reach points worked out by hand.
#include "MachineTestSupport.h"
#include "PathTestSupport.h"
#include "PtyDevice.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include "protocols/elab/ElabSimulator.h"
#include <QFile>
#include <QSet>
#include <QSignalSpy>
#include <QtTest>
#include <cmath>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;

namespace {

using Device = test::PtyDevice;
constexpr double kCamStepsPerMm = 100;

struct Point3
{
    double x = 0, y = 0, z = 0;
};

using test::near;
using test::pointText;

// The first of `points` that `path` does not pass within `tolerance`, in order (empty: all).
QString firstNotPassed(const QList<Point3>& path, const QList<Point3>& points, double tolerance)
{
    const qsizetype i = test::firstNotPassed(path, points, tolerance);
    return i < 0 ? QString()
                 : QStringLiteral("planned point %1 %2 not passed")
                       .arg(i)
                       .arg(pointText(points.at(i)));
}

} // namespace

class TestCamPrograms : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void cleanup();
    void run_camStyles_boardFollowsThePlannedPath_data();
    void run_camStyles_boardFollowsThePlannedPath();
    void pause_duringPeckCycle_holdsBetweenMovesResumeFinishesIt();

private:
    Point3 boardMm(); // where the board stands, machine mm from the reference
    qsizetype traceSize();
    QList<Point3> boardTrace(qsizetype from); // the E-LAB's path, machine mm from the reference
    bool setUp(const QString& model);
    bool prepare();

    std::unique_ptr<Device> m_elab; // the board, of either model
    std::unique_ptr<Machine> m_machine;
    std::unique_ptr<ProgramRunner> m_runner;
    qint64 m_origin[3] = {0, 0, 0}; // the simulator's count at the reference
};

bool TestCamPrograms::setUp(const QString& model)
{
    m_elab = std::make_unique<Device>(model);
    MachineDescription d;
    d.name = QStringLiteral("CAM table");
    d.controllers = {{"table", model, m_elab->path(), {}, {}, {}, {}, {}}};
    if (model == QLatin1String("elab"))
        d.spindle.maxRpm = 24000; // CAM programs' S in rpm (the SMC-IC4 has no spindle)
    d.axes = {test::machineAxis("X", "table", Axis::X, AxisUnit::Millimetre, kCamStepsPerMm),
              test::machineAxis("Y", "table", Axis::Y, AxisUnit::Millimetre, kCamStepsPerMm),
              test::machineAxis("Z", "table", Axis::Z, AxisUnit::Millimetre, kCamStepsPerMm)};
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
    return true;
}

void TestCamPrograms::cleanup()
{
    m_runner.reset();
    m_machine.reset();
    m_elab.reset();
}

// The setup and reference run (test::prepareTableForPrograms), then the board's count at the
// reference.
bool TestCamPrograms::prepare()
{
    if (!test::prepareTableForPrograms(m_machine.get(), QStringLiteral("table")))
        return false;
    return m_elab->probe([&] {
        for (int i = 0; i < 3; ++i)
            m_origin[i] = m_elab->sim()->position(Axis::at(i));
        return true;
    });
}

Point3 TestCamPrograms::boardMm()
{
    return m_elab->probe([&] {
        Point3 p;
        p.x = double(m_elab->sim()->position(Axis::X) - m_origin[0]) / kCamStepsPerMm;
        p.y = double(m_elab->sim()->position(Axis::Y) - m_origin[1]) / kCamStepsPerMm;
        p.z = double(m_elab->sim()->position(Axis::Z) - m_origin[2]) / kCamStepsPerMm;
        return p;
    });
}

qsizetype TestCamPrograms::traceSize()
{
    return m_elab->probe([&] {
        return qsizetype(static_cast<elab::ElabSimulator*>(m_elab->sim())->positionTrace().size());
    });
}

QList<Point3> TestCamPrograms::boardTrace(qsizetype from)
{
    return m_elab->probe([&] {
        QList<Point3> out;
        const auto& trace = static_cast<elab::ElabSimulator*>(m_elab->sim())->positionTrace();
        for (size_t i = size_t(from); i < trace.size(); ++i)
            out << Point3{double(trace[i][0] - m_origin[0]) / kCamStepsPerMm,
                          double(trace[i][1] - m_origin[1]) / kCamStepsPerMm,
                          double(trace[i][2] - m_origin[2]) / kCamStepsPerMm};
        return out;
    });
}

void TestCamPrograms::run_camStyles_boardFollowsThePlannedPath_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("prompt");      // of the tool change the run holds at; empty: none
    QTest::addColumn<QList<double>>("spots"); // machine x, y, z the board must reach, in order
    for (const char* model : {"elab", "emis"}) {
        const auto row = [model](const char* style) -> QTestData& {
            return QTest::newRow(QByteArray(model).append(' ').append(style).constData())
                   << QString::fromLatin1(model);
        };
        // G54 at machine X10 Y10 Z-20; T1 is 5 mm long, T2 0 mm.
        row("Fusion 360") << "fusion360_style.ngc"
                          << "Load tool 1 (3 mm flat end mill)"
                          << QList<double>{12, 12, 0,   // N35 G0 X2 Y2 (Z at G53 0)
                                           12, 12, -10, // N40 G43 Z5 H1: 5 - 20 + 5
                                           12, 12, -16, // N50 G1 Z-1
                                           20, 14, -16, // N60 G3's end
                                           18, 18, -16, // N70 G2 R2's end
                                           12, 18, -10, // N80 G0 Z5
                                           12, 18, 0};  // N90 G53 G0 Z0
        // Issue 50 item 7: G41 D1 (tool 1, 3 mm) round the outline (0,0) (0,8) arc (4,12) (10,12)
        // (10,0), clockwise, the tool 1.5 mm outside it (worked out by hand in program
        // coordinates, then + G54): the entry from (-5,0) meets the line at Y1.1007
        // (inside corner); the arc grows to 5.5 about (4,8); arcs round the outside corners
        // (10,12) and (10,0); G40 leaves from (0,-1.5) to (-5,0). Both boards follow the tool's
        // path, not the outline.
        row("Fanuc cutter compensation")
            << "fanuc_cutter_comp_style.nc"
            << "Load tool 1 (3 mm flat end mill)"
            << QList<double>{5,    10,    -10, // G43 Z5 H1
                             5,    10,    -16, // G1 Z-1
                             8.5,  11.10, -16, // the entry's end (11.1007), to the step
                             8.5,  18,    -16, // N80
                             14,   23.5,  -16, // N90's end
                             20,   23.5,  -16, // N100
                             21.5, 22,    -16, // round (10,12)
                             21.5, 10,    -16, // N110
                             20,   8.5,   -16, // round (10,0)
                             10,   8.5,   -16, // N120
                             5,    10,    -16, // G40's exit
                             5,    10,    -10};
        row("FreeCAD") << "freecad_style.ngc"
                       << "Load tool 2 (2 mm ball nose)"
                       << QList<double>{16, 15, -20.5, // the full circle back at its start
                                        14, 17, -21};  // the helix' end
        // Inch; G98 back to Z0.2 (machine -14.92), G99 to R (-18.73); Q0.025 in = 0.635 mm pecks.
        row("CamBam drilling") << "cambam_style.nc"
                               << "Load tool 1 (3 mm flat end mill)"
                               << QList<double>{15.08, 15.08, -18.73, // G81 at R
                                                15.08, 15.08, -22.54, // its bottom
                                                15.08, 15.08, -14.92, // G98
                                                20.16, 15.08, -22.54, // X0.4's bottom
                                                20.16, 15.08, -14.92, //
                                                15.08, 20.16, -18.73, // G83 at R
                                                15.08, 20.16, -20.0,  // second peck
                                                15.08, 20.16, -22.54, // the bottom
                                                15.08, 20.16, -18.73, // G99
                                                15.08, 20.16, -14.92};
        // A pen plotter's program in the style of Inkscape's G-code extensions: "%" around it,
        // Z words on every line, a comment glued to a number, comments after M2.
        row("Inkscape plotter") << "inkscape_plotter_style.ngc" << QString()
                                << QList<double>{12, 12, -15, 12, 12, -20, 16, 12, -20, // G01
                                                 18, 14, -20,                           // G02
                                                 18, 16, -20, 16, 18, -20,              // G03
                                                 12, 12, -20, 12, 12, -15, 10, 10, -15};
        // The SMC-IC4 has no spindle and no coolant: programs with M3, M5, M8 are refused there.
        if (QLatin1String(model) == QLatin1String("emis"))
            continue;
        // No spaces between words; S and M3 beside G0 (switched before the move).
        row("Vectric") << "vectric_style.tap" << QString()
                       << QList<double>{13, 13, -15,                                 // G0X3Y3Z5
                                        13, 13, -20.5,                               // G1Z-0.5
                                        19, 13, -20.5, 19, 17, -20.5, 17, 19, -20.5, // G3's end
                                        13, 13, -20.5, 10, 10, -15};
        // A laser's program: S on G1 lines, M3 constant power, M8 air, Z never moves.
        row("LightBurn") << "lightburn_style.gc" << QString()
                         << QList<double>{12, 12, 0, 18, 12, 0, 18, 16, 0,
                                          12, 16, 0, 12, 12, 0, 10, 10, 0};
        // A drill file: S on G00, M6 and M0, G81 with its numbers first, X Y lines after it.
        row("pcb2gcode drilling") << "pcb2gcode_style.ngc"
                                  << "Load tool 1 (Tool change.)"
                                  << QList<double>{15,    15,    -18,   // G81 at R
                                                   15,    15,    -21.8, // the bottom
                                                   15,    15,    -10,   // G98: the initial level
                                                   17.54, 15,    -21.8, 20.08, 15,
                                                   -21.8, 20.08, 15,    -10};
        // LinuxCNC's own style: G10 L2 sets G55 (X20 Y10 Z-20), T1 (5 mm) with G43 on its M6 line,
        // "S12000 M3 M8" and "M5 M9" (issue 50: several words on one line), a repeat
        // of incremental squares, G53 at the end.
        QList<double> pockets{0, 0, -10, 20, 10, -10};
        for (double x : {20, 24, 28})
            pockets << QList<double>{x, 10, -15.5, x + 2, 10, -15.5, x + 2, 12, -15.5, x, 12, -15.5,
                                     x, 10, -15.5, x,     10, -10,   x + 4, 10, -10};
        pockets << QList<double>{32, 10, 0};
        row("LinuxCNC") << "linuxcnc_style.ngc"
                        << "Load tool 1 (3 mm flat end mill)" << pockets;
        row("Estlcam") << "estlcam_style.nc" << QString()
                       << QList<double>{13, 13, -20.5, 15, 15, -20.5, 17, 13, -20.5};
        // Issue 50: "%" and O1001 around it, a sender's $X, $H (the reference run, at the
        // reference already) and $32=0, arcs with K0.000, a "/M0" that block delete skips (no
        // pause: no prompt), and a G0 after the closing "%" that is never read.
        row("GRBL sender, Fanuc wrapper")
            << "grbl_sender_style.nc" << QString()
            << QList<double>{0,  0,  -15,   // G0 Z5 after $H
                             13, 13, -15,   // G0 X3 Y3
                             13, 13, -20.5, // G1 Z-0.5
                             19, 13, -20.5, // G1 X9
                             21, 15, -20.5, // the first G3 K0.000's end
                             21, 17, -20.5, //
                             19, 19, -20.5, // the second's end
                             13, 19, -20.5, 13, 13, -20.5, 13, 13, -15};
    }
}

void TestCamPrograms::run_camStyles_boardFollowsThePlannedPath()
{
    QFETCH(QString, model);
    QFETCH(QString, file);
    QFETCH(QString, prompt);
    QFETCH(QList<double>, spots);
    QVERIFY(setUp(model));
    QFile f(QStringLiteral(STEPDECK_CAM_DIR "/") + file);
    QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(f.fileName()));
    QList<ProgramError> errors;
    const std::optional<Program> program = ProgramParser::parse(
        f.readAll(), {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")}, &errors);
    QVERIFY2(program, qPrintable(errors.isEmpty() ? QString() : errors.first().text()));
    CoordinateSystems systems;
    systems[0] = {{"X", 10.0}, {"Y", 10.0}, {"Z", -20.0}};
    m_runner->setCoordinateSystems(systems, 0);
    m_runner->setToolTable(
        *ToolTable::parse("T1 Z5 D3 ;3 mm flat end mill\nT2 Z0 ;2 mm ball nose", nullptr));
    QList<Point3> arrived;
    connect(m_machine.get(), &Machine::moveFinished, this, [&](quint64, bool ok) {
        if (ok)
            arrived << boardMm();
    });
    const bool elab = model == QLatin1String("elab");
    const qsizetype traceStart = elab ? traceSize() : 0;
    const Point3 startMm = boardMm();
    QVERIFY2(m_runner->start(*program, 1, &errors),
             qPrintable(errors.isEmpty() ? QString() : errors.first().text()));
    // The operator resumes at every pause (M6, M0); the first one's prompt is compared.
    QStringList prompts;
    while (!isEnded(m_runner->state())) {
        QVERIFY(QTest::qWaitFor(
            [&] { return isEnded(m_runner->state()) || m_runner->state() == RunState::Paused; },
            120000));
        if (m_runner->state() == RunState::Paused) {
            prompts << m_runner->prompt();
            m_runner->resume();
        }
    }
    QCOMPARE(prompts.value(0), prompt);
    QVERIFY2(m_runner->state() == RunState::Finished, qPrintable(m_runner->endMessage()));
    // Every point the check planned (work coordinates, G54 here) was reached within a step.
    // A dwell (G4) adds a point where the path stands and moves nothing.
    QSet<int> dwells;
    for (const ProgramBlock& b : program->allBlocks())
        if (b.kind == BlockKind::Dwell)
            dwells.insert(b.line);
    const QList<PreviewPoint>& planned = m_runner->preview().path;
    QList<Point3> plannedMachine;
    for (const PreviewPoint& p : planned)
        if (p.position.size() == 3 && p.line > 0 && !dwells.contains(p.line))
            plannedMachine << Point3{p.position.value("X") + 10, p.position.value("Y") + 10,
                                     p.position.value("Z") - 20};
    const double step = 1 / kCamStepsPerMm + 1e-9;
    if (elab) {
        // The board's path passes within a step of each planned point, in the plan's order,
        // from where it stood at the start (a first move may not move it at all).
        arrived = QList<Point3>{startMm} + boardTrace(traceStart);
        const QString missed = firstNotPassed(arrived, plannedMachine, step);
        QVERIFY2(missed.isEmpty(), qPrintable(missed));
        // The programs' feed moves (all but the drilling files' cycles) ran as <DC2> streams.
        const qsizetype streamed = m_elab->probe([&] {
            return qsizetype(
                static_cast<elab::ElabSimulator*>(m_elab->sim())->executedStepRecord().size());
        });
        const bool cyclesOnly =
            file.startsWith(QLatin1String("cambam")) || file.startsWith(QLatin1String("pcb2gcode"));
        QVERIFY2(cyclesOnly || streamed > 0, qPrintable(file));
    } else {
        QCOMPARE(arrived.size(), plannedMachine.size());
        for (int i = 0; i < arrived.size(); ++i)
            QVERIFY2(
                near(arrived.at(i), plannedMachine.at(i), step),
                qPrintable(QStringLiteral("move %1: board %2, planned %3")
                               .arg(i)
                               .arg(pointText(arrived.at(i)), pointText(plannedMachine.at(i)))));
    }
    // And the points worked out by hand, in their order (a contour's corner within a step).
    const double spot = elab ? step : 1e-6;
    int next = 0;
    for (const Point3& a : arrived)
        if (next + 2 < spots.size() &&
            near(a, Point3{spots.at(next), spots.at(next + 1), spots.at(next + 2)}, spot))
            next += 3;
    QVERIFY2(
        next == spots.size(),
        qPrintable(QStringLiteral("reached %1 of %2 spots").arg(next / 3).arg(spots.size() / 3)));
}

// A pause during a G83 holds between two of its moves, at the cycle's line, with the board
// standing where the last move ended; resume sends the rest, and the board reaches every point
// the check planned.
void TestCamPrograms::pause_duringPeckCycle_holdsBetweenMovesResumeFinishesIt()
{
    QVERIFY(setUp(QStringLiteral("elab")));
    QList<ProgramError> errors;
    const std::optional<Program> program = ProgramParser::parse(
        "G0 X5 Y5 Z-2\nG99 G83 X10 Y10 Z-8 R-3 Q1 F600\nG80\nG0 Z-2\nM2\n",
        {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")}, &errors);
    QVERIFY(program);
    QList<Point3> arrived;
    connect(m_machine.get(), &Machine::moveFinished, this, [&](quint64, bool ok) {
        if (ok)
            arrived << boardMm();
    });
    QSignalSpy paused(m_runner.get(), &ProgramRunner::paused);
    QVERIFY2(m_runner->start(*program, 1, &errors),
             qPrintable(errors.isEmpty() ? QString() : errors.first().text()));
    QTRY_VERIFY_WITH_TIMEOUT(arrived.size() >= 4, 60000); // the G0, then into the cycle
    m_runner->pause();
    QTRY_COMPARE_WITH_TIMEOUT(m_runner->state(), RunState::Paused, 30000);
    QCOMPARE(paused.size(), 1);
    QCOMPARE(m_runner->currentLine(), 2);
    const qsizetype held = arrived.size();
    // 18 moves in all: G0, XY, R, 5 pecks with 4 retracts and 4 returns, G99's, G0 Z-2.
    QVERIFY2(held < 1 + 16, qPrintable(QString::number(held))); // mid-cycle
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QCOMPARE(arrived.size(), held); // nothing moved while held
    const Point3 still = boardMm();
    QCOMPARE(pointText(still), pointText(arrived.last()));
    m_runner->resume();
    QTRY_VERIFY_WITH_TIMEOUT(isEnded(m_runner->state()), 60000);
    QVERIFY2(m_runner->state() == RunState::Finished, qPrintable(m_runner->endMessage()));
    QCOMPARE(arrived.size(), 18);
    QCOMPARE(m_runner->preview().path.size(), 1 + 18); // the start, then one point a move
    QCOMPARE(pointText(arrived.last()), pointText(Point3{10, 10, -2}));
}

STEPDECK_TEST_MAIN(TestCamPrograms)
#include "tst_camprograms.moc"
