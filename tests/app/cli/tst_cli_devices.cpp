// stepdeck-cli's machine commands against a simulated controller on a real pty, in a thread
// of this process (CliRunRig.h), in situations a plain simulator run does not meet: a board
// that answers as the manual allows but the simulator by default does not, a board still
// running what an earlier host started. The assertions are about what the DEVICE did and
// received, and what the CLI printed and exited with (docs/cli.md).
#include "CliRunRig.h"
#include "protocols/emis/EmisSimulator.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::test;

class TestCliDevices : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void move_inputPollAnsweredWithBel_moveCompletes();

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

QTEST_GUILESS_MAIN(TestCliDevices)
#include "tst_cli_devices.moc"
