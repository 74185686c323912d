// Referencing progress (issue 16): the bar moves within a stage by the steps the controller
// confirmed (request accepted, motion reported), never by a guess; "Reference all" in the
// safety bar runs at once, so its label has no "…".
#include "../UiTestSupport.h"
#include "position/ReferencePanel.h"
#include "position/ReferenceRunner.h"
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

    void firstStage_progressMovesWithConfirmedSteps();
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

void TestReferenceProgress::firstStage_progressMovesWithConfirmedSteps()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    ui::ReferenceRunner* runner = panel->runner();
    auto* bar = panel->findChild<QProgressBar*>();
    QVERIFY(bar);
    struct Step
    {
        int done, total;
        bool zMoving; // what the controller reported for Z when the step was shown
        int barValue;
    };
    QList<Step> steps;
    connect(runner, &ui::ReferenceRunner::progress, this, [&](int done, int total) {
        steps << Step{done, total, m_f->window->context()->status().axes.value(Axis::Z).moving,
                      bar->value()};
    });
    QSignalSpy finished(runner, &ui::ReferenceRunner::finished);
    panel->referenceAll(); // Z first, then X and Y
    QVERIFY(finished.wait(30000));
    QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
    const int perStage = ui::ReferenceRunner::kPhases;
    QVERIFY(!steps.isEmpty());
    QCOMPARE(steps.first().done, 0);
    QCOMPARE(steps.last().done, steps.last().total);
    QCOMPARE(steps.last().total, 2 * perStage);
    bool movedWithinFirst = false;
    for (int i = 0; i < steps.size(); ++i) {
        if (i > 0)
            QVERIFY(steps[i].done >= steps[i - 1].done); // never backwards
        if (steps[i].done > 0 && steps[i].done < perStage) {
            movedWithinFirst = true;
            QCOMPARE(steps[i].barValue, steps[i].done); // the panel's bar shows it
        }
        // "Moving" counts only once the controller reported Z in motion.
        if (steps[i].done == perStage - 1)
            QVERIFY(steps[i].zMoving);
    }
    QVERIFY2(movedWithinFirst, "the bar stood at 0 % for the whole Z run");
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
    QVERIFY(m_f->window->referencePanel()->runner()->isRunning());
    QTRY_VERIFY(!m_f->deviceCommands(elab::ctrl::US, mark).isEmpty()); // the run started
    m_f->window->referencePanel()->runner()->cancel(QStringLiteral("test over"));
    m_f->window->stopAll();
}

QTEST_MAIN(TestReferenceProgress)
#include "tst_referenceprogress.moc"
