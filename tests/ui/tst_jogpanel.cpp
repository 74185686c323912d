// Jog panel against the in-process E-LAB simulator through the ControllerSession: the pad's
// deflection becomes ramped <DC4> jog commands, release ramps to zero, the lease is renewed
// while held (the pointer proves it), refusals are visible, keyboard jog ends on focus loss
// and a repeat of a key that is not held starts nothing. Every end is checked at the
// simulated axis, not only at the host's commanded velocity.
#include "TestMain.h"
#include "UiTestSupport.h"
#include "console/TrafficConsole.h"
#include "jog/IncrementalJogWidget.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QToolButton>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
QList<qint64> jogValues(const QList<elab::Command>& dc4, int axisIndex)
{
    QList<qint64> out;
    for (const elab::Command& c : dc4)
        out << c.values[axisIndex];
    return out;
}
} // namespace

class TestJogPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void jog_draggedKnob_rampsUpThenReleaseRampsToZero();
    void jog_heldKnob_leaseRenewedSpeedHeld();
    void jog_notConnected_controlsDisabled();
    void keyboardJog_stateAndKeysShownOnPanel();
    void jog_panicActive_refusedWithVisibleReason();
    void jog_limitSwitch_shownOnPadEdge();
    void keyboardJog_focusLoss_endsJog();
    void keyboardJog_windowDeactivated_endsJog();
    void keyboardJog_repeatOfUnheldKey_startsNothing();
    void incrementalJog_plusButton_movesByStepSize();

private:
    bool connectAndSetUp();
    std::unique_ptr<UiFixture> m_f;
};

void TestJogPanel::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
}

void TestJogPanel::cleanup()
{
    if (QGuiApplication::mouseButtons() & Qt::LeftButton)
        QTest::mouseRelease(m_f->window->windowHandle(), Qt::LeftButton);
    m_f.reset();
}

bool TestJogPanel::connectAndSetUp()
{
    return m_f->connectAndSetUp();
}

void TestJogPanel::jog_draggedKnob_rampsUpThenReleaseRampsToZero()
{
    QVERIFY(connectAndSetUp());
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    const double max = m_f->window->jogController()->maxSpeed(ui::JogSlot::PadHorizontal);
    const qsizetype start = m_f->records.size();

    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(1.0, 0.0)));
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::X), max, 5000);
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);

    // Ramped: several intermediate rates on the way up, never a jump to full speed.
    const QList<qint64> up = jogValues(m_f->commands(elab::ctrl::DC4, start), 0);
    QVERIFY2(up.size() >= 3, qPrintable(QString::number(up.size())));
    QVERIFY(up.first() > 0 && up.first() < qint64(max));
    for (int i = 1; i < up.size(); ++i)
        QVERIFY(up.at(i) >= up.at(i - 1));
    QCOMPARE(up.last(), qint64(max));
    QCOMPARE(jogValues(m_f->commands(elab::ctrl::DC4, start), 1).last(), qint64(0)); // Y untouched

    const qsizetype released = m_f->records.size();
    const qsizetype atDevice = m_f->deviceMark();
    pointerRelease(pad, pad->pointFor(QPointF(1.0, 0.0)));
    QVERIFY(!pad->isDragging());
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 5, &why), qPrintable(why));
    QCOMPARE(m_f->commanded(Axis::X), 0.0);
    const QList<qint64> down = jogValues(m_f->commands(elab::ctrl::DC4, released), 0);
    QVERIFY(down.size() >= 3);
    QVERIFY(down.first() > 0 && down.first() < qint64(max)); // ramps, no step to zero
    QCOMPARE(down.last(), qint64(0));
    // ... and the board received exactly that ramp.
    QCOMPARE(jogValues(m_f->deviceCommands(elab::ctrl::DC4, atDevice), 0), down);
}

void TestJogPanel::jog_heldKnob_leaseRenewedSpeedHeld()
{
    QVERIFY(connectAndSetUp());
    ui::JoystickPad* z = m_f->window->jogPanel()->zStick();
    const double max = m_f->window->jogController()->maxSpeed(ui::JogSlot::ZStick);
    pointerPress(z, z->centre());
    pointerMove(z, z->pointFor(QPointF(0.0, -1.0)));
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::Z), -max, 5000);
    const qint64 start = m_f->simAxis(Axis::Z).position;
    // Far longer than the core's 300 ms lease: the held button renews it.
    const int from = m_f->statusCount;
    double slowest = max;
    QObject ctx;
    connect(m_f->session, &ControllerSession::statusChanged, &ctx, [&](const MachineStatus& s) {
        slowest = qMin(slowest, qAbs(s.axes.value(Axis::Z).commandedVelocity));
    });
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - from >= 25, 5000);
    QCOMPARE(slowest, max);
    const UiFixture::SimAxis during = m_f->simAxis(Axis::Z);
    QVERIFY(during.moving);
    QVERIFY(during.position < start);
    pointerRelease(z, z->centre());
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::Z, 5, &why), qPrintable(why));
}

