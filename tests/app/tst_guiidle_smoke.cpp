// Smoke test of stepdeck-bench --gui-idle (issue 10): the mode starts stepdeck-sim and the GUI
// (offscreen), finds the link polling and prints its figures. Nothing here is timed: the
// figures and their limits are in docs/benchmark.md.
#include "ProcessSupport.h"
#include "TestMain.h"
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

class TestGuiIdleSmoke : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void guiIdle_offscreen_pollsAndPrintsFigures();
    void guiIdle_badValue_exitTwo();
};

void TestGuiIdleSmoke::guiIdle_offscreen_pollsAndPrintsFigures()
{
    const QString bench = QDir(qEnvironmentVariable("STEPDECK_BIN_DIR")).filePath("stepdeck-bench");
    QVERIFY2(QFileInfo(bench).isExecutable(), qPrintable(bench));
    const auto run = stepdeck::testing::runProcess(
        bench, {"--gui-idle", "2", "--warmup", "2", "--platform", "offscreen", "--json"}, 60000);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject out = QJsonDocument::fromJson(run.out.trimmed()).object();
    QVERIFY2(out.value("polling").toBool(), run.out.constData());
    QVERIFY(out.value("simReadBytesPerSecond").toDouble() > 0);
    QVERIFY(out.value("guiCpuPercentOfOneCore").toDouble(-1) >= 0);
    QVERIFY(out.value("guiRssMiB").toDouble() > 1); // a GUI process was sampled
    QCOMPARE(out.value("pollIntervalMs").toInt(), 50);
    QCOMPARE(out.value("platform").toString(), QStringLiteral("offscreen"));
}

void TestGuiIdleSmoke::guiIdle_badValue_exitTwo()
{
    const QString bench = QDir(qEnvironmentVariable("STEPDECK_BIN_DIR")).filePath("stepdeck-bench");
    const auto run = stepdeck::testing::runProcess(bench, {"--gui-idle", "x"}, 10000);
    QCOMPARE(run.exitCode, 2);
}

STEPDECK_TEST_GUILESS_MAIN(TestGuiIdleSmoke)
#include "tst_guiidle_smoke.moc"
