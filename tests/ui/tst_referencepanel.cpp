// Referencing and the position read-out: Reference all runs Z first, then X and Y together;
// the read-out shows unknown before and referenced after, estimated after a jog, and the work
// origin and units apply.
#include "UiTestSupport.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "position/ReferenceRunner.h"
#include "protocols/laser/LaserAxisSimulator.h"

using namespace stepdeck;
using namespace stepdeck::test;

class TestReferencePanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void plan_defaultOrder_zFirstThenXY();
    void plan_skippedAxis_left_out();
    void referenceAll_runsStagesInOrder_allReferenced();
    void referenceAll_laserAxes_finishOnTheirReports();
    void position_unknownBeforeReference_estimatedAfterJog();
    void position_workZeroAndUnits_applied();
    void position_duringMove_estimateAndTargetNotReferenced();
    void position_duringReferenceRun_saysReferencingNotMovingTo();
    void position_duringMove_rampUnknown_showsTargetNeverBlank();
    void position_disconnected_showsNoLinkNotReferenced();
    void successMessage_afterPanic_replaced();

private:
    bool referenceX();
    bool setUp();
    std::unique_ptr<UiFixture> m_f;
};

void TestReferencePanel::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(setUp());
}

bool TestReferencePanel::setUp()
{
    if (!m_f->connectSim())
        return false;
    QSignalSpy done(m_f->session, &ControllerSession::requestFinished);
    m_f->writeRampSetup(5000, 4000);
    return done.wait(3000) && done.first().at(0).value<CommandResult>().ok();
}

void TestReferencePanel::plan_defaultOrder_zFirstThenXY()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    const auto stages = ui::ReferenceRunner::plan(panel->directions(), panel->order());
    QCOMPARE(stages.size(), 2);
    QCOMPARE(stages[0].keys(), QList<Axis>{Axis::Z});
    QCOMPARE(stages[1].keys(), (QList<Axis>{Axis::X, Axis::Y}));
}

void TestReferencePanel::plan_skippedAxis_left_out()
{
    const auto stages = ui::ReferenceRunner::plan({{Axis::X, -1}, {Axis::Y, 0}, {Axis::Z, 1}},
                                                  {{Axis::X, 1}, {Axis::Y, 1}, {Axis::Z, 2}});
    QCOMPARE(stages.size(), 2);
    QCOMPARE(stages[0], (ui::ReferenceRunner::Stage{{Axis::X, -1}}));
    QCOMPARE(stages[1], (ui::ReferenceRunner::Stage{{Axis::Z, 1}}));
}

void TestReferencePanel::referenceAll_runsStagesInOrder_allReferenced()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    QSignalSpy finished(panel->runner(), &ui::ReferenceRunner::finished);
    const qsizetype start = m_f->records.size();
    panel->referenceAll();
    QVERIFY(finished.wait(30000));
    QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
    for (const AxisStatus& a : m_f->window->context()->status().axes)
        QVERIFY(a.referenced);
    // <US> reference moves: Z alone first, then X and Y together (manual: -1/0/+1 per axis).
    const QList<elab::Command> runs = m_f->commands(elab::ctrl::US, start);
    QCOMPARE(runs.size(), 2);
    QCOMPARE(runs[0].values, (std::array<qint64, 3>{0, 0, -1}));
    QCOMPARE(runs[1].values, (std::array<qint64, 3>{-1, -1, 0}));
    QCOMPARE(m_f->window->positionPanel()->stateText(Axis::Z), QStringLiteral("REFERENCED"));
}

void TestReferencePanel::position_unknownBeforeReference_estimatedAfterJog()
{
    ui::PositionPanel* dro = m_f->window->positionPanel();
    QCOMPARE(dro->stateText(Axis::X), QStringLiteral("UNKNOWN"));
    QSignalSpy finished(m_f->window->referencePanel()->runner(), &ui::ReferenceRunner::finished);
    m_f->window->referencePanel()->referenceAxis(Axis::X);
    QVERIFY(finished.wait(30000));
    QVERIFY(finished.first().at(0).toBool());
    QTRY_COMPARE(dro->stateText(Axis::X), QStringLiteral("REFERENCED"));
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(0.7, 0.0)));
    QTRY_VERIFY_WITH_TIMEOUT(m_f->window->context()->status().axes.value(Axis::X).position > 50,
                             5000);
    pointerRelease(pad, pad->pointFor(QPointF(0.7, 0.0)));
    QTRY_COMPARE(dro->stateText(Axis::X), QStringLiteral("ESTIMATED"));
    QVERIFY(dro->displayedValue(Axis::X).startsWith(QStringLiteral("\u2248")));
}

