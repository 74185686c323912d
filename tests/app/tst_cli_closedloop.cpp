// stepdeck-cli's closed-loop workflow (Nanotec manual 8.1) end to end: the CLI runs as a
// process on a real pty with QSerialPort, the simulated drive runs in this process, so every
// test asserts what the DRIVE received and did -- calibrated, referenced, closed loop kept,
// standing still.
#include "TestMain.h"
#include "TestSupport.h"
#include "controller/Controller.h"
#include "protocols/nanotec/NanotecModel.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include "sim/PtyEndpoint.h"
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>
#include <csignal>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::nanotec;

class TestCliClosedLoop : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void workflow_checkCalibrateReferenceEnable();
    void calibrate_withoutEncoder_exit4_namesTheDrivesError();
    void calibrate_signal_stopReachesDrive_exit130();
    void calibrate_modelWithoutClosedLoop_exit8();
    void usage_badAxisOrDirection_data();
    void usage_badAxisOrDirection();

private:
    struct Result
    {
        int exitCode = -1;
        QByteArray out;
        QByteArray err;
    };
    void startCli(const QStringList& args);
    bool finished(int timeoutMs = 30000);
    Result cli(const QStringList& args);
    NanotecDrive* drive() const { return m_sim->drive(1); }

    QString m_binDir;
    std::unique_ptr<PtyEndpoint> m_device;
    std::unique_ptr<NanotecSimulator> m_sim;
    std::unique_ptr<QProcess> m_cli;
    QByteArray m_out;
    QByteArray m_err;
};

void TestCliClosedLoop::initTestCase()
{
    m_binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!m_binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
}

void TestCliClosedLoop::init()
{
    m_device = std::make_unique<PtyEndpoint>();
    QString error;
    QVERIFY2(m_device->create(&error), qPrintable(error));
    SimulatorOptions options;
    options.line = lineSettings();
    options.addresses = {1};
    m_sim = std::make_unique<NanotecSimulator>(options);
    m_sim->setCalibrationMs(400); // the real run takes longer; the workflow is the same
    m_sim->attach(m_device.get());
}

void TestCliClosedLoop::cleanup()
{
    if (m_cli && m_cli->state() != QProcess::NotRunning) {
        m_cli->kill();
        m_cli->waitForFinished(5000);
    }
    m_cli.reset();
    m_sim.reset();
    m_device.reset();
}

void TestCliClosedLoop::startCli(const QStringList& args)
{
    m_cli = std::make_unique<QProcess>();
    m_out.clear();
    m_err.clear();
    connect(m_cli.get(), &QProcess::readyReadStandardOutput, this,
            [this] { m_out += m_cli->readAllStandardOutput(); });
    connect(m_cli.get(), &QProcess::readyReadStandardError, this,
            [this] { m_err += m_cli->readAllStandardError(); });
    const QStringList common{"--model",   "nanotec", "--port", m_device->slavePath(),
                             "--address", "1"};
    m_cli->start(QDir(m_binDir).filePath("stepdeck-cli"), common + args);
    QVERIFY(m_cli->waitForStarted(5000));
}

bool TestCliClosedLoop::finished(int timeoutMs)
{
    // Not waitForFinished(): the simulator lives in this thread and must keep answering.
    QElapsedTimer clock;
    clock.start();
    while (m_cli->state() != QProcess::NotRunning && clock.elapsed() < timeoutMs)
        QSignalSpy(m_cli.get(), &QProcess::finished).wait(50);
    m_out += m_cli->readAllStandardOutput();
    m_err += m_cli->readAllStandardError();
    return m_cli->state() == QProcess::NotRunning;
}

TestCliClosedLoop::Result TestCliClosedLoop::cli(const QStringList& args)
{
    startCli(args);
    if (!finished())
        return {};
    return {m_cli->exitCode(), m_out, m_err};
}

