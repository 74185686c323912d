// stepdeck-cli --model M --port P without a machine file (issue 19): the machine commands run
// on a machine of that one controller, its axes under their controller names in steps -- the
// same code path as --machine FILE. The E-LAB simulator is on a real pty in this process.
#include "TestMain.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabCodec.h"
#include "sim/PtyEndpoint.h"
#include "sim/Simulator.h"
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>
#include <algorithm>
#include <memory>

using namespace stepdeck;

class TestCliSingleMachine : public QObject
{
    Q_OBJECT
    int run(const QStringList& command); // the CLI on the pty; its exit code

    QString m_cli;
    std::unique_ptr<PtyEndpoint> m_end;
    std::unique_ptr<Simulator> m_sim;
    QByteArray m_out;
    QByteArray m_err;

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void statusJson_oneController_axesCarryTheMachineFields();
    void statusHuman_axisTableThenTheControllersOwnLines();
    void stop_reachesTheDevice();
    void move_steps_reachTheBoardAsOneFastMove();
    void move_json_positionsInTheControllersObject();
    void jog_overTheCeiling_refusedNothingMoves();
    void home_minusOnEmis_refused();
    void setupDefaults_emis_writesWhatTheBoardTakes();
};

void TestCliSingleMachine::initTestCase()
{
    const QString binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    m_cli = QDir(binDir).filePath(QStringLiteral("stepdeck-cli"));
}

void TestCliSingleMachine::init()
{
    const ModelInfo* info = findModel(QStringLiteral("elab"));
    m_end = std::make_unique<PtyEndpoint>();
    QString error;
    QVERIFY2(m_end->create(&error), qPrintable(error));
    SimulatorOptions options;
    options.line = info->line;
    m_sim.reset(info->createSimulator(options));
    m_sim->attach(m_end.get());
}

void TestCliSingleMachine::cleanup()
{
    m_sim.reset();
    m_end.reset();
}

int TestCliSingleMachine::run(const QStringList& command)
{
    QProcess process;
    m_out.clear();
    m_err.clear();
    process.start(
        m_cli, QStringList{"--model", "elab", "--port", m_end->slavePath(), "--timeout", "10000"} +
                   command);
    if (!process.waitForStarted(5000))
        return -1;
    // Not waitForFinished(): the simulator lives in this thread and must keep answering.
    QElapsedTimer clock;
    clock.start();
    while (process.state() != QProcess::NotRunning && clock.elapsed() < 30000)
        QSignalSpy(&process, &QProcess::finished).wait(50);
    m_out = process.readAllStandardOutput();
    m_err = process.readAllStandardError();
    if (process.state() != QProcess::NotRunning) {
        process.kill();
        process.waitForFinished(5000);
        return -1;
    }
    return process.exitCode();
}

// The controller's object as always ("model", "machine" flags, "axes" by name), each axis with
// the fields only a machine has: its name, controller, controller axis, unit and knowledge.
void TestCliSingleMachine::statusJson_oneController_axesCarryTheMachineFields()
{
    QCOMPARE(run({"status", "--json"}), 0);
    const QJsonObject status = QJsonDocument::fromJson(m_out).object();
    QCOMPARE(status.value("model").toString(), QStringLiteral("elab"));
    QVERIFY(status.value("machine").toObject().value("setupIncomplete").toBool());
    QCOMPARE(status.value("state").toString(), QStringLiteral("idle"));
    const QJsonObject axes = status.value("axes").toObject();
    QCOMPARE(axes.keys(), (QStringList{"X", "Y", "Z"}));
    for (const QString& name : axes.keys()) {
        const QJsonObject axis = axes.value(name).toObject();
        QCOMPARE(axis.value("name").toString(), name);
        QCOMPARE(axis.value("controller").toString(), QStringLiteral("elab"));
        QCOMPARE(axis.value("axis").toString(), name);
        QCOMPARE(axis.value("unit").toString(), QStringLiteral("steps"));
        QCOMPARE(axis.value("known").toString(), QStringLiteral("unknown"));
        QCOMPARE(axis.value("steps").toInteger(-1), qint64(0));
        QVERIFY(axis.contains("limitSwitch")); // the controller's own field stays
    }
    const QJsonArray controllers = status.value("controllers").toArray();
    QCOMPARE(controllers.size(), 1);
    QCOMPARE(controllers.at(0).toObject().value("port").toString(), m_end->slavePath());
    QCOMPARE(controllers.at(0).toObject().value("link").toString(), QStringLiteral("connected"));
}

