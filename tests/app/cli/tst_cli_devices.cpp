// stepdeck-cli's machine commands against a simulated controller on a real pty, in a thread
// of this process (CliRunRig.h), in situations a plain simulator run does not meet: a board
// that answers as the manual allows but the simulator by default does not, a board still
// running what an earlier host started. The assertions are about what the DEVICE did and
// received, and what the CLI printed and exited with (docs/cli.md).
#include "CliRunRig.h"
#include "TestMain.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/emis/EmisSimulator.h"
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::test;

class TestCliDevices : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void move_inputPollAnsweredWithBel_moveCompletes();
    void status_motionTheHostDidNotCommand_printsTheReadSaysItStopped();

private:
    static QList<QByteArray> emisCommands(RunDevice& device);
};

void TestCliDevices::initTestCase()
{
    QVERIFY2(!qEnvironmentVariableIsEmpty("STEPDECK_BIN_DIR"),
             "STEPDECK_BIN_DIR is not set (run through ctest)");
}

QList<QByteArray> TestCliDevices::emisCommands(RunDevice& device)
{
    return device.probe(
        [&device] { return static_cast<emis::EmisSimulator*>(device.sim())->receivedCommands(); });
}

// EMIS (issue 28): the SMC-IC4 answers every @IG with <BEL> while a motor moves (chapter 9:
// <BEL> "abhängig vom ... Betriebszustand", read as "a motor still moving"). The machine's
// status read after the move was accepted meets that <BEL>: the move still completes, exit 0
// with the position the board reached, never "refused '@IG'" (exit 4).
void TestCliDevices::move_inputPollAnsweredWithBel_moveCompletes()
{
    RunDevice device(QStringLiteral("emis"));
    device.probe([&device] {
        static_cast<emis::EmisSimulator*>(device.sim())->setBellOnPollWhileMoving(true);
        return true;
    });
    const CliRun r = runCli(cliArgs("emis", device.path()) + QStringList{"move", "X=500"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("X=500"), r.out.constData());
    const QList<DeviceMove> moves = device.moves();
    QCOMPARE(moves.size(), 1);
    QCOMPARE(moves.at(0).axis, Axis::X);
    QCOMPARE(moves.at(0).steps, qint64(500));
    QVERIFY(device.still());
    QCOMPARE(device.position(Axis::X), qint64(500));
    // The connection's status read and the machine's read once the move was accepted.
    QVERIFY2(emisCommands(device).count("@IG") >= 2, emisCommands(device).join(' ').constData());
}

// E-LAB (issue 28): the board still runs a FastMove X, Y that an earlier host started (it
// ended without a stop, e.g. it crashed). `--json status` reads the status words, the adapter
// stops the motion it did not command (safety contract) and the read still prints what it
// read: exit 0, the JSON with X and Y moving, and a line on stderr that the motion was stopped;
// never "cancelled by stop" (exit 10) with nothing printed. The board got the stop.
void TestCliDevices::status_motionTheHostDidNotCommand_printsTheReadSaysItStopped()
{
    RunDevice device(QStringLiteral("elab"));
    device.probe([&device] {
        Simulator* sim = device.sim();
        sim->faults().silent = true; // the earlier host's replies went nowhere
        using elab::RampKind;
        sim->receive(elab::encode::ramp(RampKind::StartSpeed, {100, 100, 100}) +
                     elab::encode::ramp(RampKind::MaxSpeed, {5000, 5000, 5000}) +
                     elab::encode::ramp(RampKind::Acceleration, {1000, 1000, 1000}) +
                     elab::encode::fastMoveXY(100000, 100000));
        sim->faults().silent = false;
        sim->clearReceivedFrames();
        return true;
    });
    // Up to speed, so that it is still braking when the read comes after the stop.
    QTRY_VERIFY_WITH_TIMEOUT(device.position(Axis::X) > 500, 10000);
    QVERIFY(device.moving(Axis::Y));

    const CliRun r = runCli(
        {"--model", "elab", "--port", device.path(), "--timeout", "10000", "--json", "status"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject status = QJsonDocument::fromJson(r.out).object();
    QVERIFY2(!status.isEmpty(), r.out.constData());
    const QJsonObject axes = status.value("axes").toObject();
    QVERIFY2(axes.value("X").toObject().value("moving").toBool(), r.out.constData());
    QVERIFY2(axes.value("Y").toObject().value("moving").toBool(), r.out.constData());
    QVERIFY2(!axes.value("Z").toObject().value("moving").toBool(), r.out.constData());
    QVERIFY2(r.err.contains("did not command"), r.err.constData());

    // At the board: the stop came, the carriages stand short of the old target, and this
    // invocation started nothing.
    QVERIFY(device.probe([&device] {
        const QList<QByteArray> frames = device.sim()->receivedFrames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [&device](const QByteArray& f) { return device.sim()->isStopFrame(f); });
    }));
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 10000);
    QVERIFY(device.position(Axis::X) < 100000);
    QVERIFY(device.position(Axis::Y) < 100000);
    QVERIFY(device.moves().isEmpty());
}

STEPDECK_TEST_GUILESS_MAIN(TestCliDevices)
#include "tst_cli_devices.moc"
