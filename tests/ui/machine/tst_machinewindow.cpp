// The main window running a machine of two controllers (issue 19): an E-LAB X/Y/Z table and a
// Nanotec rotary A, each simulated on a pseudo-terminal of its own. Opening a machine file
// (an invalid one names the field and opens nothing), the controller selector, one connect for
// all, STOP reaching both devices and the read-out in the machine's units.
#include "../LayoutChecks.h"
#include "../UiTestSupport.h"
#include "ModelBench.h"
#include "PtyDevice.h"
#include "common/LedIndicator.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include "machine/Machine.h"
#include "machine/MachineBar.h"
#include "machine/MachineDro.h"
#include "machine/MachineGoTo.h"
#include "machine/MachineReferenceRows.h"
#include "messages/StatusMessages.h"
#include "position/PositionPanel.h"
#include "position/ReferencePanel.h"
#include "safety/SafetyBar.h"
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QToolButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMachineWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();
    void openMachine_invalidFile_messageNamesTheFieldNothingOpened();
    void openMachine_twoControllers_titleSelectorAndSelectedSession();
    void selectController_pagesRebuildOnTheOtherSession();
    void connectAll_bothLampsConnected_disconnectAllClosesBoth();
    void closeMachine_singleControllerBarBackAndConnectable();
    void stop_duringMoveOnBothControllers_bothDevicesStandStill();
    void stop_controllerWithoutStopCommand_messageNamesIt();
    void stop_duringTwoControllerJog_bothStillThenConfirmedMessage();
    void stop_controllerSilent_messageNamesItNotConfirmed();
    void jog_otherControllerLinkLost_heldJogDoesNotResume();
    void banner_tableReferencedRotaryNot_machineNotReady();
    void jog_heldKeyOnRotary_limitedToMaxJogSpeedAtTheDrive();
    void dro_afterMoveX2point5_shows2point500mm();
    void layout_sixAxisMachineAt1366x768_fitsAndNothingIsCut();
    void machineBar_longNamesAndPorts_elidedFullTextInTooltip();
    void goTo_unreferencedAxis_refusedNothingSent();
    void goTo_referencedX_deviceAtTheNearestStep();
    void referenceAll_machine_everyControllerInTheFilesOrder();
    void referenceAxis_machine_fileRowsShownOnlyThatControllerRuns();
    void zero_referencedX_digitsZeroAndGoToWorkMovesDeviceToOffsetPlusTarget();
    void zero_unknownPosition_refusedWithReasonNoOffset();
    void zero_reopenMachine_offsetsRemembered();

private:
    QString writeFile(const QByteArray& json);
    QByteArray machineJson() const;
    bool openAndConnect();
    bool referenceTable();
    QToolButton* zeroButton(const QString& axis) const;
    void writeElabSetup();
    ui::MainWindow* window() const { return m_f->window.get(); }
    machine::Machine* machine() const { return window()->context()->machine(); }

    std::unique_ptr<PtyDevice> m_elab;
    std::unique_ptr<PtyDevice> m_nanotec;
    std::unique_ptr<UiFixture> m_f;
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestMachineWindow::init()
{
    QSettings().clear();
    m_elab = std::make_unique<PtyDevice>(QStringLiteral("elab"));
    m_nanotec = std::make_unique<PtyDevice>(QStringLiteral("nanotec"));
    m_dir = std::make_unique<QTemporaryDir>();
    m_f = std::make_unique<UiFixture>();
    window()->show();
    QVERIFY(QTest::qWaitForWindowActive(window()));
}

void TestMachineWindow::cleanup()
{
    if (QGuiApplication::mouseButtons() & Qt::LeftButton)
        QTest::mouseRelease(window()->windowHandle(), Qt::LeftButton);
    m_f.reset(); // the window stops and closes every controller first
    m_elab.reset();
    m_nanotec.reset();
    m_dir.reset();
}

QString TestMachineWindow::writeFile(const QByteArray& json)
{
    const QString path = m_dir->filePath(QStringLiteral("test.machine.json"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        qFatal("cannot write %s", qPrintable(path));
    file.write(json);
    return path;
}

QByteArray TestMachineWindow::machineJson() const
{
    return QStringLiteral(R"({
  "format": "stepdeck-machine", "version": 1, "name": "Table with rotary axis",
  "controllers": [
    { "id": "table", "model": "elab", "port": "%1" },
    { "id": "rotary", "model": "nanotec", "port": "%2", "axes": { "X": 1 } }
  ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 800 },
    { "name": "A", "controller": "rotary", "axis": "X", "unit": "deg", "stepsPerUnit": 100 }
  ]
})")
        .arg(m_elab->path(), m_nanotec->path())
        .toUtf8();
}

