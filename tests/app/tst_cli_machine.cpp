// stepdeck-cli machine check FILE (issue 19): a valid file prints its resolved axes, an
// invalid one exits 7 with the field named, an unreadable one exits 12; nothing is opened.
#include "TestMain.h"
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

class TestCliMachine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void check_example_printsAxesInReferenceOrder();
    void check_json_givesTheFileForm();
    void check_invalid_exit7NamesTheField();
    void check_missingFile_exit12();
    void machineCheck_namedDrives_namesShownAsWritten();

private:
    int run(const QStringList& args, QByteArray* out, QByteArray* err);
    QString m_cli;
    QString m_examples;
};

void TestCliMachine::initTestCase()
{
    const QString binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    m_cli = binDir + QStringLiteral("/stepdeck-cli");
    m_examples = QStringLiteral(STEPDECK_SOURCE_DIR "/docs/examples/");
}

int TestCliMachine::run(const QStringList& args, QByteArray* out, QByteArray* err)
{
    QProcess p;
    p.start(m_cli, args);
    if (!p.waitForFinished(30000))
        return -1;
    *out = p.readAllStandardOutput();
    *err = p.readAllStandardError();
    return p.exitCode();
}

void TestCliMachine::check_example_printsAxesInReferenceOrder()
{
    QByteArray out, err;
    QCOMPARE(
        run({"machine", "check", m_examples + "elab-xyz-nanotec-rotary.machine.json"}, &out, &err),
        0);
    QVERIFY2(out.contains("2 controllers, 4 axes"), out.constData());
    QVERIFY(out.contains("rotary") && out.contains("drives X=1"));
    // Z (order 0) before X and Y (1) before A (2).
    const int z = out.indexOf("\n  Z  "), x = out.indexOf("\n  X  "), a = out.indexOf("\n  A  ");
    QVERIFY2(z > 0 && z < x && x < a, out.constData());
    QVERIFY(out.contains("400 steps/mm"));
}

void TestCliMachine::check_json_givesTheFileForm()
{
    QByteArray out, err;
    QCOMPARE(run({"--json", "machine", "check", m_examples + "emis-xyzu.machine.json"}, &out, &err),
             0);
    const QJsonObject o = QJsonDocument::fromJson(out).object();
    QCOMPARE(o.value("format").toString(), QStringLiteral("stepdeck-machine"));
    QCOMPARE(o.value("axes").toArray().size(), 4);
}

void TestCliMachine::check_invalid_exit7NamesTheField()
{
    QTemporaryDir dir;
    QFile file(dir.filePath("bad.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format":"stepdeck-machine","version":1,"name":"m",
        "controllers":[{"id":"t","model":"elab","port":"/dev/ttyS0"}],
        "axes":[{"name":"X","controller":"t","axis":"X","unit":"mm","stepsPerUnit":-2}]})");
    file.close();
    QByteArray out, err;
    QCOMPARE(run({"machine", "check", file.fileName()}, &out, &err), 7);
    QVERIFY2(err.contains("axes[0].stepsPerUnit"), err.constData());
    QVERIFY(out.isEmpty());
}

void TestCliMachine::check_missingFile_exit12()
{
    QByteArray out, err;
    QCOMPARE(run({"machine", "check", "/nonexistent/machine.json"}, &out, &err), 12);
    QVERIFY2(err.contains("/nonexistent/machine.json"), err.constData());
}

// Issue 47, item 11b: the names the file gives a bus' drives are the names shown, in the
// controller's drive list and in the machine axes' mapping, by `machine check FILE` and by
// `--machine FILE machine` (nothing is opened for either).
void TestCliMachine::machineCheck_namedDrives_namesShownAsWritten()
{
    QTemporaryDir dir;
    QFile file(dir.filePath("feeders.machine.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format":"stepdeck-machine","version":2,"name":"feeders",
        "controllers":[{"id":"bus","model":"nanotec","port":"sim","axes":[
            {"name":"feed1","address":1},{"name":"feed2","address":2},
            {"name":"feed3","address":3},{"name":"feed4","address":4},
            {"name":"feed5","address":5},{"name":"feed6","address":6}]}],
        "axes":[
            {"name":"X","controller":"bus","axis":"feed1","unit":"mm","stepsPerUnit":100},
            {"name":"Y","controller":"bus","axis":"feed2","unit":"mm","stepsPerUnit":100},
            {"name":"Z","controller":"bus","axis":"feed3","unit":"mm","stepsPerUnit":100},
            {"name":"U","controller":"bus","axis":"feed4","unit":"mm","stepsPerUnit":100},
            {"name":"V","controller":"bus","axis":"feed5","unit":"mm","stepsPerUnit":100},
            {"name":"W","controller":"bus","axis":"feed6","unit":"mm","stepsPerUnit":100}]})");
    file.close();

    const QList<QStringList> commands = {
        {"machine", "check", file.fileName()},
        {"--machine", file.fileName(), "machine"},
    };
    for (const QStringList& command : commands) {
        QByteArray out, err;
        QCOMPARE(run(command, &out, &err), 0);
        QVERIFY2(out.contains("drives feed1=1,feed2=2,feed3=3,feed4=4,feed5=5,feed6=6"),
                 out.constData());
        for (const char* mapped :
             {"bus.feed1", "bus.feed2", "bus.feed3", "bus.feed4", "bus.feed5", "bus.feed6"})
            QVERIFY2(out.contains(mapped), out.constData());
        QVERIFY2(!out.contains("axis5") && !out.contains("axis6"), out.constData());
        QVERIFY2(!out.contains("X=1") && !out.contains("U=4"), out.constData());
        for (const char* letter : {"bus.X ", "bus.Y ", "bus.Z ", "bus.U "})
            QVERIFY2(!out.contains(letter), out.constData());
    }
}

STEPDECK_TEST_GUILESS_MAIN(TestCliMachine)
#include "tst_cli_machine.moc"
