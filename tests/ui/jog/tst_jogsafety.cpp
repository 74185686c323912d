// Issue 7, rules 3 and 4, asserted at the simulated E-LAB board: for each jog input
// (keyboard, on-screen pad, gamepad) and each way a jog ends (release, focus loss, a lost
// key-up / mouse release / gamepad sample, STOP, PANIC) the device's axis stands still and
// the device received the stop (zero jog rate, <XOFF> or <BEL>). After STOP, PANIC and focus
// loss the same input, still held, does not restart the axis until it has been released.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include "safety/SafetyBar.h"
#include <QCheckBox>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {

// Swallows the pad's mouse release: the window system saw it, the pad never does.
class EatRelease : public QObject
{
public:
    bool eventFilter(QObject*, QEvent* e) override
    {
        if (e->type() != QEvent::MouseButtonRelease)
            return false;
        ++eaten;
        return true;
    }
    int eaten = 0; // releases the pad never saw
};
} // namespace

class TestJogSafety : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void jogEnds_deviceStandsStill_data();
    void jogEnds_deviceStandsStill();
    void keyboard_autoRepeat_keepsJoggingPastTheLease();
    void gamepad_freshSamples_keepJoggingPastTheLease();

private:
    void engage(const QString& source);
    void endBy(const QString& source, const QString& how);
    void keepHolding(const QString& source);
    void letGo(const QString& source);
    bool xRateSentSince(qsizetype mark) const;
    ui::JoystickPad* pad() const { return m_f->window->jogPanel()->xyPad(); }

    std::unique_ptr<UiFixture> m_f;
    std::unique_ptr<KeyRepeater> m_repeat;
    std::unique_ptr<QWidget> m_other;
    EatRelease m_eatRelease;
};

void TestJogSafety::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectAndSetUp());
}

void TestJogSafety::cleanup()
{
    m_repeat.reset();
    m_other.reset();
    if (m_f && pad())
        pad()->removeEventFilter(&m_eatRelease);
    if (QGuiApplication::mouseButtons() & Qt::LeftButton)
        QTest::mouseRelease(m_f->window->windowHandle(), Qt::LeftButton);
    m_f.reset();
}

void TestJogSafety::engage(const QString& source)
{
    if (source == QLatin1String("keyboard")) {
        m_f->window->jogPanel()->keyboardCheck()->setChecked(true);
        m_f->window->jogPanel()->setFocus();
        QTRY_VERIFY(m_f->window->jogPanel()->hasFocus());
        QTest::keyPress(m_f->window->jogPanel(), Qt::Key_Right);
        m_repeat = std::make_unique<KeyRepeater>(Qt::Key_Right);
        m_repeat->start();
    } else if (source == QLatin1String("pad")) {
        pointerPress(pad(), pad()->centre());
        pointerMove(pad(), pad()->pointFor(QPointF(1.0, 0.0)));
    } else {
        m_f->gamepad->plug(true);
        m_f->gamepad->moveAxis(kLeftX, 1.0);
        m_f->gamepad->press(kDeadman, true);
    }
    QTRY_VERIFY_WITH_TIMEOUT(m_f->commanded(Axis::X) > 0, 5000);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::X).moving, 5000);
}

