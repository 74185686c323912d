// STOP (Esc) and PANIC (F1) work in every state of the window (issue 7, rule 5): whatever
// widget has the focus, inside an item-view cell editor, with a file dialog or a message box
// open, with a popup open -- by key and by clicking the buttons. Dialogs are non-modal, so
// the buttons stay clickable. After a panic the UI says that positions are lost.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "console/TrafficConsole.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "safety/SafetyBar.h"
#include "setup/ParameterField.h"
#include "setup/SetupPage.h"
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>

using namespace stepdeck;
using namespace stepdeck::test;

class TestSafetyShortcuts : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void escape_fromAnyFocusedWidget_sendsStop_data();
    void escape_fromAnyFocusedWidget_sendsStop();
    void f1_fromTextField_sendsPanicAndAsksForReferencing();
    void escape_inModalDialog_stopsAndClosesDialog();
    void f1_inOpenComboPopup_panics();
    void stopAndPanicButtons_enabledWhileConnected();
    void stop_whileJogging_endsJogAtOnce();
    void keys_inCellEditor_stopAndPanic_data();
    void keys_inCellEditor_stopAndPanic();
    void fileDialog_nonModal_keysAndButtonsWork_data();
    void fileDialog_nonModal_keysAndButtonsWork();
    void messageBox_nonModal_keysAndButtonsWork_data();
    void messageBox_nonModal_keysAndButtonsWork();
    void popupOpen_clickOnStop_stops();

private:
    QWidget* focusTarget(const QString& which) const;
    // Esc/F1 typed into `target`, or the STOP/PANIC button clicked through the window
    // system; the device must receive <XOFF> or <BEL>.
    void actAndExpect(const QString& how, QWidget* target);
    template <typename T> T* topLevel() const;
    std::unique_ptr<UiFixture> m_f;
};

void TestSafetyShortcuts::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    QVERIFY(m_f->connectSim());
}

QWidget* TestSafetyShortcuts::focusTarget(const QString& which) const
{
    ui::MainWindow* w = m_f->window.get();
    if (which == QLatin1String("console send line")) {
        w->raisePage(w->trafficConsole());
        return w->trafficConsole()->sendLine();
    }
    if (which == QLatin1String("setup field")) {
        w->raisePage(w->setupPage());
        return w->setupPage()->field(QStringLiteral("max-speed"), Axis::Y)->lineEdit();
    }
    if (which == QLatin1String("poll interval spin box"))
        return w->findChild<QSpinBox*>();
    if (which == QLatin1String("jog panel"))
        return w->jogPanel();
    return nullptr;
}

void TestSafetyShortcuts::escape_fromAnyFocusedWidget_sendsStop_data()
{
    QTest::addColumn<QString>("which");
    QTest::newRow("text field") << QStringLiteral("console send line");
    QTest::newRow("setup editor") << QStringLiteral("setup field");
    QTest::newRow("spin box") << QStringLiteral("poll interval spin box");
    QTest::newRow("jog panel") << QStringLiteral("jog panel");
}

void TestSafetyShortcuts::escape_fromAnyFocusedWidget_sendsStop()
{
    QFETCH(QString, which);
    QWidget* target = focusTarget(which);
    QVERIFY(target);
    target->setFocus();
    QTRY_VERIFY(target->hasFocus());
    const qsizetype start = m_f->records.size();
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    // ForceStopMove is <XOFF> (0x13).
    QTRY_VERIFY_WITH_TIMEOUT(m_f->sent(start).contains(char(elab::ctrl::XOFF)), 3000);
}

void TestSafetyShortcuts::f1_fromTextField_sendsPanicAndAsksForReferencing()
{
    QWidget* target = focusTarget(QStringLiteral("console send line"));
    target->setFocus();
    QTRY_VERIFY(target->hasFocus());
    const qsizetype start = m_f->records.size();
    QTest::keyClick(target, Qt::Key_F1);
    // ForcePanicStop is <BEL> (0x07); it overtakes anything queued.
    QTRY_VERIFY_WITH_TIMEOUT(m_f->sent(start).contains(char(elab::ctrl::BEL)), 3000);
    ui::SafetyBar* bar = m_f->window->safetyBar();
    QVERIFY(bar->positionsLost());
    QTRY_VERIFY(bar->bannerText().contains(QStringLiteral("lost")));
    QVERIFY(bar->bannerText().contains(QStringLiteral("reference")));
    for (const AxisStatus& a : m_f->window->context()->status().axes)
        QVERIFY(!a.referenced);
}