bool TestMachineWindow::openAndConnect()
{
    if (!window()->openMachine(writeFile(machineJson())))
        return false;
    window()->machineBar()->connectButton()->click();
    for (const char* id : {"table", "rotary"}) {
        ControllerSession* s = machine()->session(QString::fromLatin1(id));
        if (!QTest::qWaitFor([s] { return s->linkState() == LinkState::Connected; }, 10000))
            return false;
    }
    writeElabSetup();
    return true;
}

// The board moves only after its ramp setup was written (ModelInfo::setupBeforeMotion).
void TestMachineWindow::writeElabSetup()
{
    ControllerSession* table = machine()->session(QStringLiteral("table"));
    QSignalSpy done(table, &ControllerSession::requestFinished);
    const RequestId id = table->writeParameters(setupBeforeMotionDefaults(*table->model()), false);
    QTRY_VERIFY_WITH_TIMEOUT(std::any_of(done.cbegin(), done.cend(),
                                         [id](const QList<QVariant>& args) {
                                             const auto r = args.at(0).value<CommandResult>();
                                             return r.id == id && r.ok();
                                         }),
                             10000);
}

void TestMachineWindow::openMachine_invalidFile_messageNamesTheFieldNothingOpened()
{
    QByteArray json = machineJson();
    json.replace(R"("stepsPerUnit": 800)", R"("stepsPerUnit": -2)");
    const QString title = window()->windowTitle();
    QVERIFY(!window()->openMachine(writeFile(json)));
    QVERIFY2(window()->lastError().contains(QStringLiteral("axes[2].stepsPerUnit")),
             qPrintable(window()->lastError()));
    QVERIFY(!window()->context()->hasMachine());
    QCOMPARE(window()->context()->session(), m_f->session); // the single controller's
    QCOMPARE(window()->windowTitle(), title);
    QTRY_VERIFY(!window()->machineBar()->isVisible());
    QTRY_VERIFY(window()->connectionBar()->isVisible());
    // Nothing reached either device.
    QCOMPARE(m_elab->receivedCount(), 0);
    QCOMPARE(m_nanotec->receivedCount(), 0);
}

void TestMachineWindow::openMachine_twoControllers_titleSelectorAndSelectedSession()
{
    QVERIFY(window()->openMachine(writeFile(machineJson())));
    QVERIFY(window()->windowTitle().contains(QStringLiteral("Table with rotary axis")));
    QTRY_VERIFY(window()->machineBar()->isVisible());
    QTRY_VERIFY(!window()->connectionBar()->isVisible());
    QComboBox* selector = window()->machineBar()->controllerCombo();
    QTRY_VERIFY(selector->isVisible());
    QCOMPARE(selector->count(), 2);
    QCOMPARE(window()->context()->selectedController(), QStringLiteral("table"));
    QCOMPARE(window()->context()->session(), machine()->session(QStringLiteral("table")));
    QCOMPARE(window()->context()->modelId(), QStringLiteral("elab"));
    // Links are not opened by opening the file.
    QCOMPARE(machine()->session(QStringLiteral("table"))->linkState(), LinkState::Disconnected);
}

void TestMachineWindow::selectController_pagesRebuildOnTheOtherSession()
{
    QVERIFY(openAndConnect());
    QSignalSpy rebuilt(window()->context(), &ui::MachineContext::modelChanged);
    QSignalSpy relayed(m_f->session, &ControllerSession::statusChanged);
    QComboBox* selector = window()->machineBar()->controllerCombo();
    selector->setCurrentIndex(selector->findData(QStringLiteral("rotary")));
    Q_EMIT selector->activated(selector->currentIndex());
    QCOMPARE(rebuilt.size(), 1);
    QCOMPARE(window()->context()->session(), machine()->session(QStringLiteral("rotary")));
    QCOMPARE(window()->context()->modelId(), QStringLiteral("nanotec"));
    QVERIFY(window()->context()->isConnected());
    // The panels hear the selected controller: its status polls arrive at the session they
    // connected to when they were built.
    QTRY_VERIFY_WITH_TIMEOUT(relayed.size() >= 3, 10000);
    const auto status = relayed.last().at(0).value<MachineStatus>();
    QVERIFY(status.axes.contains(Axis::X));
    QVERIFY(!status.axes.contains(Axis::Z)); // the drive on the bus, not the E-LAB board
}

