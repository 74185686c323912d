// stepdeck-sim's fault options (issue 12): --drop, --corrupt, --noise, --freeze-after, --seed,
// run as processes on a real pseudo-terminal against stepdeck-cli and QSerialPort.
#include "ProcessSupport.h"
#include "TestMain.h"
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSerialPort>
#include <QtTest>

class TestSimEndToEnd : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup();

    void badFaultOption_exitTwoWithOneLine_data();
    void badFaultOption_exitTwoWithOneLine();
    void help_listsTheFaultOptions();
    void input_emisPartSensor_statusReadsItHigh();
    void input_refused_exitTwoNamingTheInputs_data();
    void input_refused_exitTwoNamingTheInputs();
    void drop_everyReply_cliTimesOut();
    void freezeAfter_zero_cliTimesOut();
    void corrupt_everyReply_cliFailsWithoutCrash();
    void noise_bytesArriveUnasked();
    void lowFaultRates_statusStillWorks();
    // The same options on the simulators of EMIS and the laser axes (Simulator base class).
    void faults_emisAndLaser_data();
    void faults_emisAndLaser();
    void noise_emisAndLaser_data();
    void noise_emisAndLaser();

private:
    using Run = stepdeck::testing::ProcessRun;
    QString binary(const QString& name) const { return QDir(m_binDir).filePath(name); }
    QString startSim(const QStringList& args);
    Run cli(const QStringList& args);

    QString m_binDir;
    QProcess* m_sim = nullptr;
};

void TestSimEndToEnd::initTestCase()
{
    m_binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!m_binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    QVERIFY(QFileInfo(binary("stepdeck-sim")).isExecutable());
    QVERIFY(QFileInfo(binary("stepdeck-cli")).isExecutable());
}

void TestSimEndToEnd::cleanup()
{
    if (!m_sim)
        return;
    m_sim->terminate();
    if (!m_sim->waitForFinished(5000))
        m_sim->kill();
    QCOMPARE(m_sim->exitStatus(), QProcess::NormalExit); // no crash under any fault
    delete m_sim;
    m_sim = nullptr;
}

QString TestSimEndToEnd::startSim(const QStringList& args)
{
    m_sim = new QProcess(this);
    QString error;
    const QString pty =
        stepdeck::testing::startSimulator(m_sim, binary("stepdeck-sim"), args, &error);
    if (pty.isEmpty())
        qWarning() << "stepdeck-sim" << args << error;
    return pty;
}

TestSimEndToEnd::Run TestSimEndToEnd::cli(const QStringList& args)
{
    return stepdeck::testing::runProcess(binary("stepdeck-cli"), args, 20000);
}

void TestSimEndToEnd::badFaultOption_exitTwoWithOneLine_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("needle");
    QTest::newRow("drop above 1") << QStringList{"--drop", "2"} << "--drop";
    QTest::newRow("drop nan") << QStringList{"--drop", "nan"} << "--drop";
    QTest::newRow("drop percent") << QStringList{"--drop=1%"} << "probability";
    QTest::newRow("corrupt negative") << QStringList{"--corrupt", "-0.1"} << "--corrupt";
    QTest::newRow("noise negative") << QStringList{"--noise", "-5"} << "--noise";
    QTest::newRow("noise inf") << QStringList{"--noise", "inf"} << "--noise";
    QTest::newRow("freeze-after word") << QStringList{"--freeze-after", "soon"} << "--freeze-after";
    QTest::newRow("freeze-after hex") << QStringList{"--freeze-after", "0x10"} << "--freeze-after";
    QTest::newRow("seed negative") << QStringList{"--seed", "-1"} << "--seed";
    QTest::newRow("seed missing") << QStringList{"--seed"} << "needs a value";
}

void TestSimEndToEnd::badFaultOption_exitTwoWithOneLine()
{
    QFETCH(QStringList, args);
    QFETCH(QString, needle);
    const Run run = stepdeck::testing::runProcess(binary("stepdeck-sim"), args, 10000);
    QCOMPARE(run.exitCode, 2);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains(needle.toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty()); // no pty path: nothing to connect to
}

void TestSimEndToEnd::help_listsTheFaultOptions()
{
    const Run run = stepdeck::testing::runProcess(binary("stepdeck-sim"), {"--help"}, 10000);
    QCOMPARE(run.exitCode, 0);
    for (const char* option : {"--drop", "--corrupt", "--noise", "--freeze-after", "--seed"})
        QVERIFY2(run.out.contains(option), option);
}

