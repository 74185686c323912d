// End to end: stepdeck-cli against `stepdeck-sim --model nanotec --drives ...` over a real
// pseudo-terminal (QSerialPort at 19200 8N1). Each CLI invocation is its own session; the
// drives' settings persist in the simulator process between invocations.
#include "ProcessSupport.h"
#include "TestMain.h"
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
    void set_byAddress_writesThatDriveOnly();
    void move_byAddress_movesThatDrive();
    void scan_listsDrivesWithFirmware();
    void scan_json_isAnArrayOfDrives();
    void set_ignoredInvalidValue_verifyFailedNamingValues();
    void set_noVerify_writesWithoutReadBack();
    void status_human_axisMap_rowPerDrive();
    void status_human_silentDriveNamed();
    void records_byAddress_allThirtyTwo();
    void setupDefaults_keepsDriveAddresses();
    void bus32_namedDrives_oneMovesAndArrives_everyDriveAnswers();
    void bus12_moveJogHomeScanStatus_byDriveName();
    void status_human_namedDrives_rowsAndMachineLinesShowNames();

private:
    using Run = stepdeck::testing::ProcessRun;
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
    // The contract: the pty path is the first line of stdout, flushed at once.
    QString error;
    m_pty = stepdeck::testing::startSimulator(m_sim, QDir(m_binDir).filePath("stepdeck-sim"),
                                              QStringList{"--model", "nanotec", "--drives", drives},
                                              &error);
    QVERIFY2(!m_pty.isEmpty(), qPrintable(error));
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
    return stepdeck::testing::runProcess(QDir(m_binDir).filePath("stepdeck-cli"), all, 30000);
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

// Issue 4: `--address N` is one drive as axis X -- the axes come from the controller's axis
// map, not from the model's default X,Y,Z.
void TestNanotecEndToEnd::set_byAddress_writesThatDriveOnly()
{
    startSim("1,2,3");
    Run r = cli({"--address", "2", "set", "phase-current=77"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("verified") && r.out.contains("phase-current=77"), r.out.constData());
    r = cli({"--address", "2", "get", "phase-current"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.out.trimmed(), QByteArray("phase-current=77"));
    r = cli({"get", "phase-current"}); // the machine: only drive 2 changed (default 50)
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.out.trimmed(), QByteArray("phase-current=50,77,50"));
    r = cli({"--address", "2", "set", "phase-current=70,70"}, QString());
    QCOMPARE(r.exitCode, 7); // one axis: two values are one too many
}

void TestNanotecEndToEnd::move_byAddress_movesThatDrive()
{
    startSim("1,2,3");
    Run r = cli({"--address", "2", "move", "Y=10"}, QString());
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("no axis Y"), r.err.constData());
    r = cli({"--address", "2", "move", "X=120"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("X=120"), r.out.constData());
    const QJsonObject axes = statusJson()["axes"].toObject();
    QCOMPARE(axes["X"].toObject()["position"].toInt(), 0);
    QCOMPARE(axes["Y"].toObject()["position"].toInt(), 120);
}

void TestNanotecEndToEnd::scan_listsDrivesWithFirmware()
{
    startSim("1,2,3");
    const Run r = cli({"scan"}, QString()); // the whole range 1..254
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 4); // header and three drives
    for (int i = 1; i <= 3; ++i) {
        const QList<QByteArray> cols = lines[i].simplified().split(' ');
        QCOMPARE(cols.value(0), QByteArray::number(i));
        QVERIFY2(cols.value(1).startsWith("SMCI47-S_RS485"), lines[i].constData());
    }
}