void TestMachineWindow::connectAll_bothLampsConnected_disconnectAllClosesBoth()
{
    QVERIFY(openAndConnect());
    ui::MachineBar* bar = window()->machineBar();
    QCOMPARE(bar->lamp(QStringLiteral("table"))->state(), ui::LedIndicator::State::On);
    QCOMPARE(bar->lamp(QStringLiteral("rotary"))->state(), ui::LedIndicator::State::On);
    QVERIFY(bar->lampText(QStringLiteral("rotary")).contains(QStringLiteral("Connected")));
    QCOMPARE(bar->connectButton()->text(), QStringLiteral("Disconnect all"));
    bar->connectButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(bar->lamp(QStringLiteral("table"))->state(),
                              ui::LedIndicator::State::Off, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(bar->lamp(QStringLiteral("rotary"))->state(),
                              ui::LedIndicator::State::Off, 10000);
    QCOMPARE(bar->connectButton()->text(), QStringLiteral("Connect all"));
}

void TestMachineWindow::closeMachine_singleControllerBarBackAndConnectable()
{
    QVERIFY(openAndConnect());
    window()->closeMachine();
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->still() && m_nanotec->still(), 10000);
    QVERIFY(!window()->context()->hasMachine());
    QTRY_VERIFY(window()->connectionBar()->isVisible());
    QVERIFY(!window()->windowTitle().contains(QStringLiteral("Table with rotary axis")));
    QVERIFY(m_f->connectSim()); // today's single controller, unchanged
    QCOMPARE(window()->context()->session(), m_f->session);
}

void TestMachineWindow::stop_duringMoveOnBothControllers_bothDevicesStandStill()
{
    QVERIFY(openAndConnect());
    QString refusal;
    QVERIFY2(machine()->move({{QStringLiteral("X"), 200.0}, {QStringLiteral("A"), 3600.0}}, false,
                             &refusal) != 0,
             qPrintable(refusal));
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->moving() && m_nanotec->moving(), 10000);
    window()->safetyBar()->stopButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->receivedStop() && m_nanotec->receivedStop(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->still() && m_nanotec->still(), 10000);
    QVERIFY(m_elab->position() < 80000);
    QVERIFY(m_nanotec->position() < 3000); // stopped, not at its limit switch
    QTRY_COMPARE_WITH_TIMEOUT(
        window()->lastError(),
        QStringLiteral("Stopped: every controller confirmed standstill (table, rotary)."), 10000);
}

void TestMachineWindow::stop_controllerWithoutStopCommand_messageNamesIt()
{
    // The laser marker's motor axes have no stop command (Capabilities::stopCommand).
    const QByteArray json = R"({
  "format": "stepdeck-machine", "version": 1, "name": "Board and marker",
  "controllers": [
    { "id": "table", "model": "elab", "port": "sim" },
    { "id": "marker", "model": "laser-axis", "port": "sim" }
  ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "U", "controller": "marker", "axis": "X", "unit": "steps" }
  ]
})";
    QVERIFY(window()->openMachine(writeFile(json)));
    window()->machineBar()->connectButton()->click();
    for (const char* id : {"table", "marker"}) {
        ControllerSession* s = machine()->session(QString::fromLatin1(id));
        QTRY_COMPARE_WITH_TIMEOUT(s->linkState(), LinkState::Connected, 10000);
    }
    window()->safetyBar()->stopButton()->click();
    const QString text = window()->lastError();
    QVERIFY2(text.contains(QStringLiteral("Stop sent to table:")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("marker cannot be stopped")), qPrintable(text));
    // The table confirms; the marker is still named as not stopped.
    QTRY_VERIFY2_WITH_TIMEOUT(
        window()->lastError().startsWith(QStringLiteral("Stopped: table confirmed standstill.")),
        qPrintable(window()->lastError()), 10000);
    QVERIFY(window()->lastError().contains(QStringLiteral("marker cannot be stopped")));
}

// STOP during a jog of both controllers (one input, Machine::jog): the message claims the stop
// only once both devices report standstill -- and when it does, both simulators stand still.
void TestMachineWindow::stop_duringTwoControllerJog_bothStillThenConfirmedMessage()
{
    QVERIFY(openAndConnect());
    QString refusal;
    const QMap<QString, double> rates{{QStringLiteral("X"), 5.0}, {QStringLiteral("A"), 10.0}};
    QVERIFY2(machine()->jog(rates, &refusal), qPrintable(refusal));
    QTimer renew; // the held input renews the controllers' jog leases
    connect(&renew, &QTimer::timeout, this, [this, &rates] {
        QString why;
        machine()->jog(rates, &why);
    });
    renew.start(50);
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->moving(Axis::X) && m_nanotec->moving(Axis::X), 10000);
    renew.stop(); // the input is released with the STOP, as the window's STOP does
    QStringList shown;
    connect(window()->messages(), &ui::StatusMessages::changed, this, [this, &shown] {
        const QString text = window()->lastError();
        if (text.startsWith(QStringLiteral("Stopped")))
            shown << QStringLiteral("%1|%2").arg(text).arg(m_elab->still() && m_nanotec->still());
    });
    window()->safetyBar()->stopButton()->click();
    QVERIFY2(window()->lastError().startsWith(QStringLiteral("Stop sent to table, rotary:")),
             qPrintable(window()->lastError()));
    QTRY_COMPARE_WITH_TIMEOUT(
        window()->lastError(),
        QStringLiteral("Stopped: every controller confirmed standstill (table, rotary)."), 10000);
    QVERIFY(m_elab->receivedStop() && m_nanotec->receivedStop());
    QVERIFY(m_elab->still() && m_nanotec->still());
    // When the words first appeared, both devices already stood still.
    QVERIFY(!shown.isEmpty());
    QVERIFY2(shown.first().endsWith(QStringLiteral("|1")), qPrintable(shown.first()));
}

