// The physical gamepad as a jog source, through a fake device: nothing moves without the
// dead-man button, the dead zone swallows rest noise, calibration re-centres a stick, and
// unplugging the pad mid-jog ramps the axes to zero -- checked at the simulated axis too.
#include "TestMain.h"
#include "UiTestSupport.h"
#include "gamepad/GamepadJogSource.h"
#include "gamepad/GamepadPanel.h"
#include "jog/JogController.h"

using namespace stepdeck;
using namespace stepdeck::test;

namespace {} // namespace

class TestGamepadJog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void stick_withoutDeadman_movesNothing();
    void stick_withDeadman_jogsAndReleaseRampsToZero();
    void unplug_midJog_rampsToZero();
    void deadZone_restNoise_movesNothing();
    void calibration_offsetRest_becomesZero();
    void panel_showsDeviceState();

private:
    bool connectAndSetUp();
    std::unique_ptr<UiFixture> m_f;
};

void TestGamepadJog::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(connectAndSetUp());
    m_f->gamepad->plug(true);
}

bool TestGamepadJog::connectAndSetUp()
{
    return m_f->connectAndSetUp();
}

void TestGamepadJog::stick_withoutDeadman_movesNothing()
{
    const qsizetype start = m_f->records.size();
    m_f->gamepad->moveAxis(kLeftX, 1.0);
    QVERIFY(m_f->window->gamepadSource()->fractions().isEmpty());
    QVERIFY(!m_f->window->jogController()->isJogging());
    // Many status rounds later still nothing was commanded.
    const int from = m_f->statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - from >= 10, 3000);
    QCOMPARE(m_f->commanded(Axis::X), 0.0);
    for (const elab::Command& c : m_f->commands(elab::ctrl::DC4, start))
        QCOMPARE(c.values[0], qint64(0));
    QVERIFY(!m_f->simAxis(Axis::X).moving);
    QCOMPARE(m_f->simAxis(Axis::X).position, qint64(0));
}

void TestGamepadJog::stick_withDeadman_jogsAndReleaseRampsToZero()
{
    m_f->gamepad->moveAxis(kLeftX, 1.0);
    m_f->gamepad->press(kDeadman, true);
    const double max = m_f->window->jogController()->maxSpeed(ui::JogSlot::PadHorizontal);
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::X), max, 5000);
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    const qsizetype released = m_f->records.size();
    const qsizetype atDevice = m_f->deviceMark();
    m_f->gamepad->press(kDeadman, false); // stick still deflected: the button alone stops
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 5, &why), qPrintable(why));
    QCOMPARE(m_f->commanded(Axis::X), 0.0);
    const QList<elab::Command> down = m_f->commands(elab::ctrl::DC4, released);
    QVERIFY(down.size() >= 2);
    QVERIFY(down.first().values[0] > 0); // ramped, not a step to zero
    QCOMPARE(m_f->deviceCommands(elab::ctrl::DC4, atDevice).last().values[0], qint64(0));
}

void TestGamepadJog::unplug_midJog_rampsToZero()
{
    m_f->gamepad->moveAxis(1, -1.0); // left stick up (SDL: negative) -> +Y
    m_f->gamepad->press(kDeadman, true);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->commanded(Axis::Y) > 100, 5000);
    QTRY_VERIFY(m_f->simAxis(Axis::Y).moving);
    const qsizetype unplugged = m_f->records.size();
    m_f->gamepad->plug(false);
    QVERIFY(!m_f->window->jogController()->isJogging());
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::Y, 5, &why), qPrintable(why));
    QCOMPARE(m_f->commanded(Axis::Y), 0.0);
    const QList<elab::Command> down = m_f->commands(elab::ctrl::DC4, unplugged);
    QVERIFY(!down.isEmpty());
    QCOMPARE(down.last().values[1], qint64(0));
}

void TestGamepadJog::deadZone_restNoise_movesNothing()
{
    m_f->gamepad->press(kDeadman, true);
    m_f->gamepad->moveAxis(kLeftX, 0.05); // a worn stick resting off-centre
    QVERIFY(m_f->window->gamepadSource()->fractions().isEmpty());
    QVERIFY(!m_f->window->jogController()->isJogging());
    m_f->gamepad->moveAxis(kLeftX, 0.5);
    QVERIFY(m_f->window->gamepadSource()->fractions().value(ui::JogSlot::PadHorizontal) > 0);
    m_f->gamepad->press(kDeadman, false);
}

void TestGamepadJog::calibration_offsetRest_becomesZero()
{
    ui::GamepadJogSource* source = m_f->window->gamepadSource();
    m_f->gamepad->moveAxis(kLeftX, 0.3); // rests at 0.3
    source->startCalibration();
    m_f->gamepad->press(kDeadman, true);
    m_f->gamepad->moveAxis(kLeftX, 1.0);
    QVERIFY(source->fractions().isEmpty()); // no motion while calibrating
    m_f->gamepad->moveAxis(kLeftX, -1.0);
    m_f->gamepad->moveAxis(kLeftX, 0.3);
    source->finishCalibration();
    QCOMPARE(source->calibration(kLeftX).apply(0.3), 0.0);
    QVERIFY(source->fractions().isEmpty()); // at rest after calibration
    m_f->gamepad->moveAxis(kLeftX, 1.0);
    QCOMPARE(source->fractions().value(ui::JogSlot::PadHorizontal), 1.0);
    m_f->gamepad->press(kDeadman, false);
}

void TestGamepadJog::panel_showsDeviceState()
{
    QVERIFY(m_f->window->gamepadPanel()->deviceText().contains(QStringLiteral("Fake Pad")));
    m_f->gamepad->plug(false);
    QVERIFY(m_f->window->gamepadPanel()->deviceText().contains(QStringLiteral("No gamepad")));
}

STEPDECK_TEST_MAIN(TestGamepadJog)
#include "tst_gamepadjog.moc"
