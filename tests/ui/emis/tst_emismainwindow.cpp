// The main window on an EMIS SMC-IC4 (in-process simulator, offscreen): the U axis wherever
// axes appear, the U stick jogging in chunks the board saw, referencing without a direction,
// inputs and switchable outputs in the status panel, motion-unconfirmed, the refused stop,
// and storing / reading the power-on values from the setup page.
#include "EmisUiFixture.h"
#include "TestMain.h"
#include "common/LedIndicator.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "machine/MachineDro.h"
#include "machine/MachineReferenceRows.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "programs/InputProgramsPage.h"
#include "safety/SafetyBar.h"
#include "setup/ParameterField.h"
#include "setup/SetupPage.h"
#include "setup/StoredParametersBar.h"
#include "status/DigitalIoGroup.h"
#include "status/StatusPanel.h"
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMouseEvent>
#include <QPushButton>
#include <QToolButton>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
QList<QByteArray> vectorMoves(const QList<QByteArray>& commands)
{
    QList<QByteArray> out;
    for (const QByteArray& c : commands) {
        if (c.startsWith("L1,"))
            out << c;
    }
    return out;
}
} // namespace

class TestEmisMainWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();
    void uAxis_everywhere();
    void uStick_jogsInChunks_releaseSendsNoMore();
    void reference_noDirection_allReferenced();
    void status_inputsFollowBoard_outputsSwitchable();
    void lostArrival_motionUnconfirmedLamp();
    void stop_refusedWithEmergencyStopText();
    void storedValues_storeAndReadBack();
    void storedBar_hiddenForElab();

private:
    std::unique_ptr<EmisUiFixture> m_f;
};

void TestEmisMainWindow::init()
{
    m_f = std::make_unique<EmisUiFixture>();
    QVERIFY(m_f->connectEmis());
}

void TestEmisMainWindow::cleanup()
{
    m_f.reset();
}

void TestEmisMainWindow::uAxis_everywhere()
{
    ui::MainWindow* w = m_f->window.get();
    QVERIFY(w->jogPanel()->uStick()->isVisibleTo(w));
    QVERIFY(w->setupPage()->field("work-speed", Axis::U));
    QVERIFY(w->setupPage()->field("reference-switch-type", Axis::U));
    QCOMPARE(w->referencePanel()->machineRows()->axisNames(), (QStringList{"U", "X", "Y", "Z"}));
    QCOMPARE(w->context()->axes().size(), 4);
    // A U row in the read-out.
    QVERIFY(!w->positionPanel()->machineDro()->displayedValue(QStringLiteral("U")).isEmpty());
    auto* programsDock = w->dockOf(w->inputProgramsPage());
    QVERIFY(programsDock && programsDock->toggleViewAction()->isVisible());
}

void TestEmisMainWindow::uStick_jogsInChunks_releaseSendsNoMore()
{
    m_f->window->show(); // jog needs the active window (losing it ends every jog)
    QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    ui::JoystickPad* u = m_f->window->jogPanel()->uStick();
    pointerPress(u, u->centre());
    pointerMove(u, u->pointFor(QPointF(0.0, 1.0)));
    QTRY_VERIFY_WITH_TIMEOUT(vectorMoves(m_f->boardCommands()).size() >= 2, 5000);

    pointerRelease(u, u->centre());
    QTRY_VERIFY_WITH_TIMEOUT(!m_f->window->context()->status().anyMoving(), 5000);
    bool still = false;
    QTRY_VERIFY_WITH_TIMEOUT(
        m_f->withEmis([&](emis::EmisSimulator* s) { still = !s->anyMoving(); }) && still, 5000);
    const QList<QByteArray> moves = vectorMoves(m_f->boardCommands());
    for (const QByteArray& m : moves)
        QVERIFY2(m.startsWith("L1,u"), m.constData()); // only U; up is positive
    qint64 board = 0;
    m_f->withEmis([&](emis::EmisSimulator* s) { board = s->position(Axis::U); });
    QVERIFY(board > 0);
    QCOMPARE(m_f->window->context()->status().axes.value(Axis::U).position, board);
    QSignalSpy traffic(m_f->session, &ControllerSession::traffic);
    stepdeck::test::staysQuiet(traffic, 300); // the event loop runs; polls go on
    QCOMPARE(vectorMoves(m_f->boardCommands()).size(), moves.size()); // nothing after release
}

void TestEmisMainWindow::reference_noDirection_allReferenced()
{
    ui::ReferencePanel* panel = m_f->window->referencePanel();
    // The board picks the direction of its reference runs itself (EMIS 9.9).
    QCOMPARE(panel->machineRows()->directionText(QStringLiteral("U")),
             QStringLiteral("controller chooses"));
    panel->referenceAll();
    QTRY_VERIFY_WITH_TIMEOUT(panel->messageText().contains("referenced"), 15000);
    for (Axis a : letterAxes())
        QVERIFY(m_f->window->context()->status().axes.value(a).referenced);
    const QList<QByteArray> homes = [&] {
        QList<QByteArray> out;
        for (const QByteArray& c : m_f->boardCommands())
            if (c.startsWith("$H"))
                out << c;
        return out;
    }();
    QCOMPARE(homes, (QList<QByteArray>{"$Hz", "$Hxyu"})); // Z first, then the others
}