// A controller that does not answer its stop (the drive went silent): the message does not
// claim the stop, it names the controller and why.
void TestMachineWindow::stop_controllerSilent_messageNamesItNotConfirmed()
{
    QVERIFY(openAndConnect());
    m_nanotec->probe([this] {
        SimulatorFaults faults;
        faults.silent = true;
        m_nanotec->sim()->setFaults(faults);
        return true;
    });
    window()->safetyBar()->stopButton()->click();
    QVERIFY2(window()->lastError().startsWith(QStringLiteral("Stop sent to table, rotary:")),
             qPrintable(window()->lastError()));
    auto named = [this] {
        const auto& log = window()->messages()->log();
        return std::any_of(log.cbegin(), log.cend(), [](const auto& entry) {
            return entry.text.startsWith(QStringLiteral("STOP not confirmed by \"rotary\": "));
        });
    };
    QTRY_VERIFY_WITH_TIMEOUT(named(), 15000);
    // Never the claim that every controller stopped.
    const auto& log = window()->messages()->log();
    QVERIFY(std::none_of(log.cbegin(), log.cend(), [](const auto& entry) {
        return entry.text.startsWith(QStringLiteral("Stopped"));
    }));
}

void TestMachineWindow::jog_otherControllerLinkLost_heldJogDoesNotResume()
{
    QVERIFY(openAndConnect());
    // The pages show the table: its Z jogs from the stick, held for the whole test.
    ui::JoystickPad* z = window()->jogPanel()->zStick();
    pointerPress(z, z->centre());
    pointerMove(z, z->pointFor(QPointF(0.0, -1.0)));
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->moving(Axis::Z), 10000);
    m_nanotec->vanish();
    // The machine stops the table and the window names the failed controller.
    // (In the message log: a later message may be the newest on the line by then.)
    auto named = [this] {
        const auto& log = window()->messages()->log();
        return std::any_of(log.cbegin(), log.cend(), [](const auto& entry) {
            return entry.text.contains(QStringLiteral("controller \"rotary\" lost its link"));
        });
    };
    QTRY_VERIFY_WITH_TIMEOUT(named(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->still(), 10000);
    // The stick is still held: its input was released, so the jog does not start again.
    ControllerSession* table = machine()->session(QStringLiteral("table"));
    QSignalSpy polls(table, &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 10, 10000);
    QVERIFY(m_elab->still());
    QVERIFY(!window()->jogController()->isJogging());
    pointerRelease(z, z->centre());
}

void TestMachineWindow::banner_tableReferencedRotaryNot_machineNotReady()
{
    QVERIFY(openAndConnect());
    // The pages show the table; every axis of it is referenced, the rotary drive's is not.
    ControllerSession* table = machine()->session(QStringLiteral("table"));
    table->reference({{Axis::X, -1}, {Axis::Y, -1}, {Axis::Z, -1}});
    QTRY_VERIFY_WITH_TIMEOUT(std::all_of(table->status().axes.cbegin(), table->status().axes.cend(),
                                         [](const AxisStatus& a) { return a.referenced; }),
                             20000);
    QCOMPARE(window()->context()->session(), table);
    QVERIFY2(!window()->safetyBar()->bannerText().startsWith(QStringLiteral("Ready")),
             qPrintable(window()->safetyBar()->bannerText()));
    QCOMPARE(window()->safetyBar()->bannerSeverity(), QStringLiteral("warning"));
}

