// Issue 16 blocker, safety contract rule 6, asserted at the in-process E-LAB simulator: a held
// jog never reverses and never moves another axis when the layout moves under the input.
// Seen before the fix: a message grew the status bar, the pad jumped up under the held
// pointer, the pointer was now below the pad's centre and +Y became -1000 steps/s.
//
// For each input (XY pad, Z stick, keyboard, gamepad) and each layout change (the widgets
// above the pad give way and it moves up, the window shrinks, a long error is shown) the
// device receives jog rates of the held direction or zero, never the opposite sign and never
// another axis. A pointer input whose pad moved ends its jog (the device ramps to zero and
// stands still while the button is still held) and stays ended until the button is released.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include <QCheckBox>
#include <QLabel>
#include <QVBoxLayout>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
constexpr int kSpacerHeight = 260;

int valueIndex(Axis axis)
{
    return axis == Axis::X ? 0 : axis == Axis::Y ? 1 : 2;
}
} // namespace

class TestJogHoldStill : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void heldInput_layoutChanges_neverReverses_data();
    void heldInput_layoutChanges_neverReverses();
    void pad_frameChangedWhileHeld_endsDragUntilRelease();

private:
    ui::JoystickPad* padOf(const QString& source) const;
    Axis axisOf(const QString& source) const;
    void engage(const QString& source);
    void change(const QString& how);
    void holdStill(const QString& source);
    void letGo(const QString& source);
    QString wrongRates(qsizetype mark, Axis axis) const;
    static void settle()
    {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
    }

    std::unique_ptr<UiFixture> m_f;
    std::unique_ptr<KeyRepeater> m_repeat;
    QWidget* m_spacer = nullptr;
    QPoint m_heldAt; // the pointer, in window coordinates: the operator's hand holds still
};

void TestJogHoldStill::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    ui::MainWindow* w = m_f->window.get();
    // Room above the jog panel that can give way: the pad moves up by up to kSpacerHeight.
    m_spacer = new QWidget(w->centralWidget());
    m_spacer->setFixedHeight(kSpacerHeight);
    static_cast<QVBoxLayout*>(w->centralWidget()->layout())->insertWidget(0, m_spacer);
    w->show();
    w->resize(1366, 768);
    QVERIFY(QTest::qWaitForWindowActive(w));
    QVERIFY(m_f->connectAndSetUp());
    settle();
}

void TestJogHoldStill::cleanup()
{
    if (m_repeat)
        m_repeat->stop();
    m_repeat.reset();
    if (m_f && (QGuiApplication::mouseButtons() & Qt::LeftButton))
        QTest::mouseRelease(m_f->window->windowHandle(), Qt::LeftButton, Qt::NoModifier, m_heldAt);
    m_f.reset();
    m_spacer = nullptr;
}

ui::JoystickPad* TestJogHoldStill::padOf(const QString& source) const
{
    if (source == QLatin1String("XY pad"))
        return m_f->window->jogPanel()->xyPad();
    if (source == QLatin1String("Z stick"))
        return m_f->window->jogPanel()->zStick();
    return nullptr;
}

Axis TestJogHoldStill::axisOf(const QString& source) const
{
    if (source == QLatin1String("XY pad") || source == QLatin1String("keyboard"))
        return Axis::Y;
    if (source == QLatin1String("Z stick"))
        return Axis::Z;
    return Axis::X; // gamepad: left stick X
}

void TestJogHoldStill::engage(const QString& source)
{
    if (ui::JoystickPad* pad = padOf(source)) {
        // A small deflection towards +: a layout that moves the pad up by more than this
        // puts the held pointer below the pad's centre.
        pointerPress(pad, pad->centre());
        const QPoint target = pad->pointFor(QPointF(0.0, 0.3)).toPoint();
        pointerMove(pad, target);
        m_heldAt = pad->mapTo(pad->window(), target);
    } else if (source == QLatin1String("keyboard")) {
        m_f->window->jogPanel()->keyboardCheck()->setChecked(true);
        m_f->window->jogPanel()->setFocus();
        QTRY_VERIFY(m_f->window->jogPanel()->hasFocus());
        QTest::keyPress(m_f->window->jogPanel(), Qt::Key_Up);
        m_repeat = std::make_unique<KeyRepeater>(Qt::Key_Up);
        m_repeat->start();
    } else {
        m_f->gamepad->plug(true);
        m_f->gamepad->moveAxis(kLeftX, 0.6);
        m_f->gamepad->press(kDeadman, true);
    }
    const Axis axis = axisOf(source);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->commanded(axis) > 0, 5000);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(axis).moving, 5000);
}

void TestJogHoldStill::change(const QString& how)
{
    ui::MainWindow* w = m_f->window.get();
    if (how == QLatin1String("widgets above give way"))
        m_spacer->hide();
    else if (how == QLatin1String("window shrinks"))
        w->resize(w->width(), w->height() - 200);
    else
        w->showError(
            QStringLiteral("Jog refused: below the drive's start frequency. ").repeated(8));
    settle();
}

// The hand holds still; the pointer jitters by a pixel (a real hand does), which makes the pad
// compute its deflection again. Meanwhile the jog lease is renewed several times.
void TestJogHoldStill::holdStill(const QString& source)
{
    if (padOf(source)) {
        QTest::mouseMove(m_f->window->windowHandle(), m_heldAt + QPoint(1, 0));
        QTest::mouseMove(m_f->window->windowHandle(), m_heldAt);
    }
    const int from = m_f->statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - from >= 8, 10000);
    if (padOf(source))
        QTest::mouseMove(m_f->window->windowHandle(), m_heldAt + QPoint(0, 1));
}