void TestReferencePanel::position_workZeroAndUnits_applied()
{
    ui::MachineContext* ctx = m_f->window->context();
    ui::AxisUnits u;
    u.stepsPerUnit = 200;
    u.unit = QStringLiteral("mm");
    u.workOffset = 400;
    ctx->setUnits(Axis::Y, u);
    QCOMPARE(ctx->toUserUnits(Axis::Y, 1400), 5.0);
    QCOMPARE(ctx->unitName(Axis::Y), QStringLiteral("mm"));
    // Zero: the current position becomes the work origin.
    m_f->window->positionPanel()->zeroAxis(Axis::Y);
    QCOMPARE(ctx->units(Axis::Y).workOffset, ctx->status().axes.value(Axis::Y).position);
    QCOMPARE(m_f->window->positionPanel()->displayedValue(Axis::Y), QStringLiteral("0.000"));
}

bool TestReferencePanel::referenceX()
{
    QSignalSpy finished(m_f->window->referencePanel()->runner(), &ui::ReferenceRunner::finished);
    m_f->window->referencePanel()->referenceAxis(Axis::X);
    return finished.wait(30000) && finished.first().at(0).toBool();
}

void TestReferencePanel::position_duringMove_estimateAndTargetNotReferenced()
{
    // E-LAB reports no position during a move; the core counts the target at once. The
    // read-out must show an estimate and the target, not the target as if reached.
    QVERIFY(referenceX());
    ui::PositionPanel* dro = m_f->window->positionPanel();
    QTRY_COMPARE(dro->stateText(Axis::X), QStringLiteral("REFERENCED"));
    m_f->session->moveRelative({{Axis::X, 8000}});
    QTRY_COMPARE_WITH_TIMEOUT(dro->stateText(Axis::X), QStringLiteral("MOVING"), 3000);
    QVERIFY(dro->detailText(Axis::X).contains(QStringLiteral("8000")));
    QVERIFY(m_f->simAxis(Axis::X).moving);
    // While it moves the value is an estimate between start and target.
    bool inBetween = false;
    QObject ctx;
    connect(m_f->session, &ControllerSession::statusChanged, &ctx, [&] {
        const QString shown = dro->displayedValue(Axis::X);
        if (dro->stateText(Axis::X) == QLatin1String("MOVING")) {
            QVERIFY(shown.startsWith(QStringLiteral("\u2248")));
            QVERIFY(dro->stateText(Axis::X) != QLatin1String("REFERENCED"));
            bool ok = false;
            const qint64 v = shown.mid(1).toLongLong(&ok);
            inBetween = inBetween || (ok && v > 0 && v < 8000);
        }
    });
    QTRY_COMPARE_WITH_TIMEOUT(dro->stateText(Axis::X), QStringLiteral("REFERENCED"), 15000);
    QVERIFY(inBetween);
    QCOMPARE(dro->displayedValue(Axis::X), QStringLiteral("8000"));
    QVERIFY(!m_f->simAxis(Axis::X).moving);
}

void TestReferencePanel::position_duringReferenceRun_saysReferencingNotMovingTo()
{
    // Issue 16: the read-out said "moving to 0" while the axis searched its switch.
    ui::PositionPanel* dro = m_f->window->positionPanel();
    QSignalSpy finished(m_f->window->referencePanel()->runner(), &ui::ReferenceRunner::finished);
    bool sawReferencing = false;
    QString wrongDetail;
    QObject ctx;
    connect(m_f->session, &ControllerSession::statusChanged, &ctx, [&] {
        if (!m_f->window->referencePanel()->runner()->isRunning())
            return;
        const QString detail = dro->detailText(Axis::X);
        if (dro->stateText(Axis::X) == QLatin1String("REFERENCING") &&
            detail == QStringLiteral("referencing\u2026") &&
            !dro->displayedValue(Axis::X).isEmpty())
            sawReferencing = true;
        else if (detail.contains(QStringLiteral("moving to")) && wrongDetail.isEmpty())
            wrongDetail = detail;
    });
    m_f->window->referencePanel()->referenceAxis(Axis::X);
    QVERIFY(finished.wait(30000));
    QVERIFY(finished.first().at(0).toBool());
    QVERIFY2(wrongDetail.isEmpty(), qPrintable(wrongDetail));
    QVERIFY(sawReferencing);
    QTRY_COMPARE(dro->stateText(Axis::X), QStringLiteral("REFERENCED"));
    QCOMPARE(dro->detailText(Axis::X), QStringLiteral("machine 0 steps"));
}