void TestMachineWindow::jog_heldKeyOnRotary_limitedToMaxJogSpeedAtTheDrive()
{
    // A at most 4 deg/s = 400 steps/s; the operator's setting asks for 50 deg/s.
    QByteArray json = machineJson();
    json.replace(R"("unit": "deg", "stepsPerUnit": 100 })",
                 R"("unit": "deg", "stepsPerUnit": 100, "maxJogSpeed": 4 })");
    QVERIFY(window()->openMachine(writeFile(json)));
    window()->machineBar()->connectButton()->click();
    for (const char* id : {"table", "rotary"}) {
        ControllerSession* s = machine()->session(QString::fromLatin1(id));
        QTRY_COMPARE_WITH_TIMEOUT(s->linkState(), LinkState::Connected, 10000);
    }
    // Home/End jog the other stick's machine axis, A here (on whichever page is shown).
    window()->jogController()->setMaxSpeed(Axis::U, 50.0);
    QCOMPARE(window()->jogController()->maxSpeed(Axis::U), 4.0);
    window()->keyboardJog()->setSpeedFraction(1.0);
    window()->jogPanel()->keyboardCheck()->setChecked(true);
    window()->jogPanel()->xyPad()->window()->setFocus();
    QTest::keyPress(window(), Qt::Key_Home); // held: +A
    QTRY_VERIFY_WITH_TIMEOUT(m_nanotec->moving(Axis::X), 10000);
    ControllerSession* rotary = machine()->session(QStringLiteral("rotary"));
    QSignalSpy polls(rotary, &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 10, 10000);
    // At the drive: the speed-mode frequency ('o', manual 6.2) never went above 400.
    const QRegularExpression speed(QStringLiteral("^#1o(\\d+)\r$"));
    int highest = 0;
    for (const QByteArray& f : m_nanotec->frames()) {
        const QRegularExpressionMatch m = speed.match(QString::fromLatin1(f));
        if (m.hasMatch())
            highest = qMax(highest, m.captured(1).toInt());
    }
    QCOMPARE(highest, 400);
    QVERIFY(!m_elab->moving(Axis::X));
    QTest::keyRelease(window(), Qt::Key_Home);
}

void TestMachineWindow::dro_afterMoveX2point5_shows2point500mm()
{
    QVERIFY(openAndConnect());
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QVERIFY(dro->isVisibleTo(window()));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm"));
    QCOMPARE(dro->unitText(QStringLiteral("A")), QStringLiteral("deg"));
    QSignalSpy finished(machine(), &machine::Machine::moveFinished);
    QString refusal;
    QVERIFY2(machine()->move({{QStringLiteral("X"), 2.5}, {QStringLiteral("A"), 25.0}}, false,
                             &refusal) != 0,
             qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
    QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
    QCOMPARE(m_elab->position(), qint64(1000)); // at the device: 2.5 mm x 400 steps/mm
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("X")), QStringLiteral("2.500"),
                              10000);
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("A")), QStringLiteral("25.000"),
                              10000);
    QVERIFY(dro->detailText(QStringLiteral("X")).contains(QStringLiteral("1000")));
    // Not referenced since the connect: the position is counted, not known from the origin.
    QCOMPARE(dro->stateText(QStringLiteral("X")), QStringLiteral("UNKNOWN"));
}

void TestMachineWindow::layout_sixAxisMachineAt1366x768_fitsAndNothingIsCut()
{
    const QByteArray json = R"({
  "format": "stepdeck-machine", "version": 1, "name": "Six-axis cell with a long name",
  "controllers": [
    { "id": "table", "model": "elab", "port": "sim" },
    { "id": "wrist", "model": "nanotec", "port": "sim", "axes": { "X": 1, "Y": 2, "Z": 3 } }
  ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 800 },
    { "name": "A", "controller": "wrist", "axis": "X", "unit": "deg", "stepsPerUnit": 88.8889 },
    { "name": "B", "controller": "wrist", "axis": "Y", "unit": "deg", "stepsPerUnit": 100 },
    { "name": "C", "controller": "wrist", "axis": "Z", "unit": "steps" }
  ]
})";
    QVERIFY(window()->openMachine(writeFile(json)));
    window()->machineBar()->connectButton()->click();
    for (const char* id : {"table", "wrist"}) {
        ControllerSession* s = machine()->session(QString::fromLatin1(id));
        QTRY_COMPARE_WITH_TIMEOUT(s->linkState(), LinkState::Connected, 10000);
    }
    const QSize available(1366, 768 - 40); // room for a panel or title bar
    const QSize minimum = window()->minimumSizeHint().expandedTo(window()->minimumSize());
    QVERIFY2(
        minimum.width() <= available.width() && minimum.height() <= available.height(),
        qPrintable(QStringLiteral("minimum %1x%2").arg(minimum.width()).arg(minimum.height())));
    QCOMPARE(QGuiApplication::primaryScreen()->availableGeometry().size(), QSize(1366, 768));
    window()->raisePage(window()->positionPanel());
    QCoreApplication::processEvents();
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_COMPARE(dro->stateText(QStringLiteral("C")), QStringLiteral("UNKNOWN"));
    const QStringList cut = clippedTexts(dro) + clippedTexts(window()->machineBar()) +
                            clippedTexts(window()->positionPanel()->machineGoTo());
    QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QStringLiteral("; "))));
    QVERIFY(window()->safetyBar()->stopButton()->visibleRegion().boundingRect().width() > 100);
}