void TestCliClosedLoop::workflow_checkCalibrateReferenceEnable()
{
    m_sim->setCalibrationMs(2500); // long enough for progress lines (one a second)
    Result r = cli({"closed-loop"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("Motor pole pairs:  50") && r.out.contains("fit for closed loop"),
             r.out.constData());
    // Before the runs the drive ignores closed loop on (8.1), and the CLI says why.
    r = cli({"closed-loop", "X", "on"});
    QCOMPARE(r.exitCode, 11);
    QVERIFY2(r.err.contains("!101") && r.err.contains("!8"), r.err.constData());
    QCOMPARE(drive()->longValue("CL_enable"), qint64(0));

    m_sim->clearReceivedFrames();
    r = cli({"calibrate", "X"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.startsWith("calibration run (!101) of axis X: THE MOTOR TURNS"),
             r.out.constData());
    QVERIFY2(r.out.contains("calibrating axis X: "), r.out.constData()); // progress
    QVERIFY2(r.out.contains("calibration of axis X done in"), r.out.constData());
    const QList<QByteArray> f = m_sim->receivedFrames();
    QVERIFY(f.indexOf("#1!101\r") >= 0 && f.indexOf("#1A\r") > f.indexOf("#1!101\r"));
    QVERIFY(drive()->closedLoop().calibrated());
    QCOMPARE(drive()->value('!'), qint64(1));
    QVERIFY(m_sim->standingStill());

    r = cli({"home", "--closed-loop", "X=1"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(m_sim->receivedFrames().contains("#1!8\r"));
    QVERIFY(drive()->closedLoop().referencedSincePowerOn());
    QCOMPARE(drive()->position(), qint64(0));
    QVERIFY2(r.out.contains("X=0") && !r.out.contains("unknown"), r.out.constData());

    r = cli({"closed-loop", "X", "on"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("on (read back)"), r.out.constData());
    QCOMPARE(drive()->longValue("CL_enable"), qint64(1));
    r = cli({"--json", "closed-loop"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(QJsonDocument::fromJson(r.out).object().value("enabled").toBool(), true);
}

void TestCliClosedLoop::calibrate_withoutEncoder_exit4_namesTheDrivesError()
{
    m_sim->setEncoderConnected(1, false);
    const Result r = cli({"calibrate"});
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("ERROR_QEI") && r.err.contains("encoder"), r.err.constData());
    QVERIFY(!drive()->closedLoop().calibrated());
    QVERIFY(m_sim->standingStill());
    // The drive's position error stays until cleared: the next run is refused, reset works.
    QCOMPARE(cli({"calibrate"}).exitCode, 3);
    QCOMPARE(cli({"closed-loop", "reset-error"}).exitCode, 0);
    QCOMPARE(drive()->statusWord() & 0x04, 0);
}

void TestCliClosedLoop::calibrate_signal_stopReachesDrive_exit130()
{
    m_sim->setCalibrationMs(20000);
    startCli({"calibrate", "X"});
    QTRY_VERIFY_WITH_TIMEOUT(drive()->speed() != 0.0, 20000);
    m_sim->clearReceivedFrames();
    QCOMPARE(::kill(pid_t(m_cli->processId()), SIGINT), 0);
    QVERIFY(finished());
    QCOMPARE(m_cli->exitStatus(), QProcess::NormalExit);
    QVERIFY2(m_cli->exitCode() == 130, m_err.constData());
    QVERIFY2(m_err.contains("acknowledged the stop"), m_err.constData());
    QVERIFY(m_sim->receivedFrames().contains("#1S\r"));
    QVERIFY(m_sim->standingStill()); // at the device
    QVERIFY(!drive()->closedLoop().calibrated());
}

void TestCliClosedLoop::calibrate_modelWithoutClosedLoop_exit8()
{
    m_cli = std::make_unique<QProcess>();
    m_cli->start(QDir(m_binDir).filePath("stepdeck-cli"),
                 {"--model", "elab", "--port", "sim", "calibrate", "X"});
    QVERIFY(finished());
    QCOMPARE(m_cli->exitCode(), 8);
    QVERIFY2(m_err.contains("no closed-loop workflow"), m_err.constData());
}

void TestCliClosedLoop::usage_badAxisOrDirection_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::newRow("no such axis") << QStringList{"calibrate", "Y"} << 2;
    QTest::newRow("two axes") << QStringList{"calibrate", "X", "X"} << 2;
    QTest::newRow("unknown word") << QStringList{"closed-loop", "X", "maybe"} << 2;
    QTest::newRow("direction 2") << QStringList{"home", "--closed-loop", "X=2"} << 7;
}

void TestCliClosedLoop::usage_badAxisOrDirection()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    m_sim->clearReceivedFrames();
    const Result r = cli(args);
    QCOMPARE(r.exitCode, exitCode);
    QCOMPARE(r.err.count('\n'), 1); // one line naming the cause
    QVERIFY(!m_sim->receivedFrames().contains("#1A\r"));
}

STEPDECK_TEST_GUILESS_MAIN(TestCliClosedLoop)
#include "tst_cli_closedloop.moc"
