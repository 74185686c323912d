// The jog panel with a machine open (issue 19): the pad, the sticks, the keyboard and the
// gamepad jog the machine's named axes in their units per second, on whichever controller
// drives them, through one Machine::jog input. An E-LAB (X/Y/Z, 400 steps/mm) and a Nanotec
// drive (A, 100 steps/deg) simulator on two pseudo-terminals.
#include "../LayoutChecks.h"
#include "MachineWindowRig.h"
#include "TestMain.h"
#include "gamepad/GamepadPanel.h"
#include "jog/IncrementalJogWidget.h"
#include "jog/JogAxisMap.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JogVelocityReadout.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include "machine/Machine.h"
#include "machine/MachineBar.h"
#include "machine/MachineContext.h"
#include "window/Translations.h"
#include <QCheckBox>
#include <QComboBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QToolButton>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {

constexpr int kRightX = 2; // gamepad axis of the U slot (the other stick)

// The highest X jog rate the E-LAB board received (<DC4>XXXX,YYYY;ZZZZ., manual: SetJogSpeed).
int highestElabJogX(const QList<QByteArray>& frames)
{
    int highest = 0;
    for (const QByteArray& f : frames) {
        if (f.size() == 16 && f.at(0) == 0x14)
            highest = qMax(highest, int(qint16(f.mid(1, 4).toUShort(nullptr, 16))));
    }
    return highest;
}

// The highest speed-mode frequency the Nanotec drive 1 received ('o', manual 6.2).
int highestNanotecSpeed(const QList<QByteArray>& frames)
{
    const QRegularExpression speed(QStringLiteral("^#1o(-?\\d+)\r$"));
    int highest = 0;
    for (const QByteArray& f : frames) {
        const QRegularExpressionMatch m = speed.match(QString::fromLatin1(f));
        if (m.hasMatch())
            highest = qMax(highest, m.captured(1).toInt());
    }
    return highest;
}

} // namespace

class TestMachineJog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }
    void slots_tableAndRotary_padXYStickZOtherStickAKeysSayWhich();
    void jog_padXAndStickA_oneInputDevicesAtUnitRatesLossStopsBoth();
    void jog_padX_velocityReadoutInMillimetresPerSecond();
    void incremental_oneUnitOnXAndA_devicesMoveByStepsPerUnit();
    void sixAxes_otherStickReachesABC_fitsAt1366x768_data();
    void sixAxes_otherStickReachesABC_fitsAt1366x768();

private:
    bool openAndConnect(const QByteArray& limits = {});
    ui::MainWindow* window() const { return m_rig.window(); }
    machine::Machine* machine() const { return m_rig.machine(); }
    void waitForPolls(const char* controller, int count);

    MachineWindowRig m_rig;
};

// X at most 2 mm/s (800 steps/s), A at most 4 deg/s (400 steps/s) when `limits` is set.
bool TestMachineJog::openAndConnect(const QByteArray& limits)
{
    const bool limited = !limits.isEmpty();
    return m_rig.openAndConnect(m_rig.machineJson(
        QStringLiteral("Jog table"), limited ? QStringLiteral(", \"maxJogSpeed\": 2") : QString(),
        limited ? QStringLiteral(", \"maxJogSpeed\": 4") : QString()));
}

void TestMachineJog::waitForPolls(const char* controller, int count)
{
    QSignalSpy polls(machine()->session(QString::fromLatin1(controller)),
                     &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= count, 10000);
}

void TestMachineJog::slots_tableAndRotary_padXYStickZOtherStickAKeysSayWhich()
{
    QVERIFY(openAndConnect());
    ui::JogPanel* panel = window()->jogPanel();
    const ui::JogAxisMap* map = window()->jogController()->axisMap();
    QCOMPARE(map->label(ui::JogSlot::PadHorizontal), QStringLiteral("X"));
    QCOMPARE(map->label(ui::JogSlot::PadVertical), QStringLiteral("Y"));
    QCOMPARE(map->label(ui::JogSlot::ZStick), QStringLiteral("Z"));
    QCOMPARE(map->label(ui::JogSlot::OtherStick), QStringLiteral("A"));
    QVERIFY(panel->uStick()->isVisibleTo(window()));
    QVERIFY(panel->otherStickAxis()->isVisibleTo(window()));
    QCOMPARE(panel->otherStickAxis()->currentText(), QStringLiteral("A"));
    QCOMPARE(window()->gamepadPanel()->rowName(ui::JogSlot::OtherStick), QStringLiteral("A"));
    panel->keyboardCheck()->setChecked(true);
    QTRY_VERIFY2(panel->keyboardStateText().contains(QStringLiteral("End/Home A")),
                 qPrintable(panel->keyboardStateText()));
    QVERIFY(panel->keyboardStateText().contains(QStringLiteral("Page Down/Up Z")));
}

