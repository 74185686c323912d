// Machine: an E-LAB X/Y/Z table and a Nanotec rotary A as one machine, over two real
// pseudo-terminals against the project's simulators (issue 19). Every assertion that matters
// is made at the devices: the moves they accepted, the frames they received, whether they
// stand still.
#include "MachineTestSupport.h"
#include "PtyDevice.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "machine/MachineSetup.h"
#include "program/ProgramCheck.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "sim/PtyEndpoint.h"
#include <QSignalSpy>
#include <QThread>
#include <QtTest>
#include <algorithm>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::machine;

namespace {

using Device = test::PtyDevice;

qint64 acceptedSteps(Device& d, Axis axis)
{
    return d.probe([&] {
        qint64 sum = 0;
        for (const SimulatedMove& m : d.sim()->acceptedMoves()) {
            if (m.axis == axis)
                sum += m.steps;
        }
        return sum;
    });
}

bool receivedContaining(Device& d, const QByteArray& part)
{
    return d.probe([&] {
        const QList<QByteArray> frames = d.sim()->receivedFrames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [&](const QByteArray& f) { return f.contains(part); });
    });
}

bool receivedStop(Device& d)
{
    return d.probe([&] {
        const QList<QByteArray> frames = d.sim()->receivedFrames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [&](const QByteArray& f) { return d.sim()->isStopFrame(f); });
    });
}

bool moving(Device& d)
{
    return d.probe([&] { return d.sim()->isMoving(Axis::X); });
}

bool axisMoving(Device& d, Axis axis)
{
    return d.probe([&] { return d.sim()->isMoving(axis); });
}

bool still(Device& d)
{
    return d.probe([&] { return d.sim()->standingStill(); });
}

qint64 positionX(Device& d)
{
    return d.probe([&] { return d.sim()->position(Axis::X); });
}

int acceptedCount(Device& d)
{
    return d.probe([&] { return int(d.sim()->acceptedMoves().size()); });
}

} // namespace

class TestMachine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void move_xAndA_eachControllerGetsItsStepsAndPositionsReadBackInUnits();
    void move_partRefused_nothingSentToEitherController();
    void move_endsShortOfTarget_failsNamingTheAxis();
    void stop_duringMoveOnBoth_bothDevicesStandStill();
    void linkLost_nanotecVanishes_elabStopsAndTheControllerIsNamed();
    void jog_xAndA_inputLost_bothLeasesRunOut();
    void jog_stopDuringJogOfXAndA_bothDevicesGetTheirStop();
    void jog_unknownAxis_refusedNothingJogs();
    void jog_laserAxisByTargets_withElab_oneInputEndsBoth();
    void create_invalidDescription_refusedWithTheField();
    void reference_zFirst_xAndATogetherAfterZIsReferenced();
    void reference_unknownAxis_refusedNothingSent();
    void reference_invertedAxis_fileDirectionIsTheMachines();
    void reference_linkLostDuringRun_failsNamingTheControllerAndStopsTheOthers();
    void stop_duringReferencedMove_positionsStayKnownAndAnAbsoluteMoveLandsThere();
    void connect_setupFromTheFile_writtenOnEveryConnectAndKnown();

private:
    MachineDescription description() const;
    void writeElabSetup();

    std::unique_ptr<Device> m_elab;
    std::unique_ptr<Device> m_nanotec;
    std::unique_ptr<Machine> m_machine;
};

MachineDescription TestMachine::description() const
{
    MachineDescription d;
    d.name = QStringLiteral("Table with rotary axis");
    MachineController table{
        QStringLiteral("table"), QStringLiteral("elab"), m_elab->path(), {}, {}, {}, {}, {}};
    MachineController rotary{QStringLiteral("rotary"),
                             QStringLiteral("nanotec"),
                             m_nanotec->path(),
                             {{Axis::X, 1}},
                             {},
                             {},
                             {},
                             {}};
    d.controllers = {table, rotary};
    d.axes = {test::machineAxis("X", "table", Axis::X, AxisUnit::Millimetre, 400),
              test::machineAxis("Y", "table", Axis::Y, AxisUnit::Millimetre, 400),
              test::machineAxis("Z", "table", Axis::Z, AxisUnit::Millimetre, 800),
              test::machineAxis("A", "rotary", Axis::X, AxisUnit::Degree, 100)};
    return d;
}

