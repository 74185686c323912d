// Soft limits on the E-LAB simulator (issue 11): a move beyond a limit is refused with the
// reason and the board receives no move command; a move inside goes; a jog pushed into the
// limit stops inside it (the simulated axis' position) and may move back; Go to position and
// Go to work zero move a referenced machine.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/IncrementalJogWidget.h"
#include "jog/JogPanel.h"
#include "machine/MachineGoTo.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestSoftLimitsUi : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup() { m_f.reset(); }
    void limits_refuseMovesAndStopJogInside();

private:
    int moveCommandsSince(qsizetype mark) const;
    qint64 hostX() const { return m_f->window->context()->status().axes.value(Axis::X).position; }
    std::unique_ptr<UiFixture> m_f;
};

void TestSoftLimitsUi::initTestCase()
{
    isolateSettings();
}

int TestSoftLimitsUi::moveCommandsSince(qsizetype mark) const
{
    // FastMove XYZ <EOT>, XY <FF>, Z <BS>.
    return int(m_f->deviceCommands(elab::ctrl::EOT, mark).size() +
               m_f->deviceCommands(elab::ctrl::FF, mark).size() +
               m_f->deviceCommands(elab::ctrl::BS, mark).size());
}

void TestSoftLimitsUi::limits_refuseMovesAndStopJogInside()
{
    QSettings settings; // X: -1000..3000 steps (the former dialog's keys)
    settings.setValue(QStringLiteral("softLimits/elab/X/rangeSet"), true);
    settings.setValue(QStringLiteral("softLimits/elab/X/minimum"), -1000);
    settings.setValue(QStringLiteral("softLimits/elab/X/maximum"), 3000);
    m_f = std::make_unique<UiFixture>();
    ui::MainWindow* w = m_f->window.get();
    w->show();
    QVERIFY(QTest::qWaitForWindowActive(w));
    QVERIFY(m_f->connectSim());
    QSignalSpy written(m_f->session, &ControllerSession::requestFinished);
    m_f->writeRampSetup(5000, 4000);
    QVERIFY(written.wait(3000));
    ui::ReferencePanel* panel = w->referencePanel();
    panel->referenceAll();
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 40000);
    QVERIFY2(panel->messageText().contains(QStringLiteral("referenced")),
             qPrintable(panel->messageText()));
    QTRY_VERIFY(!m_f->simAxis(Axis::X).moving);
    const qint64 offset = m_f->simAxis(Axis::X).position - hostX(); // board vs. machine steps

    // A step beyond the limit: refused, nothing reaches the board.
    qsizetype mark = m_f->deviceMark();
    w->jogPanel()->incremental()->setUnitStepSize(10000);
    w->jogPanel()->incremental()->machineButton(QStringLiteral("X"), +1)->click();
    QTRY_VERIFY2(w->jogPanel()->refusalLabel()->text().contains(QStringLiteral("soft limit")),
                 qPrintable(w->jogPanel()->refusalLabel()->text()));
    QCOMPARE(moveCommandsSince(mark), 0);
    QCOMPARE(m_f->simAxis(Axis::X).position, offset);

    // Go to a position inside: it goes there.
    ui::MachineGoTo* goTo = w->positionPanel()->machineGoTo();
    QVERIFY(goTo->goButton()->isEnabled());
    goTo->choose({QStringLiteral("X")});
    goTo->targetBox(QStringLiteral("X"))->setValue(2000);
    goTo->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::X).moving, 3000);
    QTRY_VERIFY_WITH_TIMEOUT(!m_f->simAxis(Axis::X).moving, 10000);
    QCOMPARE(m_f->simAxis(Axis::X).position - offset, qint64(2000));
    // ... and not beyond.
    QTRY_VERIFY(goTo->goButton()->isEnabled());
    mark = m_f->deviceMark();
    goTo->targetBox(QStringLiteral("X"))->setValue(5000);
    goTo->goButton()->click();
    QTRY_VERIFY2(goTo->resultText().contains(QStringLiteral("soft limit")),
                 qPrintable(goTo->resultText()));
    QCOMPARE(moveCommandsSince(mark), 0);

    // Jog pushed into the limit: stops inside it, says why, and may move back.
    m_f->gamepad->plug(true);
    m_f->gamepad->moveAxis(0, 1.0);
    m_f->gamepad->press(9, true);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::X).moving, 3000);
    QTRY_VERIFY2_WITH_TIMEOUT(
        w->jogPanel()->refusalLabel()->text().contains(QStringLiteral("jog stopped")) &&
            w->jogPanel()->refusalLabel()->text().contains(QStringLiteral("soft limit")),
        qPrintable(w->jogPanel()->refusalLabel()->text()), 10000);
    // Still pushed: it may creep up to the limit in single steps, never beyond.
    qint64 highest = std::numeric_limits<qint64>::min();
    const int from = m_f->statusCount;
    while (m_f->statusCount - from < 15) {
        highest = qMax(highest, m_f->simAxis(Axis::X).position - offset);
        QTest::qWait(20);
    }
    const qint64 stopped = m_f->simAxis(Axis::X).position - offset;
    QVERIFY2(highest <= 3000 && stopped > 2900,
             qPrintable(QStringLiteral("%1 / %2").arg(highest).arg(stopped)));
    QString why;
    m_f->gamepad->moveAxis(0, -1.0);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::X).position - offset < stopped - 100, 5000);
    m_f->gamepad->press(9, false);
    QVERIFY2(m_f->simStandsStill(Axis::X, 5, &why), qPrintable(why));
}

STEPDECK_TEST_MAIN(TestSoftLimitsUi)
#include "tst_softlimitsui.moc"