void TestJogHoldStill::letGo(const QString& source)
{
    if (padOf(source)) {
        QTest::mouseRelease(m_f->window->windowHandle(), Qt::LeftButton, Qt::NoModifier, m_heldAt);
    } else if (source == QLatin1String("keyboard")) {
        m_repeat->stop();
        QTest::keyRelease(QApplication::focusWidget(), Qt::Key_Up);
    } else {
        m_f->gamepad->press(kDeadman, false);
    }
}

// Every jog rate the device received since `mark`: the held axis at zero or positive, every
// other axis at zero. Empty if so, else the first offending command.
QString TestJogHoldStill::wrongRates(qsizetype mark, Axis axis) const
{
    for (const elab::Command& c : m_f->deviceCommands(elab::ctrl::DC4, mark)) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
            const qint64 v = c.values[size_t(valueIndex(a))];
            if ((a == axis && v < 0) || (a != axis && v != 0))
                return QStringLiteral("device received %1 (axis %2 at %3)")
                    .arg(QString::fromLatin1(c.raw.toHex(' ')), axisName(a))
                    .arg(v);
        }
    }
    return {};
}

void TestJogHoldStill::heldInput_layoutChanges_neverReverses_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("how");
    for (const char* source : {"XY pad", "Z stick", "keyboard", "gamepad"}) {
        for (const char* how : {"widgets above give way", "window shrinks", "long error shown"})
            QTest::addRow("%s, %s", source, how)
                << QString::fromLatin1(source) << QString::fromLatin1(how);
    }
}

void TestJogHoldStill::heldInput_layoutChanges_neverReverses()
{
    QFETCH(QString, source);
    QFETCH(QString, how);
    const Axis axis = axisOf(source);
    ui::JoystickPad* pad = padOf(source);
    engage(source);
    const QRect frameBefore = pad ? QRect(pad->mapToGlobal(QPoint(0, 0)), pad->size()) : QRect();
    const qsizetype mark = m_f->deviceMark();

    change(how);
    const bool padMoved = pad && QRect(pad->mapToGlobal(QPoint(0, 0)), pad->size()) != frameBefore;
    if (pad && how == QLatin1String("widgets above give way")) {
        // The situation that reversed the jog: the still-held pointer is now on the other
        // side of the pad's centre.
        QVERIFY(padMoved);
        QVERIFY2(pad->mapTo(pad->window(), pad->centre().toPoint()).y() < m_heldAt.y(),
                 "the layout change did not put the held pointer below the pad's centre");
    }
    holdStill(source);

    const QString wrong = wrongRates(mark, axis);
    QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
    QString why;
    if (padMoved) {
        // The pointer is still held, the jog is over: ramped to zero at the device.
        QVERIFY(QGuiApplication::mouseButtons() & Qt::LeftButton);
        QVERIFY(!pad->isDragging());
        QVERIFY2(m_f->simStandsStill(axis, 4, &why), qPrintable(why));
        QCOMPARE(m_f->deviceCommands(elab::ctrl::DC4, mark).last().values[size_t(valueIndex(axis))],
                 qint64(0));
        QVERIFY(!m_f->window->jogPanel()->refusalLabel()->text().isEmpty()); // says why
    } else {
        // Nothing under the input moved: the jog goes on in the same direction.
        QVERIFY(m_f->simAxis(axis).moving);
        QVERIFY(m_f->commanded(axis) > 0);
    }
    letGo(source);
    QVERIFY2(m_f->simStandsStill(axis, 4, &why), qPrintable(why));
    const QString wrongAfter = wrongRates(mark, axis);
    QVERIFY2(wrongAfter.isEmpty(), qPrintable(wrongAfter));
}

// The latch: after the pad moved under it, the still-held pointer moves nothing, wherever it
// goes; a new press jogs again.
void TestJogHoldStill::pad_frameChangedWhileHeld_endsDragUntilRelease()
{
    ui::JoystickPad* pad = m_f->window->jogPanel()->xyPad();
    engage(QStringLiteral("XY pad"));
    QSignalSpy interrupted(pad, &ui::JoystickPad::dragInterrupted);
    change(QStringLiteral("widgets above give way"));
    QCOMPARE(interrupted.count(), 1);
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::Y, 4, &why), qPrintable(why));

    const qsizetype mark = m_f->deviceMark();
    for (const QPointF d : {QPointF(0.0, 0.9), QPointF(0.9, 0.0), QPointF(0.0, -0.9)})
        pointerMove(pad, pad->pointFor(d));
    const int from = m_f->statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - from >= 6, 10000);
    for (const elab::Command& c : m_f->deviceCommands(elab::ctrl::DC4, mark))
        QVERIFY2(c.values[0] == 0 && c.values[1] == 0 && c.values[2] == 0,
                 "the still-held pointer jogged after the pad moved");
    QVERIFY(m_f->simStandsStill(Axis::X, 2, &why));
    QVERIFY(m_f->simStandsStill(Axis::Y, 2, &why));

    // Released and pressed again: the pad jogs, measured against where it is now.
    QTest::mouseRelease(m_f->window->windowHandle(), Qt::LeftButton, Qt::NoModifier, m_heldAt);
    pointerPress(pad, pad->centre());
    pointerMove(pad, pad->pointFor(QPointF(0.0, 0.5)));
    m_heldAt = pad->mapTo(pad->window(), pad->pointFor(QPointF(0.0, 0.5)).toPoint());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->commanded(Axis::Y) > 0, 5000);
    QTest::mouseRelease(m_f->window->windowHandle(), Qt::LeftButton, Qt::NoModifier, m_heldAt);
    QVERIFY2(m_f->simStandsStill(Axis::Y, 4, &why), qPrintable(why));
}

STEPDECK_TEST_MAIN(TestJogHoldStill)
#include "tst_jogholdstill.moc"