// Ports like /dev/serial/by-id/... paths made the bar wider than a 1366 screen with three
// controllers: each is elided in the middle, the full port in its lamp's tooltip.
void TestMachineWindow::machineBar_longNamesAndPorts_elidedFullTextInTooltip()
{
    const QString longPort =
        QStringLiteral("/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0");
    const QByteArray json = QStringLiteral(R"({
  "format": "stepdeck-machine", "version": 1,
  "name": "Gantry of the second assembly line, hall 4, with rotary wrist and tool changer",
  "controllers": [
    { "id": "table", "model": "elab", "port": "%1" },
    { "id": "wrist", "model": "nanotec", "port": "%1.1", "axes": { "X": 1 } },
    { "id": "turntable", "model": "emis", "port": "%1.2" }
  ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "A", "controller": "wrist", "axis": "X", "unit": "deg", "stepsPerUnit": 100 },
    { "name": "U", "controller": "turntable", "axis": "U", "unit": "deg", "stepsPerUnit": 50 }
  ]
})")
                                .arg(longPort)
                                .toUtf8();
    QVERIFY(window()->openMachine(writeFile(json)));
    ui::MachineBar* bar = window()->machineBar();
    QVERIFY(bar->lampText(QStringLiteral("turntable")).contains(longPort + QStringLiteral(".2")));
    const ui::LedIndicator* lamp = bar->lamp(QStringLiteral("wrist"));
    QVERIFY(lamp->text().startsWith(QStringLiteral("wrist @ /dev/")));
    QVERIFY(lamp->text().contains(QChar(0x2026)));
    QVERIFY2(bar->sizeHint().width() < 1366 / 2,
             qPrintable(QString::number(bar->sizeHint().width())));
    const QSize minimum = window()->minimumSizeHint().expandedTo(window()->minimumSize());
    QVERIFY2(minimum.width() <= 1366, qPrintable(QString::number(minimum.width())));
}

void TestMachineWindow::goTo_unreferencedAxis_refusedNothingSent()
{
    QVERIFY(openAndConnect());
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    QVERIFY(goTo->isVisibleTo(window()));
    goTo->axisCombo()->setCurrentIndex(goTo->axisCombo()->findData(QStringLiteral("X")));
    goTo->targetBox()->setValue(1.25);
    goTo->goButton()->click();
    QVERIFY2(goTo->resultText().contains(QStringLiteral("X is not referenced")),
             qPrintable(goTo->resultText()));
    // Three more status polls: a move sent before them would have reached the board by now.
    QSignalSpy polls(machine()->session(QStringLiteral("table")),
                     &ControllerSession::statusChanged);
    QTRY_VERIFY_WITH_TIMEOUT(polls.size() >= 3, 10000);
    QCOMPARE(m_elab->probe([this] { return int(m_elab->acceptedMoveCount()); }), 0);
}

void TestMachineWindow::goTo_referencedX_deviceAtTheNearestStep()
{
    QVERIFY(openAndConnect());
    ControllerSession* table = machine()->session(QStringLiteral("table"));
    table->reference({{Axis::X, -1}, {Axis::Y, -1}, {Axis::Z, -1}});
    QTRY_VERIFY_WITH_TIMEOUT(
        table->status().axes.value(Axis::X).referenced && !table->status().anyMoving(), 20000);
    const qint64 origin = m_elab->position();
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    goTo->axisCombo()->setCurrentIndex(goTo->axisCombo()->findData(QStringLiteral("X")));
    goTo->targetBox()->setValue(1.25);
    goTo->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo->resultText() == QStringLiteral("X arrived."), 30000);
    QCOMPARE(m_elab->position() - origin, qint64(500)); // 1.25 mm x 400 steps/mm
    QVERIFY(m_elab->still());
}

