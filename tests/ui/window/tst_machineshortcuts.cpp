// Issue 47, item 6 (safety): the keys of actions that move the machine or change its link do
// not fire while a text field has the focus. Ctrl+H typed into the program editor started
// Reference all, Ctrl+K disconnected. In the program editor, the MDI line, a form's line edit
// and a spin box the key now goes to the field and the simulated board sees nothing: no <US>
// reference move, its axes standing, the link still up. With the focus on a widget that takes
// no text the same keys work, and STOP (Esc) and PANIC (F1) work from the text fields too, on
// a reference run under way (tst_safetyshortcuts has them from the other fields and dialogs).
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/JogPanel.h"
#include "position/ReferencePanel.h"
#include "program/MdiLine.h"
#include "program/ProgramEditor.h"
#include "program/ProgramPage.h"
#include "setup/ParameterField.h"
#include "setup/SetupPage.h"
#include "window/MachineShortcutGuard.h"
#include <QAction>
#include <QKeyEvent>
#include <QKeySequence>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSpinBox>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
// Counts the key presses of one key combination that reach a widget: the proof that a key
// went to the text field instead of being taken by a shortcut.
class KeyPressCounter : public QObject
{
public:
    KeyPressCounter(QWidget* target, const QKeySequence& keys) : m_keys(keys)
    {
        target->installEventFilter(this);
    }
    int count() const { return m_count; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::KeyPress) {
            const auto* key = static_cast<QKeyEvent*>(event);
            const QKeySequence pressed(QKeyCombination(key->modifiers(), Qt::Key(key->key())));
            if (pressed == m_keys)
                ++m_count;
        }
        return QObject::eventFilter(watched, event);
    }

private:
    QKeySequence m_keys;
    int m_count = 0;
};
} // namespace

class TestMachineShortcuts : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void guard_coversMachineActionsNotStopOrPanic();
    void shortcut_inProgramEditor_doesNotFire_data() { machineKeys(); }
    void shortcut_inProgramEditor_doesNotFire();
    void shortcut_inMdiLine_doesNotFire_data() { machineKeys(); }
    void shortcut_inMdiLine_doesNotFire();
    void shortcut_inFormLineEdit_doesNotFire_data() { machineKeys(); }
    void shortcut_inFormLineEdit_doesNotFire();
    void shortcut_inSpinBox_doesNotFire_data() { machineKeys(); }
    void shortcut_inSpinBox_doesNotFire();
    void shortcut_referenceAllOutsideTextField_fires();
    void shortcut_disconnectOutsideTextField_fires();
    void stopKeys_inTextField_stopTheReferenceRun_data();
    void stopKeys_inTextField_stopTheReferenceRun();

private:
    // Rows that differ only by the shortcut: every key of an action that moves the machine or
    // changes its link.
    static void machineKeys();
    QWidget* field(const QString& which) const;
    // Focuses the field, types the row's key into it and checks that the key reached the
    // field while the machine saw nothing of it.
    void typeIntoFieldExpectNothing(const QString& which);
    // A reference run under way: Z travels towards its switch at the board.
    void startReferenceRun();
    std::unique_ptr<UiFixture> m_f;
};

void TestMachineShortcuts::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectAndSetUp()); // the board refuses motion without its ramp setup
}

void TestMachineShortcuts::machineKeys()
{
    QTest::addColumn<QKeySequence>("keys");
    QTest::newRow("Ctrl+H reference all") << QKeySequence(Qt::CTRL | Qt::Key_H);
    QTest::newRow("Ctrl+K disconnect") << QKeySequence(Qt::CTRL | Qt::Key_K);
}

QWidget* TestMachineShortcuts::field(const QString& which) const
{
    ui::MainWindow* w = m_f->window.get();
    ui::ProgramPage* program = w->programPage();
    if (which == QLatin1String("program editor")) {
        w->raisePage(program);
        program->editor()->setPlainText(QStringLiteral("G21 G90\nG0 X10 Y5\n"));
        return program->editor();
    }
    if (which == QLatin1String("MDI line")) {
        w->raisePage(program);
        program->mdiLine()->lineEdit()->setText(QStringLiteral("G0 X10"));
        return program->mdiLine()->lineEdit();
    }
    if (which == QLatin1String("form line edit")) {
        w->raisePage(w->setupPage());
        return w->setupPage()->field(QStringLiteral("max-speed"), Axis::Y)->lineEdit();
    }
    if (which == QLatin1String("spin box")) {
        w->raisePage(program);
        return program->findChild<QSpinBox*>(QStringLiteral("programFeedOverride"));
    }
    return nullptr;
}

