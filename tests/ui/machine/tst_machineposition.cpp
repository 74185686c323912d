// Positions of a machine in the window (issue 19): the read-out in the machine's units, Go to
// (refused unreferenced, at the nearest step at the device), referencing in the file's order
// and per machine axis, and work zero in units remembered per machine file.
#include "../LaptopScreen.h"
#include "../LayoutChecks.h"
#include "MachineWindowRig.h"
#include "TestMain.h"
#include "common/LedIndicator.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include "machine/Machine.h"
#include "machine/MachineBar.h"
#include "machine/MachineDro.h"
#include "machine/MachineGoTo.h"
#include "machine/MachineReferenceRows.h"
#include "messages/StatusMessages.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "safety/SafetyBar.h"
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QToolButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMachinePosition : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }
    void dro_afterMoveX2point5_shows2point500mm();
    void goTo_unreferencedAxis_refusedNothingSent();
    void goTo_referencedX_deviceAtTheNearestStep();
    void referenceAll_machine_everyControllerInTheFilesOrder();
    void referenceAxis_machine_fileRowsShownOnlyThatControllerRuns();
    void zero_referencedX_digitsZeroAndGoToWorkMovesDeviceToOffsetPlusTarget();
    void zero_unknownPosition_refusedReasonGoneOnceReferenced();
    void zero_reopenMachine_offsetsRemembered();

private:
    ui::MainWindow* window() const { return m_rig.window(); }
    machine::Machine* machine() const { return m_rig.machine(); }
    QToolButton* zeroButton(const QString& axis) const;

    MachineWindowRig m_rig;
};

QToolButton* TestMachinePosition::zeroButton(const QString& axis) const
{
    return window()->positionPanel()->machineDro()->findChild<QToolButton*>(
        QStringLiteral("machineZero") + axis);
}

void TestMachinePosition::dro_afterMoveX2point5_shows2point500mm()
{
    QVERIFY(m_rig.openAndConnect());
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QVERIFY(dro->isVisibleTo(window()));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm"));
    QCOMPARE(dro->unitText(QStringLiteral("A")), QStringLiteral("deg"));
    QSignalSpy finished(machine(), &machine::Machine::moveFinished);
    QString refusal;
    QVERIFY2(machine()->move({{QStringLiteral("X"), 2.5}, {QStringLiteral("A"), 25.0}}, false,
                             &refusal) != 0,
             qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
    QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
    QCOMPARE(m_rig.elab->position(), qint64(1000)); // at the device: 2.5 mm x 400 steps/mm
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("X")), QStringLiteral("2.500"),
                              10000);
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("A")), QStringLiteral("25.000"),
                              10000);
    QVERIFY(dro->detailText(QStringLiteral("X")).contains(QStringLiteral("1000")));
    // Not referenced since the connect: the position is counted, not known from the origin.
    QCOMPARE(dro->stateText(QStringLiteral("X")), QStringLiteral("UNKNOWN"));
}

void TestMachinePosition::goTo_unreferencedAxis_refusedNothingSent()
{
    QVERIFY(m_rig.openAndConnect());
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    QVERIFY(goTo->isVisibleTo(window()));
    goTo->choose({QStringLiteral("X")});
    goTo->targetBox(QStringLiteral("X"))->setValue(1.25);
    goTo->goButton()->click();
    // Refused by the check a program's G0 has, off the GUI thread: said once it ran.
    QTRY_VERIFY2(goTo->resultText().contains(QStringLiteral("Go-to refused: X: the position is "
                                                            "unknown")),
                 qPrintable(goTo->resultText()));
    // Three more status polls: a move sent before them would have reached the board by now.
    QSignalSpy polls(machine()->session(QStringLiteral("table")),
                     &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 3, 10000);
    QCOMPARE(m_rig.elab->probe([this] { return int(m_rig.elab->acceptedMoveCount()); }), 0);
}

