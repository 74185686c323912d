// Laser bridge page: the main window connected to the in-process E-LAB simulator, a scripted
// laser on a real pty; start, a home and a move answered, the live log and the axis table,
// stop; refusals in the form; German labels.
#include "../EmisUiFixture.h"
#include "TestMain.h"
#include "bridge/LaserBridgePage.h"
#include "connection/ConnectionBar.h"
#include "connection/PortScanner.h"
#include "sim/PtyEndpoint.h"
#include "window/Translations.h"
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTranslator>

using namespace stepdeck;
using namespace stepdeck::test;

class TestLaserBridgePage : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void page_isADock_startNeedsConnection();
    void portList_followsTheScanner_keepsTypedPort();
    void start_homeAndMove_answeredLoggedAndShownPerAxis();
    void stop_closesLaserPortAndSaysSo();
    void emisBehind_referenceDirectionByController_homeAnswered();
    void controllerFailsMidMove_failureShownAtOnce_laserToldNothing();
    void form_invalidChoices_refusedWithReason();
    void german_pageLabelsTranslated();
    void window_withPage_fitsSmallScreen();

private:
    ui::LaserBridgePage* page() const { return m_f->window->laserBridgePage(); }
    bool startOnLaserPty();

    std::unique_ptr<EmisUiFixture> m_f;
    std::unique_ptr<PtyEndpoint> m_laser;
    QByteArray m_laserGot;
};

void TestLaserBridgePage::init()
{
    m_f = std::make_unique<EmisUiFixture>();
    m_f->window->show();
    m_laser = std::make_unique<PtyEndpoint>();
    QVERIFY(m_laser->create());
    m_laser->open({});
    m_laserGot.clear();
    connect(m_laser.get(), &Transport::dataReceived, this,
            [this](const QByteArray& b) { m_laserGot += b; });
}

void TestLaserBridgePage::cleanup()
{
    m_f.reset();
    m_laser.reset();
}

bool TestLaserBridgePage::startOnLaserPty()
{
    if (!m_f->connectSim())
        return false;
    RequestId setup = m_f->writeRampSetup(4000, 20000);
    QSignalSpy done(m_f->session, &ControllerSession::requestFinished);
    while (done.isEmpty() || done.last().first().value<CommandResult>().id != setup) {
        if (!done.wait(5000))
            return false;
    }
    m_f->withSim([](elab::ElabSimulator* s) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            s->setReferencePosition(a, -200, 5);
    });
    page()->portCombo()->setCurrentText(m_laser->slavePath());
    page()->startButton()->click();
    return QTest::qWaitFor([this] { return page()->isRunning(); }, 5000);
}

void TestLaserBridgePage::page_isADock_startNeedsConnection()
{
    QDockWidget* dock = m_f->window->dockOf(page());
    QVERIFY(dock);
    QCOMPARE(dock->objectName(), QStringLiteral("laserBridgeDock"));
    // The dock's title is not repeated by a group inside it (issue 31).
    for (const QGroupBox* box : page()->findChildren<QGroupBox*>())
        QVERIFY2(box->title() != dock->windowTitle(), qPrintable(box->title()));
    QVERIFY(!page()->startButton()->isEnabled()); // nothing connected yet
    page()->startBridge();
    QVERIFY(page()->stateLabel()->text().contains("Connect the controller"));
    QVERIFY(!page()->isRunning());
}

// The page lists the ports the application's scanner found in its worker thread (never an
// enumeration of its own in the GUI thread); a port that comes or goes updates the list, and
// a typed path stays in the field.
void TestLaserBridgePage::portList_followsTheScanner_keepsTypedPort()
{
    ui::PortScanner* scanner = m_f->window->connectionBar()->portScanner();
    ui::PortEntry usb;
    usb.path = QStringLiteral("/dev/ttyUSB7");
    usb.label = QStringLiteral("ttyUSB7 \u2013 FT232R USB UART (0403:6001)");
    scanner->setScanFunction([usb] { return QList<ui::PortEntry>{usb}; });
    page()->portCombo()->setCurrentText(m_laser->slavePath());

    scanner->rescan();
    QTRY_VERIFY(page()->portCombo()->findData(usb.path) >= 0);
    QCOMPARE(page()->portCombo()->currentText(), m_laser->slavePath());

    scanner->setScanFunction([] { return QList<ui::PortEntry>{}; });
    scanner->rescan();
    QTRY_COMPARE(page()->portCombo()->count(), 0);
    QCOMPARE(page()->portCombo()->currentText(), m_laser->slavePath());
}