void TestMachine::init()
{
    m_elab = std::make_unique<Device>("elab");
    m_nanotec = std::make_unique<Device>("nanotec");
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(description(), &error), qPrintable(error));
    m_machine->open();
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->session("table")->linkState(), LinkState::Connected,
                              10000);
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->session("rotary")->linkState(), LinkState::Connected,
                              10000);
    writeElabSetup();
}

void TestMachine::cleanup()
{
    m_machine.reset();
    m_elab.reset();
    m_nanotec.reset();
}

// The board moves only after its ramp setup was written (ModelInfo::setupBeforeMotion).
void TestMachine::writeElabSetup()
{
    QVERIFY(test::writeSetupBeforeMotion(m_machine->session("table")));
}

void TestMachine::move_xAndA_eachControllerGetsItsStepsAndPositionsReadBackInUnits()
{
    QSignalSpy finished(m_machine.get(), &Machine::moveFinished);
    QString refusal;
    // (The simulated drive's limit switches sit at +-3000 steps: 25 deg stay inside.)
    const quint64 id = m_machine->move({{"X", 2.5}, {"A", 25}}, false, &refusal);
    QVERIFY2(id != 0, qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
    QCOMPARE(finished.at(0).at(0).toULongLong(), id);
    QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
    // At the devices: 2.5 mm x 400 steps/mm on the board's X, 25 deg x 100 steps/deg on drive 1.
    QCOMPARE(acceptedSteps(*m_elab, Axis::X), qint64(1000));
    QCOMPARE(acceptedSteps(*m_nanotec, Axis::X), qint64(2500));
    QVERIFY(receivedContaining(*m_nanotec, "s2500"));
    QCOMPARE(positionX(*m_elab), qint64(1000));
    QCOMPARE(positionX(*m_nanotec), qint64(2500));
    QVERIFY(still(*m_elab) && still(*m_nanotec));
    // Shown in units: the devices' counts converted back.
    const MachineAxisStatus a = m_machine->axisStatus(*m_machine->description().axis("A"));
    QCOMPARE(a.steps, qint64(2500));
    QCOMPARE(a.position, 25.0);
    QCOMPARE(m_machine->axisStatus(*m_machine->description().axis("X")).position, 2.5);
}

void TestMachine::move_partRefused_nothingSentToEitherController()
{
    QString refusal;
    // Absolute targets on unreferenced axes: A (the Nanotec part) is refused, so X is not sent.
    QCOMPARE(m_machine->move({{"X", 1.0}, {"A", 5.0}}, true, &refusal), quint64(0));
    QVERIFY2(refusal.contains("A is not referenced"), qPrintable(refusal));
    // A (checked first) is fine, X is not: the whole move is refused, A's part is not sent.
    QCOMPARE(m_machine->move({{"A", 5.0}, {"X", qQNaN()}}, false, &refusal), quint64(0));
    QVERIFY2(refusal.contains("X: the target is not a finite number"), qPrintable(refusal));
    QCOMPARE(m_machine->move({{"X", 1.0}, {"Q", 5.0}}, false, &refusal), quint64(0));
    QVERIFY2(refusal.contains("no axis Q"), qPrintable(refusal));
    // Three more status polls of each controller: a move sent before them would have been
    // received by now (one request in flight per link). No move reached either device.
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QSignalSpy rotary(m_machine->session("rotary"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3 && rotary.size() >= 3, 10000);
    QVERIFY(acceptedCount(*m_elab) == 0);
    QVERIFY(acceptedCount(*m_nanotec) == 0);
}

void TestMachine::move_endsShortOfTarget_failsNamingTheAxis()
{
    QSignalSpy finished(m_machine.get(), &Machine::moveFinished);
    QString refusal;
    // 90 deg = 9000 steps: the drive stops at its limit switch at 3000 (and frees it).
    QVERIFY(m_machine->move({{"A", 90}}, false, &refusal) != 0);
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
    QVERIFY(!finished.at(0).at(1).toBool());
    QVERIFY2(finished.at(0).at(2).toString().contains("A stands at"),
             qPrintable(finished.at(0).at(2).toString()));
    QVERIFY(still(*m_nanotec));
    QVERIFY(positionX(*m_nanotec) < 9000);
}

void TestMachine::stop_duringMoveOnBoth_bothDevicesStandStill()
{
    QString refusal;
    QVERIFY(m_machine->move({{"X", 200.0}, {"A", 3600.0}}, false, &refusal) != 0);
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab) && moving(*m_nanotec), 10000);
    QSignalSpy finished(m_machine.get(), &Machine::moveFinished);
    m_machine->stop();
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab) && still(*m_nanotec), 10000);
    QVERIFY(receivedStop(*m_elab));
    QVERIFY(receivedStop(*m_nanotec));
    QVERIFY(positionX(*m_elab) < 80000);
    QVERIFY(positionX(*m_nanotec) < 3000); // stopped, not at its limit switch
}