void TestCliSingleMachine::statusHuman_axisTableThenTheControllersOwnLines()
{
    QCOMPARE(run({"status"}), 0);
    const QString out = QString::fromUtf8(m_out);
    QVERIFY2(out.startsWith(QStringLiteral("machine \"")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("(0 steps on elab.Z) (unknown)")), qPrintable(out));
    const qsizetype table = out.indexOf(QStringLiteral("steps on elab.X"));
    const qsizetype own = out.indexOf(QStringLiteral("SETUP INCOMPLETE"));
    QVERIFY2(table > 0 && own > table, qPrintable(out));
}

void TestCliSingleMachine::stop_reachesTheDevice()
{
    QCOMPARE(run({"stop"}), 0);
    const QList<QByteArray> frames = m_sim->receivedFrames();
    QVERIFY(std::any_of(frames.cbegin(), frames.cend(),
                        [this](const QByteArray& f) { return m_sim->isStopFrame(f); }));
}

// X=1000 in steps at 1 step per unit: the board gets the fast move of exactly 1000 steps on X.
void TestCliSingleMachine::move_steps_reachTheBoardAsOneFastMove()
{
    const int code = run({"--setup-defaults", "move", "X=1000"});
    QVERIFY2(code == 0, m_err.constData());
    const QByteArray frame = elab::encode::fastMoveXY(1000, 0);
    QCOMPARE(m_sim->receivedFrames().count(frame), qsizetype(1));
    QCOMPARE(m_sim->position(Axis::X), qint64(1000));
    QVERIFY(m_sim->standingStill());
    QVERIFY2(m_out.startsWith("X=1000"), m_out.constData());
}

void TestCliSingleMachine::move_json_positionsInTheControllersObject()
{
    const int code = run({"--setup-defaults", "move", "Y=-20", "--json"});
    QVERIFY2(code == 0, m_err.constData());
    const QJsonObject y =
        QJsonDocument::fromJson(m_out).object().value("axes").toObject().value("Y").toObject();
    QCOMPARE(y.value("position").toInteger(), qint64(-20));
    QCOMPARE(y.value("steps").toInteger(), qint64(-20));
    QCOMPARE(y.value("unit").toString(), QStringLiteral("steps"));
}

// A typed rate above the controller's jog ceiling is refused (exit 7), not limited: no jog
// frame reaches the board.
void TestCliSingleMachine::jog_overTheCeiling_refusedNothingMoves()
{
    QCOMPARE(run({"--setup-defaults", "jog", "X=1000000", "--for", "300"}), 7);
    QVERIFY2(m_err.contains("out of range"), m_err.constData());
    const QByteArray jogFrame = elab::encode::jogSpeed({0, 0, 0}).left(1);
    for (const QByteArray& f : m_sim->receivedFrames())
        QVERIFY2(!f.startsWith(jogFrame), f.toHex().constData());
    QVERIFY(m_sim->standingStill());
}

// The machine's home takes AXIS=DIR: -1 on a controller that picks the direction itself is
// refused before anything is opened (here: the in-process EMIS simulator).
void TestCliSingleMachine::home_minusOnEmis_refused()
{
    QProcess process;
    process.start(m_cli, {"--model", "emis", "--port", "sim", "home", "X=-1"});
    QVERIFY(process.waitForFinished(30000));
    QCOMPARE(process.exitCode(), 7);
    QVERIFY(process.readAllStandardError().contains("picks the reference direction itself"));
}

// --setup-defaults leaves out what carries a warning (EMIS run-current) and what the board
// writes only together with it (idle-current, one command "c,x100,20", manual 9.8): the rest
// is written and the command runs (it once failed with exit 7, "idle-current ... needs
// run-current").
void TestCliSingleMachine::setupDefaults_emis_writesWhatTheBoardTakes()
{
    QProcess process;
    process.start(m_cli, {"--model", "emis", "--port", "sim", "--setup-defaults", "status"});
    QVERIFY(process.waitForFinished(30000));
    const QByteArray err = process.readAllStandardError();
    QVERIFY2(process.exitCode() == 0, err.constData());
    QVERIFY2(!err.contains("idle-current"), err.constData());
}

STEPDECK_TEST_GUILESS_MAIN(TestCliSingleMachine)
#include "tst_cli_single_machine.moc"