void TestJogSafety::endBy(const QString& source, const QString& how)
{
    const bool keyboard = source == QLatin1String("keyboard");
    const bool padSource = source == QLatin1String("pad");
    ui::SafetyBar* bar = m_f->window->safetyBar();
    if (how == QLatin1String("release")) {
        if (keyboard) {
            m_repeat->stop();
            QTest::keyRelease(QApplication::focusWidget(), Qt::Key_Right);
        } else if (padSource) {
            pointerRelease(pad(), pad()->pointFor(QPointF(1.0, 0.0)));
        } else {
            m_f->gamepad->press(kDeadman, false);
        }
    } else if (how == QLatin1String("focus loss")) {
        m_other = std::make_unique<QWidget>();
        m_other->resize(200, 100);
        m_other->show();
        m_other->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_other.get()));
    } else if (how == QLatin1String("lost release")) {
        if (keyboard) {
            m_repeat->stop(); // the key-up never arrives; the repeats end with the key
        } else if (padSource) {
            m_eatRelease.eaten = 0;
            pad()->installEventFilter(&m_eatRelease);
            pointerRelease(pad(), pad()->pointFor(QPointF(1.0, 0.0)));
            QCOMPARE(QGuiApplication::mouseButtons() & Qt::LeftButton, Qt::NoButton);
            // The pad itself never saw the release. (Whether it still drags here depends on
            // whether the jog loop's next tick, which ends a drag whose button is up, ran while
            // the release was delivered: under load it may have.)
            QCOMPARE(m_eatRelease.eaten, 1);
        } else {
            m_f->gamepad->setSampling(false); // stick and dead-man stay put, samples stop
        }
    } else if (how == QLatin1String("STOP")) {
        // The pointer drags the pad: its STOP comes from the keyboard, the others click.
        if (padSource)
            QTest::keyClick(m_f->window.get(), Qt::Key_Escape);
        else
            pointerClick(bar->stopButton());
    } else if (how == QLatin1String("PANIC")) {
        if (padSource)
            QTest::keyClick(m_f->window.get(), Qt::Key_F1);
        else
            pointerClick(bar->panicButton());
    }
}

// The input stays held (and busy) after STOP/PANIC/focus loss, and the window comes back.
void TestJogSafety::keepHolding(const QString& source)
{
    if (m_other) {
        m_other->hide();
        m_f->window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    }
    if (source == QLatin1String("pad")) {
        pointerMove(pad(), pad()->pointFor(QPointF(0.8, 0.1)));
        pointerMove(pad(), pad()->pointFor(QPointF(1.0, 0.0)));
    } else if (source == QLatin1String("gamepad")) {
        m_f->gamepad->moveAxis(kLeftX, 0.9);
        m_f->gamepad->moveAxis(kLeftX, 1.0);
    } // keyboard: the repeater keeps sending the held key's auto-repeat
}

void TestJogSafety::letGo(const QString& source)
{
    if (source == QLatin1String("keyboard")) {
        m_repeat->stop();
        QTest::keyRelease(QApplication::focusWidget(), Qt::Key_Right);
    } else if (source == QLatin1String("pad")) {
        pointerRelease(pad(), pad()->pointFor(QPointF(1.0, 0.0)));
    } else {
        m_f->gamepad->moveAxis(kLeftX, 0.0);
    }
}

bool TestJogSafety::xRateSentSince(qsizetype mark) const
{
    for (const elab::Command& c : m_f->deviceCommands(elab::ctrl::DC4, mark)) {
        if (c.values[0] != 0)
            return true;
    }
    return false;
}

void TestJogSafety::jogEnds_deviceStandsStill_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("how");
    for (const char* source : {"keyboard", "pad", "gamepad"}) {
        for (const char* how : {"release", "focus loss", "lost release", "STOP", "PANIC"})
            QTest::addRow("%s, %s", source, how)
                << QString::fromLatin1(source) << QString::fromLatin1(how);
    }
}

