// End to end over pseudo-terminals: `stepdeck-cli --model laser-axis` against
// `stepdeck-sim --model laser-axis`, and `stepdeck-cli laser-bridge` with a scripted laser on a
// pty of this test and the E-LAB simulator process behind it.
#include "ProcessSupport.h"
#include "TestMain.h"
#include "protocols/laser/LaserCodec.h"
#include "sim/PtyEndpoint.h"
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>
#include <csignal>

using namespace stepdeck;
using stepdeck::testing::ProcessRun;

class TestCliLaserEndToEnd : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup();

    void home_sendsHomeFrame_succeeds();
    void moveAbs_waitsForArrival_printsPosition();
    void moveAbs_outOfRange_exit7();
    void moveRelative_positionUnknown_exit3();
    void moveAbs_endSwitch_exit13();
    void moveAbs_silentAxes_exit5();
    void moveAbs_noWait_returnsBeforeArrival();
    void stopAndPanic_noStopCommand_exit8_data();
    void stopAndPanic_noStopCommand_exit8();
    void statusJson_laserAxis_contract();

    void bridge_homeAndMove_thenSignal_exitsZeroAndStopsMotion_data();
    void bridge_homeAndMove_thenSignal_exitsZeroAndStopsMotion();
    void bridge_malformedFrame_loggedIgnored();
    void bridge_usageErrors_data();
    void bridge_usageErrors();

private:
    QString binary(const QString& name) const { return QDir(m_binDir).filePath(name); }
    QString startSim(const QStringList& args);
    ProcessRun cli(const QStringList& args, int timeoutMs = 30000);
    bool waitForLine(QProcess* p, const QByteArray& containing, QByteArray* all, int ms);

    QString m_binDir;
    QProcess* m_sim = nullptr;
    QString m_pty;
    QByteArray m_laserGot;
};

void TestCliLaserEndToEnd::initTestCase()
{
    m_binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!m_binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    QVERIFY(QFileInfo(binary("stepdeck-cli")).isExecutable());
    QVERIFY(QFileInfo(binary("stepdeck-sim")).isExecutable());
}

void TestCliLaserEndToEnd::cleanup()
{
    if (m_sim) {
        m_sim->terminate();
        if (!m_sim->waitForFinished(5000))
            m_sim->kill();
        delete m_sim;
        m_sim = nullptr;
    }
    m_laserGot.clear();
}

QString TestCliLaserEndToEnd::startSim(const QStringList& args)
{
    m_sim = new QProcess(this);
    QString error;
    m_pty = testing::startSimulator(m_sim, binary("stepdeck-sim"), args, &error);
    if (m_pty.isEmpty())
        qWarning() << error;
    return m_pty;
}

ProcessRun TestCliLaserEndToEnd::cli(const QStringList& args, int timeoutMs)
{
    return testing::runProcess(binary("stepdeck-cli"),
                               QStringList{"--model", "laser-axis", "--port", m_pty} + args,
                               timeoutMs);
}