void TestMachine::linkLost_nanotecVanishes_elabStopsAndTheControllerIsNamed()
{
    QSignalSpy failed(m_machine.get(), &Machine::controllerFailed);
    QString refusal;
    QVERIFY(m_machine->move({{"X", 200.0}}, false, &refusal) != 0);
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    m_nanotec->vanish();
    // Within the poll-loss time the machine learns of it and the table is told to stop.
    QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), 10000);
    QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("rotary"));
    QVERIFY(failed.at(0).at(1).toString().contains("rotary"));
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QVERIFY(receivedStop(*m_elab));
    QVERIFY(positionX(*m_elab) < 80000);
}

void TestMachine::jog_xAndA_inputLost_bothLeasesRunOut()
{
    QString refusal;
    // 2 mm/s = 800 steps/s on the board, 10 deg/s = 1000 steps/s on the drive (above its start
    // frequency). Renewed until both move, then the input is "lost": no renewal comes.
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->jog({{"X", 2.0}, {"A", 10.0}}, &refusal) &&
                                 moving(*m_elab) && moving(*m_nanotec),
                             10000);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab) && still(*m_nanotec), 10000);
    QVERIFY(positionX(*m_elab) > 0);
    QVERIFY(positionX(*m_nanotec) > 0);
}

void TestMachine::jog_stopDuringJogOfXAndA_bothDevicesGetTheirStop()
{
    QString refusal;
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->jog({{"X", -2.0}, {"A", -10.0}}, &refusal) &&
                                 moving(*m_elab) && moving(*m_nanotec),
                             10000);
    m_machine->stop();
    m_machine->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(receivedStop(*m_elab) && receivedStop(*m_nanotec), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab) && still(*m_nanotec), 10000);
}

void TestMachine::jog_unknownAxis_refusedNothingJogs()
{
    QString refusal;
    QVERIFY(!m_machine->jog({{"X", 2.0}, {"Q", 1.0}}, &refusal));
    QVERIFY2(refusal.contains("no axis Q"), qPrintable(refusal));
    QVERIFY(!m_machine->jog({{"A", qInf()}}, &refusal));
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QVERIFY(still(*m_elab) && still(*m_nanotec));
}

