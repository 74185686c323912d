// stepdeck-cli --machine FILE (issue 19): an E-LAB X/Y/Z table and a Nanotec drive as rotary A,
// each simulator on a real pty in this process, the CLI as a process. Every motion test
// asserts what the DEVICES saw and that they end standing still.
#include "TestMain.h"
#include "program/WorkOffsetStore.h"
#include "protocols/Registry.h"
#include "sim/PtyEndpoint.h"
#include "sim/Simulator.h"
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <csignal>
#include <memory>

using namespace stepdeck;

namespace {
struct Device
{
    std::unique_ptr<PtyEndpoint> end;
    std::unique_ptr<Simulator> sim;
};

Device startDevice(const QString& model)
{
    Device d;
    const ModelInfo* info = findModel(model);
    d.end = std::make_unique<PtyEndpoint>();
    QString error;
    if (!d.end->create(&error))
        qFatal("pty: %s", qPrintable(error));
    SimulatorOptions options;
    options.line = info->line;
    options.addresses = {1};
    d.sim.reset(info->createSimulator(options));
    d.sim->attach(d.end.get());
    return d;
}

qint64 acceptedSteps(const Simulator& sim, Axis axis)
{
    qint64 sum = 0;
    for (const SimulatedMove& m : sim.acceptedMoves()) {
        if (m.axis == axis)
            sum += m.steps;
    }
    return sum;
}

bool receivedStop(const Simulator& sim)
{
    const QList<QByteArray> frames = sim.receivedFrames();
    return std::any_of(frames.cbegin(), frames.cend(),
                       [&sim](const QByteArray& f) { return sim.isStopFrame(f); });
}

bool receivedContaining(const Simulator& sim, const QByteArray& part)
{
    const QList<QByteArray> frames = sim.receivedFrames();
    return std::any_of(frames.cbegin(), frames.cend(),
                       [&part](const QByteArray& f) { return f.contains(part); });
}

QJsonObject byName(const QJsonArray& list, const QString& key, const QString& value)
{
    for (const QJsonValue& v : list) {
        if (v.toObject().value(key).toString() == value)
            return v.toObject();
    }
    return {};
}
} // namespace

class TestCliMachineRun : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void move_xAndA_devicesGetTheirStepsAndPositionsPrintInUnits();
    void moveAbs_unreferenced_refusedNothingSent();
    void home_namedAxes_runToTheirSwitchesOthersStay();
    void jog_xAndAForAWhile_bothMoveThenStandStill();
    void status_json_axesInUnitsAndControllersWithTheirLink();
    void parameterCommand_twoControllers_needsController();
    void controllerStatus_givenController_talksToThatController();
    void signal_duringTwoControllerJog_bothDevicesStandStill_data();
    void signal_duringTwoControllerJog_bothDevicesStandStill();
    void nanotecVanishes_duringXJog_exit6NamesItAndTheTableStandsStill();
    void connect_portMissing_exit6NamesTheControllerNothingMoves();
    void machineFile_invalidOrUnreadable_exit7Or12_data();
    void machineFile_invalidOrUnreadable_exit7Or12();
    void run_referenceWithTheWindowsOffsets_boardCutsInTheWindowsZero_data();
    void run_referenceWithTheWindowsOffsets_boardCutsInTheWindowsZero();
    void signal_duringProgramRun_abortedAtItsLineBoardStandsRestNeverSent();

private:
    void writeMachineFile();
    void startCli(const QStringList& command);
    bool finished(int timeoutMs = 30000);
    int run(const QStringList& command); // starts, waits, returns the exit code

    QString m_cli;
    std::unique_ptr<QTemporaryDir> m_dir;
    QString m_file;
    Device m_elab;
    Device m_nanotec;
    std::unique_ptr<QProcess> m_process;
    QByteArray m_out;
    QByteArray m_err;
};

void TestCliMachineRun::initTestCase()
{
    const QString binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    m_cli = QDir(binDir).filePath(QStringLiteral("stepdeck-cli"));
}

void TestCliMachineRun::init()
{
    m_elab = startDevice(QStringLiteral("elab"));
    m_nanotec = startDevice(QStringLiteral("nanotec"));
    m_dir = std::make_unique<QTemporaryDir>();
    writeMachineFile();
}