void TestJogPanel::jog_notConnected_controlsDisabled()
{
    // Without a connection the pads and step buttons are disabled: nothing to drag.
    ui::JogPanel* panel = m_f->window->jogPanel();
    QVERIFY(!panel->xyPad()->isEnabled());
    QVERIFY(!panel->zStick()->isEnabled());
    QVERIFY(!panel->incremental()->isEnabled());
    ui::JoystickPad* pad = panel->xyPad();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(0.0, 0.8)));
    QVERIFY(!pad->isDragging());
    QVERIFY(!m_f->window->jogController()->isJogging());
    pointerRelease(pad, pad->centre());
    QVERIFY(connectAndSetUp());
    QVERIFY(panel->xyPad()->isEnabled());
    QVERIFY(panel->incremental()->isEnabled());
}

void TestJogPanel::keyboardJog_stateAndKeysShownOnPanel()
{
    QVERIFY(connectAndSetUp());
    ui::JogPanel* panel = m_f->window->jogPanel();
    QVERIFY2(panel->keyboardStateText().contains(QStringLiteral("off")),
             qPrintable(panel->keyboardStateText()));
    panel->keyboardCheck()->setChecked(true);
    QTRY_VERIFY(panel->hasFocus());
    const QString on = panel->keyboardStateText();
    QVERIFY2(on.contains(QStringLiteral("ON")) && on.contains(QStringLiteral("\u2190/\u2192 X")) &&
                 on.contains(QStringLiteral("Page Down/Up Z")),
             qPrintable(on));
    // A text field takes the focus: the arrows edit the field, the panel says jog is paused.
    QLineEdit* line = m_f->window->trafficConsole()->sendLine();
    m_f->window->raisePage(m_f->window->trafficConsole());
    line->setText(QStringLiteral("abc"));
    line->setFocus();
    QTRY_VERIFY(line->hasFocus());
    QTRY_VERIFY2(panel->keyboardStateText().contains(QStringLiteral("paused")),
                 qPrintable(panel->keyboardStateText()));
    line->setCursorPosition(3);
    QTest::keyClick(line, Qt::Key_Left);
    QCOMPARE(line->cursorPosition(), 2);
    QVERIFY(!m_f->window->keyboardJog()->isJogging());
    QVERIFY(!m_f->simAxis(Axis::X).moving);
    panel->setFocus();
    QTRY_VERIFY(panel->keyboardStateText().contains(QStringLiteral("ON")));
}

void TestJogPanel::jog_panicActive_refusedWithVisibleReason()
{
    QVERIFY(connectAndSetUp());
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->setPanicButton(true); }));
    QTRY_VERIFY_WITH_TIMEOUT(m_f->window->context()->status().panic, 3000);
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    const qsizetype start = m_f->records.size();
    const qsizetype atDevice = m_f->deviceMark();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(1.0, 0.0)));
    QTRY_VERIFY(
        m_f->window->jogPanel()->refusalLabel()->text().contains(QStringLiteral("emergency stop")));
    pointerRelease(pad, pad->centre());
    for (const elab::Command& c : m_f->commands(elab::ctrl::DC4, start))
        QCOMPARE(c.values[0], qint64(0)); // nothing but zero rates ever sent
    for (const elab::Command& c : m_f->deviceCommands(elab::ctrl::DC4, atDevice))
        QCOMPARE(c.values[0], qint64(0));
    QVERIFY(!m_f->simAxis(Axis::X).moving);
}

void TestJogPanel::jog_limitSwitch_shownOnPadEdge()
{
    QVERIFY(connectAndSetUp());
    ui::JogPanel* panel = m_f->window->jogPanel();
    QVERIFY(!panel->xyPad()->isLimitActive(1));
    QVERIFY(
        m_f->withSim([](elab::ElabSimulator* sim) { sim->setLimitSwitchActuated(Axis::Y, true); }));
    QTRY_VERIFY_WITH_TIMEOUT(panel->xyPad()->isLimitActive(1), 3000);
    QVERIFY(!panel->xyPad()->isLimitActive(0));
    QVERIFY(!panel->zStick()->isLimitActive(1));
    QVERIFY(m_f->withSim(
        [](elab::ElabSimulator* sim) { sim->setLimitSwitchActuated(Axis::Y, false); }));
    QTRY_VERIFY_WITH_TIMEOUT(!panel->xyPad()->isLimitActive(1), 3000);
}

