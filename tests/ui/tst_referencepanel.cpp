// Referencing through the Referencing panel on the connection bar's controller, which is a
// machine of one controller (issue 28, item 0): Reference all runs the machine's order (Z
// first, then X and Y together, asserted at the board's commands), laser axes finish on their
// own reports, and a success message does not outlive a panic.
#include "TestMain.h"
#include "UiTestSupport.h"
#include "machine/MachineReferenceRows.h"
#include "position/ReferencePanel.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include <QProgressBar>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestReferencePanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void rows_connectionMachine_defaultOrderZFirst();
    void referenceAll_runsStagesInOrder_allReferenced();
    void referenceAxis_rowButton_onlyThatAxisAtTheBoard();
    void referenceAll_laserAxes_finishOnTheirReports();
    void successMessage_afterPanic_replaced();
    void cancel_duringRun_saysCancelledAndBoardStops();

private:
    bool referenceAll();
    std::unique_ptr<UiFixture> m_f;
};

void TestReferencePanel::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectAndSetUp());
}

bool TestReferencePanel::referenceAll()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    panel->referenceAll();
    QElapsedTimer t;
    t.start();
    while (panel->isRunning() && t.elapsed() < 30000)
        QTest::qWait(20);
    return !panel->isRunning() && panel->messageText().contains(QStringLiteral("referenced"));
}

void TestReferencePanel::rows_connectionMachine_defaultOrderZFirst()
{
    ui::MachineReferenceRows* rows = m_f->window->referencePanel()->machineRows();
    QCOMPARE(rows->axisNames(), (QStringList{"X", "Y", "Z"}));
    QCOMPARE(rows->orderText(QStringLiteral("Z")), QStringLiteral("1"));
    QCOMPARE(rows->orderText(QStringLiteral("X")), QStringLiteral("2"));
    QCOMPARE(rows->directionText(QStringLiteral("X")), QStringLiteral("\u2212 (negative)"));
}

void TestReferencePanel::referenceAll_runsStagesInOrder_allReferenced()
{
    const qsizetype start = m_f->records.size();
    QVERIFY2(referenceAll(), qPrintable(m_f->window->referencePanel()->messageText()));
    for (const AxisStatus& a : m_f->window->context()->status().axes)
        QVERIFY(a.referenced);
    // The bar says the run is complete (issue 31: it showed 0 % after success).
    const QProgressBar* bar = m_f->window->referencePanel()->progressBar();
    QCOMPARE(bar->value(), bar->maximum());
    QVERIFY(bar->maximum() > 0);
    // <US> reference moves: Z alone first, then X and Y together (manual: -1/0/+1 per axis).
    const QList<elab::Command> runs = m_f->commands(elab::ctrl::US, start);
    QCOMPARE(runs.size(), 2);
    QCOMPARE(runs[0].values, (std::array<qint64, 3>{0, 0, -1}));
    QCOMPARE(runs[1].values, (std::array<qint64, 3>{-1, -1, 0}));
}

void TestReferencePanel::referenceAxis_rowButton_onlyThatAxisAtTheBoard()
{
    const qsizetype start = m_f->records.size();
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    QPushButton* run = panel->machineRows()->runButton(QStringLiteral("Y"));
    QTRY_VERIFY(run->isEnabled());
    run->click();
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 30000);
    QVERIFY2(panel->messageText().contains(QStringLiteral("Y referenced")),
             qPrintable(panel->messageText()));
    const QList<elab::Command> runs = m_f->commands(elab::ctrl::US, start);
    QCOMPARE(runs.size(), 1);
    QCOMPARE(runs[0].values, (std::array<qint64, 3>{0, -1, 0}));
    QVERIFY(m_f->window->context()->status().axes.value(Axis::Y).referenced);
    QVERIFY(!m_f->window->context()->status().axes.value(Axis::X).referenced);
    QCOMPARE(panel->progressBar()->value(), panel->progressBar()->maximum());
}

void TestReferencePanel::successMessage_afterPanic_replaced()
{
    QVERIFY(referenceAll());
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    m_f->window->panicAction()->trigger();
    QTRY_VERIFY2(panel->messageText().contains(QStringLiteral("no longer referenced")),
                 qPrintable(panel->messageText()));
    QTRY_VERIFY(!m_f->window->context()->status().axes.value(Axis::X).referenced);
    QCOMPARE(panel->progressBar()->value(), 0); // no longer complete
}

void TestReferencePanel::cancel_duringRun_saysCancelledAndBoardStops()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    panel->referenceAll();
    QVERIFY(panel->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::Z).moving, 5000);
    panel->cancel();
    QVERIFY(!panel->isRunning());
    QCOMPARE(panel->messageText(), QStringLiteral("Referencing cancelled."));
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::Z, 5, &why), qPrintable(why));
    // The failure the machine reports for the cancelled run does not replace the message.
    QTest::qWait(300);
    QCOMPARE(panel->messageText(), QStringLiteral("Referencing cancelled."));
}

void TestReferencePanel::referenceAll_laserAxes_finishOnTheirReports()
{
    // No poller: the machine learns the end of each stage from the request itself.
    ConnectionSpec spec{QStringLiteral("sim"), {}, {}};
    QString error;
    QVERIFY2(
        m_f->window->context()->connectTo(*findModel(QStringLiteral("laser-axis")), spec, &error),
        qPrintable(error));
    QVERIFY(m_f->waitConnected());
    QVERIFY2(referenceAll(), qPrintable(m_f->window->referencePanel()->messageText()));
    bool homed = false;
    QVERIFY(m_f->withSimulatorAs<laser::LaserAxisSimulator>([&](laser::LaserAxisSimulator* s) {
        homed = s->isHomed(Axis::X) && s->isHomed(Axis::Y) && s->isHomed(Axis::Z);
    }));
    QVERIFY(homed);
    for (Axis a : {Axis::X, Axis::Y, Axis::Z})
        QVERIFY(m_f->window->context()->status().axes.value(a).referenced);
}

STEPDECK_TEST_MAIN(TestReferencePanel)
#include "tst_referencepanel.moc"