void TestCliMachineRun::cleanup()
{
    if (m_process && m_process->state() != QProcess::NotRunning) {
        m_process->kill();
        m_process->waitForFinished(5000);
    }
    m_process.reset();
    m_elab = {};
    m_nanotec = {};
    m_dir.reset();
}

// X/Y/Z in mm at 400 steps/mm on the board, A in degrees at 100 steps/deg on drive 1; Z is
// referenced first, then the others.
void TestCliMachineRun::writeMachineFile()
{
    QJsonArray axes;
    for (const char* name : {"X", "Y", "Z"})
        axes.append(
            QJsonObject{{"name", name},
                        {"controller", "table"},
                        {"axis", name},
                        {"unit", "mm"},
                        {"stepsPerUnit", 400},
                        {"reference", QJsonObject{{"order", QByteArray(name) == "Z" ? 0 : 1}}}});
    axes.append(QJsonObject{{"name", "A"},
                            {"controller", "rotary"},
                            {"axis", "X"},
                            {"unit", "deg"},
                            {"stepsPerUnit", 100}});
    const QJsonObject machine{
        {"format", "stepdeck-machine"},
        {"version", 1},
        {"name", "Table with rotary axis"},
        {"controllers",
         QJsonArray{
             QJsonObject{{"id", "table"}, {"model", "elab"}, {"port", m_elab.end->slavePath()}},
             QJsonObject{{"id", "rotary"},
                         {"model", "nanotec"},
                         {"port", m_nanotec.end->slavePath()},
                         {"axes", QJsonObject{{"X", 1}}}}}},
        {"axes", axes}};
    m_file = m_dir->filePath(QStringLiteral("table.machine.json"));
    QFile file(m_file);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(machine).toJson());
}

void TestCliMachineRun::startCli(const QStringList& command)
{
    m_process = std::make_unique<QProcess>();
    m_out.clear();
    m_err.clear();
    connect(m_process.get(), &QProcess::readyReadStandardError, this,
            [this] { m_err += m_process->readAllStandardError(); });
    connect(m_process.get(), &QProcess::readyReadStandardOutput, this,
            [this] { m_out += m_process->readAllStandardOutput(); });
    // A generous link timeout: the machine shares two cores with builds.
    // The window's settings of this test only (the CLI reads its work offsets: issue 47).
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), m_dir->filePath(QStringLiteral("config")));
    m_process->setProcessEnvironment(env);
    m_process->start(m_cli,
                     QStringList{"--machine", m_file, "--setup-defaults", "--timeout", "10000"} +
                         command);
    QVERIFY(m_process->waitForStarted(5000));
}

bool TestCliMachineRun::finished(int timeoutMs)
{
    // Not waitForFinished(): the simulators live in this thread and must keep answering.
    QElapsedTimer clock;
    clock.start();
    while (m_process->state() != QProcess::NotRunning && clock.elapsed() < timeoutMs)
        QSignalSpy(m_process.get(), &QProcess::finished).wait(50);
    m_out += m_process->readAllStandardOutput();
    m_err += m_process->readAllStandardError();
    return m_process->state() == QProcess::NotRunning;
}

int TestCliMachineRun::run(const QStringList& command)
{
    startCli(command);
    if (!finished())
        return -1;
    return m_process->exitCode();
}

void TestCliMachineRun::move_xAndA_devicesGetTheirStepsAndPositionsPrintInUnits()
{
    const int code = run({"move", "X=2.5", "A=25"});
    QVERIFY2(code == 0, m_err.constData());
    // 2.5 mm x 400 on the board's X; 25 deg x 100 as "s2500" to drive 1 (inside its switches).
    QCOMPARE(acceptedSteps(*m_elab.sim, Axis::X), qint64(1000));
    QCOMPARE(acceptedSteps(*m_nanotec.sim, Axis::X), qint64(2500));
    QVERIFY(receivedContaining(*m_nanotec.sim, "s2500"));
    QCOMPARE(m_elab.sim->position(Axis::X), qint64(1000));
    QCOMPARE(m_nanotec.sim->position(Axis::X), qint64(2500));
    QVERIFY(m_elab.sim->standingStill() && m_nanotec.sim->standingStill());
    QVERIFY2(m_out.contains("X=2.500") && m_out.contains("A=25.000"), m_out.constData());
}

