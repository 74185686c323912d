// End to end: stepdeck-cli against `stepdeck-sim --model nanotec --drives ...` over a real
// pseudo-terminal (QSerialPort at 19200 8N1). Each CLI invocation is its own session; the
// drives' settings persist in the simulator process between invocations.
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

class TestNanotecEndToEnd : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup();
    void status_threeDrives_listedWithFirmware();
    void status_singleDriveByAddress();
    void status_missingDrive_flaggedOthersAnswer();
    void status_noDriveAtAddress_failsNamingIt();
    void set_get_verifiedPerDrive();
    void set_outOfRange_refusedNamingRange();
    void move_relative_printsEndPositions();
    void home_thenAbsoluteMove_inOneSession();
    void panic_stopsEveryDrive();

private:
    struct Run
    {
        int exitCode = -1;
        QByteArray out;
        QByteArray err;
    };
    void startSim(const QString& drives);
    Run cli(const QStringList& args, const QString& axes = QStringLiteral("X=1,Y=2,Z=3"));
    QJsonObject statusJson(const QString& axes = QStringLiteral("X=1,Y=2,Z=3"));

    QString m_binDir;
    QProcess* m_sim = nullptr;
    QString m_pty;
};

void TestNanotecEndToEnd::initTestCase()
{
    m_binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!m_binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    QVERIFY(QFileInfo(QDir(m_binDir).filePath("stepdeck-cli")).isExecutable());
    QVERIFY(QFileInfo(QDir(m_binDir).filePath("stepdeck-sim")).isExecutable());
}

void TestNanotecEndToEnd::startSim(const QString& drives)
{
    m_sim = new QProcess(this);
    m_sim->setStandardErrorFile(QProcess::nullDevice());
    m_sim->start(QDir(m_binDir).filePath("stepdeck-sim"),
                 {"--model", "nanotec", "--drives", drives});
    QVERIFY2(m_sim->waitForStarted(5000), qPrintable(m_sim->errorString()));
    while (!m_sim->canReadLine())
        QVERIFY2(m_sim->waitForReadyRead(5000), "stepdeck-sim printed no pty path");
    m_pty = QString::fromLocal8Bit(m_sim->readLine()).trimmed();
    QVERIFY2(m_pty.startsWith("/dev/"), qPrintable(m_pty));
}

void TestNanotecEndToEnd::cleanup()
{
    if (!m_sim)
        return;
    m_sim->terminate();
    if (!m_sim->waitForFinished(5000))
        m_sim->kill();
    delete m_sim;
    m_sim = nullptr;
}

TestNanotecEndToEnd::Run TestNanotecEndToEnd::cli(const QStringList& args, const QString& axes)
{
    QStringList all{"--model", "nanotec", "--port", m_pty};
    if (!axes.isEmpty())
        all << "--axes" << axes;
    all << args;
    QProcess process;
    process.start(QDir(m_binDir).filePath("stepdeck-cli"), all);
    Run run;
    if (!process.waitForFinished(30000)) {
        process.kill();
        process.waitForFinished();
        qWarning() << "stepdeck-cli" << all << "did not finish";
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

QJsonObject TestNanotecEndToEnd::statusJson(const QString& axes)
{
    const Run r = cli({"--json", "status"}, axes);
    if (r.exitCode != 0)
        qWarning() << r.err;
    return QJsonDocument::fromJson(r.out).object();
}

void TestNanotecEndToEnd::status_threeDrives_listedWithFirmware()
{
    startSim("1,2,3");
    const QJsonObject s = statusJson();
    QCOMPARE(s["model"].toString(), QStringLiteral("nanotec"));
    const QJsonArray drives = s["drives"].toArray();
    QCOMPARE(drives.size(), 3);
    for (int i = 0; i < 3; ++i) {
        const QJsonObject d = drives[i].toObject();
        QCOMPARE(d["address"].toInt(), i + 1);
        QVERIFY(d["responding"].toBool());
        QVERIFY(d["firmware"].toString().startsWith("SMCI47-S_RS485"));
    }
    QVERIFY(s["machine"].toObject()["driveOn"].toBool());
    QVERIFY(!s["machine"].toObject()["commFault"].toBool());
    QVERIFY(!s["axes"].toObject()["X"].toObject()["referenced"].toBool());
}

void TestNanotecEndToEnd::status_singleDriveByAddress()
{
    startSim("7");
    const Run r = cli({"--address", "7", "--json", "status"}, QString());
    QCOMPARE(r.exitCode, 0);
    const QJsonObject s = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(s["drives"].toArray().size(), 1);
    QCOMPARE(s["drives"].toArray()[0].toObject()["address"].toInt(), 7);
    QCOMPARE(s["axes"].toObject().keys(), QStringList{"X"});
}

void TestNanotecEndToEnd::status_missingDrive_flaggedOthersAnswer()
{
    startSim("1,3");
    const QJsonObject s = statusJson();
    const QJsonArray drives = s["drives"].toArray();
    QCOMPARE(drives.size(), 3);
    QVERIFY(drives[0].toObject()["responding"].toBool());
    QVERIFY(!drives[1].toObject()["responding"].toBool());
    QVERIFY(drives[2].toObject()["responding"].toBool());
    QVERIFY(s["machine"].toObject()["commFault"].toBool());
}

void TestNanotecEndToEnd::status_noDriveAtAddress_failsNamingIt()
{
    startSim("1");
    const Run r = cli({"status"}, QStringLiteral("X=9"));
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains("address 9"), r.err.constData());
    QCOMPARE(r.err.count('\n'), 1);
}

void TestNanotecEndToEnd::set_get_verifiedPerDrive()
{
    startSim("1,2,3");
    Run r = cli({"set", "phase-current=80,70,60", "step-mode=16",
                 "limit-switch-behaviour-external-normal=stop"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    r = cli({"get", "phase-current", "step-mode", "limit-switch-behaviour-external-normal",
             "limit-switch-behaviour-external-reference"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains("phase-current=80,70,60"), r.out.constData());
    QVERIFY(r.out.contains("step-mode=16,16,16"));
    QVERIFY(r.out.contains("limit-switch-behaviour-external-normal=stop,stop,stop"));
    QVERIFY(r.out.contains("limit-switch-behaviour-external-reference=free-backward"));
}

void TestNanotecEndToEnd::set_outOfRange_refusedNamingRange()
{
    startSim("1,2,3");
    const Run r = cli({"set", "min-frequency=59"});
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains("min-frequency") && r.err.contains("60..25000"), r.err.constData());
}

void TestNanotecEndToEnd::move_relative_printsEndPositions()
{
    startSim("1,2,3");
    const Run r = cli({"move", "X=200", "Z=-100"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("X=200") && r.out.contains("Z=-100"), r.out.constData());
}

void TestNanotecEndToEnd::home_thenAbsoluteMove_inOneSession()
{
    startSim("1,2,3");
    Run r = cli({"move", "--abs", "Y=50"});
    QVERIFY(r.exitCode != 0); // not referenced in this session
    QVERIFY2(r.err.contains("reference"), r.err.constData());
    r = cli({"home", "Y=-1"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("Y=0"), r.out.constData());
}

void TestNanotecEndToEnd::panic_stopsEveryDrive()
{
    startSim("1,2,3");
    const Run r = cli({"panic"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject s = statusJson();
    for (const QJsonValue& d : s["drives"].toArray())
        QVERIFY(d.toObject()["detail"].toString().startsWith("ready"));
}

QTEST_GUILESS_MAIN(TestNanotecEndToEnd)
#include "tst_nanotec_e2e.moc"
