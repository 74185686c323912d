// The window's STOP feedback (MachineControl, every connection a machine: issue 28, item 0)
// and refusals that end (issue 16): Esc during a jog says "stopped" only once the controller
// reported standstill -- checked against the simulated board, which must stand still when the
// words appear -- and a jog refusal for an active emergency stop goes when the emergency stop
// is released.
#include "../UiTestSupport.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "messages/StatusMessages.h"
#include <QLabel>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMachineControl : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void escDuringJog_saysStoppedOnlyAtDeviceStandstill();
    void escWhileIdle_stoppedSaidAfterTheStatusRead();
    void jogRefusal_emergencyStop_goesWhenReleased();

private:
    // Every text the status bar showed, with whether the simulated X axis was moving then.
    struct Shown
    {
        QString text;
        bool deviceMoving = false;
    };
    void recordMessages();
    std::unique_ptr<UiFixture> m_f;
    QList<Shown> m_shown;
};

void TestMachineControl::init()
{
    QSettings().clear();
    m_shown.clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectAndSetUp());
}

void TestMachineControl::recordMessages()
{
    // The device's state at the moment a text appears: read in the controller thread without
    // running the GUI's event loop (the simulator lives there).
    auto* messages = m_f->window->messages();
    QObject::connect(messages, &ui::StatusMessages::changed, messages, [this, messages] {
        Shown shown{messages->currentText(), false};
        QSemaphore done;
        m_f->session->withSimulator([&shown, &done](Simulator* s) {
            shown.deviceMoving = static_cast<elab::ElabSimulator*>(s)->isMoving(Axis::X);
            done.release();
        });
        done.tryAcquire(1, 5000);
        m_shown << shown;
    });
}

void TestMachineControl::escDuringJog_saysStoppedOnlyAtDeviceStandstill()
{
    recordMessages();
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(0.8, 0.0)));
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::X).moving, 5000);
    QTest::keyClick(m_f->window.get(), Qt::Key_Escape);
    QVERIFY2(m_f->window->lastError().startsWith(QStringLiteral("Stop sent")),
             qPrintable(m_f->window->lastError()));
    QTRY_VERIFY_WITH_TIMEOUT(
        m_f->window->lastError().startsWith(QStringLiteral("Stopped: every controller confirmed")),
        10000);
    pointerRelease(pad, pad->pointFor(QPointF(0.8, 0.0)));
    // When the words appeared, the board stood still -- and it stays so.
    bool said = false;
    for (const Shown& s : std::as_const(m_shown)) {
        if (!s.text.startsWith(QStringLiteral("Stopped")))
            continue;
        said = true;
        QVERIFY2(!s.deviceMoving, "'stopped' was said while the board still moved");
    }
    QVERIFY(said);
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 3, &why), qPrintable(why));
}

void TestMachineControl::escWhileIdle_stoppedSaidAfterTheStatusRead()
{
    // Sent first; "stopped" only once a status read after the acknowledgement showed the
    // board standing (here it never moved), never at the key press.
    recordMessages();
    QTest::keyClick(m_f->window.get(), Qt::Key_Escape);
    QVERIFY2(m_f->window->lastError().startsWith(QStringLiteral("Stop sent")),
             qPrintable(m_f->window->lastError()));
    QTRY_VERIFY(m_f->window->lastError().startsWith(QStringLiteral("Stopped:")));
    QVERIFY(m_shown.size() >= 2);
    QVERIFY(m_shown.first().text.startsWith(QStringLiteral("Stop sent")));
}

void TestMachineControl::jogRefusal_emergencyStop_goesWhenReleased()
{
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->setPanicButton(true); }));
    QTRY_VERIFY(m_f->window->context()->status().panic);
    QLabel* refusal = m_f->window->jogPanel()->refusalLabel();
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(0.6, 0.0)));
    QTRY_COMPARE(refusal->text(), QStringLiteral("Jog refused: emergency stop is active"));
    pointerRelease(pad, pad->pointFor(QPointF(0.6, 0.0)));
    QVERIFY(!m_f->simAxis(Axis::X).moving);
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->setPanicButton(false); }));
    QTRY_VERIFY(!m_f->window->context()->status().panic);
    // Gone with its cause, in the same status round, not by a timer seconds later.
    QCoreApplication::processEvents();
    QCOMPARE(refusal->text(), QString());
}

QTEST_MAIN(TestMachineControl)
#include "tst_machinecontrol.moc"