void TestCliMachineRun::moveAbs_unreferenced_refusedNothingSent()
{
    QCOMPARE(run({"move", "--abs", "X=1", "A=5"}), 3);
    QVERIFY2(m_err.contains("not referenced"), m_err.constData());
    QCOMPARE(m_elab.sim->acceptedMoves().size(), 0);
    QCOMPARE(m_nanotec.sim->acceptedMoves().size(), 0);
}

void TestCliMachineRun::home_namedAxes_runToTheirSwitchesOthersStay()
{
    const int code = run({"home", "Z", "X"});
    QVERIFY2(code == 0, m_err.constData());
    // At the board: Z and X searched their reference switches (the simulated switch sits at
    // -20000 steps), Y was not sent anywhere.
    QVERIFY(qAbs(m_elab.sim->position(Axis::Z) + 20000) <= 10);
    QVERIFY(qAbs(m_elab.sim->position(Axis::X) + 20000) <= 10);
    QCOMPARE(m_elab.sim->position(Axis::Y), qint64(0));
    QVERIFY(m_elab.sim->standingStill());
    // Referenced axes print without a mark, the others stay unknown.
    QVERIFY2(m_out.contains("X=0.000 Y=0.000 (unknown) Z=0.000 A="), m_out.constData());
}

void TestCliMachineRun::jog_xAndAForAWhile_bothMoveThenStandStill()
{
    const int code = run({"jog", "X=2", "A=-10", "--for", "800"});
    QVERIFY2(code == 0, m_err.constData());
    // Both moved in the jogged directions and were ramped down before the CLI let go.
    QVERIFY(m_elab.sim->position(Axis::X) > 0);
    QVERIFY(m_nanotec.sim->position(Axis::X) < 0);
    QVERIFY(m_elab.sim->standingStill() && m_nanotec.sim->standingStill());
    QVERIFY2(m_out.contains("X=") && m_out.contains("A=-"), m_out.constData());
}

void TestCliMachineRun::status_json_axesInUnitsAndControllersWithTheirLink()
{
    QVERIFY2(run({"move", "A=12.5"}) == 0, m_err.constData());
    QVERIFY2(run({"--json", "status"}) == 0, m_err.constData());
    const QJsonObject o = QJsonDocument::fromJson(m_out).object();
    QCOMPARE(o.value("machine").toString(), QStringLiteral("Table with rotary axis"));
    const QJsonObject a = byName(o.value("axes").toArray(), "name", "A");
    QCOMPARE(a.value("controller").toString(), QStringLiteral("rotary"));
    QCOMPARE(a.value("axis").toString(), QStringLiteral("X"));
    QCOMPARE(a.value("unit").toString(), QStringLiteral("deg"));
    QCOMPARE(a.value("steps").toInteger(), qint64(1250)); // the drive's own count, read back
    QCOMPARE(a.value("position").toDouble(), 12.5);
    QCOMPARE(a.value("known").toString(), QStringLiteral("unknown")); // never referenced
    const QJsonObject x = byName(o.value("axes").toArray(), "name", "X");
    QCOMPARE(x.value("unit").toString(), QStringLiteral("mm"));
    QVERIFY(x.contains("position") && x.contains("steps") && x.contains("known"));
    const QJsonArray controllers = o.value("controllers").toArray();
    QCOMPARE(controllers.size(), 2);
    QCOMPARE(byName(controllers, "id", "table").value("link").toString(),
             QStringLiteral("connected"));
    QCOMPARE(byName(controllers, "id", "rotary").value("model").toString(),
             QStringLiteral("nanotec"));
}

void TestCliMachineRun::parameterCommand_twoControllers_needsController()
{
    QCOMPARE(run({"get", "speed"}), 2);
    QVERIFY2(m_err.contains("--controller") && m_err.contains("table, rotary"), m_err.constData());
    QCOMPARE(run({"--controller", "spindle", "params"}), 2);
    QVERIFY2(m_err.contains("no controller \"spindle\""), m_err.constData());
    QCOMPARE(run({"--controller", "table", "move", "X=1"}), 2); // move takes machine axes
    QCOMPARE(m_elab.sim->acceptedMoves().size(), 0);
}