void TestCliLaserEndToEnd::home_sendsHomeFrame_succeeds()
{
    QVERIFY(!startSim({"--model", "laser-axis"}).isEmpty());
    const ProcessRun r = cli({"home", "X=1"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains("X=0"), r.out.constData());
    QVERIFY(r.err.isEmpty());
}

void TestCliLaserEndToEnd::moveAbs_waitsForArrival_printsPosition()
{
    QVERIFY(!startSim({"--model", "laser-axis", "--speed", "50000"}).isEmpty());
    const ProcessRun r = cli({"--json", "move", "--abs", "Y=150"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject s = QJsonDocument::fromJson(r.out).object();
    const QJsonObject y = s["axes"].toObject()["Y"].toObject();
    QCOMPARE(y["position"].toInt(), 150);
    QVERIFY(y["positionKnown"].toBool());
    QVERIFY(!y["moving"].toBool());
    QVERIFY(!s["machine"].toObject()["motionUnconfirmed"].toBool());
}

void TestCliLaserEndToEnd::moveAbs_outOfRange_exit7()
{
    QVERIFY(!startSim({"--model", "laser-axis"}).isEmpty());
    const ProcessRun r = cli({"move", "--abs", "X=100000"});
    QCOMPARE(r.exitCode, 7);
    QVERIFY2(r.err.contains("0..99999"), r.err.constData());
    QCOMPARE(r.err.count('\n'), 1);
    QCOMPARE(cli({"move", "--abs", "X=-1"}).exitCode, 7);
}

void TestCliLaserEndToEnd::moveRelative_positionUnknown_exit3()
{
    QVERIFY(!startSim({"--model", "laser-axis"}).isEmpty());
    const ProcessRun r = cli({"move", "X=10"});
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains("unknown"), r.err.constData());
}

void TestCliLaserEndToEnd::moveAbs_endSwitch_exit13()
{
    QVERIFY(!startSim({"--model", "laser-axis", "--end-switch", "Y=100"}).isEmpty());
    const ProcessRun r = cli({"move", "--abs", "Y=150"});
    QCOMPARE(r.exitCode, 13);
    QVERIFY2(r.err.contains("end switch"), r.err.constData());
    QVERIFY2(r.err.contains("Y=100"), r.err.constData());
}

void TestCliLaserEndToEnd::moveAbs_silentAxes_exit5()
{
    QVERIFY(!startSim({"--model", "laser-axis", "--silent"}).isEmpty());
    const ProcessRun r = cli({"--arrival-timeout", "300", "move", "--abs", "Z=20"});
    QCOMPARE(r.exitCode, 5);
    QVERIFY2(r.err.contains("axis Z"), r.err.constData());
}

void TestCliLaserEndToEnd::moveAbs_noWait_returnsBeforeArrival()
{
    // The end switch frame would make a waiting move exit 13; --no-wait returns before it.
    QVERIFY(
        !startSim({"--model", "laser-axis", "--speed", "200", "--end-switch", "X=100"}).isEmpty());
    const ProcessRun r = cli({"move", "--no-wait", "--abs", "X=500"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(cli({"move", "--no-wait", "--abs", "X=100000"}).exitCode, 7);
}

void TestCliLaserEndToEnd::stopAndPanic_noStopCommand_exit8_data()
{
    QTest::addColumn<QString>("command");
    QTest::newRow("stop") << "stop";
    QTest::newRow("panic") << "panic";
}

void TestCliLaserEndToEnd::stopAndPanic_noStopCommand_exit8()
{
    QFETCH(QString, command);
    QVERIFY(!startSim({"--model", "laser-axis"}).isEmpty());
    const ProcessRun r = cli({command});
    QCOMPARE(r.exitCode, 8);
    QVERIFY2(r.err.contains("no stop command"), r.err.constData());
    QVERIFY2(r.err.contains("emergency stop"), r.err.constData());
    QCOMPARE(r.err.count('\n'), 1);
}

void TestCliLaserEndToEnd::statusJson_laserAxis_contract()
{
    QVERIFY(!startSim({"--model", "laser-axis"}).isEmpty());
    const ProcessRun r = cli({"status", "--json"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject s = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(s["model"].toString(), QStringLiteral("laser-axis"));
    QCOMPARE(s["axes"].toObject().keys(), (QStringList{"X", "Y", "Z"}));
    QVERIFY(!s["axes"].toObject()["X"].toObject()["positionKnown"].toBool());
    QVERIFY(!s["machine"].toObject().contains("doorOpen")); // not reported yet
}

// ---------------------------------------------------------------- laser-bridge

bool TestCliLaserEndToEnd::waitForLine(QProcess* p, const QByteArray& containing, QByteArray* all,
                                       int ms)
{
    QElapsedTimer t;
    t.start();
    while (!all->contains(containing) && t.elapsed() < ms) {
        p->waitForReadyRead(50);
        *all += p->readAllStandardOutput();
    }
    return all->contains(containing);
}

void TestCliLaserEndToEnd::bridge_homeAndMove_thenSignal_exitsZeroAndStopsMotion_data()
{
    QTest::addColumn<int>("signal");
    QTest::newRow("SIGTERM") << int(SIGTERM);
    QTest::newRow("SIGINT") << int(SIGINT);
    QTest::newRow("SIGHUP") << int(SIGHUP);
}

void TestCliLaserEndToEnd::bridge_homeAndMove_thenSignal_exitsZeroAndStopsMotion()
{
    QFETCH(int, signal);
    QVERIFY(!startSim({"--model", "elab", "--setup-complete", "--position", "X=-19500"}).isEmpty());
    PtyEndpoint laser;
    QVERIFY(laser.create());
    laser.open({});
    connect(&laser, &Transport::dataReceived, this,
            [this](const QByteArray& b) { m_laserGot += b; });

    QProcess bridge;
    bridge.start(binary("stepdeck-cli"),
                 {"--model", "elab", "--port", m_pty, "laser-bridge", laser.slavePath()});
    QByteArray out;
    QVERIFY2(waitForLine(&bridge, "serving the laser", &out, 10000), out.constData());

    laser.write("1100000\r");
    QTRY_COMPARE_WITH_TIMEOUT(m_laserGot, QByteArray("1000002\r"), 15000);
    laser.write("2199999\r"); // about 20 s of travel
    QVERIFY(waitForLine(&bridge, "move X to 99999", &out, 5000));
    QTest::qWait(300); // under way (the board ramps up)
    ::kill(pid_t(bridge.processId()), signal);
    QVERIFY(bridge.waitForFinished(10000));
    out += bridge.readAllStandardOutput();
    QCOMPARE(bridge.exitStatus(), QProcess::NormalExit);
    QCOMPARE(bridge.exitCode(), 0);
    QVERIFY2(out.contains("stopping the motion the bridge started"), out.constData());
    QCOMPARE(m_laserGot, QByteArray("1000002\r")); // no '0' for a target never reached

    // The board itself: standing well before the target (the move would take ~20 s). A status
    // read that meets the board still braking prints it (exit 0, the adapter stops motion it
    // did not command and says so on stderr); read again.
    QElapsedTimer t;
    t.start();
    bool moving = true;
    while (moving && t.elapsed() < 8000) {
        const ProcessRun s =
            testing::runProcess(binary("stepdeck-cli"),
                                {"--model", "elab", "--port", m_pty, "--json", "status"}, 10000);
        QVERIFY2(s.exitCode == 0, s.err.constData());
        moving = QJsonDocument::fromJson(s.out)["axes"]["X"]["moving"].toBool();
    }
    QVERIFY(!moving);
}

void TestCliLaserEndToEnd::bridge_malformedFrame_loggedIgnored()
{
    QVERIFY(!startSim({"--model", "elab", "--setup-complete"}).isEmpty());
    PtyEndpoint laser;
    QVERIFY(laser.create());
    laser.open({});
    connect(&laser, &Transport::dataReceived, this,
            [this](const QByteArray& b) { m_laserGot += b; });
    QProcess bridge;
    bridge.start(binary("stepdeck-cli"), {"--model", "elab", "--port", m_pty, "laser-bridge",
                                          laser.slavePath(), "--map", "1=X"});
    QByteArray out;
    QVERIFY2(waitForLine(&bridge, "serving the laser", &out, 10000), out.constData());
    laser.write("2x00150\r2300150\r");
    QVERIFY2(waitForLine(&bridge, "not mapped", &out, 5000), out.constData());
    QVERIFY(out.contains("ignored malformed frame"));
    bridge.terminate();
    QVERIFY(bridge.waitForFinished(10000));
    QCOMPARE(bridge.exitCode(), 0);
    QVERIFY(m_laserGot.isEmpty());
}

void TestCliLaserEndToEnd::bridge_usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::newRow("no port") << QStringList{"laser-bridge"} << 2;
    QTest::newRow("two ports") << QStringList{"laser-bridge", "/dev/a", "/dev/b"} << 2;
    QTest::newRow("bad map") << QStringList{"laser-bridge", "/dev/a", "--map", "1=Q"} << 2;
    QTest::newRow("bad scale") << QStringList{"laser-bridge", "/dev/a", "--scale", "nan"} << 2;
    QTest::newRow("bad home") << QStringList{"laser-bridge", "/dev/a", "--home", "X=2"} << 2;
    QTest::newRow("unknown option") << QStringList{"laser-bridge", "/dev/a", "--fast"} << 2;
    QTest::newRow("axis U on elab") << QStringList{"laser-bridge", "/dev/a", "--map", "1=U"} << 2;
    QTest::newRow("door on elab") << QStringList{"laser-bridge", "/dev/null-laser", "--door-input",
                                                 "1"}
                                  << 8;
    QTest::newRow("laser port missing") << QStringList{"laser-bridge", "/dev/no-such-laser"} << 6;
}

void TestCliLaserEndToEnd::bridge_usageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    const ProcessRun r = testing::runProcess(
        binary("stepdeck-cli"), QStringList{"--model", "elab", "--port", "sim"} + args, 20000);
    QCOMPARE(r.exitCode, exitCode);
    QCOMPARE(r.err.count('\n'), 1);
}

STEPDECK_TEST_GUILESS_MAIN(TestCliLaserEndToEnd)
#include "tst_cli_laser_e2e.moc"
