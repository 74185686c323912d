// The safety bar against the in-process E-LAB simulator: what it says after a link loss
// (with and without motion), a host panic, the machine's own emergency stop, and on first
// connection to a board whose setup is incomplete; the permanent note of a model without a
// stop command.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "safety/SafetyBanner.h"
#include "safety/SafetyBar.h"
#include <QLabel>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestSafetyBar : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void firstConnection_setupIncomplete_saidFirst();
    void linkLost_whileJogging_saysMayStillMove();
    void linkLost_idle_saysPositionsUnknownOnly();
    void hostPanic_saysPanicSent_notRelease();
    void machineEmergencyStop_saysRelease();
    void noStopCommand_permanentNoteAndLabels();

private:
    ui::SafetyBar* bar() const { return m_f->window->safetyBar(); }
    std::unique_ptr<UiFixture> m_f;
};

void TestSafetyBar::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
}

void TestSafetyBar::firstConnection_setupIncomplete_saidFirst()
{
    QVERIFY(m_f->connectSim()); // power-on board: setup incomplete, nothing referenced
    QTRY_VERIFY(m_f->window->context()->status().setupIncomplete);
    QTRY_VERIFY2(bar()->bannerText().contains(QStringLiteral("write the setup")),
                 qPrintable(bar()->bannerText()));
    QVERIFY(!bar()->bannerText().contains(QStringLiteral("eference")));
    QVERIFY(m_f->connectAndSetUp());
    QTRY_VERIFY2(bar()->bannerText().contains(QStringLiteral("referenced")),
                 qPrintable(bar()->bannerText()));
}

void TestSafetyBar::linkLost_whileJogging_saysMayStillMove()
{
    QVERIFY(m_f->connectAndSetUp());
    m_f->gamepad->plug(true);
    m_f->gamepad->moveAxis(0, 1.0);
    m_f->gamepad->press(9, true);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::X).moving, 5000);
    // The board goes silent while it jogs: the host cannot confirm any stop.
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->faults().silent = true; }));
    QTRY_COMPARE_WITH_TIMEOUT(m_f->session->linkState(), LinkState::Lost, 20000);
    QVERIFY(bar()->movingWhenLinkEnded());
    QVERIFY2(bar()->bannerText().contains(ui::SafetyBanner::mayStillMoveText()),
             qPrintable(bar()->bannerText()));
    QVERIFY(!bar()->bannerText().contains(QStringLiteral("stopped")));
    QCOMPARE(bar()->bannerSeverity(), QStringLiteral("fault"));
}

void TestSafetyBar::linkLost_idle_saysPositionsUnknownOnly()
{
    QVERIFY(m_f->connectAndSetUp());
    QTRY_VERIFY(!m_f->window->context()->status().anyMoving());
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->faults().silent = true; }));
    QTRY_COMPARE_WITH_TIMEOUT(m_f->session->linkState(), LinkState::Lost, 20000);
    QVERIFY(!bar()->movingWhenLinkEnded());
    QVERIFY2(bar()->bannerText().contains(QStringLiteral("Link lost")),
             qPrintable(bar()->bannerText()));
    QVERIFY(!bar()->bannerText().contains(ui::SafetyBanner::mayStillMoveText()));
    QVERIFY(!bar()->bannerText().contains(QStringLiteral("stopped")));
}

void TestSafetyBar::hostPanic_saysPanicSent_notRelease()
{
    QVERIFY(m_f->connectAndSetUp());
    pointerClick(bar()->panicButton());
    QTRY_VERIFY(m_f->window->context()->status().panic);
    QTRY_VERIFY2(bar()->bannerText().contains(QStringLiteral("PANIC STOP sent")),
                 qPrintable(bar()->bannerText()));
    QVERIFY(!bar()->bannerText().contains(QStringLiteral("Release")));
    // Several status rounds later it still does not ask to release anything.
    const int from = m_f->statusCount;
    QTRY_VERIFY(m_f->statusCount - from >= 5);
    QVERIFY2(!bar()->bannerText().contains(QStringLiteral("Release")),
             qPrintable(bar()->bannerText()));
}

void TestSafetyBar::machineEmergencyStop_saysRelease()
{
    QVERIFY(m_f->connectAndSetUp());
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->setPanicButton(true); }));
    QTRY_VERIFY2(bar()->bannerText().contains(QStringLiteral("Release the emergency stop")),
                 qPrintable(bar()->bannerText()));
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->setPanicButton(false); }));
    QTRY_VERIFY2(!bar()->bannerText().contains(QStringLiteral("Release")),
                 qPrintable(bar()->bannerText()));
}

void TestSafetyBar::noStopCommand_permanentNoteAndLabels()
{
    QVERIFY(m_f->connectSim());
    QVERIFY(bar()->noStopNote()->isHidden()); // E-LAB has a stop command
    QVERIFY(!bar()->stopButton()->text().contains(QStringLiteral("does not stop")));
    Capabilities caps = m_f->window->context()->capabilities();
    caps.stopCommand = false; // as EMIS SMC-IC4 and the laser axes
    bar()->showCapabilities(caps);
    QVERIFY(bar()->noStopNote()->isVisible());
    QCOMPARE(bar()->noStopNote()->text(), Controller::noStopCommandText());
    QVERIFY(bar()->stopButton()->text().contains(QStringLiteral("does not stop")));
    QVERIFY(bar()->panicButton()->text().contains(QStringLiteral("does not stop")));
    QVERIFY(bar()->stopButton()->isEnabled()); // still ends every jog input at once
}

STEPDECK_TEST_MAIN(TestSafetyBar)
#include "tst_safetybar.moc"
