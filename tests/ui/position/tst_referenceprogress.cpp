// Referencing progress (issue 16): the bar moves by what the machine confirmed -- a group of
// axes (equal order) ended referenced -- never by a guess; "Reference all" in the safety bar
// runs at once, so its label has no "…". On the connection bar's E-LAB, a machine of one
// controller (issue 28, item 0).
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "position/ReferencePanel.h"
#include "safety/SafetyBar.h"
#include <QProgressBar>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestReferenceProgress : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void progress_movesWithConfirmedGroups();
    void safetyBarButton_noEllipsis_runsAtOnce();

private:
    std::unique_ptr<UiFixture> m_f;
};

void TestReferenceProgress::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectAndSetUp());
}

void TestReferenceProgress::progress_movesWithConfirmedGroups()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    auto* bar = panel->findChild<QProgressBar*>();
    QVERIFY(bar);
    struct Step
    {
        QStringList axes;
        int barValue, barMaximum;
        bool zReferenced; // what the controller reported when the group started
    };
    QList<Step> steps;
    machine::Machine* m = m_f->window->context()->machine();
    connect(m, &machine::Machine::referenceGroupStarted, this,
            [&](quint64, const QStringList& axes) {
                // The panel listens first (it connected at its own run's start).
                QTimer::singleShot(0, this, [&, axes] {
                    steps << Step{axes, bar->value(), bar->maximum(),
                                  m_f->window->context()->status().axes.value(Axis::Z).referenced};
                });
            });
    panel->referenceAll(); // Z first, then X and Y
    QCOMPARE(bar->value(), 0);
    QCOMPARE(bar->maximum(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 30000);
    QVERIFY2(panel->messageText().contains(QStringLiteral("referenced")),
             qPrintable(panel->messageText()));
    QCOMPARE(steps.size(), 2);
    QCOMPARE(steps[0].axes, QStringList{QStringLiteral("Z")});
    QCOMPARE(steps[0].barValue, 0);
    QVERIFY(!steps[0].zReferenced);
    QCOMPARE(steps[1].axes, (QStringList{QStringLiteral("X"), QStringLiteral("Y")}));
    // One group confirmed: Z is referenced at the board's report, and the bar says 1 of 2.
    QCOMPARE(steps[1].barValue, 1);
    QVERIFY(steps[1].zReferenced);
    QCOMPARE(bar->value(), bar->maximum());
}

void TestReferenceProgress::safetyBarButton_noEllipsis_runsAtOnce()
{
    QPushButton* button = nullptr;
    for (QPushButton* b : m_f->window->safetyBar()->findChildren<QPushButton*>()) {
        if (b->text().startsWith(QStringLiteral("Reference all")))
            button = b;
    }
    QVERIFY(button);
    QCOMPARE(button->text(), QStringLiteral("Reference all")); // no "…": nothing asks first
    QTRY_VERIFY(button->isVisible()); // offered: nothing is referenced after connecting
    const qsizetype mark = m_f->deviceMark();
    button->click();
    QVERIFY(m_f->window->referencePanel()->isRunning());
    QTRY_VERIFY(!m_f->deviceCommands(elab::ctrl::US, mark).isEmpty()); // the run started
    m_f->window->stopAll();
    QVERIFY(!m_f->window->referencePanel()->isRunning());
}

STEPDECK_TEST_MAIN(TestReferenceProgress)
#include "tst_referenceprogress.moc"
