// Smoke test of the fault soak and replug tools (issue 12): a short stepdeck-bench --soak and
// --replug must run to the end against every simulator with no crash, no hang and no axis
// left moving at the device. The figures themselves (docs/benchmark.md) come from long runs
// by hand; nothing here is timed.
#include "ProcessSupport.h"
#include "TestMain.h"
#include "protocols/Registry.h"
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

class TestSoakSmoke : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void soak_fiftyCommands_noCrashHangOrAxisLeftMoving();
    void soak_machine_noCrashHangOrAxisLeftMoving();
    void soak_busOfDrives_everyDriveReachable_data();
    void soak_busOfDrives_everyDriveReachable();
    void replug_everyPhase_noticedEveryTime();
    void badArguments_exitTwo_data();
    void badArguments_exitTwo();

private:
    QJsonObject runJson(const QStringList& args, int* exitCode);
    void verifyMustBeZero(const QJsonObject& m);
    QString m_bench;
};

void TestSoakSmoke::initTestCase()
{
    m_bench = QDir(qEnvironmentVariable("STEPDECK_BIN_DIR")).filePath("stepdeck-bench");
    QVERIFY2(QFileInfo(m_bench).isExecutable(), qPrintable(m_bench));
}

// The soak's five must-be-zero figures of one run (docs/benchmark.md, "Fault soak").
void TestSoakSmoke::verifyMustBeZero(const QJsonObject& m)
{
    for (const char* figure :
         {"crashes", "hangs", "axesLeftMoving", "lostMoves", "duplicatedMoves"})
        QVERIFY2(m.value(QLatin1String(figure)).toInt(-1) == 0, figure);
}

QJsonObject TestSoakSmoke::runJson(const QStringList& args, int* exitCode)
{
    const auto run = stepdeck::testing::runProcess(m_bench, args, 240000);
    *exitCode = run.exitCode;
    const QJsonDocument doc = QJsonDocument::fromJson(run.out.trimmed());
    if (!doc.isObject())
        qWarning() << "no JSON:" << run.out << run.err;
    return doc.object();
}

void TestSoakSmoke::soak_fiftyCommands_noCrashHangOrAxisLeftMoving()
{
    int exitCode = 0;
    const QJsonObject out = runJson({"--soak", "50", "--seed", "12", "--json"}, &exitCode);
    const QJsonArray models = out.value("soak").toArray();
    QCOMPARE(models.size(), stepdeck::models().size()); // every registered model
    for (const QJsonValue& v : models) {
        const QJsonObject m = v.toObject();
        const QByteArray name = m.value("model").toString().toUtf8();
        QVERIFY2(m.value("sessions").toInt() > 0, name);
        QVERIFY2(m.value("results").toObject().value("ok").toInt() > 0, name); // it did work
        QVERIFY2(m.value("deviceMoves").toInt() > 0, name); // moves reached the device
        QCOMPARE(m.value("crashes").toInt(-1), 0);
        QCOMPARE(m.value("hangs").toInt(-1), 0);
        QCOMPARE(m.value("axesLeftMoving").toInt(-1), 0);
    }
    QVERIFY(exitCode == 0 || exitCode == 1); // 1: a figure was not 0 (the checks above say which)
}

// The machine soak (issue 19): an E-LAB and a Nanotec simulator as one machine, driven
// through core's Machine; moves reach both devices and nothing is left moving.
void TestSoakSmoke::soak_machine_noCrashHangOrAxisLeftMoving()
{
    int exitCode = 0;
    const QJsonObject out =
        runJson({"--soak", "30", "--machine", "--seed", "3", "--json"}, &exitCode);
    const QJsonArray runs = out.value("soak").toArray();
    QCOMPARE(runs.size(), 1);
    const QJsonObject m = runs.first().toObject();
    QCOMPARE(m.value("model").toString(), QStringLiteral("machine"));
    QVERIFY(m.value("sessions").toInt() > 0);
    QVERIFY(m.value("deviceMoves").toInt() > 0);
    QVERIFY(m.value("hostMovesOk").toInt() > 0);
    verifyMustBeZero(m);
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(exitCode, 0);
}