void TestEmisMainWindow::status_inputsFollowBoard_outputsSwitchable()
{
    ui::DigitalIoGroup* io = m_f->window->statusPanel()->digitalIo();
    QVERIFY(io);
    m_f->withEmis([](emis::EmisSimulator* s) { s->setInput(6, true); });
    QTRY_COMPARE(io->inputLamp(6)->state(), ui::LedIndicator::State::On);
    QCOMPARE(io->inputLamp(5)->state(), ui::LedIndicator::State::Off);
    QAbstractButton* out3 = io->outputSwitch(3);
    QVERIFY(out3->text().contains('?'));
    out3->click();
    bool on = false;
    QTRY_VERIFY(m_f->withEmis([&](emis::EmisSimulator* s) { on = s->output(3); }) && on);
    QTRY_VERIFY(out3->isChecked());
    out3->click();
    QTRY_VERIFY(m_f->withEmis([&](emis::EmisSimulator* s) { on = s->output(3); }) && !on);
    QTRY_VERIFY(!out3->isChecked());
    QVERIFY(m_f->window->statusPanel()->firmwareText().contains("SMC-IC4 v1.07"));
}

void TestEmisMainWindow::lostArrival_motionUnconfirmedLamp()
{
    ui::LedIndicator* lamp = m_f->window->statusPanel()->machineLamp("motionUnconfirmed");
    QVERIFY(lamp);
    QCOMPARE(lamp->state(), ui::LedIndicator::State::Off);
    m_f->withEmis([](emis::EmisSimulator* s) { s->dropArrivals(1); });
    m_f->session->moveRelative({{Axis::X, 20}});
    QTRY_COMPARE_WITH_TIMEOUT(lamp->state(), ui::LedIndicator::State::Fault, 10000);
    QVERIFY(m_f->window->lastError().contains("DC1"));
}

void TestEmisMainWindow::stop_refusedWithEmergencyStopText()
{
    // The board has no stop command: the permanent note next to STOP/PANIC says so before
    // anyone presses them, and the buttons say they do not stop the controller.
    QLabel* note = m_f->window->safetyBar()->noStopNote();
    QVERIFY(!note->isHidden());
    QVERIFY2(note->text().contains("emergency stop"), qPrintable(note->text()));
    // The SMC-IC4's own way to stop (5.8) and what the host does afterwards.
    QVERIFY2(note->text().contains("reset input (manual 5.8)"), qPrintable(note->text()));
    QVERIFY2(note->text().contains("unknown until referenced"), qPrintable(note->text()));
    QVERIFY2(note->toolTip().contains("not referenced"), qPrintable(note->toolTip()));
    m_f->window->stopAll();
    QTRY_VERIFY(m_f->window->lastError().contains("emergency stop"));
    m_f->window->panicAll();
    QTRY_VERIFY(m_f->window->lastError().contains("no stop command"));
    // A refused panic sent nothing: positions are not declared lost by it.
    QVERIFY(!m_f->window->safetyBar()->positionsLost());
}

void TestEmisMainWindow::storedValues_storeAndReadBack()
{
    ui::SetupPage* page = m_f->window->setupPage();
    auto* bar = page->findChild<ui::StoredParametersBar*>();
    QVERIFY(bar && bar->isVisibleTo(page));
    page->field("ramp")->setValue(250);
    page->field("step-resolution", Axis::Y)->setValue(QStringLiteral("64"));
    QVERIFY(bar->store(false));
    QTRY_VERIFY(bar->messageText().contains("Stored"));
    QVERIFY(bar->messageText().contains("Interpolation")); // no stored form: named, left out
    QList<QByteArray> stored;
    m_f->withEmis([&](emis::EmisSimulator* s) {
        for (const auto& e : s->storedEntries())
            stored << emis::formatSystemEntry(e);
    });
    QVERIFY(stored.contains("R,250"));
    QVERIFY(stored.contains("D,x16,y64,z16,u16"));
    page->field("ramp")->setValue(100);
    bar->readStored();
    QTRY_COMPARE(page->field("ramp")->value().toLongLong(), 250);
    QCOMPARE(page->field("step-resolution", Axis::Y)->value().toString(), QStringLiteral("64"));
}

void TestEmisMainWindow::storedBar_hiddenForElab()
{
    m_f.reset();
    m_f = std::make_unique<EmisUiFixture>();
    QVERIFY(m_f->connectSim()); // E-LAB
    auto* bar = m_f->window->setupPage()->findChild<ui::StoredParametersBar*>();
    QVERIFY(bar && !bar->isVisibleTo(m_f->window->setupPage()));
    QVERIFY(!m_f->window->statusPanel()->digitalIo());
    auto* programsDock = m_f->window->dockOf(m_f->window->inputProgramsPage());
    QVERIFY(!programsDock->toggleViewAction()->isVisible());
}

STEPDECK_TEST_MAIN(TestEmisMainWindow)
#include "tst_emismainwindow.moc"
