// Smoke test of stepdeck-bench --load / --panic-only (issue 21): the panic latency is measured
// quiet and beside busy threads, and both figures are printed; --machine-stop-only (issue 19)
// prints the machine STOP latency for every machine size. Nothing here is timed: the
// figures and the goal are in docs/benchmark.md.
#include "ProcessSupport.h"
#include "TestMain.h"
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

class TestPanicLoadSmoke : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void panicOnly_oneLoadThread_printsBothFigures();
    void machineStopOnly_fiveRuns_everySizeMeasured();
    void badArguments_exitTwo_data();
    void badArguments_exitTwo();

private:
    QString m_bench;
};

void TestPanicLoadSmoke::initTestCase()
{
    m_bench = QDir(qEnvironmentVariable("STEPDECK_BIN_DIR")).filePath("stepdeck-bench");
    QVERIFY2(QFileInfo(m_bench).isExecutable(), qPrintable(m_bench));
}

void TestPanicLoadSmoke::panicOnly_oneLoadThread_printsBothFigures()
{
    const auto run = stepdeck::testing::runProcess(
        m_bench, {"--panic-only", "--load", "1", "--panic-runs", "3", "--json"}, 60000);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject out = QJsonDocument::fromJson(run.out.trimmed()).object();
    QVERIFY2(!out.isEmpty(), run.out.constData());
    for (const char* key : {"panicLatencyMs", "panicLatencyUnderLoadMs"}) {
        const QJsonObject figure = out.value(QLatin1String(key)).toObject();
        QVERIFY2(figure.value("samples").toInt() == 3, key); // every run reached the device
        QVERIFY2(figure.value("median").toDouble(-1) > 0, key);
        QVERIFY2(figure.value("p99").toDouble(-1) >= figure.value("median").toDouble(), key);
    }
    const QJsonObject conditions = out.value("conditions").toObject();
    QCOMPARE(conditions.value("loadThreads").toInt(), 1);
    QCOMPARE(conditions.value("panicUnderLoadRepetitions").toInt(), 3);
    QVERIFY(out.value("pollRateHz").isNull()); // --panic-only measured nothing else
}

void TestPanicLoadSmoke::machineStopOnly_fiveRuns_everySizeMeasured()
{
    const auto run = stepdeck::testing::runProcess(
        m_bench, {"--machine-stop-only", "--machine-stop-runs", "5", "--json"}, 60000);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject out = QJsonDocument::fromJson(run.out.trimmed()).object();
    QVERIFY2(!out.isEmpty(), run.out.constData());
    const QJsonArray sizes = out.value("machineStopLatencyMs").toArray();
    QCOMPARE(sizes.size(), 3);
    QList<int> controllers;
    for (const QJsonValue& v : sizes) {
        const QJsonObject size = v.toObject();
        controllers << size.value("controllers").toInt();
        QCOMPARE(size.value("samples").toInt(), 5); // every stop reached every device
        QVERIFY(size.value("median").toDouble(-1) > 0);
    }
    QCOMPARE(controllers, (QList<int>{1, 2, 4}));
    QVERIFY(out.value("panicLatencyMs").toObject().value("median").isNull()); // not measured
}

void TestPanicLoadSmoke::badArguments_exitTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("load not a number") << QStringList{"--load", "x"};
    QTest::newRow("load negative") << QStringList{"--load", "-1"};
    QTest::newRow("load without value") << QStringList{"--load"};
    QTest::newRow("panic runs negative") << QStringList{"--panic-runs", "-3"};
    QTest::newRow("machine stop runs zero") << QStringList{"--machine-stop-runs", "0"};
}

void TestPanicLoadSmoke::badArguments_exitTwo()
{
    QFETCH(QStringList, args);
    const auto run = stepdeck::testing::runProcess(m_bench, args, 10000);
    QCOMPARE(run.exitCode, 2);
}

STEPDECK_TEST_GUILESS_MAIN(TestPanicLoadSmoke)
#include "tst_panicload_smoke.moc"