void TestReferencePanel::position_duringMove_rampUnknown_showsTargetNeverBlank()
{
    // Without the ramp parameters (a model whose names differ, or after a reset) there is no
    // estimate: the digits show the target, marked with an arrow, never a lone "≈".
    QVERIFY(referenceX());
    ui::PositionPanel* dro = m_f->window->positionPanel();
    QTRY_COMPARE(dro->stateText(Axis::X), QStringLiteral("REFERENCED"));
    m_f->window->context()->forgetKnownParameters();
    m_f->session->moveRelative({{Axis::X, 6000}});
    QTRY_COMPARE_WITH_TIMEOUT(dro->stateText(Axis::X), QStringLiteral("MOVING"), 3000);
    QCOMPARE(dro->displayedValue(Axis::X), QStringLiteral("\u21926000"));
    QVERIFY(dro->detailText(Axis::X).contains(QStringLiteral("6000")));
    QTRY_COMPARE_WITH_TIMEOUT(dro->stateText(Axis::X), QStringLiteral("REFERENCED"), 15000);
    QCOMPARE(dro->displayedValue(Axis::X), QStringLiteral("6000"));
}

void TestReferencePanel::position_disconnected_showsNoLinkNotReferenced()
{
    QVERIFY(referenceX());
    ui::PositionPanel* dro = m_f->window->positionPanel();
    QTRY_COMPARE(dro->stateText(Axis::X), QStringLiteral("REFERENCED"));
    m_f->window->context()->disconnectFromController();
    QTRY_VERIFY(!m_f->window->context()->isConnected());
    QTRY_COMPARE(dro->stateText(Axis::X), QStringLiteral("NO LINK"));
    for (Axis a : {Axis::X, Axis::Y, Axis::Z})
        QVERIFY(dro->stateText(a) != QLatin1String("REFERENCED"));
}

void TestReferencePanel::successMessage_afterPanic_replaced()
{
    QVERIFY(referenceX());
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    QVERIFY(panel->messageText().contains(QStringLiteral("referenced")));
    m_f->window->panicAction()->trigger();
    QVERIFY2(!panel->messageText().contains(QStringLiteral("are referenced")),
             qPrintable(panel->messageText()));
    QVERIFY(panel->messageText().contains(QStringLiteral("no longer referenced")));
}

void TestReferencePanel::referenceAll_laserAxes_finishOnTheirReports()
{
    // No poller: the runner learns the end of each stage from the request itself.
    ConnectionSpec spec{QStringLiteral("sim"), {}, {}};
    QString error;
    QVERIFY2(
        m_f->window->context()->connectTo(*findModel(QStringLiteral("laser-axis")), spec, &error),
        qPrintable(error));
    QVERIFY(m_f->waitConnected());
    QSignalSpy finished(m_f->window->referencePanel()->runner(), &ui::ReferenceRunner::finished);
    m_f->window->referencePanel()->referenceAll();
    QVERIFY(finished.wait(10000));
    QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
    bool homed = false;
    QVERIFY(m_f->withSimulatorAs<laser::LaserAxisSimulator>([&](laser::LaserAxisSimulator* s) {
        homed = s->isHomed(Axis::X) && s->isHomed(Axis::Y) && s->isHomed(Axis::Z);
    }));
    QVERIFY(homed);
    for (Axis a : {Axis::X, Axis::Y, Axis::Z})
        QVERIFY(m_f->window->context()->status().axes.value(a).referenced);
}

QTEST_MAIN(TestReferencePanel)
#include "tst_referencepanel.moc"
