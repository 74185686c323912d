// End to end: stepdeck-cli against `stepdeck-sim --model emis` over a real pseudo-terminal
// (QSerialPort at 115200 8N1). Each CLI invocation is its own session; the board's state
// (positions, stored parameters, programs, outputs) persists in the simulator process.
#include "ProcessSupport.h"
#include "TestMain.h"
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

class TestCliEmisEndToEnd : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void status_json_inputsAndFirmware();
    void status_human_firmwareInputsOutputs();
    void stopAndPanic_exit8_namesEmergencyStop();
    void move_printsTrackedPositions_boardMoved();
    void move_abs_refusedWithoutReference();
    void home_selectsAxes_simultaneous();
    void jog_forMs_chunked_printsPositions();
    void set_outOfRange_exit7();
    void store_get_clear();
    void output_switch();
    void program_writeForceErase();
    void numbers_decimalOnly_exitCodes_data();
    void numbers_decimalOnly_exitCodes();

private:
    using Run = stepdeck::testing::ProcessRun;
    Run cli(const QStringList& args);
    QJsonObject statusJson();

    QString m_binDir;
    QProcess* m_sim = nullptr;
    QString m_pty;
};

void TestCliEmisEndToEnd::initTestCase()
{
    m_binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!m_binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
}

void TestCliEmisEndToEnd::init()
{
    m_sim = new QProcess(this);
    QString error;
    m_pty = stepdeck::testing::startSimulator(m_sim, QDir(m_binDir).filePath("stepdeck-sim"),
                                              {"--model", "emis", "--position", "X=300"}, &error);
    QVERIFY2(!m_pty.isEmpty(), qPrintable(error));
}

void TestCliEmisEndToEnd::cleanup()
{
    if (!m_sim)
        return;
    m_sim->terminate();
    if (!m_sim->waitForFinished(5000))
        m_sim->kill();
    delete m_sim;
    m_sim = nullptr;
}

TestCliEmisEndToEnd::Run TestCliEmisEndToEnd::cli(const QStringList& args)
{
    return stepdeck::testing::runProcess(QDir(m_binDir).filePath("stepdeck-cli"),
                                         QStringList{"--model", "emis", "--port", m_pty} + args,
                                         30000);
}

QJsonObject TestCliEmisEndToEnd::statusJson()
{
    const Run r = cli({"--json", "status"});
    if (r.exitCode != 0)
        qWarning() << r.err;
    return QJsonDocument::fromJson(r.out).object();
}

void TestCliEmisEndToEnd::status_json_inputsAndFirmware()
{
    const QJsonObject s = statusJson();
    QCOMPARE(s["model"].toString(), QStringLiteral("emis"));
    const QJsonArray inputs = s["inputs"].toArray();
    QCOMPARE(inputs.size(), 8);
    for (const QJsonValue& v : inputs)
        QVERIFY(v.isBool());
    QCOMPARE(s["device"].toObject()["firmware"].toString(), QStringLiteral("SMC-IC4 v1.07"));
    QCOMPARE(s["axes"].toObject().keys(), (QStringList{"U", "X", "Y", "Z"}));
    QCOMPARE(s["outputs"].toArray().size(), 7);
    QVERIFY(s["machine"].toObject()["driveOn"].toBool());
}