void TestMachinePosition::goTo_referencedX_deviceAtTheNearestStep()
{
    QVERIFY(m_rig.openAndConnect());
    ControllerSession* table = machine()->session(QStringLiteral("table"));
    table->reference({{Axis::X, -1}, {Axis::Y, -1}, {Axis::Z, -1}});
    QTRY_VERIFY_WITH_TIMEOUT(
        table->status().axes.value(Axis::X).referenced && !table->status().anyMoving(), 20000);
    const qint64 origin = m_rig.elab->position();
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    goTo->choose({QStringLiteral("X")});
    goTo->targetBox(QStringLiteral("X"))->setValue(1.25);
    goTo->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo->resultText() == QStringLiteral("X arrived."), 30000);
    QCOMPARE(m_rig.elab->position() - origin, qint64(500)); // 1.25 mm x 400 steps/mm
    QVERIFY(m_rig.elab->still());
}

// "Reference all" with a machine open is the machine's run (Machine::reference): the rotary
// drive is referenced too, not only the controller the pages show, and the DRO then marks
// every axis as referenced.
void TestMachinePosition::referenceAll_machine_everyControllerInTheFilesOrder()
{
    QVERIFY(m_rig.openAndConnect());
    QCOMPARE(window()->context()->session(), machine()->session(QStringLiteral("table")));
    auto* all = window()->referencePanel()->findChild<QPushButton*>(QStringLiteral("referenceAll"));
    QVERIFY(all);
    all->click();
    // At the devices: the drive got its reference run (mode p4), the board its axes moved.
    const auto driveReferenced = [this] {
        const QList<QByteArray> frames = m_rig.nanotec->frames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [](const QByteArray& f) { return f.contains("p4"); });
    };
    QTRY_VERIFY_WITH_TIMEOUT(driveReferenced(), 30000);
    QTRY_COMPARE_WITH_TIMEOUT(window()->referencePanel()->messageText(),
                              QStringLiteral("Every axis of the machine is referenced."), 60000);
    QVERIFY(m_rig.elab->still() && m_rig.nanotec->still());
    for (const machine::MachineAxis& a : machine()->description().axes)
        QCOMPARE(machine()->axisStatus(a).known, machine::PositionKnowledge::Referenced);
    QVERIFY(all->isEnabled()); // the run is over
}

// With a machine open the panel shows the machine's axes with the direction and order of its
// file (what Machine::reference follows), and
// "Reference A" runs only the rotary drive: the board sees no motion.
void TestMachinePosition::referenceAxis_machine_fileRowsShownOnlyThatControllerRuns()
{
    QVERIFY(m_rig.openAndConnect());
    ui::ReferencePanel* panel = window()->referencePanel();
    ui::MachineReferenceRows* rows = panel->machineRows();
    QVERIFY(rows->isVisibleTo(panel));
    QCOMPARE(rows->axisNames(), (QStringList{"A", "X", "Y", "Z"}));
    QCOMPARE(rows->directionText(QStringLiteral("X")), QStringLiteral("\u2212 (negative)"));
    QCOMPARE(rows->orderText(QStringLiteral("Z")), QStringLiteral("0"));
    const qint64 boardBefore = m_rig.elab->position();
    QTRY_VERIFY_WITH_TIMEOUT(rows->runButton(QStringLiteral("A"))->isEnabled(), 5000);
    rows->runButton(QStringLiteral("A"))->click();
    const auto driveReferenced = [this] {
        const QList<QByteArray> frames = m_rig.nanotec->frames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [](const QByteArray& f) { return f.contains("p4"); });
    };
    QTRY_VERIFY_WITH_TIMEOUT(driveReferenced(), 30000);
    QTRY_COMPARE_WITH_TIMEOUT(panel->messageText(), QStringLiteral("A referenced."), 60000);
    const machine::MachineDescription& d = machine()->description();
    QCOMPARE(machine()->axisStatus(*d.axis(QStringLiteral("A"))).known,
             machine::PositionKnowledge::Referenced);
    QCOMPARE(machine()->axisStatus(*d.axis(QStringLiteral("X"))).known,
             machine::PositionKnowledge::Unknown);
    QVERIFY(m_rig.elab->still());
    QCOMPARE(m_rig.elab->position(), boardBefore);
    window()->closeMachine();
    // The connection bar's machine of one controller in its place: its axes, no A.
    QCOMPARE(rows->axisNames(), (QStringList{"X", "Y", "Z"}));
}