void TestLaserBridgePage::start_homeAndMove_answeredLoggedAndShownPerAxis()
{
    QVERIFY(startOnLaserPty());
    QVERIFY(!page()->startButton()->isEnabled());
    QVERIFY(page()->stopButton()->isEnabled());
    QVERIFY(!page()->scaleSpin()->isEnabled()); // no changes while it runs
    QTRY_COMPARE(page()->axisTable()->rowCount(), 3);

    m_laser->write("1200000\r");
    QTRY_COMPARE_WITH_TIMEOUT(m_laserGot, QByteArray("2000002\r"), 10000);
    m_laser->write("2200123\r");
    QTRY_COMPARE_WITH_TIMEOUT(m_laserGot, QByteArray("2000002\r2001230\r"), 10000);

    const QString log = page()->logView()->toPlainText();
    QVERIFY2(log.contains("2200123") && log.contains("move Y to 123"), qPrintable(log));
    QVERIFY2(log.contains("2001230") && log.contains("Y at 123: target reached"), qPrintable(log));
    const QTableWidget* table = page()->axisTable();
    QCOMPARE(table->item(1, 1)->text(), QStringLiteral("Y"));
    QCOMPARE(table->item(1, 4)->text(), QStringLiteral("yes"));
    QCOMPARE(table->item(1, 5)->text(), QStringLiteral("Y at 123: target reached"));
    QCOMPARE(table->item(0, 4)->text(), QStringLiteral("no")); // X was never referenced
    // The device moved: 123 steps from its reference switch.
    qint64 y = 0;
    m_f->withSim([&](elab::ElabSimulator* s) { y = s->position(Axis::Y); });
    QVERIFY2(qAbs(y - (-200 + 123)) <= 5, qPrintable(QString::number(y)));
}

void TestLaserBridgePage::stop_closesLaserPortAndSaysSo()
{
    QVERIFY(startOnLaserPty());
    page()->stopButton()->click();
    QTRY_VERIFY(!page()->isRunning());
    QTRY_VERIFY(page()->startButton()->isEnabled());
    QVERIFY(page()->stateLabel()->text().contains("Not running"));
    QVERIFY(page()->logView()->toPlainText().contains("laser bridge stopped"));
    m_laser->write("1100000\r");
    QSignalSpy quiet(m_laser.get(), &Transport::dataReceived);
    QVERIFY(test::staysQuiet(quiet, 200));
    QVERIFY(m_laserGot.isEmpty());
}

// The EMIS board chooses the direction of its reference runs (9.9): the page offers none and
// the bridge's home is answered with the bridge's defaults.
void TestLaserBridgePage::emisBehind_referenceDirectionByController_homeAnswered()
{
    QVERIFY(m_f->connectEmis());
    QVERIFY(m_f->withEmis([](emis::EmisSimulator* s) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            s->setSwitchPosition(a, -20);
    }));
    QComboBox* home = page()->homeCombo(Axis::X);
    QCOMPARE(home->count(), 1);
    QCOMPARE(home->currentText(), QStringLiteral("chosen by the controller"));
    QVERIFY(!home->isEnabled());
    page()->portCombo()->setCurrentText(m_laser->slavePath());
    page()->startButton()->click();
    QTRY_VERIFY(page()->isRunning());
    m_laser->write("1100000\r");
    QTRY_COMPARE_WITH_TIMEOUT(m_laserGot, QByteArray("1000002\r"), 10000);
    QVERIFY(m_f->boardCommands().contains("$Hx")); // the board's own reference run of X
}