void TestSafetyShortcuts::escape_inModalDialog_stopsAndClosesDialog()
{
    // Qt blocks the main window's shortcuts while a modal dialog is open.
    QDialog dialog(m_f->window.get());
    auto* edit = new QLineEdit(&dialog);
    dialog.setModal(true);
    dialog.show();
    QTRY_VERIFY(QApplication::activeModalWidget() == &dialog);
    edit->setFocus();
    QTRY_VERIFY(edit->hasFocus());
    const qsizetype start = m_f->records.size();
    QTest::keyClick(edit, Qt::Key_Escape);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->sent(start).contains(char(elab::ctrl::XOFF)), 3000);
    QTRY_VERIFY(!dialog.isVisible()); // Esc still closes the dialog
}

void TestSafetyShortcuts::f1_inOpenComboPopup_panics()
{
    QComboBox* combo = m_f->window->positionPanel()->findChild<QComboBox*>();
    QVERIFY(combo);
    combo->showPopup();
    QTRY_VERIFY(QApplication::activePopupWidget());
    const qsizetype start = m_f->records.size();
    QWidget* popup = QApplication::activePopupWidget();
    QTest::keyClick(popup->focusWidget() ? popup->focusWidget() : popup, Qt::Key_F1);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->sent(start).contains(char(elab::ctrl::BEL)), 3000);
    QVERIFY(m_f->window->safetyBar()->positionsLost());
    combo->hidePopup();
}

void TestSafetyShortcuts::stopAndPanicButtons_enabledWhileConnected()
{
    ui::SafetyBar* bar = m_f->window->safetyBar();
    QVERIFY(bar->stopButton()->isVisible());
    QVERIFY(bar->stopButton()->isEnabled());
    QVERIFY(bar->panicButton()->isEnabled());
    const qsizetype start = m_f->records.size();
    bar->stopButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_f->sent(start).contains(char(elab::ctrl::XOFF)), 3000);
    // Still enabled after use: stop can always be pressed again.
    QVERIFY(bar->stopButton()->isEnabled());
}

void TestSafetyShortcuts::stop_whileJogging_endsJogAtOnce()
{
    QSignalSpy done(m_f->session, &ControllerSession::requestFinished);
    m_f->writeRampSetup();
    QTRY_VERIFY_WITH_TIMEOUT(!done.isEmpty(), 3000);
    m_f->window->jogPanel()->setFocus();
    m_f->gamepad->plug(true); // a held jog input that proves itself with fresh samples
    m_f->gamepad->moveAxis(0, 1.0);
    m_f->gamepad->press(9, true);
    const double max = m_f->window->jogController()->maxSpeed(ui::JogSlot::PadHorizontal);
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::X), max, 5000);
    QTRY_VERIFY(m_f->simAxis(Axis::X).moving);
    const qsizetype atDevice = m_f->deviceMark();
    QTest::keyClick(m_f->window.get(), Qt::Key_Escape);
    QVERIFY(!m_f->window->jogController()->isJogging());
    QString why;
    QVERIFY2(m_f->simStandsStill(Axis::X, 5, &why), qPrintable(why));
    QVERIFY(m_f->deviceBytes().mid(atDevice).contains(elab::ctrl::XOFF));
    QCOMPARE(m_f->commanded(Axis::X), 0.0);
}

template <typename T> T* TestSafetyShortcuts::topLevel() const
{
    for (QWidget* w : QApplication::topLevelWidgets()) {
        if (auto* t = qobject_cast<T*>(w); t && t->isVisible())
            return t;
    }
    return nullptr;
}

void TestSafetyShortcuts::actAndExpect(const QString& how, QWidget* target)
{
    ui::SafetyBar* bar = m_f->window->safetyBar();
    const qsizetype start = m_f->deviceMark();
    const bool panic = how.contains(QLatin1String("PANIC")) || how.contains(QLatin1String("F1"));
    if (how == QLatin1String("Esc"))
        QTest::keyClick(target, Qt::Key_Escape);
    else if (how == QLatin1String("F1"))
        QTest::keyClick(target, Qt::Key_F1);
    else
        pointerClick(panic ? bar->panicButton() : bar->stopButton());
    const char expected = panic ? elab::ctrl::BEL : elab::ctrl::XOFF;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->deviceBytes().mid(start).contains(expected), 3000);
}

void TestSafetyShortcuts::keys_inCellEditor_stopAndPanic_data()
{
    QTest::addColumn<QString>("how");
    QTest::newRow("Esc") << QStringLiteral("Esc");
    QTest::newRow("F1") << QStringLiteral("F1");
}