void TestJogPanel::keyboardJog_focusLoss_endsJog()
{
    QVERIFY(connectAndSetUp());
    m_f->window->jogPanel()->keyboardCheck()->setChecked(true);
    m_f->window->jogPanel()->xyPad()->window()->setFocus();
    QTest::keyPress(m_f->window.get(), Qt::Key_Right);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->commanded(Axis::X) > 0, 3000);
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    QVERIFY(m_f->window->keyboardJog()->isJogging());

    // The key is never released: moving the focus alone must end the jog.
    QLineEdit* other = m_f->window->trafficConsole()->sendLine();
    m_f->window->raisePage(m_f->window->trafficConsole());
    other->setFocus();
    QTRY_VERIFY(other->hasFocus());
    QVERIFY(!m_f->window->keyboardJog()->isJogging());
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 5, &why), qPrintable(why));
    QCOMPARE(m_f->commanded(Axis::X), 0.0);
}

void TestJogPanel::keyboardJog_windowDeactivated_endsJog()
{
    QVERIFY(connectAndSetUp());
    m_f->window->jogPanel()->keyboardCheck()->setChecked(true);
    QTest::keyPress(m_f->window.get(), Qt::Key_PageUp);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->commanded(Axis::Z) > 0, 3000);
    QTRY_VERIFY(m_f->simAxis(Axis::Z).moving);
    // Another window takes the focus; the key-up would go there.
    QWidget other;
    other.show();
    other.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&other));
    QVERIFY(!m_f->window->keyboardJog()->isJogging());
    QVERIFY(!m_f->window->jogController()->isJogging());
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::Z, 5, &why), qPrintable(why));
}

void TestJogPanel::keyboardJog_repeatOfUnheldKey_startsNothing()
{
    QVERIFY(connectAndSetUp());
    m_f->window->jogPanel()->keyboardCheck()->setChecked(true);
    ui::KeyboardJog* keyboard = m_f->window->keyboardJog();
    // An auto-repeat press without a real press first (the real one went elsewhere).
    QKeyEvent repeat(QEvent::KeyPress, Qt::Key_Left, Qt::NoModifier, QString(), true);
    QApplication::sendEvent(m_f->window.get(), &repeat);
    QVERIFY(!keyboard->isJogging());
    QTest::keyPress(m_f->window.get(), Qt::Key_Left);
    QVERIFY(keyboard->isJogging());
    // Auto-repeat release/press pairs neither stop nor restart the motion.
    QKeyEvent repRelease(QEvent::KeyRelease, Qt::Key_Left, Qt::NoModifier, QString(), true);
    QApplication::sendEvent(m_f->window.get(), &repRelease);
    QApplication::sendEvent(m_f->window.get(), &repeat);
    QVERIFY(keyboard->isJogging());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->commanded(Axis::X) < 0, 3000);
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    QTest::keyRelease(m_f->window.get(), Qt::Key_Left);
    QVERIFY(!keyboard->isJogging());
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 5, &why), qPrintable(why));
    QCOMPARE(m_f->commanded(Axis::X), 0.0);
}

void TestJogPanel::incrementalJog_plusButton_movesByStepSize()
{
    QVERIFY(connectAndSetUp());
    const qsizetype start = m_f->records.size();
    ui::JogPanel* panel = m_f->window->jogPanel();
    panel->incremental()->setUnitStepSize(1000); // the connection's axes count steps
    panel->incremental()->machineButton(QStringLiteral("Y"), +1)->click();
    // FastMoveXY with Y = +1000 (0x3E8): the narrowest command for an X/Y move.
    QTRY_VERIFY_WITH_TIMEOUT(!m_f->commands(elab::ctrl::FF, start).isEmpty(), 3000);
    const elab::Command move = m_f->commands(elab::ctrl::FF, start).first();
    QCOMPARE(move.values[0], qint64(0));
    QCOMPARE(move.values[1], qint64(1000));
}

STEPDECK_TEST_MAIN(TestJogPanel)
#include "tst_jogpanel.moc"
