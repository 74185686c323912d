// Status panel: the raw E-LAB words with the manual's bit names, the normalised flags, the
// temperature warning before the 50 degC bit, and the counters.
#include "TestMain.h"
#include "UiTestSupport.h"
#include "common/LedIndicator.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "status/RawWordView.h"
#include "status/StatusPanel.h"

using namespace stepdeck;
using namespace stepdeck::test;

class TestStatusPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void rawWords_namedAsInManualWithTooltips();
    void setupIncomplete_bitLitUntilWritten();
    void temperature_warnsBeforeOverTemperature_data();
    void temperature_warnsBeforeOverTemperature();
    void counters_shown();
    void machineLamps_onlyWhatTheModelHas_doorFollowsTheSwitch();

private:
    ui::StatusPanel* panel() const { return m_f->window->statusPanel(); }
    std::unique_ptr<UiFixture> m_f;
};

void TestStatusPanel::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectSim());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount > 2, 3000);
}

void TestStatusPanel::rawWords_namedAsInManualWithTooltips()
{
    ui::RawWordView* machine = panel()->rawWord(QStringLiteral("machineState"));
    ui::RawWordView* axe = panel()->rawWord(QStringLiteral("axeState"));
    QVERIFY(machine && axe);
    for (const char* name : {"tmDriveOn", "tmSpindleOn", "tmBusy", "tmOverTemp", "tmInvSetup",
                             "tmLimSwX", "tmRefSwZ", "tmPanicStop"}) {
        ui::LedIndicator* lamp = machine->lamp(QString::fromLatin1(name));
        QVERIFY2(lamp, name);
        QVERIFY(lamp->toolTip().contains(QString::fromLatin1(name)));
    }
    for (const char* name : {"taXMove", "taXJog", "taZJog", "taLimSw", "taRefSw"})
        QVERIFY2(axe->lamp(QString::fromLatin1(name)), name);
    // Documented but never set by the firmware: shown disabled.
    QVERIFY(!machine->lamp(QStringLiteral("tmCOMfail"))->isEnabled());
    QVERIFY(machine->hexText().startsWith(QStringLiteral("0x")));
    QCOMPARE(machine->hexText().size(), 6); // 16 bits
    QCOMPARE(axe->hexText().size(), 4);     // 8 bits
}

void TestStatusPanel::setupIncomplete_bitLitUntilWritten()
{
    ui::LedIndicator* lamp =
        panel()->rawWord(QStringLiteral("machineState"))->lamp(QStringLiteral("tmInvSetup"));
    QTRY_COMPARE(lamp->state(), ui::LedIndicator::State::Fault);
    QCOMPARE(panel()->machineLamp(QStringLiteral("setupIncomplete"))->state(),
             ui::LedIndicator::State::Warning);
    m_f->writeRampSetup();
    QTRY_COMPARE_WITH_TIMEOUT(lamp->state(), ui::LedIndicator::State::Off, 3000);
    QCOMPARE(panel()->machineLamp(QStringLiteral("setupIncomplete"))->state(),
             ui::LedIndicator::State::Off);
}

void TestStatusPanel::temperature_warnsBeforeOverTemperature_data()
{
    QTest::addColumn<int>("celsius");
    QTest::addColumn<QString>("note");
    QTest::newRow("normal") << 30 << QString();
    QTest::newRow("approaching") << 47 << QStringLiteral("approaching");
    QTest::newRow("over") << 55 << QStringLiteral("Over-temperature");
}

void TestStatusPanel::temperature_warnsBeforeOverTemperature()
{
    QFETCH(int, celsius);
    QFETCH(QString, note);
    QVERIFY(m_f->withSim([celsius](elab::ElabSimulator* sim) { sim->setTemperature(celsius); }));
    QTRY_VERIFY_WITH_TIMEOUT(
        panel()->temperatureText().startsWith(QString::number(celsius) + QStringLiteral(" ")),
        3000);
    if (note.isEmpty())
        QVERIFY(panel()->temperatureNote().isEmpty());
    else
        QVERIFY2(panel()->temperatureNote().contains(note), qPrintable(panel()->temperatureNote()));
}

void TestStatusPanel::counters_shown()
{
    QVERIFY(panel()->countersText().contains(QStringLiteral("Comm faults: 0")));
    QVERIFY(panel()->countersText().contains(QStringLiteral("Resyncs:")));
}

void TestStatusPanel::machineLamps_onlyWhatTheModelHas_doorFollowsTheSwitch()
{
    using State = ui::LedIndicator::State;
    QVERIFY(!panel()->findChild<ui::LedIndicator*>(QStringLiteral("doorOpen"))); // E-LAB: none
    // The E-LAB has a spindle relay and reports over-temperature; the laser axes have neither.
    QVERIFY(panel()->findChild<ui::LedIndicator*>(QStringLiteral("spindleOn")));
    QVERIFY(panel()->findChild<ui::LedIndicator*>(QStringLiteral("overTemperature")));
    ConnectionSpec spec{QStringLiteral("sim"), {}, {}};
    QString error;
    QVERIFY2(
        m_f->window->context()->connectTo(*findModel(QStringLiteral("laser-axis")), spec, &error),
        qPrintable(error));
    QVERIFY(m_f->waitConnected());
    ui::LedIndicator* door = nullptr;
    QTRY_VERIFY((door = panel()->findChild<ui::LedIndicator*>(QStringLiteral("doorOpen"))));
    QVERIFY(!panel()->findChild<ui::LedIndicator*>(QStringLiteral("spindleOn")));
    QVERIFY(!panel()->findChild<ui::LedIndicator*>(QStringLiteral("overTemperature")));
    QTRY_COMPARE(door->state(), State::Unknown); // no frame about the door yet
    QVERIFY(m_f->withSimulatorAs<laser::LaserAxisSimulator>(
        [](laser::LaserAxisSimulator* s) { s->setDoorOpen(true); }));
    QTRY_COMPARE(door->state(), State::Warning);
    QVERIFY(m_f->withSimulatorAs<laser::LaserAxisSimulator>(
        [](laser::LaserAxisSimulator* s) { s->setDoorOpen(false); }));
    QTRY_COMPARE(door->state(), State::Off);
}

STEPDECK_TEST_MAIN(TestStatusPanel)
#include "tst_statuspanel.moc"
