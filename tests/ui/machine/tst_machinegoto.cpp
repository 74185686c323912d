// Go to position on the connection bar's E-LAB, a machine of one controller (issues 16 and 28,
// item 0): Enter in the target field moves like the Go button, with its checks; a second
// go-to while the first still moves sends nothing; "arrived" is said only once the board
// stands at the target, and Esc during a go-to says "stopped" only at the board's standstill.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "machine/MachineGoTo.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMachineGoTo : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void enter_inTargetField_movesLikeGo();
    void enter_whileMoving_sendsNothing();
    void arrived_saidAtDeviceStandstill();
    void escDuringGo_saysStoppedAtDeviceStandstill();

private:
    ui::MachineGoTo* goTo() const { return m_f->window->positionPanel()->machineGoTo(); }
    int movesSince(qsizetype mark) const
    {
        return int(m_f->deviceCommands(elab::ctrl::EOT, mark).size() +
                   m_f->deviceCommands(elab::ctrl::FF, mark).size() +
                   m_f->deviceCommands(elab::ctrl::BS, mark).size());
    }
    // As an operator does: typing a target checks its axis.
    void typeTarget(const QString& axis, const QString& text)
    {
        QDoubleSpinBox* box = goTo()->targetBox(axis);
        QVERIFY(box);
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, text);
        QVERIFY(goTo()->axisCheck(axis)->isChecked());
    }
    std::unique_ptr<UiFixture> m_f;
};

void TestMachineGoTo::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectSim());
    QSignalSpy written(m_f->session, &ControllerSession::requestFinished);
    m_f->writeRampSetup(3000, 2000);
    QVERIFY(written.wait(3000));
    // The carriages near their reference switches (the simulator's at -20000): short runs.
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            sim->setPosition(a, -19500);
    }));
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    panel->referenceAll();
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 40000);
    QVERIFY2(panel->messageText().contains(QStringLiteral("referenced")),
             qPrintable(panel->messageText()));
    QTRY_VERIFY(goTo()->goButton()->isEnabled());
}

void TestMachineGoTo::enter_inTargetField_movesLikeGo()
{
    typeTarget(QStringLiteral("X"), QStringLiteral("400"));
    const qsizetype mark = m_f->deviceMark();
    QTest::keyClick(goTo()->targetBox(QStringLiteral("X")), Qt::Key_Return);
    QTRY_COMPARE(movesSince(mark), 1);
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 2, &why), qPrintable(why));
    QTRY_COMPARE(m_f->window->context()->status().axes.value(Axis::X).position, qint64(400));
}

void TestMachineGoTo::enter_whileMoving_sendsNothing()
{
    typeTarget(QStringLiteral("X"), QStringLiteral("3000"));
    QTest::keyClick(goTo()->targetBox(QStringLiteral("X")), Qt::Key_Enter); // the keypad's
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    QVERIFY(!goTo()->goButton()->isEnabled());
    const qsizetype mark = m_f->deviceMark();
    typeTarget(QStringLiteral("Y"), QStringLiteral("200"));
    QTest::keyClick(goTo()->targetBox(QStringLiteral("Y")), Qt::Key_Return);
    QVERIFY2(goTo()->resultText().contains(QStringLiteral("still moving")),
             qPrintable(goTo()->resultText()));
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 2, &why), qPrintable(why));
    QCOMPARE(movesSince(mark), 0);
    QVERIFY(!m_f->simAxis(Axis::Y).moving);
}

void TestMachineGoTo::arrived_saidAtDeviceStandstill()
{
    // The message as it changes, with the board's state at that moment (controller thread).
    QList<QPair<QString, bool>> seen;
    QTimer probe;
    probe.setInterval(0);
    QString last;
    connect(&probe, &QTimer::timeout, this, [&] {
        const QString text = goTo()->resultText();
        if (text == last)
            return;
        last = text;
        seen.append({text, m_f->simAxis(Axis::X).moving});
    });
    probe.start();
    typeTarget(QStringLiteral("X"), QStringLiteral("2500"));
    goTo()->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo()->resultText() == QStringLiteral("X arrived."), 15000);
    probe.stop();
    // The wait above may have seen the last text before the probe did: the board now.
    if (goTo()->resultText() != last)
        seen.append({goTo()->resultText(), m_f->simAxis(Axis::X).moving});
    bool moving = false;
    bool arrived = false;
    for (const auto& [text, boardMoving] : std::as_const(seen)) {
        moving = moving || text.startsWith(QStringLiteral("Moving X to"));
        if (text == QStringLiteral("X arrived.")) {
            arrived = true;
            QVERIFY2(!boardMoving, "the arrival was said while the board still moved");
        }
    }
    QVERIFY(moving);
    QVERIFY(arrived);
    QCOMPARE(m_f->window->context()->status().axes.value(Axis::X).position, qint64(2500));
}

void TestMachineGoTo::escDuringGo_saysStoppedAtDeviceStandstill()
{
    typeTarget(QStringLiteral("X"), QStringLiteral("20000"));
    goTo()->goButton()->click();
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    QTest::keyClick(m_f->window.get(), Qt::Key_Escape);
    QVERIFY2(m_f->window->lastError().startsWith(QStringLiteral("Stop sent")),
             qPrintable(m_f->window->lastError()));
    QTRY_VERIFY_WITH_TIMEOUT(m_f->window->lastError().startsWith(QStringLiteral("Stopped:")),
                             10000);
    QVERIFY(!m_f->simAxis(Axis::X).moving); // said at standstill, not before
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 2, &why), qPrintable(why));
    QVERIFY(m_f->simAxis(Axis::X).position < 20000 - 19500); // stopped, not arrived
    // Never "arrived": it stands short of its target, or the move failed with the stop.
    QTRY_VERIFY2(goTo()->resultText().startsWith(QStringLiteral("X stopped at")) ||
                     goTo()->resultText().startsWith(QStringLiteral("Go-to failed")),
                 qPrintable(goTo()->resultText()));
}

STEPDECK_TEST_MAIN(TestMachineGoTo)
#include "tst_machinegoto.moc"
