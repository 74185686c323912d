// stepdeck-sim --machine FILE (issue 19): one simulator per controller on its own
// pseudo-terminal, and a copy of the machine file whose ports point at them (first stdout
// line, and --out). Each port is proven by stepdeck-cli talking to the device behind it.
#include "ProcessSupport.h"
#include "TestMain.h"
#include "machine/MachineFile.h"
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

using stepdeck::machine::MachineDescription;
using stepdeck::machine::MachineFile;

class TestSimMachine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup();

    void machine_example_copyPointsAtOneSimulatorPerController_data();
    void machine_example_copyPointsAtOneSimulatorPerController();
    void machine_refusedArguments_exitCodes_data();
    void machine_refusedArguments_exitCodes();

private:
    using Run = stepdeck::testing::ProcessRun;
    QString binary(const QString& name) const { return QDir(m_binDir).filePath(name); }
    std::optional<MachineDescription> startMachine(const QStringList& args);

    QString m_binDir;
    QString m_examples = QStringLiteral(STEPDECK_SOURCE_DIR "/docs/examples");
    QProcess* m_sim = nullptr;
};

void TestSimMachine::initTestCase()
{
    m_binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!m_binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    QVERIFY(QFileInfo(binary("stepdeck-sim")).isExecutable());
}

void TestSimMachine::cleanup()
{
    if (!m_sim)
        return;
    m_sim->terminate();
    if (!m_sim->waitForFinished(5000))
        m_sim->kill();
    QCOMPARE(m_sim->exitStatus(), QProcess::NormalExit);
    QCOMPARE(m_sim->exitCode(), 0); // SIGTERM ends it cleanly
    delete m_sim;
    m_sim = nullptr;
}

// Starts stepdeck-sim with args and reads its first stdout line as a machine file.
std::optional<MachineDescription> TestSimMachine::startMachine(const QStringList& args)
{
    m_sim = new QProcess(this);
    m_sim->setStandardErrorFile(QProcess::nullDevice());
    m_sim->start(binary("stepdeck-sim"), args);
    if (!m_sim->waitForStarted(5000))
        return std::nullopt;
    while (!m_sim->canReadLine()) {
        if (!m_sim->waitForReadyRead(10000))
            return std::nullopt;
    }
    const QByteArray line = m_sim->readLine();
    stepdeck::machine::MachineFileError error;
    std::optional<MachineDescription> copy = MachineFile::parse(line, &error);
    if (!copy)
        qWarning() << "first line is no machine file:" << error.text() << line;
    return copy;
}

void TestSimMachine::machine_example_copyPointsAtOneSimulatorPerController_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("elab + nanotec") << "elab-xyz-nanotec-rotary.machine.json";
    QTest::newRow("two nanotec buses") << "nanotec-two-buses.machine.json";
    QTest::newRow("emis") << "emis-xyzu.machine.json";
}

void TestSimMachine::machine_example_copyPointsAtOneSimulatorPerController()
{
    QFETCH(QString, file);
    const QString path = QDir(m_examples).filePath(file);
    std::optional<MachineDescription> original = MachineFile::load(path, nullptr);
    QVERIFY(original);
    // The copy names a setup file by its absolute path (it is written elsewhere).
    MachineFile::anchorSetupFiles(&*original, path);
    QTemporaryDir dir;
    const QString out = dir.filePath("sim.machine.json");
    const std::optional<MachineDescription> copy = startMachine({"--machine", path, "--out", out});
    QVERIFY(copy);
    QCOMPARE(MachineFile::load(out, nullptr), copy); // --out holds the same copy

    QCOMPARE(copy->controllers.size(), original->controllers.size());
    QSet<QString> ports;
    for (int i = 0; i < copy->controllers.size(); ++i) {
        stepdeck::machine::MachineController c = copy->controllers.at(i);
        QVERIFY2(c.port.startsWith("/dev/"), qPrintable(c.port));
        ports << c.port;
        original->controllers[i].port = c.port;
        // The device behind the port answers as its model does.
        QStringList args{"--model", c.modelId, "--port", c.port};
        if (!c.busAddresses.isEmpty()) {
            QStringList map;
            for (auto it = c.busAddresses.cbegin(); it != c.busAddresses.cend(); ++it)
                map << QStringLiteral("%1=%2").arg(stepdeck::axisName(it.key())).arg(it.value());
            args << "--axes" << map.join(',');
        }
        const Run status =
            stepdeck::testing::runProcess(binary("stepdeck-cli"), args << "status", 20000);
        QVERIFY2(status.exitCode == 0, status.err.constData());
    }
    QCOMPARE(ports.size(), copy->controllers.size()); // a terminal each
    QCOMPARE(*copy, *original);                       // nothing else changed
}

void TestSimMachine::machine_refusedArguments_exitCodes_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("needle");
    const QString example = m_examples + "/elab-xyz-nanotec-rotary.machine.json";
    QTest::newRow("unreadable") << QStringList{"--machine", "/nonexistent/m.json"} << 12
                                << "cannot read";
    QTest::newRow("with --model") << QStringList{"--machine", example, "--model", "elab"} << 2
                                  << "--model";
    QTest::newRow("with --limit") << QStringList{"--machine", example, "--limit", "X=-5:5"} << 2
                                  << "--machine";
    QTest::newRow("--out alone") << QStringList{"--out", "/tmp/x.json"} << 2 << "--machine";
}

void TestSimMachine::machine_refusedArguments_exitCodes()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, needle);
    const Run run = stepdeck::testing::runProcess(binary("stepdeck-sim"), args, 10000);
    QCOMPARE(run.exitCode, exitCode);
    QVERIFY2(run.err.contains(needle.toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty()); // no machine to connect to
}

STEPDECK_TEST_GUILESS_MAIN(TestSimMachine)
#include "tst_sim_machine.moc"