// A controller without a jog command (laser motor axes) in a machine: while the input is
// renewed its axis gets short targets one after the other; when the renewals stop (the input
// is lost), no further target is sent and the board's lease runs out too (issue 19).
void TestMachine::jog_laserAxisByTargets_withElab_oneInputEndsBoth()
{
    m_machine.reset(); // this test's machine: the table's board and a laser marker's axes
    Device laser("laser-axis");
    laser.probe([&] {
        static_cast<laser::LaserAxisSimulator*>(laser.sim())->setSpeed(2000);
        return true;
    });
    MachineDescription d;
    d.name = QStringLiteral("Table and marker");
    d.controllers = {{"table", "elab", m_elab->path(), {}, {}, {}, {}, {}},
                     {"marker", "laser-axis", laser.path(), {}, {}, {}, {}, {}}};
    d.axes = {test::machineAxis("X", "table", Axis::X, AxisUnit::Millimetre, 400),
              test::machineAxis("U", "marker", Axis::X, AxisUnit::Step, 1)};
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(d, &error), qPrintable(error));
    m_machine->open();
    ControllerSession* marker = m_machine->session("marker");
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    writeElabSetup();
    // The laser axes home first after power-up (their jog targets need a known position).
    QSignalSpy results(marker, &ControllerSession::requestFinished);
    const RequestId home = marker->reference({{Axis::X, -1}});
    QTRY_VERIFY_WITH_TIMEOUT(std::any_of(results.cbegin(), results.cend(),
                                         [home](const QList<QVariant>& args) {
                                             const auto r = args.at(0).value<CommandResult>();
                                             return r.id == home && r.ok();
                                         }),
                             10000);
    QTRY_VERIFY_WITH_TIMEOUT(still(laser), 10000);
    const int homed = acceptedCount(laser);
    const qint64 start = positionX(laser);

    QTimer input; // the operator's held input, renewed every 100 ms
    input.setInterval(100);
    QString refusal;
    connect(&input, &QTimer::timeout, this, [&] {
        QVERIFY2(m_machine->jog({{"X", 2.0}, {"U", 1000.0}}, &refusal), qPrintable(refusal));
    });
    input.start();
    QVERIFY(m_machine->jog({{"X", 2.0}, {"U", 1000.0}}, &refusal));
    // Several short targets (200 units each, 0.2 s at 1000/s) reach the laser axis, one after
    // the other, while the board jogs X.
    QTRY_VERIFY_WITH_TIMEOUT(acceptedCount(laser) >= homed + 3 && moving(*m_elab), 10000);
    input.stop(); // the input is lost: nobody renews
    // Both stand, and the host saw the last target arrive: the board now stops within ~30 ms
    // of its lease (issue 28 item 6), so the devices alone can stand still while the last
    // target's arrival is still on its way to the host.
    QTRY_VERIFY_WITH_TIMEOUT(
        still(*m_elab) && still(laser) && m_machine->state() == MachineState::Idle, 10000);
    const int sent = acceptedCount(laser);
    QVERIFY(positionX(laser) > start);
    for (const SimulatedMove& m :
         laser.probe([&] { return laser.sim()->acceptedMoves(); }).mid(homed))
        QVERIFY2(m.steps > 0 && m.steps <= 200, qPrintable(QString::number(m.steps)));
    // No further target: nothing more finishes on the marker's link and nothing reaches it.
    QSignalSpy later(marker, &ControllerSession::requestFinished);
    QVERIFY(!later.wait(700));
    QCOMPARE(acceptedCount(laser), sent);
}

void TestMachine::create_invalidDescription_refusedWithTheField()
{
    MachineDescription d = description();
    d.axes[3].stepsPerUnit = 0;
    Machine other;
    QString error;
    QVERIFY(!other.create(d, &error));
    QVERIFY2(error.startsWith("axes[3].stepsPerUnit"), qPrintable(error));
    QVERIFY(!other.session("table"));
}

// The file's order at the devices: Z (order 0) runs alone; X on the table and A on the drive
// (order 1) start only after Z is referenced, and together.
void TestMachine::reference_zFirst_xAndATogetherAfterZIsReferenced()
{
    MachineDescription d = description();
    d.axes[2].referenceOrder = 0; // Z
    d.axes[0].referenceOrder = 1; // X
    d.axes[3].referenceOrder = 1; // A
    d.axes[1].referenceOrder = 2; // Y: not named below, so not run
    QString error;
    m_machine->destroy();
    QVERIFY2(m_machine->create(d, &error), qPrintable(error));
    m_machine->open();
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->session("table")->linkState() == LinkState::Connected &&
                                 m_machine->session("rotary")->linkState() == LinkState::Connected,
                             10000);
    writeElabSetup();
    QSignalSpy finished(m_machine.get(), &Machine::referenceFinished);
    QSignalSpy groups(m_machine.get(), &Machine::referenceGroupStarted);
    QString refusal;
    const quint64 id = m_machine->reference({"A", "X", "Z"}, &refusal);
    QVERIFY2(id != 0, qPrintable(refusal));
    // While Z searches its switch, X and A have not been sent theirs.
    QTRY_VERIFY_WITH_TIMEOUT(axisMoving(*m_elab, Axis::Z), 10000);
    QVERIFY(!axisMoving(*m_elab, Axis::X));
    QVERIFY(!receivedContaining(*m_nanotec, "p4"));
    QVERIFY(!moving(*m_nanotec));
    QTRY_VERIFY_WITH_TIMEOUT(axisMoving(*m_elab, Axis::X) && moving(*m_nanotec), 30000);
    QVERIFY(!axisMoving(*m_elab, Axis::Z));
    QVERIFY(receivedContaining(*m_nanotec, "p4"));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 60000);
    QCOMPARE(finished.at(0).at(0).toULongLong(), id);
    QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
    QCOMPARE(groups.size(), 2);
    QCOMPARE(groups.at(0).at(1).toStringList(), QStringList{"Z"});
    QCOMPARE(groups.at(1).at(1).toStringList(), (QStringList{"X", "A"}));
    QVERIFY(still(*m_elab) && still(*m_nanotec));
    QVERIFY(!axisMoving(*m_elab, Axis::Y));
    for (const char* name : {"X", "Z", "A"}) {
        const MachineAxisStatus a = m_machine->axisStatus(*m_machine->description().axis(name));
        QCOMPARE(a.known, PositionKnowledge::Referenced);
    }
    QVERIFY(m_machine->axisStatus(*m_machine->description().axis("Y")).known !=
            PositionKnowledge::Referenced);
}