void TestJogSafety::jogEnds_deviceStandsStill()
{
    QFETCH(QString, source);
    QFETCH(QString, how);
    engage(source);
    const qsizetype ended = m_f->deviceMark();
    endBy(source, how);

    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 8, &why), qPrintable(why));
    // What the device was told.
    if (how == QLatin1String("STOP")) {
        QVERIFY2(m_f->deviceBytes().mid(ended).contains(elab::ctrl::XOFF), "no ForceStopMove");
    } else if (how == QLatin1String("PANIC")) {
        QVERIFY2(m_f->deviceBytes().mid(ended).contains(elab::ctrl::BEL), "no ForcePanicStop");
    } else {
        const QList<elab::Command> jog = m_f->deviceCommands(elab::ctrl::DC4, ended);
        QVERIFY2(!jog.isEmpty(), "no jog rate after the end");
        QCOMPARE(jog.last().values[0], qint64(0)); // the board was told rate 0
    }
    QVERIFY(!m_f->window->jogController()->isJogging());
    if (how == QLatin1String("release") || how == QLatin1String("lost release"))
        return;

    // Latched: the same input, still held, does not restart the axis...
    const qsizetype held = m_f->deviceMark();
    keepHolding(source);
    QVERIFY2(m_f->simStandsStill(Axis::X, 10, &why), qPrintable(why));
    QVERIFY2(!xRateSentSince(held), "a held input restarted the jog");
    if (how == QLatin1String("PANIC"))
        return; // jog stays refused until the panic is cleared by a reference run
    // ... until it has been released; then it jogs again.
    letGo(source);
    engage(source);
}

void TestJogSafety::keyboard_autoRepeat_keepsJoggingPastTheLease()
{
    m_f->window->jogPanel()->keyboardCheck()->setChecked(true);
    m_f->window->jogPanel()->setFocus();
    QTRY_VERIFY(m_f->window->jogPanel()->hasFocus());
    QTest::keyPress(m_f->window->jogPanel(), Qt::Key_Right);
    // The first repeat comes after the platform's delay (500-660 ms on common desktops),
    // longer than the core's 300 ms lease: the press itself carries the jog until then.
    KeyRepeater repeat(Qt::Key_Right);
    QTimer::singleShot(450, &repeat, [&repeat] { repeat.start(); });
    const double target = m_f->window->keyboardJog()->speedFraction() *
                          m_f->window->jogController()->maxSpeed(ui::JogSlot::PadHorizontal);
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::X), target, 5000);
    double slowest = target;
    QObject ctx;
    connect(m_f->session, &ControllerSession::statusChanged, &ctx, [&](const MachineStatus& s) {
        slowest = qMin(slowest, s.axes.value(Axis::X).commandedVelocity);
    });
    const qint64 from = m_f->simAxis(Axis::X).position;
    QTRY_VERIFY_WITH_TIMEOUT(repeat.sent() >= 40, 10000); // well past lease and first window
    QCOMPARE(slowest, target);                            // never dipped
    QVERIFY(m_f->simAxis(Axis::X).moving);
    QVERIFY(m_f->simAxis(Axis::X).position > from);
    // The key-up is lost: the repeats end, and so does the jog.
    repeat.stop();
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 8, &why), qPrintable(why));
    QCOMPARE(m_f->deviceCommands(elab::ctrl::DC4).last().values[0], qint64(0));
}

void TestJogSafety::gamepad_freshSamples_keepJoggingPastTheLease()
{
    m_f->gamepad->plug(true);
    m_f->gamepad->moveAxis(kLeftX, 1.0);
    m_f->gamepad->press(kDeadman, true);
    const double max = m_f->window->jogController()->maxSpeed(ui::JogSlot::PadHorizontal);
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::X), max, 5000);
    double slowest = max;
    QObject ctx;
    connect(m_f->session, &ControllerSession::statusChanged, &ctx, [&](const MachineStatus& s) {
        slowest = qMin(slowest, s.axes.value(Axis::X).commandedVelocity);
    });
    const int samples = m_f->gamepad->samples();
    QTRY_VERIFY_WITH_TIMEOUT(m_f->gamepad->samples() - samples >= 60, 10000);
    QCOMPARE(slowest, max);
    QVERIFY(m_f->simAxis(Axis::X).moving);
    m_f->gamepad->press(kDeadman, false);
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 8, &why), qPrintable(why));
}

STEPDECK_TEST_MAIN(TestJogSafety)
#include "tst_jogsafety.moc"