void TestSafetyShortcuts::keys_inCellEditor_stopAndPanic()
{
    // An item view's delegate accepts ShortcutOverride for Esc (to cancel the edit), so a
    // plain window shortcut never fires inside a cell editor.
    QFETCH(QString, how);
    auto* table = new QTableWidget(2, 2);
    table->setItem(0, 0, new QTableWidgetItem(QStringLiteral("100")));
    auto* dock = new QDockWidget(QStringLiteral("cells"), m_f->window.get());
    dock->setWidget(table);
    m_f->window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->show();
    table->editItem(table->item(0, 0));
    QTRY_VERIFY(qobject_cast<QLineEdit*>(QApplication::focusWidget()));
    QWidget* editor = QApplication::focusWidget();
    actAndExpect(how, editor);
    if (how == QLatin1String("Esc"))
        QTRY_VERIFY(!qobject_cast<QLineEdit*>(QApplication::focusWidget())); // edit cancelled
}

void TestSafetyShortcuts::fileDialog_nonModal_keysAndButtonsWork_data()
{
    QTest::addColumn<QString>("how");
    QTest::newRow("Esc") << QStringLiteral("Esc");
    QTest::newRow("F1") << QStringLiteral("F1");
    QTest::newRow("STOP button") << QStringLiteral("STOP button");
    QTest::newRow("PANIC button") << QStringLiteral("PANIC button");
}

void TestSafetyShortcuts::fileDialog_nonModal_keysAndButtonsWork()
{
    QFETCH(QString, how);
    ui::SetupPage* setup = m_f->window->setupPage();
    m_f->window->raisePage(setup);
    setup->saveAs();
    const QPointer<QFileDialog> dialog = topLevel<QFileDialog>(); // deletes itself on close
    QVERIFY(dialog);
    QVERIFY(dialog->testOption(QFileDialog::DontUseNativeDialog));
    QCOMPARE(QApplication::activeModalWidget(), nullptr);
    QVERIFY(!setup->isEnabled()); // the page it belongs to waits for it
    QVERIFY(QTest::qWaitForWindowActive(dialog));
    QWidget* focus = dialog->focusWidget() ? dialog->focusWidget() : dialog;
    actAndExpect(how, focus);
    if (how == QLatin1String("Esc")) {
        QTRY_VERIFY(!dialog || !dialog->isVisible()); // Esc still closes the dialog
        QTRY_VERIFY(setup->isEnabled());
    } else if (dialog) {
        dialog->reject();
    }
}

void TestSafetyShortcuts::messageBox_nonModal_keysAndButtonsWork_data()
{
    fileDialog_nonModal_keysAndButtonsWork_data();
}

void TestSafetyShortcuts::messageBox_nonModal_keysAndButtonsWork()
{
    QFETCH(QString, how);
    QAction* about = nullptr;
    for (QAction* a : m_f->window->findChildren<QAction*>()) {
        if (a->text().contains(QStringLiteral("About StepDeck")))
            about = a;
    }
    QVERIFY(about);
    about->trigger();
    // The box deletes itself when closed (dialogs::message): watch it through a QPointer.
    const QPointer<QMessageBox> box = topLevel<QMessageBox>();
    QVERIFY(box);
    QCOMPARE(QApplication::activeModalWidget(), nullptr);
    QVERIFY(QTest::qWaitForWindowActive(box));
    QWidget* focus = box->focusWidget() ? box->focusWidget() : box;
    actAndExpect(how, focus);
    if (how == QLatin1String("Esc"))
        QTRY_VERIFY(!box || !box->isVisible());
    else if (box)
        box->close();
}

void TestSafetyShortcuts::popupOpen_clickOnStop_stops()
{
    QComboBox* combo = m_f->window->positionPanel()->findChild<QComboBox*>();
    QVERIFY(combo);
    combo->showPopup();
    QTRY_VERIFY(QApplication::activePopupWidget());
    QWidget* popup = QApplication::activePopupWidget();
    const qsizetype start = m_f->deviceMark();
    // The press goes to the popup (it has the mouse), at the STOP button's position.
    QPushButton* stop = m_f->window->safetyBar()->stopButton();
    const QPoint global = stop->mapToGlobal(stop->rect().center());
    QMouseEvent press(QEvent::MouseButtonPress, popup->mapFromGlobal(global), global,
                      Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(popup, &press);
    QTRY_VERIFY_WITH_TIMEOUT(m_f->deviceBytes().mid(start).contains(elab::ctrl::XOFF), 3000);
    combo->hidePopup();
}

STEPDECK_TEST_MAIN(TestSafetyShortcuts)
#include "tst_safetyshortcuts.moc"