// The controller's link fails while the bridge's move runs: the page shows it at once (state
// line in red, the axis row "target not reached" with the reason); the laser gets no frame
// (the position is unknown, the protocol has no error status: its timeout alarm follows).
void TestLaserBridgePage::controllerFailsMidMove_failureShownAtOnce_laserToldNothing()
{
    QVERIFY(startOnLaserPty());
    m_laser->write("1200000\r");
    QTRY_COMPARE_WITH_TIMEOUT(m_laserGot, QByteArray("2000002\r"), 10000);
    m_laser->write("2290000\r"); // long on its way
    QTRY_VERIFY_WITH_TIMEOUT(m_f->session->status().axes.value(Axis::Y).moving, 5000);
    m_f->withSim([](elab::ElabSimulator* s) { s->faults().silent = true; });
    QTRY_VERIFY_WITH_TIMEOUT(page()->stateLabel()->text().contains("link was lost"), 10000);
    const QString state = page()->stateLabel()->text();
    QVERIFY2(state.contains("move Y to 90000") && state.contains("no answer to the laser"),
             qPrintable(state));
    QVERIFY(page()->stateLabel()->property("error").toBool());
    const QTableWidgetItem* row = page()->axisTable()->item(1, 2);
    QCOMPARE(row->text(), QStringLiteral("target not reached"));
    QVERIFY(row->toolTip().contains("link was lost"));
    QTRY_VERIFY(!page()->isRunning()); // the page lets go of the laser port, as before
    QVERIFY(page()->stateLabel()->text().contains("link was lost")); // and keeps saying why
    QCOMPARE(m_laserGot, QByteArray("2000002\r"));
    m_f->withSim([](elab::ElabSimulator* s) { s->faults().silent = false; });
}

void TestLaserBridgePage::form_invalidChoices_refusedWithReason()
{
    QVERIFY(m_f->connectSim());
    // Two laser axes on one controller axis.
    page()->mapCombo(Axis::Y)->setCurrentIndex(page()->mapCombo(Axis::Y)->findText("X"));
    page()->portCombo()->setCurrentText(m_laser->slavePath());
    page()->startButton()->click();
    QVERIFY(page()->stateLabel()->text().contains("two laser axes"));
    QVERIFY(!page()->isRunning());
    page()->mapCombo(Axis::Y)->setCurrentIndex(page()->mapCombo(Axis::Y)->findText("Y"));
    page()->portCombo()->setCurrentText(QString());
    page()->startButton()->click();
    QVERIFY(page()->stateLabel()->text().contains("laser's port"));
    // A door input on a controller that publishes none.
    page()->portCombo()->setCurrentText(m_laser->slavePath());
    page()->doorInputSpin()->setValue(2);
    page()->startButton()->click();
    QVERIFY(page()->stateLabel()->text().contains("no door switch input"));
    QVERIFY(!page()->isRunning());
}

void TestLaserBridgePage::german_pageLabelsTranslated()
{
    QTranslator translator;
    QVERIFY(translator.load(QStringLiteral(":/i18n/stepdeck_de.qm")));
    QCoreApplication::installTranslator(&translator);
    ui::LaserBridgePage german(m_f->window->context(), m_f->window->connectionBar()->portScanner());
    QCoreApplication::removeTranslator(&translator);
    QCOMPARE(german.startButton()->text(), QStringLiteral("Brücke starten"));
    QCOMPARE(german.stopButton()->text(), QStringLiteral("Brücke anhalten"));
    QCOMPARE(german.axisTable()->horizontalHeaderItem(0)->text(), QStringLiteral("Laserachse"));
}

void TestLaserBridgePage::window_withPage_fitsSmallScreen()
{
    // A bottom dock page: it must not raise the window's minimum height (1366x768 screens).
    const QSize page = this->page()->minimumSizeHint();
    QVERIFY2(page.width() <= 900 && page.height() <= 200,
             qPrintable(QStringLiteral("%1x%2").arg(page.width()).arg(page.height())));
}

STEPDECK_TEST_MAIN(TestLaserBridgePage)
#include "tst_laserbridgepage.moc"