void TestNanotecEndToEnd::scan_json_isAnArrayOfDrives()
{
    startSim("1,2,3");
    const Run r = cli({"--json", "scan", "--last", "10"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.out.count('\n'), 1);
    const QJsonDocument doc = QJsonDocument::fromJson(r.out);
    QVERIFY2(doc.isArray(), r.out.constData());
    const QJsonArray drives = doc.array();
    QCOMPARE(drives.size(), 3);
    for (int i = 0; i < 3; ++i) {
        const QJsonObject d = drives[i].toObject();
        QCOMPARE(d["address"].toInt(), i + 1);
        QVERIFY(d["firmware"].toString().startsWith("SMCI47-S_RS485"));
        QCOMPARE(d["hardware"].toString(), QStringLiteral("SMCI47-S"));
    }
}

// Manual 6.6: positioning mode 2 is "nicht belegt" in speed mode; the drive echoes '#1p2' and
// ignores it (NanotecDrive::validSetting). Only the read-back catches it.
void TestNanotecEndToEnd::set_ignoredInvalidValue_verifyFailedNamingValues()
{
    startSim("1");
    Run r = cli({"--address", "1", "set", "motor-mode=speed"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    r = cli({"--address", "1", "set", "positioning-mode=2"}, QString());
    QCOMPARE(r.exitCode, 11);
    QCOMPARE(r.err.count('\n'), 1);
    QVERIFY2(r.err.contains("Positioning mode") && r.err.contains("wrote 2") &&
                 r.err.contains("kept 1"),
             r.err.constData());
    QVERIFY(r.out.isEmpty());
}

void TestNanotecEndToEnd::set_noVerify_writesWithoutReadBack()
{
    startSim("1");
    Run r = cli({"--address", "1", "set", "motor-mode=speed"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    r = cli({"--address", "1", "set", "--no-verify", "positioning-mode=2"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData()); // the echo is all there is
    QVERIFY2(r.out.contains("not verified"), r.out.constData());
    r = cli({"--address", "1", "get", "positioning-mode"}, QString());
    QCOMPARE(r.out.trimmed(), QByteArray("positioning-mode=1")); // ignored, as the manual says
}

void TestNanotecEndToEnd::status_human_axisMap_rowPerDrive()
{
    startSim("1,2,3");
    const Run r = cli({"status"}, QStringLiteral("X=1,Y=2,Z=3"));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("Drives:       3 answering"), r.out.constData());
    QVERIFY(!r.out.contains("Temperature")); // the drives report none
    const QList<QByteArray> lines = r.out.split('\n');
    for (const char* axis : {"X", "Y", "Z"}) {
        const int address = axis[0] - 'X' + 1;
        bool found = false;
        for (const QByteArray& line : lines) {
            const QList<QByteArray> cols = line.simplified().split(' ');
            if (cols.size() >= 5 && cols[0] == QByteArray::number(address) && cols[1] == axis) {
                found = true;
                QCOMPARE(cols[2], QByteArray("yes"));
                QVERIFY(cols[3].startsWith("SMCI47-S_RS485"));
                QVERIFY2(cols[4].startsWith("ready"), line.constData());
            }
        }
        QVERIFY2(found, axis);
    }
}

void TestNanotecEndToEnd::status_human_silentDriveNamed()
{
    startSim("1,3");
    const Run r = cli({"status"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("2 of 3 answering; NOT ANSWERING: drive 2 (axis Y)"),
             r.out.constData());
    QVERIFY(r.out.contains("COMMUNICATION FAULT"));
}

void TestNanotecEndToEnd::records_byAddress_allThirtyTwo()
{
    startSim("5");
    Run r = cli({"--address", "5", "records"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 32);
    QVERIFY2(lines.first().startsWith("record  1:") && lines.first().contains("travel-distance="),
             lines.first().constData());
    QVERIFY(lines.last().startsWith("record 32:"));
    r = cli({"--address", "5", "--json", "records", "X"}, QString());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray records = QJsonDocument::fromJson(r.out).array();
    QCOMPARE(records.size(), 32);
    QCOMPARE(records[31].toObject()["record"].toInt(), 32);
    QVERIFY(records[0].toObject()["values"].toObject().contains("positioning-mode"));
}

// The schema default of motor-address (1) must not be written to every drive: parameters with
// a warning are left out of --setup-defaults.
void TestNanotecEndToEnd::setupDefaults_keepsDriveAddresses()
{
    startSim("1,2,3");
    const Run r = cli({"--setup-defaults", "--json", "status"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray drives = QJsonDocument::fromJson(r.out).object()["drives"].toArray();
    QCOMPARE(drives.size(), 3);
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(drives[i].toObject()["address"].toInt(), i + 1);
        QVERIFY(drives[i].toObject()["responding"].toBool());
    }
    const Run scan = cli({"--json", "scan", "--last", "4"}, QString());
    QCOMPARE(QJsonDocument::fromJson(scan.out).array().size(), 3);
}

// Issue 32: the drives' names in the status: the drive rows, the axis rows (columns as wide
// as the longest name) and the machine lines ("on nanotec.feeder").
void TestNanotecEndToEnd::status_human_namedDrives_rowsAndMachineLinesShowNames()
{
    startSim("1,2,3");
    const Run r = cli({"status"}, QStringLiteral("feeder=1,lifter_one=2,X=3"));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QString out = QString::fromUtf8(r.out);
    QVERIFY2(out.contains(QStringLiteral("on nanotec.feeder)")), r.out.constData());
    QVERIFY2(out.contains(QStringLiteral("on nanotec.X)")), r.out.constData());
    static const QRegularExpression driveRow(QStringLiteral("\\n2 +lifter_one +yes "));
    QVERIFY2(driveRow.match(out).hasMatch(), r.out.constData());
    static const QRegularExpression axisRow(QStringLiteral("\\nfeeder {6}no {6}no "));
    QVERIFY2(axisRow.match(out).hasMatch(), r.out.constData());
}

// Issue 32: 32 drives on one bus, named by the plant (d1..d32): the sixth (machine axis B of
// the connection's machine, controller axis axis6: past the four letters) moves, and its
// arrival ends the command (the status sweeps serve it first among 32); then every drive
// answers its status, the moved one at its target, the others where they were.
void TestNanotecEndToEnd::bus32_namedDrives_oneMovesAndArrives_everyDriveAnswers()
{
    QStringList addresses, bus;
    for (int a = 1; a <= 32; ++a) {
        addresses << QString::number(a);
        bus << QStringLiteral("d%1=%1").arg(a);
    }
    startSim(addresses.join(','));
    const Run r = cli({"move", "B=500"}, bus.join(','));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("B=500"), r.out.constData());
    const QJsonObject status = statusJson(bus.join(','));
    const QJsonArray drives = status["drives"].toArray();
    QCOMPARE(drives.size(), 32);
    for (const QJsonValue& d : drives)
        QVERIFY(d.toObject()["responding"].toBool());
    // Every drive is an axis of the CLI's status: the first nine by the program letters
    // (X Y Z U A B C V W), the rest by their names (issue 32, step 5).
    const QJsonObject axes = status["axes"].toObject();
    QCOMPARE(axes.size(), 32);
    QCOMPARE(axes["d32"].toObject()["position"].toInt(), 0);
    QCOMPARE(axes["B"].toObject()["position"].toInt(), 500);
    QCOMPARE(axes["B"].toObject()["moving"].toBool(), false);
    QCOMPARE(axes["X"].toObject()["position"].toInt(), 0);
    QCOMPARE(axes["W"].toObject()["position"].toInt(), 0);
}

// Issue 32, step 5: the CLI takes a bus's drives by their names, past the ninth too (no
// program letter). Positions are what the drives report (status read over the pty).
void TestNanotecEndToEnd::bus12_moveJogHomeScanStatus_byDriveName()
{
    startSim("1,2,3,4,5,6,7,8,9,10,11,12");
    QStringList bus;
    for (int a = 1; a <= 11; ++a)
        bus << QStringLiteral("d%1=%1").arg(a);
    bus << QStringLiteral("stacker=12");
    const QString axes = bus.join(',');
    Run r = cli({"move", "stacker=300", "d2=-120"}, axes);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QJsonObject status = statusJson(axes);
    QCOMPARE(status["axes"].toObject()["stacker"].toObject()["position"].toInt(), 300);
    QCOMPARE(status["axes"].toObject()["Y"].toObject()["position"].toInt(), -120); // d2
    QCOMPARE(status["axes"].toObject()["d11"].toObject()["position"].toInt(), 0);

    r = cli({"jog", "STACKER=400", "--for", "300"}, axes); // names in any case
    QVERIFY2(r.exitCode == 0, r.err.constData());
    status = statusJson(axes);
    const QJsonObject stacker = status["axes"].toObject()["stacker"].toObject();
    QVERIFY2(stacker["position"].toInt() > 300,
             qPrintable(QString::number(stacker["position"].toInt())));
    QCOMPARE(stacker["moving"].toBool(), false);

    r = cli({"move", "nobody=5"}, axes);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("no axis nobody (its axes: X, Y, Z, U, A, B, C, V, W, d10, d11, "
                            "stacker)"),
             r.err.constData());

    r = cli({"scan", "--first", "10", "--last", "13"}, axes);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    static const QRegularExpression named(QStringLiteral("\\n +12  stacker +SMCI"));
    QVERIFY2(named.match(QString::fromUtf8(r.out)).hasMatch(), r.out.constData());
    QVERIFY2(!r.out.contains("\n     13"), r.out.constData()); // no drive at 13

    // Every drive's status word decoded, the twelfth's too ($, 5.21: bit 0 "ready").
    r = cli({"status"}, axes);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("statusaxis12=0x"), r.out.constData());
    static const QRegularExpression decoded(
        QStringLiteral("statusaxis12=0x[0-9a-f]+ \\([^)]*ready"));
    QVERIFY2(decoded.match(QString::fromUtf8(r.out)).hasMatch(), r.out.constData());
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecEndToEnd)
#include "tst_nanotec_e2e.moc"