void TestCliEmisEndToEnd::status_human_firmwareInputsOutputs()
{
    const Run r = cli({"status"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("Firmware:     SMC-IC4 v1.07"));
    QVERIFY(r.out.contains("Inputs:       00000000"));
    QVERIFY(r.out.contains("Outputs:"));
    QVERIFY(r.out.contains("\nU "));
}

void TestCliEmisEndToEnd::stopAndPanic_exit8_namesEmergencyStop()
{
    for (const char* command : {"stop", "panic"}) {
        const Run r = cli({command});
        QCOMPARE(r.exitCode, 8);
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY2(r.err.contains("emergency stop"), r.err.constData());
    }
}

void TestCliEmisEndToEnd::move_printsTrackedPositions_boardMoved()
{
    const Run r = cli({"move", "X=100", "Y=-250"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains("X=100") && r.out.contains("Y=-250"), r.out.constData());
    // Y started 200 steps from its switch: now it stands on it (input 2, normally open).
    const QJsonObject s = statusJson();
    QVERIFY(s["inputs"].toArray().at(1).toBool());
    QVERIFY(s["axes"].toObject()["Y"].toObject()["referenceSwitch"].toBool());
}

void TestCliEmisEndToEnd::move_abs_refusedWithoutReference()
{
    const Run r = cli({"move", "--abs", "X=100"});
    QCOMPARE(r.exitCode, 3);
    QVERIFY(r.err.contains("reference"));
}

void TestCliEmisEndToEnd::home_selectsAxes_simultaneous()
{
    QCOMPARE(cli({"home", "X=-1"}).exitCode, 7); // the board picks the direction
    Run r = cli({"home", "X=1", "Z=1"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains("X=0 ") && r.out.contains("Z=0 "), r.out.constData());
    QVERIFY(!r.out.contains("X=0 (unknown"));
    r = cli({"home", "--simultaneous", "Y=1", "U=1"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(!r.out.contains("U=0 (unknown"));
}

void TestCliEmisEndToEnd::jog_forMs_chunked_printsPositions()
{
    const Run r = cli({"jog", "U=-400", "--for", "500"});
    QCOMPARE(r.exitCode, 0);
    const qsizetype at = r.out.indexOf("U=-");
    QVERIFY2(at >= 0, r.out.constData());
    const qint64 steps = r.out.mid(at + 2).split(' ').first().toLongLong();
    QVERIFY2(steps <= -80 && steps >= -400, r.out.constData()); // 0.5 s at 400 steps/s
}

void TestCliEmisEndToEnd::set_outOfRange_exit7()
{
    Run r = cli({"set", "idle-current=30"});
    QCOMPARE(r.exitCode, 7);
    QVERIFY(r.err.contains("0..25"));
    r = cli({"set", "run-current=50"});
    QCOMPARE(r.exitCode, 7);
    QVERIFY(cli({"set", "run-current=50", "idle-current=10", "work-speed=800"}).exitCode == 0);
}

void TestCliEmisEndToEnd::store_get_clear()
{
    Run r = cli({"store", "step-resolution=32,16,64,1", "ramp=150", "reference-switch-type=NO"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains("##D,x32,y16,z64,u1"), r.out.constData());
    r = cli({"get", "ramp", "step-resolution", "work-speed"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("ramp=150"));
    QVERIFY(r.out.contains("step-resolution=32,16,64,1"));
    QVERIFY(r.out.contains("work-speed: not stored"));
    r = cli({"--json", "get"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject json = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(json["parameters"].toObject()["ramp"].toInt(), 150);
    QCOMPARE(cli({"store", "interpolation=on"}).exitCode, 8);
    QCOMPARE(cli({"get", "reference-offset"}).exitCode, 8);
    QCOMPARE(cli({"store", "ramp=0"}).exitCode, 7);
    QCOMPARE(cli({"store", "--clear"}).exitCode, 0);
}

void TestCliEmisEndToEnd::output_switch()
{
    QCOMPARE(cli({"output", "3", "on"}).exitCode, 0);
    QCOMPARE(cli({"output", "3", "off"}).exitCode, 0);
    QCOMPARE(cli({"output", "8", "on"}).exitCode, 7);
    QCOMPARE(cli({"output", "3", "maybe"}).exitCode, 2);
}

void TestCliEmisEndToEnd::program_writeForceErase()
{
    Run r = cli({"program", "7", "--title", "Eingang 7: Referenzfahrt X-Motor", "$H,x"});
    QCOMPARE(r.exitCode, 0);
    r = cli({"program", "3", "--title", "t", "W100"});
    QCOMPARE(r.exitCode, 3);
    QVERIFY(r.err.contains("5.2.2"));
    QCOMPARE(cli({"program", "3", "--force", "--title", "t", "W100"}).exitCode, 0);
    r = cli({"program", "8", "--title", "t", "L1,x10", "BOGUS"});
    QCOMPARE(r.exitCode, 7);
    QVERIFY(r.err.contains("BOGUS"));
    QCOMPARE(cli({"program", "8", "L1,x10"}).exitCode, 2); // no --title
    QCOMPARE(cli({"program", "7", "--erase"}).exitCode, 0);
    QCOMPARE(stepdeck::testing::runProcess(QDir(m_binDir).filePath("stepdeck-cli"),
                                           {"--model", "elab", "program", "7", "--erase"}, 30000)
                 .exitCode,
             8); // E-LAB has no input programs
}

void TestCliEmisEndToEnd::numbers_decimalOnly_exitCodes_data()
{
    // Issue 12: one notation (NumberParsing) for every number, one code per fault: malformed
    // or non-finite numbers are usage errors (2), decimal ones out of range are refused (7).
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::newRow("output 03: decimal 3") << QStringList{"output", "03", "on"} << 0;
    QTest::newRow("output +3") << QStringList{"output", "+3", "off"} << 0;
    QTest::newRow("output hex") << QStringList{"output", "0x3", "on"} << 2;
    QTest::newRow("output nan") << QStringList{"output", "nan", "on"} << 2;
    QTest::newRow("output 3.0") << QStringList{"output", "3.0", "on"} << 2;
    QTest::newRow("output huge") << QStringList{"output", "99999999999999999999", "on"} << 7;
    QTest::newRow("output -1") << QStringList{"output", "-1", "on"} << 7;
    QTest::newRow("program hex") << QStringList{"program", "0x7", "--erase"} << 2;
    QTest::newRow("program inf") << QStringList{"program", "inf", "--erase"} << 2;
    QTest::newRow("program huge") << QStringList{"program", "99999999999999999999", "--erase"} << 7;
    QTest::newRow("program 07: decimal 7") << QStringList{"program", "07", "--erase"} << 0;
    QTest::newRow("store nan") << QStringList{"store", "ramp=nan"} << 2;
    QTest::newRow("store hex") << QStringList{"store", "ramp=0x10"} << 7;
    QTest::newRow("store 0100: decimal 100") << QStringList{"store", "ramp=0100"} << 0;
    QTest::newRow("arrival-timeout nan")
        << QStringList{"--arrival-timeout", "nan", "move", "X=1"} << 2;
    QTest::newRow("arrival-timeout hex")
        << QStringList{"--arrival-timeout", "0x10", "move", "X=1"} << 2;
    QTest::newRow("move nan") << QStringList{"move", "X=nan"} << 2;
    QTest::newRow("move 1e3") << QStringList{"move", "U=1e3"} << 2;
    QTest::newRow("jog inf") << QStringList{"jog", "U=inf", "--for", "100"} << 2;
}

void TestCliEmisEndToEnd::numbers_decimalOnly_exitCodes()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    const Run r = cli(args);
    QVERIFY2(r.exitCode == exitCode,
             qPrintable(
                 QStringLiteral("exit %1: %2").arg(r.exitCode).arg(QString::fromLocal8Bit(r.err))));
}

STEPDECK_TEST_GUILESS_MAIN(TestCliEmisEndToEnd)
#include "tst_cli_emis_e2e.moc"
