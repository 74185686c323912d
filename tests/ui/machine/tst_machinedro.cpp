// The machine's read-out (MachineDro) on the connection bar's E-LAB, a machine of one
// controller (issue 28, item 0), against the in-process simulator: unknown before a reference
// run and referenced after it, estimated after a jog, no link after a disconnect, and during a
// positioning move -- which the E-LAB does not report -- an estimate or the target marked as
// such, never the target as if reached.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "machine/MachineDro.h"
#include "machine/MachineReferenceRows.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "program/MachineWorkOffsets.h"
#include <QComboBox>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMachineDro : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void position_unknownBeforeReference_estimatedAfterJog();
    void zero_referencedAxis_workPositionZero();
    void system_chosenInTheBox_zeroAndDigitsUseIt();
    void move_withoutReadback_estimateBetweenStartAndTarget();
    void move_withoutReadback_rampUnknown_showsTargetMarked();
    void disconnected_showsNoLinkNotReferenced();

private:
    ui::MachineDro* dro() const { return m_f->window->positionPanel()->machineDro(); }
    bool referenceX();
    std::unique_ptr<UiFixture> m_f;
};

void TestMachineDro::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectSim());
    QSignalSpy done(m_f->session, &ControllerSession::requestFinished);
    m_f->writeRampSetup(5000, 4000);
    QVERIFY(done.wait(3000) && done.first().at(0).value<CommandResult>().ok());
}

bool TestMachineDro::referenceX()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    panel->machineRows()->runButton(QStringLiteral("X"))->click();
    QElapsedTimer t;
    t.start();
    while (panel->isRunning() && t.elapsed() < 30000)
        QTest::qWait(20);
    return m_f->window->context()->status().axes.value(Axis::X).referenced;
}

void TestMachineDro::position_unknownBeforeReference_estimatedAfterJog()
{
    const QString x = QStringLiteral("X");
    QTRY_COMPARE(dro()->stateText(x), QStringLiteral("UNKNOWN"));
    QVERIFY(referenceX());
    QTRY_COMPARE(dro()->stateText(x), QStringLiteral("REFERENCED"));
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(0.7, 0.0)));
    QTRY_VERIFY_WITH_TIMEOUT(m_f->window->context()->status().axes.value(Axis::X).position > 50,
                             5000);
    pointerRelease(pad, pad->pointFor(QPointF(0.7, 0.0)));
    QTRY_COMPARE(dro()->stateText(x), QStringLiteral("ESTIMATED"));
    QVERIFY(dro()->displayedValue(x).startsWith(QStringLiteral("\u2248")));
}

void TestMachineDro::zero_referencedAxis_workPositionZero()
{
    QVERIFY(referenceX());
    m_f->session->moveRelative({{Axis::X, 400}});
    QTRY_VERIFY_WITH_TIMEOUT(m_f->window->context()->status().axes.value(Axis::X).position == 400 &&
                                 !m_f->simAxis(Axis::X).moving,
                             10000);
    QTRY_COMPARE(dro()->stateText(QStringLiteral("X")), QStringLiteral("REFERENCED"));
    QVERIFY(dro()->zeroAxis(QStringLiteral("X")));
    QCOMPARE(dro()->displayedValue(QStringLiteral("X")), QStringLiteral("0"));
    QVERIFY(dro()->detailText(QStringLiteral("X")).startsWith(QStringLiteral("machine 400 steps")));
}

