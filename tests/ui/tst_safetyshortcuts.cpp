// STOP (Esc) and PANIC (F1) work whatever widget has the focus, and after a panic the UI says
// that positions are lost and asks for referencing.
#include "UiTestSupport.h"
#include "console/TrafficConsole.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "main/SafetyBar.h"
#include "position/ReferencePanel.h"
#include "setup/ParameterField.h"
#include "setup/SetupPage.h"
#include <QComboBox>
#include <QDialog>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

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

private:
    QWidget* focusTarget(const QString& which) const;
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
    QComboBox* combo = m_f->window->referencePanel()->findChild<QComboBox*>();
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
    QObject input; // a held jog input; the controller renews the lease while it is deflected
    m_f->window->jogController()->setDeflection(&input, {{Axis::X, 1.0}});
    const double max = m_f->window->jogController()->maxSpeed(Axis::X);
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::X), max, 5000);
    QTest::keyClick(m_f->window.get(), Qt::Key_Escape);
    QVERIFY(!m_f->window->jogController()->isJogging());
    QTRY_COMPARE_WITH_TIMEOUT(m_f->commanded(Axis::X), 0.0, 3000);
}

QTEST_MAIN(TestSafetyShortcuts)
#include "tst_safetyshortcuts.moc"