// "Reference all" with a machine open is the machine's run (Machine::reference): the rotary
// drive is referenced too, not only the controller the pages show, and the DRO then marks
// every axis as referenced.
void TestMachineWindow::referenceAll_machine_everyControllerInTheFilesOrder()
{
    QVERIFY(openAndConnect());
    QCOMPARE(window()->context()->session(), machine()->session(QStringLiteral("table")));
    auto* all = window()->referencePanel()->findChild<QPushButton*>(QStringLiteral("referenceAll"));
    QVERIFY(all);
    all->click();
    // At the devices: the drive got its reference run (mode p4), the board its axes moved.
    const auto driveReferenced = [this] {
        const QList<QByteArray> frames = m_nanotec->frames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [](const QByteArray& f) { return f.contains("p4"); });
    };
    QTRY_VERIFY_WITH_TIMEOUT(driveReferenced(), 30000);
    QTRY_COMPARE_WITH_TIMEOUT(window()->referencePanel()->messageText(),
                              QStringLiteral("Every axis of the machine is referenced."), 60000);
    QVERIFY(m_elab->still() && m_nanotec->still());
    for (const machine::MachineAxis& a : machine()->description().axes)
        QCOMPARE(machine()->axisStatus(a).known, machine::PositionKnowledge::Referenced);
    QVERIFY(all->isEnabled()); // the run is over
}

// With a machine open the panel shows the machine's axes with the direction and order of its
// file (what Machine::reference follows), not the selected controller's editable fields, and
// "Reference A" runs only the rotary drive: the board sees no motion.
void TestMachineWindow::referenceAxis_machine_fileRowsShownOnlyThatControllerRuns()
{
    QVERIFY(openAndConnect());
    ui::ReferencePanel* panel = window()->referencePanel();
    ui::MachineReferenceRows* rows = panel->machineRows();
    QWidget* controllerRows = panel->findChild<QWidget*>(QStringLiteral("controllerReferenceRows"));
    QVERIFY(rows->isVisibleTo(panel));
    QVERIFY(!controllerRows->isVisibleTo(panel));
    QCOMPARE(rows->axisNames(), (QStringList{"A", "X", "Y", "Z"}));
    QCOMPARE(rows->directionText(QStringLiteral("X")), QStringLiteral("\u2212 (negative)"));
    QCOMPARE(rows->orderText(QStringLiteral("Z")), QStringLiteral("0"));
    const qint64 boardBefore = m_elab->position();
    QTRY_VERIFY_WITH_TIMEOUT(rows->runButton(QStringLiteral("A"))->isEnabled(), 5000);
    rows->runButton(QStringLiteral("A"))->click();
    const auto driveReferenced = [this] {
        const QList<QByteArray> frames = m_nanotec->frames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [](const QByteArray& f) { return f.contains("p4"); });
    };
    QTRY_VERIFY_WITH_TIMEOUT(driveReferenced(), 30000);
    QTRY_COMPARE_WITH_TIMEOUT(panel->messageText(), QStringLiteral("A referenced."), 60000);
    const machine::MachineDescription& d = machine()->description();
    QCOMPARE(machine()->axisStatus(*d.axis(QStringLiteral("A"))).known,
             machine::PositionKnowledge::Referenced);
    QCOMPARE(machine()->axisStatus(*d.axis(QStringLiteral("X"))).known,
             machine::PositionKnowledge::Unknown);
    QVERIFY(m_elab->still());
    QCOMPARE(m_elab->position(), boardBefore);
    window()->closeMachine();
    QVERIFY(!rows->isVisibleTo(panel));
    QVERIFY(controllerRows->isVisibleTo(panel));
}

bool TestMachineWindow::referenceTable()
{
    ControllerSession* table = machine()->session(QStringLiteral("table"));
    table->reference({{Axis::X, -1}, {Axis::Y, -1}, {Axis::Z, -1}});
    return QTest::qWaitFor(
        [table] {
            return table->status().axes.value(Axis::X).referenced && !table->status().anyMoving();
        },
        20000);
}

QToolButton* TestMachineWindow::zeroButton(const QString& axis) const
{
    return window()->positionPanel()->machineDro()->findChild<QToolButton*>(
        QStringLiteral("machineZero") + axis);
}

