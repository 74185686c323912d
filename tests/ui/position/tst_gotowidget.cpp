// Go to position (issue 16): Enter in a target field moves like the Go button, with its checks;
// "Move accepted" gives way once the controller reports the axes at standstill -- never while
// the simulated board still moves -- and Esc during a Go says "stopped" only at standstill.
#include "../UiTestSupport.h"
#include "position/GoToWidget.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "position/ReferenceRunner.h"
#include <QLineEdit>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestGoToWidget : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void enter_inTargetField_movesLikeGo();
    void enter_whileMoving_sendsNothing();
    void moveAccepted_replacedAtDeviceStandstill();
    void escDuringGo_saysStoppedAtDeviceStandstill();

private:
    ui::GoToWidget* goTo() const { return m_f->window->positionPanel()->goTo(); }
    int movesSince(qsizetype mark) const
    {
        return int(m_f->deviceCommands(elab::ctrl::EOT, mark).size() +
                   m_f->deviceCommands(elab::ctrl::FF, mark).size() +
                   m_f->deviceCommands(elab::ctrl::BS, mark).size());
    }
    void typeTarget(Axis axis, const QString& text)
    {
        QLineEdit* edit = goTo()->target(axis);
        edit->setFocus();
        edit->selectAll();
        QTest::keyClicks(edit, text);
    }
    std::unique_ptr<UiFixture> m_f;
};

void TestGoToWidget::init()
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
    QSignalSpy referenced(m_f->window->referencePanel()->runner(), &ui::ReferenceRunner::finished);
    m_f->window->referencePanel()->referenceAll();
    QVERIFY(referenced.wait(40000));
    QVERIFY(referenced.first().at(0).toBool());
    QTRY_VERIFY(goTo()->goButton()->isEnabled());
}

void TestGoToWidget::enter_inTargetField_movesLikeGo()
{
    typeTarget(Axis::X, QStringLiteral("400"));
    const qsizetype mark = m_f->deviceMark();
    QTest::keyClick(goTo()->target(Axis::X), Qt::Key_Return);
    QTRY_COMPARE(movesSince(mark), 1);
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 2, &why), qPrintable(why));
    QTRY_COMPARE(m_f->window->context()->status().axes.value(Axis::X).position, qint64(400));
}

void TestGoToWidget::enter_whileMoving_sendsNothing()
{
    typeTarget(Axis::X, QStringLiteral("3000"));
    QTest::keyClick(goTo()->target(Axis::X), Qt::Key_Enter); // the keypad's Enter
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    QTRY_VERIFY(!goTo()->goButton()->isEnabled());
    const qsizetype mark = m_f->deviceMark();
    typeTarget(Axis::Y, QStringLiteral("200"));
    QTest::keyClick(goTo()->target(Axis::Y), Qt::Key_Return);
    QVERIFY2(goTo()->messageText().contains(QStringLiteral("moving"), Qt::CaseInsensitive) ||
                 goTo()->messageText().contains(QStringLiteral("accepted")),
             qPrintable(goTo()->messageText()));
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 2, &why), qPrintable(why));
    QCOMPARE(movesSince(mark), 0);
    QVERIFY(!m_f->simAxis(Axis::Y).moving);
}

void TestGoToWidget::moveAccepted_replacedAtDeviceStandstill()
{
    // The message as it changes, with the board's state at that moment (controller thread).
    QList<QPair<QString, bool>> seen;
    QTimer probe;
    probe.setInterval(0);
    QString last;
    connect(&probe, &QTimer::timeout, this, [&] {
        const QString text = goTo()->messageText();
        if (text == last)
            return;
        last = text;
        QSemaphore done;
        bool moving = false;
        m_f->session->withSimulator([&](Simulator* s) {
            moving = static_cast<elab::ElabSimulator*>(s)->isMoving(Axis::X);
            done.release();
        });
        done.tryAcquire(1, 5000);
        seen.append({text, moving});
    });
    probe.start();
    typeTarget(Axis::X, QStringLiteral("2500"));
    goTo()->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo()->messageText().startsWith(QStringLiteral("The move has ended")),
                             15000);
    probe.stop();
    bool accepted = false;
    bool ended = false;
    for (const auto& [text, moving] : std::as_const(seen)) {
        accepted = accepted || text == QStringLiteral("Move accepted by the controller.");
        if (text.startsWith(QStringLiteral("The move has ended"))) {
            ended = true;
            QVERIFY2(!moving, "the end was said while the board still moved");
        }
    }
    QVERIFY(accepted);
    QVERIFY(ended);
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 2, &why), qPrintable(why));
}

void TestGoToWidget::escDuringGo_saysStoppedAtDeviceStandstill()
{
    typeTarget(Axis::X, QStringLiteral("20000"));
    goTo()->goButton()->click();
    QTRY_COMPARE(goTo()->messageText(), QStringLiteral("Move accepted by the controller."));
    QVERIFY(m_f->simAxis(Axis::X).moving);
    QTest::keyClick(m_f->window.get(), Qt::Key_Escape);
    QVERIFY2(m_f->window->lastError().startsWith(QStringLiteral("Stop sent")),
             qPrintable(m_f->window->lastError()));
    QTRY_VERIFY_WITH_TIMEOUT(
        m_f->window->lastError().startsWith(QStringLiteral("Stopped: the controller reports")),
        10000);
    QVERIFY(!m_f->simAxis(Axis::X).moving); // said at standstill, not before
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 2, &why), qPrintable(why));
    QVERIFY(m_f->simAxis(Axis::X).position < 20000); // it was stopped, not arrived
    QTRY_VERIFY(goTo()->messageText().startsWith(QStringLiteral("The move has ended")));
}

QTEST_MAIN(TestGoToWidget)
#include "tst_gotowidget.moc"
