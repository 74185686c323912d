// Smoke test of stepdeck-bench --poll-only (issue 21, item 1): every model's status poll is
// measured on its paced wire, with the limit its own frames allow. Nothing here is timed and
// no ratio is judged: the figures and the goal are in docs/benchmark.md.
#include "ProcessSupport.h"
#include "TestMain.h"
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

class TestPollWireSmoke : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void pollOnly_everyModel_achievedAndLimitPositive_data();
    void pollOnly_everyModel_achievedAndLimitPositive();
    void pollOnly_busSchedule_everyBusSize_movingDriveAndIdleDrivesRead_data();
    void pollOnly_busSchedule_everyBusSize_movingDriveAndIdleDrivesRead();
    void pollOnly_eLab_keepsTheOldFigures();
    void badArguments_exitTwo_data();
    void badArguments_exitTwo();

private:
    QString m_bench;
    QJsonObject m_out; // one --poll-only run, shared by the checks
};

void TestPollWireSmoke::initTestCase()
{
    m_bench = QDir(qEnvironmentVariable("STEPDECK_BIN_DIR")).filePath("stepdeck-bench");
    QVERIFY2(QFileInfo(m_bench).isExecutable(), qPrintable(m_bench));
    // A short window: the run proves every model is measured, not how fast.
    const auto run = stepdeck::testing::runProcess(
        m_bench, {"--poll-only", "--poll-window", "400", "--json"}, 180000);
    QCOMPARE(run.exitCode, 0);
    m_out = QJsonDocument::fromJson(run.out.trimmed()).object();
    QVERIFY2(!m_out.isEmpty(), run.out.constData());
}

void TestPollWireSmoke::pollOnly_everyModel_achievedAndLimitPositive_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("drives");
    QTest::newRow("elab") << "elab" << 0;
    QTest::newRow("nanotec, 1 drive") << "nanotec1" << 1;
    QTest::newRow("nanotec, 3 drives") << "nanotec3" << 3;
    QTest::newRow("nanotec, 4 drives") << "nanotec4" << 4;
    QTest::newRow("nanotec, 8 drives") << "nanotec8" << 8; // issue 32: axes past X, Y, Z, U
    QTest::newRow("emis") << "emis" << 0;
}

void TestPollWireSmoke::pollOnly_everyModel_achievedAndLimitPositive()
{
    QFETCH(QString, key);
    QFETCH(int, drives);
    const QJsonObject figure = m_out.value("pollWire").toObject().value(key).toObject();
    const QByteArray text = QJsonDocument(figure).toJson(QJsonDocument::Compact);
    QVERIFY2(figure.value("hz").toDouble(-1) > 0, text.constData());
    QVERIFY2(figure.value("limitHz").toDouble(-1) > 0, text.constData());
    QVERIFY2(figure.value("ratio").toDouble(-1) > 0, text.constData());
    QVERIFY2(figure.value("charsPerPoll").toDouble(-1) > 0, text.constData());
    QVERIFY2(figure.value("characterUs").toDouble(-1) > 0, text.constData());
    QVERIFY2(figure.value("polls").toInt() >= 2, text.constData());
    QCOMPARE(figure.value("drives").toInt(), drives);
    QVERIFY2(!figure.contains("note"), text.constData());
}

void TestPollWireSmoke::pollOnly_busSchedule_everyBusSize_movingDriveAndIdleDrivesRead_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("drives");
    QTest::addColumn<int>("idleReadTwice"); // at least; the short window is not a full round
    QTest::newRow("8") << "nanotec8" << 8 << 7;
    QTest::newRow("32") << "nanotec32" << 32 << 1;
    QTest::newRow("254") << "nanotec254" << 254 << 0;
}

// Issue 32, step 4: each bus size is measured at the device: the moving drive's reads and
// intervals, the idle drives' reads, the wire's use. The figures are in docs/benchmark.md.
void TestPollWireSmoke::pollOnly_busSchedule_everyBusSize_movingDriveAndIdleDrivesRead()
{
    QFETCH(QString, key);
    QFETCH(int, drives);
    QFETCH(int, idleReadTwice);
    const QJsonObject figure = m_out.value("busSchedule").toObject().value(key).toObject();
    const QByteArray text = QJsonDocument(figure).toJson(QJsonDocument::Compact);
    QVERIFY2(!figure.contains("note"), text.constData());
    QCOMPARE(figure.value("drives").toInt(), drives);
    QVERIFY2(figure.value("movingReads").toInt() >= 3, text.constData());
    QVERIFY2(figure.value("movingMedianMs").toDouble(-1) > 0, text.constData());
    QVERIFY2(figure.value("movingP99Ms").toDouble(-1) >= figure.value("movingMedianMs").toDouble(),
             text.constData());
    QVERIFY2(figure.value("idleDrivesRead").toInt() >= idleReadTwice, text.constData());
    QVERIFY2(figure.value("wireUse").toDouble(-1) > 0, text.constData());
    QVERIFY2(figure.value("wireUse").toDouble(2) <= 1.0, text.constData());
}

void TestPollWireSmoke::pollOnly_eLab_keepsTheOldFigures()
{
    QVERIFY(m_out.value("pollRateHz").toDouble(-1) > 0);
    QVERIFY(m_out.value("pollRateWireMaxHz").toDouble(-1) > 0);
    QVERIFY(m_out.value("panicLatencyMs").toObject().value("median").isNull()); // not measured
    QCOMPARE(m_out.value("conditions").toObject().value("pollWireWindowMs").toInt(), 400);
}

void TestPollWireSmoke::badArguments_exitTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("window not a number") << QStringList{"--poll-only", "--poll-window", "x"};
    QTest::newRow("window too short") << QStringList{"--poll-only", "--poll-window", "0"};
    QTest::newRow("window without value") << QStringList{"--poll-only", "--poll-window"};
}

void TestPollWireSmoke::badArguments_exitTwo()
{
    QFETCH(QStringList, args);
    const auto run = stepdeck::testing::runProcess(m_bench, args, 10000);
    QCOMPARE(run.exitCode, 2);
}

STEPDECK_TEST_GUILESS_MAIN(TestPollWireSmoke)
#include "tst_pollwire_smoke.moc"