// Issue 29: the G54..G59 box chooses the system the digits show and Zero sets.
void TestMachineDro::system_chosenInTheBox_zeroAndDigitsUseIt()
{
    QVERIFY(referenceX());
    m_f->session->moveRelative({{Axis::X, 400}});
    QTRY_VERIFY_WITH_TIMEOUT(m_f->window->context()->status().axes.value(Axis::X).position == 400 &&
                                 !m_f->simAxis(Axis::X).moving,
                             10000);
    QTRY_COMPARE(dro()->stateText(QStringLiteral("X")), QStringLiteral("REFERENCED"));
    auto* box = dro()->findChild<QComboBox*>(QStringLiteral("machineCoordinateSystem"));
    QVERIFY(box);
    QCOMPARE(box->count(), 6);
    QCOMPARE(box->currentText(), QStringLiteral("G54"));
    QVERIFY(dro()->zeroAxis(QStringLiteral("X"))); // G54 zero at 400
    box->setCurrentIndex(1);
    Q_EMIT box->activated(1); // as a click on "G55" does
    program::MachineWorkOffsets* offsets = m_f->window->context()->workOffsets();
    QCOMPARE(offsets->active(), 1);
    QCOMPARE(dro()->displayedValue(QStringLiteral("X")), QStringLiteral("400")); // G55: none
    offsets->setSystem(1, {{QStringLiteral("X"), 100.0}}); // as a program's G10 does
    QCOMPARE(dro()->displayedValue(QStringLiteral("X")), QStringLiteral("300"));
    offsets->setActive(0); // elsewhere: the box follows
    QCOMPARE(box->currentText(), QStringLiteral("G54"));
    QCOMPARE(dro()->displayedValue(QStringLiteral("X")), QStringLiteral("0"));
}

void TestMachineDro::move_withoutReadback_estimateBetweenStartAndTarget()
{
    // The E-LAB reports no position during a move; the core counts the target at once. The
    // read-out shows an estimate and the target, not the target as if reached.
    QVERIFY(referenceX());
    const QString x = QStringLiteral("X");
    QTRY_COMPARE(dro()->stateText(x), QStringLiteral("REFERENCED"));
    bool inBetween = false;
    bool targetAsReached = false;
    QObject ctx;
    connect(m_f->session, &ControllerSession::statusChanged, &ctx, [&] {
        const QString shown = dro()->displayedValue(x);
        if (m_f->simAxis(Axis::X).moving && shown == QStringLiteral("8000"))
            targetAsReached = true;
        if (dro()->stateText(x) != QLatin1String("MOVING"))
            return;
        bool ok = false;
        const qint64 v = shown.mid(1).toLongLong(&ok);
        inBetween =
            inBetween || (shown.startsWith(QStringLiteral("\u2248")) && ok && v > 0 && v < 8000);
    });
    m_f->session->moveRelative({{Axis::X, 8000}});
    QTRY_COMPARE_WITH_TIMEOUT(dro()->stateText(x), QStringLiteral("MOVING"), 3000);
    QVERIFY(dro()->detailText(x).contains(QStringLiteral("moving to 8000")));
    QTRY_COMPARE_WITH_TIMEOUT(dro()->stateText(x), QStringLiteral("REFERENCED"), 15000);
    QVERIFY(inBetween);
    QVERIFY(!targetAsReached);
    QCOMPARE(dro()->displayedValue(x), QStringLiteral("8000"));
    QVERIFY(!m_f->simAxis(Axis::X).moving);
}

void TestMachineDro::move_withoutReadback_rampUnknown_showsTargetMarked()
{
    // Without the ramp parameters (after a reset, or a model whose names differ) there is no
    // estimate: the digits show the target marked with an arrow, never a lone "≈".
    QVERIFY(referenceX());
    const QString x = QStringLiteral("X");
    QTRY_COMPARE(dro()->stateText(x), QStringLiteral("REFERENCED"));
    m_f->window->context()->forgetKnownParameters();
    m_f->session->moveRelative({{Axis::X, 6000}});
    QTRY_COMPARE_WITH_TIMEOUT(dro()->stateText(x), QStringLiteral("MOVING"), 3000);
    QCOMPARE(dro()->displayedValue(x), QStringLiteral("\u21926000"));
    QTRY_COMPARE_WITH_TIMEOUT(dro()->stateText(x), QStringLiteral("REFERENCED"), 15000);
    QCOMPARE(dro()->displayedValue(x), QStringLiteral("6000"));
}

void TestMachineDro::disconnected_showsNoLinkNotReferenced()
{
    QVERIFY(referenceX());
    QTRY_COMPARE(dro()->stateText(QStringLiteral("X")), QStringLiteral("REFERENCED"));
    m_f->window->context()->disconnectFromController();
    QTRY_VERIFY(!m_f->window->context()->isConnected());
    for (const QString& a : {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")})
        QTRY_COMPARE(dro()->stateText(a), QStringLiteral("NO LINK"));
}

STEPDECK_TEST_MAIN(TestMachineDro)
#include "tst_machinedro.moc"