void TestMachineShortcuts::typeIntoFieldExpectNothing(const QString& which)
{
    QFETCH(QKeySequence, keys);
    ui::MainWindow* w = m_f->window.get();
    // Both actions could fire now: what holds them back below is the text field alone.
    QVERIFY(w->referenceAction()->isEnabled());
    QVERIFY(w->connectAction()->isEnabled());
    QVERIFY(w->referenceAction()->shortcuts().contains(keys) ||
            w->connectAction()->shortcuts().contains(keys));
    QWidget* target = field(which);
    QVERIFY(target);
    target->setFocus();
    QTRY_VERIFY(target->hasFocus());
    QVERIFY(ui::MachineShortcutGuard::textFieldHasFocus());
    QSignalSpy references(w->referenceAction(), &QAction::triggered);
    QSignalSpy connects(w->connectAction(), &QAction::triggered);
    KeyPressCounter reached(target, keys);
    const qsizetype mark = m_f->deviceMark();

    QTest::keySequence(target, keys);
    QTest::qWait(500); // a reference run's first <US> is out within a few milliseconds

    QCOMPARE(reached.count(), 1); // the key went to the text field
    QCOMPARE(references.size(), 0);
    QCOMPARE(connects.size(), 0);
    QVERIFY(!w->referencePanel()->isRunning());
    QVERIFY(w->context()->isConnected());
    // At the board: no reference move arrived and nothing moves.
    QVERIFY(m_f->deviceCommands(elab::ctrl::US, mark).isEmpty());
    for (Axis a : {Axis::X, Axis::Y, Axis::Z})
        QVERIFY2(!m_f->simAxis(a).moving, qPrintable(axisName(a)));
}

void TestMachineShortcuts::guard_coversMachineActionsNotStopOrPanic()
{
    ui::MainWindow* w = m_f->window.get();
    const ui::MachineShortcutGuard* guard = w->machineShortcuts();
    QVERIFY(guard);
    QVERIFY(guard->guards(w->referenceAction()));
    QVERIFY(guard->guards(w->connectAction()));
    QVERIFY(!guard->guards(w->stopAction()));
    QVERIFY(!guard->guards(w->panicAction()));
}

void TestMachineShortcuts::shortcut_inProgramEditor_doesNotFire()
{
    typeIntoFieldExpectNothing(QStringLiteral("program editor"));
}

void TestMachineShortcuts::shortcut_inMdiLine_doesNotFire()
{
    typeIntoFieldExpectNothing(QStringLiteral("MDI line"));
}

void TestMachineShortcuts::shortcut_inFormLineEdit_doesNotFire()
{
    typeIntoFieldExpectNothing(QStringLiteral("form line edit"));
}

void TestMachineShortcuts::shortcut_inSpinBox_doesNotFire()
{
    typeIntoFieldExpectNothing(QStringLiteral("spin box"));
}

void TestMachineShortcuts::shortcut_referenceAllOutsideTextField_fires()
{
    ui::MainWindow* w = m_f->window.get();
    w->jogPanel()->setFocus();
    QTRY_VERIFY(w->jogPanel()->hasFocus());
    QVERIFY(!ui::MachineShortcutGuard::textFieldHasFocus());
    const qsizetype mark = m_f->deviceMark();
    QTest::keyClick(w->jogPanel(), Qt::Key_H, Qt::ControlModifier);
    QVERIFY(w->referencePanel()->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(!m_f->deviceCommands(elab::ctrl::US, mark).isEmpty(), 5000);
    w->stopAction()->trigger(); // the run is not what this test is about
}

void TestMachineShortcuts::shortcut_disconnectOutsideTextField_fires()
{
    ui::MainWindow* w = m_f->window.get();
    w->jogPanel()->setFocus();
    QTRY_VERIFY(w->jogPanel()->hasFocus());
    QTest::keyClick(w->jogPanel(), Qt::Key_K, Qt::ControlModifier);
    QTRY_VERIFY_WITH_TIMEOUT(!w->context()->isConnected(), 5000);
}

void TestMachineShortcuts::startReferenceRun()
{
    ui::MainWindow* w = m_f->window.get();
    w->referenceAction()->trigger();
    QVERIFY(w->referencePanel()->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->simAxis(Axis::Z).moving, 5000);
}

void TestMachineShortcuts::stopKeys_inTextField_stopTheReferenceRun_data()
{
    QTest::addColumn<QString>("which");
    QTest::addColumn<int>("key");
    QTest::newRow("Esc in the program editor")
        << QStringLiteral("program editor") << int(Qt::Key_Escape);
    QTest::newRow("Esc in the MDI line") << QStringLiteral("MDI line") << int(Qt::Key_Escape);
    QTest::newRow("F1 in the program editor")
        << QStringLiteral("program editor") << int(Qt::Key_F1);
    QTest::newRow("F1 in the MDI line") << QStringLiteral("MDI line") << int(Qt::Key_F1);
}

void TestMachineShortcuts::stopKeys_inTextField_stopTheReferenceRun()
{
    QFETCH(QString, which);
    QFETCH(int, key);
    startReferenceRun();
    if (QTest::currentTestFailed())
        return;
    QWidget* target = field(which);
    QVERIFY(target);
    target->setFocus();
    QTRY_VERIFY(target->hasFocus());
    const qsizetype mark = m_f->deviceMark();
    QTest::keyClick(target, Qt::Key(key));
    // STOP is ForceStopMove <XOFF>, PANIC is ForcePanicStop <BEL>.
    const char expected = key == Qt::Key_Escape ? elab::ctrl::XOFF : elab::ctrl::BEL;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->deviceBytes().mid(mark).contains(expected), 3000);
    QTRY_VERIFY_WITH_TIMEOUT(!m_f->window->referencePanel()->isRunning(), 5000);
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::Z, 5, &why), qPrintable(why));
}

STEPDECK_TEST_MAIN(TestMachineShortcuts)
#include "tst_machineshortcuts.moc"
