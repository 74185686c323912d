// Go to of several axes at once (issue 31): on the table with the rotary axis (an E-LAB X/Y/Z
// and a Nanotec A on pseudo-terminals), the checked axes go as one G0 line through the same
// check and path as a program's; each device ends at its own target and "arrived" names every
// axis the controllers confirmed. An unreferenced axis among them refuses the whole line and
// neither device gets a move. Typing a target checks its axis; nothing checked is refused.
#include "MachineWindowRig.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "machine/MachineGoTo.h"
#include "position/PositionPanel.h"
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMachineGoToAxes : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }

    void goTo_xAndA_twoControllers_eachDeviceAtItsTarget();
    void goTo_oneAxisUnreferenced_wholeLineRefusedNothingSent();
    void typing_checksItsAxis_noneChecked_refused();

private:
    ui::MachineGoTo* goTo() const { return m_rig.window()->positionPanel()->machineGoTo(); }
    machine::Machine* machine() const { return m_rig.machine(); }
    bool reference(const QStringList& axes)
    {
        QSignalSpy finished(machine(), &machine::Machine::referenceFinished);
        QString refusal;
        if (machine()->reference(axes, &refusal) == 0) {
            qWarning() << "reference:" << refusal;
            return false;
        }
        return QTest::qWaitFor([&] { return !finished.isEmpty(); }, 60000) &&
               finished.constFirst().at(1).toBool() &&
               QTest::qWaitFor([this] { return m_rig.elab->still() && m_rig.nanotec->still(); },
                               10000);
    }
    MachineWindowRig m_rig;
};

void TestMachineGoToAxes::goTo_xAndA_twoControllers_eachDeviceAtItsTarget()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(reference({}));
    const qint64 originX = m_rig.elab->position(Axis::X);
    const qint64 originY = m_rig.elab->position(Axis::Y);
    const qint64 originA = m_rig.nanotec->position(Axis::X); // drive 1 is A
    goTo()->choose({QStringLiteral("X"), QStringLiteral("A")});
    goTo()->targetBox(QStringLiteral("X"))->setValue(1.25);
    goTo()->targetBox(QStringLiteral("Y"))->setValue(3.0); // not checked: Y stays
    goTo()->targetBox(QStringLiteral("A"))->setValue(10.0);
    goTo()->goButton()->click();
    QTRY_VERIFY2_WITH_TIMEOUT(goTo()->resultText() == QStringLiteral("X, A arrived."),
                              qPrintable(goTo()->resultText()), 30000);
    QVERIFY(m_rig.elab->still() && m_rig.nanotec->still());
    QCOMPARE(m_rig.elab->position(Axis::X) - originX, qint64(500));     // 1.25 mm x 400
    QCOMPARE(m_rig.nanotec->position(Axis::X) - originA, qint64(1000)); // 10 deg x 100
    QCOMPARE(m_rig.elab->position(Axis::Y), originY);
}

void TestMachineGoToAxes::goTo_oneAxisUnreferenced_wholeLineRefusedNothingSent()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(reference({QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")}));
    const auto moves = [](PtyDevice* d) {
        return d->probe([d] { return int(d->acceptedMoveCount()); });
    };
    const int elabBefore = moves(m_rig.elab.get());
    const int driveBefore = moves(m_rig.nanotec.get());
    goTo()->choose({QStringLiteral("X"), QStringLiteral("A")});
    goTo()->targetBox(QStringLiteral("X"))->setValue(1.25);
    goTo()->targetBox(QStringLiteral("A"))->setValue(10.0);
    goTo()->goButton()->click();
    QTRY_VERIFY2(goTo()->resultText().startsWith(QStringLiteral("Go-to refused: A: the position "
                                                                "is unknown")),
                 qPrintable(goTo()->resultText()));
    // Three more status polls of each: a move sent before them would have reached its device.
    for (const QString& id : {QStringLiteral("table"), QStringLiteral("rotary")}) {
        QSignalSpy polls(machine()->session(id), &ControllerSession::statusChanged);
        QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 3, 10000);
    }
    QCOMPARE(moves(m_rig.elab.get()), elabBefore);
    QCOMPARE(moves(m_rig.nanotec.get()), driveBefore);
    QVERIFY(goTo()->goButton()->isEnabled()); // nothing under way
}

void TestMachineGoToAxes::typing_checksItsAxis_noneChecked_refused()
{
    QVERIFY(m_rig.window()->openMachine(m_rig.writeFile(m_rig.machineJson())));
    QCOMPARE(goTo()->checkedAxes(), QStringList{QStringLiteral("X")}); // a single go-to at first
    QDoubleSpinBox* y = goTo()->targetBox(QStringLiteral("Y"));
    y->setValue(2.0); // set by the program: not a choice
    QVERIFY(!goTo()->axisCheck(QStringLiteral("Y"))->isChecked());
    y->setFocus();
    y->selectAll();
    QTest::keyClicks(y, QStringLiteral("4"));
    QCOMPARE(goTo()->checkedAxes(), (QStringList{QStringLiteral("X"), QStringLiteral("Y")}));
    goTo()->choose({});
    goTo()->goButton()->click();
    QCOMPARE(goTo()->resultText(), QStringLiteral("Go-to refused: no axis is checked."));
}

STEPDECK_TEST_MAIN(TestMachineGoToAxes)
#include "tst_machinegotoaxes.moc"
