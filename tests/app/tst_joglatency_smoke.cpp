// Smoke test of stepdeck-bench --jog-latency (issue 21, item 4): the GUI's jog panel runs
// offscreen against the E-LAB and Nanotec simulators, every press reaches the device and ends
// there, and both models' figures are printed. Nothing here is timed: the figures and the goal
// are in docs/benchmark.md.
#include "ProcessSupport.h"
#include "TestMain.h"
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

class TestJogLatencySmoke : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void jogLatency_threePresses_bothModelsMeasured();
    void badArguments_exitTwo_data();
    void badArguments_exitTwo();

private:
    QString m_bench;
};

void TestJogLatencySmoke::initTestCase()
{
    m_bench = QDir(qEnvironmentVariable("STEPDECK_BIN_DIR")).filePath("stepdeck-bench");
    QVERIFY2(QFileInfo(m_bench).isExecutable(), qPrintable(m_bench));
}

void TestJogLatencySmoke::jogLatency_threePresses_bothModelsMeasured()
{
    const auto run = stepdeck::testing::runProcess(
        m_bench, {"--jog-latency", "--jog-presses", "3", "--json"}, 90000);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject out = QJsonDocument::fromJson(run.out.trimmed()).object();
    QVERIFY2(!out.isEmpty(), run.out.constData());
    QVERIFY2(out.value("notes").toArray().isEmpty(), run.out.constData());
    const QJsonObject perModel = out.value("jogLatency").toObject();
    for (const char* model : {"elab", "nanotec"}) {
        const QJsonObject m = perModel.value(QLatin1String(model)).toObject();
        for (const char* key : {"pressMs", "releaseMs"}) {
            const QJsonObject figure = m.value(QLatin1String(key)).toObject();
            const QByteArray what = QByteArray(model) + ' ' + key;
            QVERIFY2(figure.value("samples").toInt() == 3, what); // every press and release
            QVERIFY2(figure.value("median").toDouble(-1) > 0, what);
            QVERIFY2(figure.value("p99").toDouble(-1) >= figure.value("median").toDouble(), what);
        }
    }
    // E-LAB's press -> first jog frame, as the default run prints it.
    QCOMPARE(out.value("jogLatencyMs").toObject(),
             perModel.value("elab").toObject().value("pressMs").toObject());
    const QJsonObject conditions = out.value("conditions").toObject().value("jog").toObject();
    QCOMPARE(conditions.value("presses").toInt(), 3);
    QCOMPARE(conditions.value("wire").toString(), QStringLiteral("unpaced"));
}

void TestJogLatencySmoke::badArguments_exitTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("presses zero") << QStringList{"--jog-latency", "--jog-presses", "0"};
    QTest::newRow("presses not a number") << QStringList{"--jog-latency", "--jog-presses", "x"};
    QTest::newRow("presses without value") << QStringList{"--jog-latency", "--jog-presses"};
    QTest::newRow("presses too many") << QStringList{"--jog-latency", "--jog-presses", "10001"};
    QTest::newRow("unknown with jog latency") << QStringList{"--jog-latency", "--load", "1"};
    QTest::newRow("default run, presses negative") << QStringList{"--jog-presses", "-1"};
}

void TestJogLatencySmoke::badArguments_exitTwo()
{
    QFETCH(QStringList, args);
    const auto run = stepdeck::testing::runProcess(m_bench, args, 10000);
    QCOMPARE(run.exitCode, 2);
}

STEPDECK_TEST_GUILESS_MAIN(TestJogLatencySmoke)
#include "tst_joglatency_smoke.moc"