// Issue 32: the soak over a Nanotec bus of 1, 8 and 32 drives (254: docs/benchmark.md, by
// hand; it takes minutes). Moves reach the drives past the third at the device, and nothing
// is lost, duplicated or left moving.
void TestSoakSmoke::soak_busOfDrives_everyDriveReachable_data()
{
    QTest::addColumn<int>("drives");
    QTest::newRow("1") << 1;
    QTest::newRow("8") << 8;
    QTest::newRow("32") << 32;
}

void TestSoakSmoke::soak_busOfDrives_everyDriveReachable()
{
    QFETCH(int, drives);
    int exitCode = 0;
    const QJsonObject out = runJson({"--soak", "40", "--model", "nanotec", "--drives",
                                     QString::number(drives), "--seed", "5", "--json"},
                                    &exitCode);
    const QJsonArray runs = out.value("soak").toArray();
    QCOMPARE(runs.size(), 1);
    const QJsonObject m = runs.first().toObject();
    QCOMPARE(m.value("model").toString(), QStringLiteral("nanotec/%1").arg(drives));
    QVERIFY(m.value("sessions").toInt() > 0);
    QVERIFY(m.value("hostMovesOk").toInt() > 0);
    QVERIFY(m.value("deviceMoves").toInt() > 0);
    // Drives past the third were moved, each journaled as its own axis at the device.
    if (drives == 1)
        QCOMPARE(m.value("axesMoved").toInt(), 1);
    else
        QVERIFY2(m.value("axesMoved").toInt() > 3,
                 qPrintable(QString::number(m.value("axesMoved").toInt())));
    verifyMustBeZero(m);
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(exitCode, 0);
}

void TestSoakSmoke::replug_everyPhase_noticedEveryTime()
{
    int exitCode = 0;
    const QJsonObject out = runJson({"--replug", "4", "--json"}, &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonArray models = out.value("replug").toArray();
    QCOMPARE(models.size(), stepdeck::models().size());
    for (const QJsonValue& v : models) {
        const QJsonObject m = v.toObject();
        QCOMPARE(m.value("reconnectFailures").toInt(-1), 0);
        QCOMPARE(m.value("notNoticed").toInt(-1), 0);
        QCOMPARE(m.value("samples").toInt(), 4); // poll, jog, stream, write
    }
}

void TestSoakSmoke::badArguments_exitTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("count zero") << QStringList{"--soak", "0"};
    QTest::newRow("count hex") << QStringList{"--soak", "0x10"};
    QTest::newRow("unknown model") << QStringList{"--soak", "5", "--model", "warp"};
    QTest::newRow("both") << QStringList{"--soak", "5", "--replug", "5"};
    QTest::newRow("machine and model")
        << QStringList{"--soak", "5", "--machine", "--model", "elab"};
    QTest::newRow("seed negative") << QStringList{"--replug", "1", "--seed", "-1"};
    QTest::newRow("drives zero") << QStringList{"--soak",  "5",        "--model",
                                                "nanotec", "--drives", "0"};
    QTest::newRow("drives past the bus")
        << QStringList{"--soak", "5", "--model", "nanotec", "--drives", "255"};
    QTest::newRow("drives on a board")
        << QStringList{"--soak", "5", "--model", "elab", "--drives", "4"};
}

void TestSoakSmoke::badArguments_exitTwo()
{
    QFETCH(QStringList, args);
    const auto run = stepdeck::testing::runProcess(m_bench, args, 20000);
    QCOMPARE(run.exitCode, 2);
    QCOMPARE(run.err.count('\n'), 1);
}

STEPDECK_TEST_GUILESS_MAIN(TestSoakSmoke)
#include "tst_soak_smoke.moc"