void TestCliMachineRun::controllerStatus_givenController_talksToThatController()
{
    QVERIFY2(run({"--controller", "rotary", "status"}) == 0, m_err.constData());
    QVERIFY2(m_out.contains("nanotec") && m_out.contains(m_nanotec.end->slavePath().toUtf8()),
             m_out.constData());
    QCOMPARE(run({"--controller", "rotary", "--json", "params"}), 0);
    QCOMPARE(QJsonDocument::fromJson(m_out).object().value("model").toString(),
             QStringLiteral("nanotec"));
}

void TestCliMachineRun::signal_duringTwoControllerJog_bothDevicesStandStill_data()
{
    QTest::addColumn<int>("signalNumber");
    QTest::newRow("SIGTERM") << SIGTERM;
    QTest::newRow("SIGHUP") << SIGHUP;
    QTest::newRow("SIGINT") << SIGINT;
}

void TestCliMachineRun::signal_duringTwoControllerJog_bothDevicesStandStill()
{
    QFETCH(int, signalNumber);
    // 2 mm/s = 800 steps/s on the board, 10 deg/s = 1000 steps/s on the drive.
    startCli({"jog", "X=2", "A=10", "--for", "60000"});
    QTRY_VERIFY_WITH_TIMEOUT(m_elab.sim->isMoving(Axis::X) && m_nanotec.sim->isMoving(Axis::X),
                             30000);
    m_elab.sim->clearReceivedFrames();
    m_nanotec.sim->clearReceivedFrames();
    QCOMPARE(::kill(pid_t(m_process->processId()), signalNumber), 0);
    QVERIFY(finished());
    QCOMPARE(m_process->exitStatus(), QProcess::NormalExit); // handled, not killed
    QVERIFY2(m_process->exitCode() == 130, m_err.constData());
    QVERIFY2(m_err.contains("every controller acknowledged the stop"), m_err.constData());
    QVERIFY(receivedStop(*m_elab.sim));
    QVERIFY(receivedStop(*m_nanotec.sim));
    QTRY_VERIFY_WITH_TIMEOUT(m_elab.sim->standingStill() && m_nanotec.sim->standingStill(), 5000);
}

void TestCliMachineRun::nanotecVanishes_duringXJog_exit6NamesItAndTheTableStandsStill()
{
    startCli({"jog", "X=2", "--for", "60000"});
    QTRY_VERIFY_WITH_TIMEOUT(m_elab.sim->isMoving(Axis::X), 30000);
    m_elab.sim->clearReceivedFrames();
    m_nanotec.end->vanish(); // the drive's USB adapter pulled
    QVERIFY(finished());
    QVERIFY2(m_process->exitCode() == 6, m_err.constData());
    QVERIFY2(m_err.contains("\"rotary\""), m_err.constData());
    QVERIFY(receivedStop(*m_elab.sim));
    QTRY_VERIFY_WITH_TIMEOUT(m_elab.sim->standingStill(), 5000);
}

void TestCliMachineRun::connect_portMissing_exit6NamesTheControllerNothingMoves()
{
    QFile file(m_file);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    file.close();
    text.replace(m_nanotec.end->slavePath().toUtf8(), "/dev/ttyStepDeckNone");
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(text);
    file.close();
    QCOMPARE(run({"move", "X=2.5", "A=25"}), 6);
    QVERIFY2(m_err.contains("controller \"rotary\"") && m_err.contains("/dev/ttyStepDeckNone"),
             m_err.constData());
    QCOMPARE(m_elab.sim->acceptedMoves().size(), 0);
}

void TestCliMachineRun::machineFile_invalidOrUnreadable_exit7Or12_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    QTest::newRow("bad stepsPerUnit")
        << QByteArray(R"({"format":"stepdeck-machine","version":1,"name":"m",
            "controllers":[{"id":"t","model":"elab","port":"/dev/ttyS0"}],
            "axes":[{"name":"X","controller":"t","axis":"X","unit":"mm","stepsPerUnit":-2}]})")
        << 7 << QStringLiteral("axes[0].stepsPerUnit");
    QTest::newRow("missing") << QByteArray() << 12 << QStringLiteral("cannot read");
}