void TestMachineJog::jog_padXAndStickA_oneInputDevicesAtUnitRatesLossStopsBoth()
{
    QVERIFY(openAndConnect("limits"));
    // One gamepad: its left stick is the pad's X, its right stick the other stick's A.
    m_rig.f->gamepad->plug(true);
    m_rig.f->gamepad->moveAxis(kLeftX, 1.0);
    m_rig.f->gamepad->moveAxis(kRightX, 1.0);
    m_rig.f->gamepad->press(kDeadman, true);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.nanotec->moving(Axis::X), 10000);
    waitForPolls("rotary", 10);
    // Full deflection at 100 %: 2 mm/s x 400 steps/mm and 4 deg/s x 100 steps/deg.
    QTRY_COMPARE_WITH_TIMEOUT(highestElabJogX(m_rig.elab->frames()), 800, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(highestNanotecSpeed(m_rig.nanotec->frames()), 400, 10000);
    const ui::JogVelocityReadout* readout = window()->jogPanel()->velocityReadout();
    QTRY_COMPARE_WITH_TIMEOUT(readout->valueText(QStringLiteral("A")), QStringLiteral("+4.00"),
                              10000);
    QCOMPARE(readout->unitText(QStringLiteral("A")), QStringLiteral("deg/s"));
    // The one input goes silent (a stalled gamepad driver): nothing renews either lease, so
    // both devices come to a stand.
    m_rig.f->gamepad->setSampling(false);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.nanotec->still(), 10000);
    QVERIFY(!window()->jogController()->isJogging());
}

void TestMachineJog::jog_padX_velocityReadoutInMillimetresPerSecond()
{
    QVERIFY(openAndConnect("limits"));
    ui::JoystickPad* pad = window()->jogPanel()->xyPad();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(1.0, 0.0)));
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->moving(Axis::X), 10000);
    const ui::JogVelocityReadout* readout = window()->jogPanel()->velocityReadout();
    QTRY_COMPARE_WITH_TIMEOUT(readout->valueText(QStringLiteral("X")), QStringLiteral("+2.00"),
                              10000);
    QCOMPARE(readout->unitText(QStringLiteral("X")), QStringLiteral("mm/s"));
    QCOMPARE(highestElabJogX(m_rig.elab->frames()), 800);
    QVERIFY(!m_rig.nanotec->moving(Axis::X));
    pointerRelease(pad, pad->pointFor(QPointF(1.0, 0.0)));
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still(), 10000);
}

void TestMachineJog::incremental_oneUnitOnXAndA_devicesMoveByStepsPerUnit()
{
    QVERIFY(openAndConnect());
    ui::IncrementalJogWidget* incremental = window()->jogPanel()->incremental();
    QCOMPARE(incremental->unitStepSize(), 1.0); // the third preset: 1 mm or 1 deg
    QVERIFY(incremental->machineButton(QStringLiteral("A"), +1));
    incremental->machineButton(QStringLiteral("X"), +1)->click();
    QTRY_COMPARE_WITH_TIMEOUT(m_rig.elab->position(Axis::X), qint64(400), 10000);
    incremental->machineButton(QStringLiteral("A"), -1)->click();
    QTRY_COMPARE_WITH_TIMEOUT(m_rig.nanotec->position(Axis::X), qint64(-100), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.elab->still() && m_rig.nanotec->still(), 10000);
    QCOMPARE(m_rig.elab->position(Axis::X), qint64(400));
}

void TestMachineJog::sixAxes_otherStickReachesABC_fitsAt1366x768_data()
{
    QTest::addColumn<QString>("language");
    // English first: a German translator, once installed, stays for the process.
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("de") << QStringLiteral("de");
}

void TestMachineJog::sixAxes_otherStickReachesABC_fitsAt1366x768()
{
    QFETCH(QString, language);
    ui::translations::install(qApp, language);
    m_rig.f = std::make_unique<UiFixture>(); // built in the language
    window()->show();
    QVERIFY(QTest::qWaitForWindowActive(window()));
    QVERIFY(m_rig.openAndConnect(MachineWindowRig::sixAxisJson(),
                                 {QStringLiteral("table"), QStringLiteral("wrist")}));
    ui::JogPanel* panel = window()->jogPanel();
    QComboBox* other = panel->otherStickAxis();
    QCOMPARE(other->count(), 3);
    QCOMPARE(other->itemText(0), QStringLiteral("A"));
    QCOMPARE(other->itemText(2), QStringLiteral("C"));
    other->setCurrentIndex(2);
    Q_EMIT other->activated(2);
    const ui::JogAxisMap* map = window()->jogController()->axisMap();
    QCOMPARE(map->label(ui::JogSlot::OtherStick), QStringLiteral("C"));
    QCOMPARE(other->currentText(), QStringLiteral("C"));
    // The read-out has every machine axis in its unit.
    if (language == QLatin1String("en"))
        QCOMPARE(panel->velocityReadout()->unitText(QStringLiteral("B")), QStringLiteral("deg/s"));
    QVERIFY(!panel->velocityReadout()->unitText(QStringLiteral("C")).isEmpty());
    panel->keyboardCheck()->setChecked(true);
    QTRY_VERIFY2(panel->keyboardStateText().endsWith(QStringLiteral(" C")),
                 qPrintable(panel->keyboardStateText()));
    // The window fits 1366x768 and nothing of the jog panel is cut.
    const QSize minimum = window()->minimumSizeHint().expandedTo(window()->minimumSize());
    QVERIFY2(
        minimum.width() <= 1366 && minimum.height() <= 768 - 40,
        qPrintable(QStringLiteral("minimum %1x%2").arg(minimum.width()).arg(minimum.height())));
    window()->resize(1366, 768 - 40);
    QCoreApplication::processEvents();
    const QStringList cut = clippedTexts(panel);
    QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QStringLiteral("; "))));
}

STEPDECK_TEST_MAIN(TestMachineJog)
#include "tst_machinejog.moc"