// Zero X at a known position: the digits read 0.000 in work coordinates, the line below keeps
// the machine position, and a go-to in work coordinates reaches the board at offset + target.
void TestMachinePosition::zero_referencedX_digitsZeroAndGoToWorkMovesDeviceToOffsetPlusTarget()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable());
    const qint64 origin = m_rig.elab->position();
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    goTo->choose({QStringLiteral("X")});
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to:"));
    goTo->targetBox(QStringLiteral("X"))->setValue(2.5);
    goTo->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo->resultText() == QStringLiteral("X arrived."), 30000);
    QCOMPARE(m_rig.elab->position() - origin, qint64(1000));
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("X")), QStringLiteral("2.500"),
                              10000);
    QToolButton* zero = zeroButton(QStringLiteral("X"));
    QVERIFY(zero && zero->isVisibleTo(window()));
    zero->click();
    QCOMPARE(dro->displayedValue(QStringLiteral("X")), QStringLiteral("0.000"));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm work"));
    QCOMPARE(dro->stateText(QStringLiteral("X")), QStringLiteral("REFERENCED"));
    QVERIFY2(dro->detailText(QStringLiteral("X")).contains(QStringLiteral("machine 2.500 mm")),
             qPrintable(dro->detailText(QStringLiteral("X"))));
    QVERIFY(dro->detailText(QStringLiteral("X")).contains(QStringLiteral("1000 steps")));
    QCOMPARE(dro->displayedValue(QStringLiteral("Y")), QStringLiteral("0.000")); // untouched
    QCOMPARE(dro->unitText(QStringLiteral("Y")), QStringLiteral("mm"));
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to (work):"));
    // Go to (work) X = 1: machine 3.5 mm, 1400 steps from the origin at the board.
    goTo->targetBox(QStringLiteral("X"))->setValue(1.0);
    goTo->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo->resultText() == QStringLiteral("X arrived."), 30000);
    QCOMPARE(m_rig.elab->position() - origin, qint64(1400));
    QVERIFY(m_rig.elab->still());
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("X")), QStringLiteral("1.000"),
                              10000);
    // Clear: machine coordinates again, for the read-out and the go-to.
    dro->clearOffsets();
    QCOMPARE(dro->displayedValue(QStringLiteral("X")), QStringLiteral("3.500"));
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to:"));
}

// Not referenced since the connect: a work origin there would say nothing about the machine.
void TestMachinePosition::zero_unknownPosition_refusedReasonGoneOnceReferenced()
{
    QVERIFY(m_rig.openAndConnect());
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_COMPARE(dro->stateText(QStringLiteral("X")), QStringLiteral("UNKNOWN"));
    zeroButton(QStringLiteral("X"))->click();
    QVERIFY2(dro->messageText().contains(QStringLiteral("position is unknown")),
             qPrintable(dro->messageText()));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm"));
    QCOMPARE(window()->positionPanel()->machineGoTo()->labelText(), QStringLiteral("Go to:"));
    // Once X is referenced the refusal no longer holds and leaves the line.
    QVERIFY(m_rig.referenceTable());
    QTRY_VERIFY_WITH_TIMEOUT(dro->messageText().isEmpty(), 10000);
}

// The offsets belong to the machine file: closing and opening it again brings them back.
void TestMachinePosition::zero_reopenMachine_offsetsRemembered()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable());
    QSignalSpy finished(machine(), &machine::Machine::moveFinished);
    QString refusal;
    QVERIFY2(machine()->move({{QStringLiteral("Y"), 1.25}}, true, &refusal) != 0,
             qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_COMPARE_WITH_TIMEOUT(dro->stateText(QStringLiteral("Y")), QStringLiteral("REFERENCED"),
                              10000);
    QVERIFY(dro->zeroAxis(QStringLiteral("Y")));
    QCOMPARE(dro->displayedValue(QStringLiteral("Y")), QStringLiteral("0.000"));
    window()->closeMachine();
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still() && m_rig.nanotec->still(), 10000);
    QVERIFY(window()->openMachine(m_rig.dir->filePath(QStringLiteral("test.machine.json"))));
    QCOMPARE(dro->unitText(QStringLiteral("Y")), QStringLiteral("mm work"));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm"));
    // Not connected: the last value known, in work coordinates, marked as such.
    QCOMPARE(dro->stateText(QStringLiteral("Y")), QStringLiteral("NO LINK"));
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    goTo->choose({QStringLiteral("Y")});
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to (work):"));
}

STEPDECK_TEST_MAIN_WITH(TestMachinePosition, runOnLaptopScreen<TestMachinePosition>)

#include "tst_machineposition.moc"