// Issue 28, item 4: STOP brakes the E-LAB with its ramp (ForceStopMove "ohne
// Schrittverluste"; the remaining steps read with RequestRelPosition): X's position stays known,
// and an absolute move without a new reference run lands where the board says. (A Nanotec drive
// stops without a ramp, 6.2 "Schrittverluste": its position is not claimed after a STOP.)
void TestMachine::stop_duringReferencedMove_positionsStayKnownAndAnAbsoluteMoveLandsThere()
{
    QSignalSpy referenced(m_machine.get(), &Machine::referenceFinished);
    QString refusal;
    QVERIFY2(m_machine->reference({"X"}, &refusal) != 0, qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(referenced.size(), 1, 60000);
    QVERIFY2(referenced.at(0).at(1).toBool(), qPrintable(referenced.at(0).at(2).toString()));
    const qint64 xHome = positionX(*m_elab); // the board counts from power-on, the host from here

    QVERIFY(m_machine->move({{"X", 100.0}}, false, &refusal) != 0);
    QTRY_VERIFY_WITH_TIMEOUT(moving(*m_elab), 10000);
    m_machine->stop();
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QVERIFY(receivedStop(*m_elab));
    const MachineDescription& d = m_machine->description();
    // The host's position follows the board once it answered the stop.
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->axisStatus(*d.axis("X")).steps, positionX(*m_elab) - xHome,
                              10000);
    QCOMPARE(m_machine->axisStatus(*d.axis("X")).known, PositionKnowledge::Referenced);
    // Stopped short of the target (under load the stop may come before the first step).
    QVERIFY(m_machine->axisStatus(*d.axis("X")).steps >= 0);
    QVERIFY(m_machine->axisStatus(*d.axis("X")).steps < 40000);

    QSignalSpy moved(m_machine.get(), &Machine::moveFinished);
    QVERIFY2(m_machine->move({{"X", 5.0}}, true, &refusal) != 0, qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(moved.size(), 1, 30000);
    QVERIFY2(moved.at(0).at(1).toBool(), qPrintable(moved.at(0).at(2).toString()));
    QCOMPARE(positionX(*m_elab) - xHome, qint64(2000)); // 5 mm x 400 steps/mm
}

// The file's direction is in the machine's sense: an inverted Z referenced "+1" searches the
// negative way at the board, where its switch is (the simulated one at -20000 steps).
void TestMachine::reference_invertedAxis_fileDirectionIsTheMachines()
{
    MachineDescription d = description();
    d.axes[2].invert = true;          // Z
    d.axes[2].referenceDirection = 1; // up, in the machine's sense
    QString error;
    m_machine->destroy();
    QVERIFY2(m_machine->create(d, &error), qPrintable(error));
    m_machine->open();
    QTRY_VERIFY_WITH_TIMEOUT(m_machine->session("table")->linkState() == LinkState::Connected,
                             10000);
    writeElabSetup();
    QSignalSpy finished(m_machine.get(), &Machine::referenceFinished);
    QString refusal;
    QVERIFY2(m_machine->reference({"Z"}, &refusal) != 0, qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 60000);
    QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
    QVERIFY(qAbs(m_elab->probe([this] { return m_elab->sim()->position(Axis::Z); }) + 20000) <= 10);
}

void TestMachine::reference_unknownAxis_refusedNothingSent()
{
    QString refusal;
    QCOMPARE(m_machine->reference({"X", "Q"}, &refusal), quint64(0));
    QVERIFY2(refusal.contains("no axis Q"), qPrintable(refusal));
    QVERIFY(!m_machine->isReferencing());
    QSignalSpy table(m_machine->session("table"), &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(table.size() >= 3, 10000);
    QVERIFY(still(*m_elab) && still(*m_nanotec));
    QVERIFY(!receivedContaining(*m_nanotec, "p4"));
}

void TestMachine::reference_linkLostDuringRun_failsNamingTheControllerAndStopsTheOthers()
{
    QSignalSpy finished(m_machine.get(), &Machine::referenceFinished);
    QString refusal;
    // Every axis has order 0: all of them run together.
    QVERIFY2(m_machine->reference({}, &refusal) != 0, qPrintable(refusal));
    QTRY_VERIFY_WITH_TIMEOUT(axisMoving(*m_elab, Axis::X), 10000);
    m_nanotec->vanish();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
    QVERIFY(!finished.at(0).at(1).toBool());
    QVERIFY2(finished.at(0).at(2).toString().contains("rotary"),
             qPrintable(finished.at(0).at(2).toString()));
    QTRY_VERIFY_WITH_TIMEOUT(still(*m_elab), 10000);
    QVERIFY(receivedStop(*m_elab));
}

// Issue 28, item 1: a controller's setup from the machine file (controllers[i].setup) is
// written on every connect: the board receives its values, the machine knows them (the
// program check judges by them, the board's setup is complete), and a reconnect writes it
// again; the written signal says so.
void TestMachine::connect_setupFromTheFile_writtenOnEveryConnectAndKnown()
{
    m_machine.reset(); // init's machine: its links closed
    MachineDescription d = description();
    ParameterSet setup;
    auto perAxis = [](qint64 v) {
        ParameterValue p;
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            p.perAxis.insert(a, v);
        return p;
    };
    setup.insert(QStringLiteral("start-speed"), perAxis(150));
    setup.insert(QStringLiteral("max-speed"), perAxis(4000));
    setup.insert(QStringLiteral("acceleration"), perAxis(1200));
    d.controllers[0].setupFile = QStringLiteral("table.setup.json");
    d.controllers[0].setup = setup;
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(d, &error), qPrintable(error));
    QSignalSpy written(m_machine->setupWriter(), &MachineSetup::written);
    const QByteArray startSpeed = elab::encode::ramp(elab::RampKind::StartSpeed, {150, 150, 150});
    auto sentToBoard = [this, &startSpeed] {
        const QList<QByteArray> frames = m_elab->frames();
        return int(std::count(frames.cbegin(), frames.cend(), startSpeed));
    };
    const int before = sentToBoard();
    for (int connect = 1; connect <= 2; ++connect) {
        m_machine->open();
        QTRY_COMPARE_WITH_TIMEOUT(written.size(), connect, 10000);
        QCOMPARE(written.last().at(0).toString(), QStringLiteral("table"));
        QVERIFY2(written.last().at(1).toBool(), qPrintable(written.last().at(2).toString()));
        QVERIFY(written.last().at(2).toString().contains(QStringLiteral("table.setup.json")));
        QCOMPARE(sentToBoard(), before + connect); // at the board, once per connect
        const program::MachineFacts facts = program::factsOf(*m_machine);
        QCOMPARE(facts.knownParameters.value("table")
                     .value("start-speed")
                     .perAxis.value(Axis::Y)
                     .toLongLong(),
                 150);
        QVERIFY(!facts.setupIncomplete.contains(QStringLiteral("table")));
        m_machine->close();
        QTRY_COMPARE_WITH_TIMEOUT(m_machine->session("table")->linkState(), LinkState::Disconnected,
                                  10000);
    }
    QVERIFY(!m_machine->setupWriter()->pending());
}

STEPDECK_TEST_GUILESS_MAIN(TestMachine)
#include "tst_machine.moc"