// --input sets what the machine drives at an input (issue 28: the part sensor emis.ngc waits
// for); the board reports it in its input status like any other level.
void TestSimEndToEnd::input_emisPartSensor_statusReadsItHigh()
{
    const QString pty = startSim({"--model", "emis", "--input", "5=1", "--input", "7=0"});
    QVERIFY(!pty.isEmpty());
    const Run r = cli({"--model", "emis", "--port", pty, "--json", "status"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray inputs = QJsonDocument::fromJson(r.out).object().value("inputs").toArray();
    QCOMPARE(inputs.size(), 8);
    QCOMPARE(inputs.at(4).toBool(), true);  // input 5
    QCOMPARE(inputs.at(6).toBool(), false); // input 7
}

void TestSimEndToEnd::input_refused_exitTwoNamingTheInputs_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("needle");
    QTest::newRow("a reference switch input")
        << QStringList{"--model", "emis", "--input", "2=1"} << "inputs 5, 6, 7, 8";
    QTest::newRow("a model without such inputs")
        << QStringList{"--model", "elab", "--input", "1=1"} << "no inputs the machine sets";
    QTest::newRow("level 2") << QStringList{"--model", "emis", "--input", "5=2"} << "--input";
    QTest::newRow("no level") << QStringList{"--model", "emis", "--input", "5"} << "--input";
}

void TestSimEndToEnd::input_refused_exitTwoNamingTheInputs()
{
    QFETCH(QStringList, args);
    QFETCH(QString, needle);
    const Run run = stepdeck::testing::runProcess(binary("stepdeck-sim"), args, 10000);
    QVERIFY2(run.exitCode != 0, run.out.constData());
    QVERIFY2(run.err.contains(needle.toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

void TestSimEndToEnd::drop_everyReply_cliTimesOut()
{
    const QString pty = startSim({"--drop", "1"});
    QVERIFY(!pty.isEmpty());
    const Run run = cli({"--port", pty, "status"});
    QCOMPARE(run.exitCode, 5);
    QCOMPARE(run.err.count('\n'), 1);
}

void TestSimEndToEnd::freezeAfter_zero_cliTimesOut()
{
    // The clock starts at the first reply: the first request is answered, then nothing.
    const QString pty = startSim({"--model", "nanotec", "--drives", "1", "--freeze-after", "0"});
    QVERIFY(!pty.isEmpty());
    const Run run = cli({"--model", "nanotec", "--address", "1", "--port", pty, "status"});
    QVERIFY2(run.exitCode == 5 || run.exitCode == 6, run.err.constData()); // timeout / link lost
    QCOMPARE(run.err.count('\n'), 1);
}

void TestSimEndToEnd::corrupt_everyReply_cliFailsWithoutCrash()
{
    const QString pty = startSim({"--corrupt", "1", "--seed", "4"});
    QVERIFY(!pty.isEmpty());
    const Run run = cli({"--port", pty, "status"});
    // Every reply broken: a timeout or a protocol error, never a crash or a success.
    QVERIFY2(run.exitCode == 5 || run.exitCode == 9, run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
}

void TestSimEndToEnd::noise_bytesArriveUnasked()
{
    const QString pty = startSim({"--noise", "2000", "--seed", "9"});
    QVERIFY(!pty.isEmpty());
    QSerialPort port(pty);
    QVERIFY2(port.open(QIODevice::ReadOnly), qPrintable(port.errorString()));
    QByteArray received;
    while (received.size() < 50 && port.waitForReadyRead(5000))
        received += port.readAll();
    QVERIFY2(received.size() >= 50, qPrintable(QString::number(received.size())));
}

void TestSimEndToEnd::lowFaultRates_statusStillWorks()
{
    // Faults off by default and only where asked: 0 % drop and corruption change nothing.
    const QString pty =
        startSim({"--drop", "0", "--corrupt", "0.0", "--noise", "0", "--seed", "2"});
    QVERIFY(!pty.isEmpty());
    const Run run = cli({"--port", pty, "status", "--json"});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(run.out.contains("\"model\""));
}

void TestSimEndToEnd::faults_emisAndLaser_data()
{
    QTest::addColumn<QStringList>("simArgs");
    QTest::addColumn<QList<QStringList>>("cliRuns"); // all but the last must exit 0
    QTest::addColumn<QList<int>>("lastExit");        // the allowed codes of the last run
    const QStringList emis{"--model", "emis"};
    const QStringList laser{"--model", "laser-axis", "--speed", "50000"};
    const QStringList laserMove{"--model", "laser-axis", "--arrival-timeout", "500", "move",
                                "--abs",   "X=20"};
    const QStringList emisStatus{"--model", "emis", "status"};
    QTest::newRow("emis: no fault") << emis << QList<QStringList>{emisStatus} << QList<int>{0};
    QTest::newRow("emis: every reply dropped")
        << emis + QStringList{"--drop", "1"} << QList<QStringList>{emisStatus} << QList<int>{5};
    // One byte of every reply replaced: the reply reading is lenient (an answer after the
    // last echo, 9.x), so a poll may still find a valid answer; what must hold is a defined
    // code, one line, no crash (cleanup()).
    QTest::newRow("emis: every reply corrupted")
        << emis + QStringList{"--corrupt", "1", "--seed", "4"} << QList<QStringList>{emisStatus}
        << QList<int>{0, 5, 6, 9};
    // The first reply (the connect probe @V) is answered, then nothing: the adapter's link
    // supervision (three unanswered input polls @IG) declares the link lost, exit 6, whichever
    // command runs -- EMIS-specific ones included.
    for (const QStringList& command :
         {QStringList{"status"}, QStringList{"output", "3", "on"},
          QStringList{"program", "7", "--erase"}, QStringList{"store", "ramp=100"},
          QStringList{"move", "X=10"}}) {
        QTest::addRow("emis: frozen, %s", qPrintable(command.join(' ')))
            << emis + QStringList{"--freeze-after", "0"}
            << QList<QStringList>{QStringList{"--model", "emis"} + command} << QList<int>{6};
    }
    QTest::newRow("laser: no fault") << laser << QList<QStringList>{laserMove} << QList<int>{0};
    QTest::newRow("laser: every frame dropped")
        << laser + QStringList{"--drop", "1"} << QList<QStringList>{laserMove} << QList<int>{5};
    QTest::newRow("laser: every frame corrupted")
        << laser + QStringList{"--corrupt", "1", "--seed", "4"} << QList<QStringList>{laserMove}
        << QList<int>{5, 9};
    QTest::newRow("laser: frozen after the first frame")
        << laser + QStringList{"--freeze-after", "0"} << QList<QStringList>{laserMove, laserMove}
        << QList<int>{5};
}

void TestSimEndToEnd::faults_emisAndLaser()
{
    QFETCH(QStringList, simArgs);
    QFETCH(QList<QStringList>, cliRuns);
    QFETCH(QList<int>, lastExit);
    const QString pty = startSim(simArgs);
    QVERIFY(!pty.isEmpty());
    for (int i = 0; i < cliRuns.size(); ++i) {
        const Run run = cli(QStringList{"--port", pty} + cliRuns[i]);
        if (i + 1 < cliRuns.size()) {
            QVERIFY2(run.exitCode == 0, run.err.constData());
            continue;
        }
        QVERIFY2(lastExit.contains(run.exitCode),
                 qPrintable(QStringLiteral("exit %1: %2")
                                .arg(run.exitCode)
                                .arg(QString::fromLocal8Bit(run.err))));
        if (run.exitCode != 0)
            QCOMPARE(run.err.count('\n'), 1);
    }
}

void TestSimEndToEnd::noise_emisAndLaser_data()
{
    QTest::addColumn<QString>("model");
    QTest::newRow("emis") << "emis";
    QTest::newRow("laser-axis") << "laser-axis";
}

void TestSimEndToEnd::noise_emisAndLaser()
{
    QFETCH(QString, model);
    const QString pty = startSim({"--model", model, "--noise", "2000", "--seed", "9"});
    QVERIFY(!pty.isEmpty());
    QSerialPort port(pty);
    QVERIFY2(port.open(QIODevice::ReadOnly), qPrintable(port.errorString()));
    QByteArray received;
    while (received.size() < 50 && port.waitForReadyRead(5000))
        received += port.readAll();
    QVERIFY2(received.size() >= 50, qPrintable(QString::number(received.size())));
}

STEPDECK_TEST_GUILESS_MAIN(TestSimEndToEnd)
#include "tst_sim_e2e.moc"
