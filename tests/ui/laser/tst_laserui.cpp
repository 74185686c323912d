// The main window on laser motor axes (issue 16), against the in-process laser simulator:
// - the read-out names the protocol's units (Capabilities::positionUnit), not steps;
// - an idle link stays green: the protocol has no status request, the rate field says so;
// - a jog by targets shows its commanded rate while the simulated axis moves and never
//   lights "motion unconfirmed" while every target is tracked;
// - the setup page offers no buttons that would do nothing and says why.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "connection/ConnectionBar.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "machine/MachineDro.h"
#include "position/PositionPanel.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "setup/SetupPage.h"
#include <QFileDialog>
#include <QLabel>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestLaserUi : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void readOut_namesUnitsNotSteps();
    void idleLink_staysGreen_saysThereIsNoPoll();
    void jog_showsCommandedRate_neverUnconfirmed();
    void setupPage_noParameters_noButtonsAndSaysWhy();

private:
    bool withLaser(std::function<void(laser::LaserAxisSimulator*)> fn)
    {
        return m_f->withSimulatorAs<laser::LaserAxisSimulator>(std::move(fn));
    }
    std::unique_ptr<UiFixture> m_f;
};

void TestLaserUi::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    m_f->window->connectionBar()->setSelectedModel(QStringLiteral("laser-axis"));
    m_f->window->connectionBar()->setPortSpec(QStringLiteral("sim"));
    m_f->window->connectionBar()->connectNow();
    QVERIFY(m_f->waitConnected());
}

void TestLaserUi::readOut_namesUnitsNotSteps()
{
    // The connection's machine: its axes count what the controller counts, named so.
    ui::MachineDro* dro = m_f->window->positionPanel()->machineDro();
    QTRY_COMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("units"));
    QTRY_VERIFY2(dro->detailText(QStringLiteral("X")).startsWith(QStringLiteral("machine 0 units")),
                 qPrintable(dro->detailText(QStringLiteral("X"))));
    QVERIFY(!dro->detailText(QStringLiteral("X")).contains(QStringLiteral("steps")));
    // The commanded jog rates too.
    QStringList rateUnits;
    for (QLabel* label : m_f->window->jogPanel()->findChildren<QLabel*>()) {
        if (label->text().endsWith(QStringLiteral("/s")))
            rateUnits << label->text();
    }
    QCOMPARE(rateUnits, (QStringList{"units/s", "units/s", "units/s"}));
}

void TestLaserUi::idleLink_staysGreen_saysThereIsNoPoll()
{
    ui::ConnectionBar* bar = m_f->window->connectionBar();
    QCOMPARE(bar->linkText(), QStringLiteral("Connected"));
    // Longer than a polled link may stay silent before it turns amber: no change.
    QSignalSpy changed(bar, &ui::ConnectionBar::linkTextChanged);
    QVERIFY(!changed.wait(bar->overdueAfterMs() + 600));
    QCOMPARE(bar->linkText(), QStringLiteral("Connected"));
    QVERIFY(!bar->replyOverdue());
    QCOMPARE(bar->linkLamp()->state(), ui::LedIndicator::State::On);
    bool said = false;
    for (QLabel* label : bar->findChildren<QLabel*>())
        said = said || label->text() == QStringLiteral("no status poll");
    QVERIFY(said);
}

void TestLaserUi::jog_showsCommandedRate_neverUnconfirmed()
{
    // Home X so that relative targets have a start (the protocol reports positions only).
    QSignalSpy done(m_f->session, &ControllerSession::requestFinished);
    const RequestId home = m_f->session->reference({{Axis::X, 1}});
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            for (const QList<QVariant>& a : done)
                if (a.at(0).value<CommandResult>().id == home)
                    return true;
            return false;
        }(),
        15000);
    // Slow axes: each short target takes longer than it is meant to cover (0.2 s).
    QVERIFY(withLaser([](laser::LaserAxisSimulator* s) { s->setSpeed(300); }));
    bool unconfirmed = false;
    double fastest = 0;
    connect(m_f->session, &ControllerSession::statusChanged, this, [&](const MachineStatus& s) {
        unconfirmed = unconfirmed || s.motionUnconfirmed;
        fastest = qMax(fastest, s.axes.value(Axis::X).commandedVelocity);
    });
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(0.8, 0.0)));
    bool movedWhileShown = false;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            bool moving = false;
            withLaser([&](laser::LaserAxisSimulator* s) { moving = s->isMoving(Axis::X); });
            movedWhileShown =
                moving &&
                m_f->window->context()->status().axes.value(Axis::X).commandedVelocity > 0;
            return movedWhileShown;
        }(),
        10000);
    pointerRelease(pad, pad->pointFor(QPointF(0.8, 0.0)));
    QTRY_COMPARE_WITH_TIMEOUT(
        m_f->window->context()->status().axes.value(Axis::X).commandedVelocity, 0.0, 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!m_f->window->context()->status().busy, 5000);
    bool stillMoving = true;
    withLaser([&](laser::LaserAxisSimulator* s) { stillMoving = s->isMoving(Axis::X); });
    QVERIFY(!stillMoving); // the last short target arrived: the device stands
    QVERIFY(fastest > 0);
    QVERIFY2(!unconfirmed, "a tracked jog lit 'motion unconfirmed'");
}

void TestLaserUi::setupPage_noParameters_noButtonsAndSaysWhy()
{
    ui::SetupPage* page = m_f->window->setupPage();
    for (QPushButton* b : page->findChildren<QPushButton*>()) {
        if (b->parent() == page) // the page's own bar, not a stored-parameters bar
            QVERIFY2(b->isHidden(), qPrintable(b->text()));
    }
    bool said = false;
    for (QLabel* label : page->findChildren<QLabel*>())
        said =
            said || (label->isVisible() && label->text().contains(QStringLiteral("no parameters")));
    QVERIFY(said);
    // Write (called directly, as the screenshot script does) sends nothing and says why.
    QVERIFY(!page->write(false));
    QVERIFY2(page->messageText().contains(QStringLiteral("no parameters")),
             qPrintable(page->messageText()));
    // The File menu's Save parameters... opens no dialog for nothing and says why.
    page->saveAs();
    QVERIFY(m_f->window->findChildren<QFileDialog*>().isEmpty());
    QVERIFY2(page->messageText().contains(QStringLiteral("no parameters")),
             qPrintable(page->messageText()));
}

STEPDECK_TEST_MAIN(TestLaserUi)
#include "tst_laserui.moc"