void TestCliMachineRun::machineFile_invalidOrUnreadable_exit7Or12()
{
    QFETCH(QByteArray, content);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    m_file = m_dir->filePath(QStringLiteral("other.machine.json"));
    if (!content.isEmpty()) {
        QFile file(m_file);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(content);
    }
    QCOMPARE(run({"status"}), exitCode);
    QVERIFY2(m_err.contains(message.toUtf8()), m_err.constData());
}

// Issue 47 item 16: an ordinary CAM file (no G28, absolute moves) runs from the CLI as in the
// window: --reference references every axis first, and the work zero the window keeps for
// this machine file is used unless --offsets gives another. At the board (400 steps/mm): X1 in
// the window's zero X=2 is machine 3 mm, 1200 steps from the reference point.
void TestCliMachineRun::run_referenceWithTheWindowsOffsets_boardCutsInTheWindowsZero_data()
{
    QTest::addColumn<QStringList>("offsets");
    QTest::addColumn<qint64>("steps");
    QTest::addColumn<bool>("saidFromWindow");
    QTest::newRow("the window's zero") << QStringList() << qint64(1200) << true;
    QTest::newRow("--offsets overrides it")
        << QStringList{"--offsets", "G54:X=0.5"} << qint64(600) << false;
}

void TestCliMachineRun::run_referenceWithTheWindowsOffsets_boardCutsInTheWindowsZero()
{
    QFETCH(QStringList, offsets);
    QFETCH(qint64, steps);
    QFETCH(bool, saidFromWindow);
    {
        // Where the window keeps it: $XDG_CONFIG_HOME/StepDeck/StepDeck.conf.
        QSettings settings(m_dir->filePath(QStringLiteral("config/StepDeck/StepDeck.conf")),
                           QSettings::IniFormat);
        program::StoredOffsets stored;
        stored.systems[0] = {{QStringLiteral("X"), 2.0}};
        program::WorkOffsetStore::save(settings, QFileInfo(m_file).absoluteFilePath(), stored);
    }
    const QString program = m_dir->filePath(QStringLiteral("part.ngc"));
    {
        QFile file(program);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("G90 G21\nG0 X1\nM30\n");
    }
    const int code = run(QStringList{"run", program, "--reference"} + offsets);
    QVERIFY2(code == 0, m_err.constData());
    QCOMPARE(acceptedSteps(*m_elab.sim, Axis::X), steps);
    QVERIFY(qAbs(m_elab.sim->position(Axis::X) - (-20000 + steps)) <= 10);
    QVERIFY(m_elab.sim->standingStill());
    QCOMPARE(m_err.contains("as the window keeps them"), saidFromWindow);
}

// Ctrl+C during `run` stops the machine, which aborts the run holding its motion (issue 49 item
// 4): the board stands, the run got no further than line 2, and line 3 never reaches it.
void TestCliMachineRun::signal_duringProgramRun_abortedAtItsLineBoardStandsRestNeverSent()
{
    const QString program = m_dir->filePath(QStringLiteral("long.ngc"));
    {
        QFile file(program);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("G91 G21\nG0 X100\nG0 X1\nM30\n");
    }
    startCli({"run", program});
    QTRY_VERIFY_WITH_TIMEOUT(m_elab.sim->isMoving(Axis::X), 30000);
    m_elab.sim->clearReceivedFrames();
    QCOMPARE(::kill(pid_t(m_process->processId()), SIGINT), 0);
    QVERIFY(finished());
    QCOMPARE(m_process->exitStatus(), QProcess::NormalExit); // handled, not killed
    QVERIFY2(m_process->exitCode() == 130, m_err.constData());
    QVERIFY2(m_err.contains("line 2/4: G0 X100") && !m_err.contains("line 3/4"), m_err.constData());
    QVERIFY2(m_err.contains("interrupted: every controller acknowledged the stop"),
             m_err.constData());
    QVERIFY(receivedStop(*m_elab.sim));
    QTRY_VERIFY_WITH_TIMEOUT(m_elab.sim->standingStill(), 5000);
    QCOMPARE(m_elab.sim->acceptedMoves().size(), 1); // line 2's only
    QCOMPARE(acceptedSteps(*m_elab.sim, Axis::X), 40000);
}

STEPDECK_TEST_GUILESS_MAIN(TestCliMachineRun)
#include "tst_cli_machine_run.moc"