// Zero X at a known position: the digits read 0.000 in work coordinates, the line below keeps
// the machine position, and a go-to in work coordinates reaches the board at offset + target.
void TestMachineWindow::zero_referencedX_digitsZeroAndGoToWorkMovesDeviceToOffsetPlusTarget()
{
    QVERIFY(openAndConnect());
    QVERIFY(referenceTable());
    const qint64 origin = m_elab->position();
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    goTo->axisCombo()->setCurrentIndex(goTo->axisCombo()->findData(QStringLiteral("X")));
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to:"));
    goTo->targetBox()->setValue(2.5);
    goTo->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo->resultText() == QStringLiteral("X arrived."), 30000);
    QCOMPARE(m_elab->position() - origin, qint64(1000));
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("X")), QStringLiteral("2.500"),
                              10000);
    QToolButton* zero = zeroButton(QStringLiteral("X"));
    QVERIFY(zero && zero->isVisibleTo(window()));
    zero->click();
    QCOMPARE(dro->displayedValue(QStringLiteral("X")), QStringLiteral("0.000"));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm work"));
    QCOMPARE(dro->stateText(QStringLiteral("X")), QStringLiteral("REFERENCED"));
    QVERIFY2(dro->detailText(QStringLiteral("X")).contains(QStringLiteral("machine 2.500 mm")),
             qPrintable(dro->detailText(QStringLiteral("X"))));
    QVERIFY(dro->detailText(QStringLiteral("X")).contains(QStringLiteral("1000 steps")));
    QCOMPARE(dro->displayedValue(QStringLiteral("Y")), QStringLiteral("0.000")); // untouched
    QCOMPARE(dro->unitText(QStringLiteral("Y")), QStringLiteral("mm"));
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to (work):"));
    // Go to (work) X = 1: machine 3.5 mm, 1400 steps from the origin at the board.
    goTo->targetBox()->setValue(1.0);
    goTo->goButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(goTo->resultText() == QStringLiteral("X arrived."), 30000);
    QCOMPARE(m_elab->position() - origin, qint64(1400));
    QVERIFY(m_elab->still());
    QTRY_COMPARE_WITH_TIMEOUT(dro->displayedValue(QStringLiteral("X")), QStringLiteral("1.000"),
                              10000);
    // Clear: machine coordinates again, for the read-out and the go-to.
    dro->clearOffsets();
    QCOMPARE(dro->displayedValue(QStringLiteral("X")), QStringLiteral("3.500"));
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to:"));
}

// Not referenced since the connect: a work origin there would say nothing about the machine.
void TestMachineWindow::zero_unknownPosition_refusedWithReasonNoOffset()
{
    QVERIFY(openAndConnect());
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_COMPARE(dro->stateText(QStringLiteral("X")), QStringLiteral("UNKNOWN"));
    zeroButton(QStringLiteral("X"))->click();
    QVERIFY2(dro->messageText().contains(QStringLiteral("position is unknown")),
             qPrintable(dro->messageText()));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm"));
    QCOMPARE(window()->positionPanel()->machineGoTo()->labelText(), QStringLiteral("Go to:"));
}

// The offsets belong to the machine file: closing and opening it again brings them back.
void TestMachineWindow::zero_reopenMachine_offsetsRemembered()
{
    QVERIFY(openAndConnect());
    QVERIFY(referenceTable());
    QSignalSpy finished(machine(), &machine::Machine::moveFinished);
    QString refusal;
    QVERIFY2(machine()->move({{QStringLiteral("Y"), 1.25}}, true, &refusal) != 0,
             qPrintable(refusal));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_COMPARE_WITH_TIMEOUT(dro->stateText(QStringLiteral("Y")), QStringLiteral("REFERENCED"),
                              10000);
    QVERIFY(dro->zeroAxis(QStringLiteral("Y")));
    QCOMPARE(dro->displayedValue(QStringLiteral("Y")), QStringLiteral("0.000"));
    window()->closeMachine();
    QTRY_VERIFY_WITH_TIMEOUT(m_elab->still() && m_nanotec->still(), 10000);
    QVERIFY(window()->openMachine(m_dir->filePath(QStringLiteral("test.machine.json"))));
    QCOMPARE(dro->unitText(QStringLiteral("Y")), QStringLiteral("mm work"));
    QCOMPARE(dro->unitText(QStringLiteral("X")), QStringLiteral("mm"));
    // Not connected: the last value known, in work coordinates, marked as such.
    QCOMPARE(dro->stateText(QStringLiteral("Y")), QStringLiteral("NO LINK"));
    ui::MachineGoTo* goTo = window()->positionPanel()->machineGoTo();
    goTo->axisCombo()->setCurrentIndex(goTo->axisCombo()->findData(QStringLiteral("Y")));
    QCOMPARE(goTo->labelText(), QStringLiteral("Go to (work):"));
}

// The offscreen screen is a 1366x768 laptop's (as in tst_layoutholdsstill): the window sizes
// its docks for the screen it starts on.
int main(int argc, char** argv)
{
    const QString config = QDir::temp().filePath(
        QStringLiteral("stepdeck-machine-screen-%1.json").arg(QCoreApplication::applicationPid()));
    QFile file(config);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(R"({"screens": [{"name": "laptop", "x": 0, "y": 0, "width": 1366,
            "height": 768, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]})") < 0)
        return 2;
    file.close();
    qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + config.toLocal8Bit());
    int result = 0;
    {
        QApplication app(argc, argv);
        TestMachineWindow test;
        QTEST_SET_MAIN_SOURCE_PATH
        result = QTest::qExec(&test, argc, argv);
    }
    QFile::remove(config);
    return result;
}

#include "tst_machinewindow.moc"
