// stepdeck-cli run PROGRAM on each simulated controller (issue 20): the device receives the
// blocks in order, one motion at a time per axis, a dwell lasts at least its P at the device;
// a signal, a refused block and M66 end the run as docs/cli.md says. Each simulator is on a real
// pty in a thread of this process (CliRunRig.h); the assertions are about what the DEVICE did.
#include "CliRunRig.h"
#include "TestMain.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/emis/EmisSimulator.h"
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>
#include <csignal>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
constexpr double kDwellSeconds = 0.4;

// The same program on every model: a reference run of X, moves, a dwell, a 3x repeat. Only
// EMIS has digital outputs; on the other models M64/M65 would be a check error (exit 7), so
// their program leaves those two lines out (the line numbers stay: they become comments).
QByteArray commonProgram(bool outputs)
{
    const QByteArray on = outputs ? "M64 P1" : "; (no outputs on this model)";
    const QByteArray off = outputs ? "M65 P1" : "; (no outputs on this model)";
    return "G21 G90\n"
           "G28 X0\n"
           "G0 X200\n" +
           on + "\nG4 P0.4\n" + off +
           "\n"
           "O1 repeat [3]\n"
           "  G0 X300\n"
           "  G0 X200\n"
           "O1 endrepeat\n"
           "M2\n";
}

// The moves the program makes X do after its reference run, as the device counts them.
const QList<qint64> kExpectedSteps{200, 100, -100, 100, -100, 100, -100};
} // namespace

class TestCliRunDevices : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void sameProgram_eachModel_blocksInOrderOneMotionAtATimeDwellHeld_data();
    void sameProgram_eachModel_blocksInOrderOneMotionAtATimeDwellHeld();
    void issue50Forms_eachModel_runAsLinuxCncReadsThem_data();
    void issue50Forms_eachModel_runAsLinuxCncReadsThem();
    void sigint_duringABlock_deviceStandsStillNextBlockNeverArrives();
    void sigint_midArcChain_deviceStandsNoChordAfter_data();
    void sigint_midArcChain_deviceStandsNoChordAfter();
    void refusedBlock_failsAtItsLine_laterBlocksNeverArrive_thenFromLineRunsOn();
    void linkLost_duringABlock_exit6NamesTheLine();
    void waitInput_goesHighAfterASecond_runOnThenTimeoutExit5();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestCliRunDevices::initTestCase()
{
    QVERIFY2(!qEnvironmentVariableIsEmpty("STEPDECK_BIN_DIR"),
             "STEPDECK_BIN_DIR is not set (run through ctest)");
}

void TestCliRunDevices::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

void TestCliRunDevices::cleanup()
{
    m_dir.reset();
}

// Issue 50's forms on every controller family, in its own steps.
// - "forms": "%" and a program number around it (item 3), GRBL's $H (every axis referenced) and
//   $32 (not run, a note), a deleted line (item 6, block delete on), polar words to X0 Y300 and
//   X400 Y0, a feed far above the highest the controller runs (item 1: it runs at that
//   highest, with a note), a G2 with K0.000 (item 8) from X500 round (550,0) to X600, M2, and
//   a move after it that is never read. The laser axes take no F: their program stops after
//   the polar moves. EMIS moves with G1 only (it cannot read its fast speed back,
//   docs/programs.md), so its polar moves are G1s.
// - "language" (item 9): a sub's return with a value inside its if (X = 3 x 100) and EXISTS of
//   a named parameter that is set (Y200) and of one that is not (no Y999).
void TestCliRunDevices::issue50Forms_eachModel_runAsLinuxCncReadsThem_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<QByteArray>("program");
    QTest::addColumn<QList<int>>("lines");  // the lines whose blocks ran, in order
    QTest::addColumn<QList<qint64>>("end"); // where X and Y end, in steps from the reference
    QTest::addColumn<QStringList>("notes"); // what the check's notes name
    QTest::addColumn<QStringList>("options");
    const QByteArray head = "%\nO5001 (ISSUE 50 FORMS)\nG90\n$H\n$32=1\n/G0 X999\n";
    const QByteArray feed = "G1 X500 F60000000\nG2 X600 Y0 I50 J0 K0.000\n";
    const QByteArray tail = "M2\nG0 X999\n%\n";
    const QList<int> withFeed{4, 7, 8, 9, 10, 11};
    const QStringList feedNotes{"$32=1", "F60000000 "};
    const auto language = [](const char* move) {
        return QByteArray("o100 sub\n  o101 if [#1 GT 0]\n    o100 return [#1 * 100]\n"
                          "  o101 endif\n  o100 return [0]\no100 endsub\nG90\nG28\n"
                          "o100 call [3]\n") +
               move + " X#<_value>\n#<set> = 1\no102 if [EXISTS[#<set>]]\n  " + move +
               " Y200\no102 endif\no103 if [EXISTS[#<unset>]]\n  " + move +
               " Y999\no103 endif\nM2\n";
    };
    const QList<int> languageLines{8, 10, 13, 18};
    const QByteArray polar = "G0 @300 ^90\nG0 @400 ^0\n";
    QTest::newRow("elab forms") << "elab" << head + polar + feed + tail << withFeed
                                << QList<qint64>{600, 0} << feedNotes << QStringList{};
    // LinuxCNC's switch off: the "/" line runs (X999) before the polar moves.
    QTest::newRow("elab forms, block delete off")
        << "elab" << head + polar + feed + tail << QList<int>{4, 6, 7, 8, 9, 10, 11}
        << QList<qint64>{600, 0} << feedNotes << QStringList{"--block-delete", "off"};
    QTest::newRow("elab language") << "elab" << language("G0") << languageLines
                                   << QList<qint64>{300, 200} << QStringList{} << QStringList{};
    // The program number in its other form, ":5001".
    QByteArray colon = head;
    colon.replace("O5001", ":5001");
    QTest::newRow("nanotec forms") << "nanotec" << colon + polar + feed + tail << withFeed
                                   << QList<qint64>{600, 0} << feedNotes << QStringList{};
    QTest::newRow("nanotec language") << "nanotec" << language("G0") << languageLines
                                      << QList<qint64>{300, 200} << QStringList{} << QStringList{};
    QTest::newRow("emis forms") << "emis"
                                << head + "G1 @300 ^90 F60000000\nG1 @400 ^0\n" + feed + tail
                                << withFeed << QList<qint64>{600, 0} << feedNotes << QStringList{};
    QTest::newRow("emis language") << "emis" << language("G1 F6000") << languageLines
                                   << QList<qint64>{300, 200} << QStringList{} << QStringList{};
    QTest::newRow("laser-axis forms")
        << "laser-axis" << head + polar + tail << QList<int>{4, 7, 8, 9} << QList<qint64>{400, 0}
        << QStringList{"$32=1"} << QStringList{};
    QTest::newRow("laser-axis language")
        << "laser-axis" << language("G0") << languageLines << QList<qint64>{300, 200}
        << QStringList{} << QStringList{};
}

void TestCliRunDevices::issue50Forms_eachModel_runAsLinuxCncReadsThem()
{
    QFETCH(QString, model);
    QFETCH(QByteArray, program);
    QFETCH(QList<int>, lines);
    QFETCH(QList<qint64>, end);
    QFETCH(QStringList, notes);
    QFETCH(QStringList, options);
    const bool nanotec = model == QLatin1String("nanotec");
    RunDevice device(model, nanotec ? QList<int>{1, 2, 3} : QList<int>{1});
    qint64 reference = 0; // the E-LAB counts from power-on; its switches sit 20000 below
    if (model == QLatin1String("elab"))
        reference = device.probe([&device] {
            auto* sim = static_cast<elab::ElabSimulator*>(device.sim());
            for (Axis a : {Axis::X, Axis::Y, Axis::Z})
                sim->setPosition(a, sim->switchConfig(a).referencePosition + 200); // a short $H
            return sim->switchConfig(Axis::X).referencePosition;
        });
    QStringList args = cliArgs(model, device.path());
    if (nanotec) // X and Y: the model's drives 1, 2, 3
        args = QStringList{"--model", model, "--port", device.path(), "--timeout", "10000"};
    const QString path = writeProgram(*m_dir, "forms.nc", program);
    const CliRun r = runCli(args + QStringList{"--json", "run", path} + options, 120000);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QList<int> ran;
    QStringList noted;
    for (const QByteArray& line : r.out.split('\n')) {
        const QJsonObject o = QJsonDocument::fromJson(line).object();
        if (o.value("event").toString() == QLatin1String("block") &&
            o.value("state").toString() == QLatin1String("done") &&
            (ran.isEmpty() || ran.last() != o.value("line").toInt()))
            ran << o.value("line").toInt();
        if (o.value("event").toString() == QLatin1String("note"))
            noted << o.value("message").toString();
    }
    QCOMPARE(ran, lines);
    for (const QString& what : std::as_const(notes))
        QVERIFY2(std::any_of(noted.cbegin(), noted.cend(),
                             [&](const QString& n) { return n.contains(what); }),
                 qPrintable(what + " not in: " + noted.join('\n')));
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 5000);
    // The E-LAB's reference run stops within its switch's window (ElabSimSwitchConfig).
    const qint64 slack = model == QLatin1String("elab") ? 10 : 0;
    const qint64 x = device.position(Axis::X) - reference;
    const qint64 y = device.position(Axis::Y) - reference;
    QVERIFY2(qAbs(x - end.at(0)) <= slack && qAbs(y - end.at(1)) <= slack,
             qPrintable(QStringLiteral("X %1, Y %2").arg(x).arg(y)));
}

void TestCliRunDevices::sameProgram_eachModel_blocksInOrderOneMotionAtATimeDwellHeld_data()
{
    QTest::addColumn<QString>("model");
    for (const char* model : {"elab", "nanotec", "emis", "laser-axis"})
        QTest::newRow(model) << QString::fromLatin1(model);
}

void TestCliRunDevices::sameProgram_eachModel_blocksInOrderOneMotionAtATimeDwellHeld()
{
    QFETCH(QString, model);
    RunDevice device(model);
    if (model == QLatin1String("elab")) // its reference switch near, so G28 is short
        device.probe([&device] {
            static_cast<elab::ElabSimulator*>(device.sim())->setPosition(Axis::X, -19800);
            return true;
        });
    const bool outputs = model == QLatin1String("emis");
    const QString path = writeProgram(*m_dir, "common.ngc", commonProgram(outputs));
    const CliRun r = runCli(cliArgs(model, device.path()) + QStringList{"run", path});
    QVERIFY2(r.exitCode == 0, r.err.constData());

    // In order, each move of X exactly once, each one only once X stood still.
    const QList<DeviceMove> moves = device.moves();
    QList<qint64> steps;
    for (const DeviceMove& m : moves) {
        QCOMPARE(m.axis, Axis::X);
        QVERIFY2(!m.axisMoving,
                 qPrintable(QStringLiteral("move %1 came while X moved").arg(steps.size() + 1)));
        steps << m.steps;
    }
    QCOMPARE(steps, kExpectedSteps);
    QVERIFY(device.still());
    // The dwell: from the moment X came to rest after its first move to the next move. The
    // stop lies after the last moment X was seen moving (CliRunRig.h) and after the move was
    // accepted: the later of the two bounds it from below, so a late look never fails this.
    qint64 stoppedBy = moves.at(0).atMs;
    for (qint64 t : device.restTimes()) {
        if (t >= moves.at(0).atMs && t < moves.at(1).atMs)
            stoppedBy = t;
    }
    QVERIFY2(moves.at(1).atMs - stoppedBy >= qint64(kDwellSeconds * 1000),
             qPrintable(QStringLiteral("dwell at the device: at most %1 ms")
                            .arg(moves.at(1).atMs - stoppedBy)));
    if (outputs) {
        // M64 then M65 reached the board (it ends with the output off again).
        const QList<QByteArray> frames = device.probe([&device] {
            return static_cast<emis::EmisSimulator*>(device.sim())->receivedCommands();
        });
        const qsizetype on = frames.indexOf(QByteArrayLiteral("A1,1"));
        const qsizetype off = frames.indexOf(QByteArrayLiteral("A1,0"));
        QVERIFY2(on >= 0 && off > on, frames.join(' ').constData());
    }
}

// SIGINT while the device runs a block's move: the CLI stops the machine and exits 130; the
// device stands still and never receives the next block.
void TestCliRunDevices::sigint_duringABlock_deviceStandsStillNextBlockNeverArrives()
{
    RunDevice device(QStringLiteral("elab"));
    const QString path = writeProgram(*m_dir, "long.ngc", "G91\nG0 X30000\nG0 X100\n");
    QProcess cli;
    cli.start(cliPath(), cliArgs("elab", device.path()) + QStringList{"run", path});
    QVERIFY(cli.waitForStarted(5000));
    QTRY_VERIFY_WITH_TIMEOUT(device.moving(), 20000);
    ::kill(pid_t(cli.processId()), SIGINT);
    QVERIFY(cli.waitForFinished(20000));
    QCOMPARE(cli.exitCode(), 130);
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 5000);
    const QList<DeviceMove> moves = device.moves();
    QCOMPARE(moves.size(), 1);
    QCOMPARE(moves.at(0).steps, qint64(30000));
    QVERIFY(device.position() < 30000); // stopped on its way
    QVERIFY(device.probe([&device] {
        const QList<QByteArray> frames = device.sim()->receivedFrames();
        return std::any_of(frames.cbegin(), frames.cend(),
                           [&device](const QByteArray& f) { return device.sim()->isStopFrame(f); });
    }));
}

void TestCliRunDevices::sigint_midArcChain_deviceStandsNoChordAfter_data()
{
    QTest::addColumn<QString>("model");
    QTest::newRow("emis") << QStringLiteral("emis");
    QTest::newRow("nanotec") << QStringLiteral("nanotec");
}

// SIGINT in the middle of a circle run as a chain of coordinated chords (issue 30): exit 130
// and the device stands on its way round: the Nanotec's drives stopped by 'S' with no 'A'
// after it; the EMIS, which has no stop command, at the end of the chord it ran.
void TestCliRunDevices::sigint_midArcChain_deviceStandsNoChordAfter()
{
    QFETCH(QString, model);
    const bool nanotec = model == QLatin1String("nanotec");
    RunDevice device(model, nanotec ? QList<int>{1, 2} : QList<int>{1});
    // In steps: a circle of radius 2 000 around (2 000, 0) at 60 000 steps/min (1 000/s).
    const QString path =
        writeProgram(*m_dir, "circle.ngc", "G28 X0 Y0\nG90\nG2 X0 Y0 I2000 J0 F60000\nM2\n");
    QStringList args{"--model", model, "--port", device.path(), "--timeout", "10000"};
    if (nanotec)
        args << "--axes"
             << "X=1,Y=2";
    QProcess cli;
    cli.start(cliPath(), args + QStringList{"run", path});
    QVERIFY(cli.waitForStarted(5000));
    QTRY_VERIFY_WITH_TIMEOUT(device.moves().size() >= 8, 30000); // some chords into the circle
    ::kill(pid_t(cli.processId()), SIGINT);
    QVERIFY(cli.waitForFinished(20000));
    const QByteArray err = cli.readAllStandardError();
    QVERIFY2(cli.exitCode() == 130, err.constData());
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 5000);
    if (nanotec) {
        // The first stop frame and the last start, found in the device's thread in one look.
        qsizetype stop = -1, lastStart = -1;
        const QList<QByteArray> frames = device.probe([&] {
            const QList<QByteArray> got = device.sim()->receivedFrames();
            for (qsizetype i = 0; i < got.size(); ++i) {
                if (stop < 0 && device.sim()->isStopFrame(got.at(i)))
                    stop = i;
                if (got.at(i).endsWith("A\r"))
                    lastStart = i;
            }
            return got;
        });
        QVERIFY2(stop >= 0, frames.join(' ').constData());
        QVERIFY2(lastStart < stop, frames.mid(stop - 3, 10).join(' ').constData());
    }
    // Stopped on its way round: neither at the start nor back at it.
    QVERIFY(device.position(Axis::X) != 0 || device.position(Axis::Y) != 0);
}

// The board refuses the second move (NAK): the run fails at that line with exit 4, the third
// never arrives. With the fault gone, --from-line of that line runs the rest.
void TestCliRunDevices::refusedBlock_failsAtItsLine_laterBlocksNeverArrive_thenFromLineRunsOn()
{
    RunDevice device(QStringLiteral("elab"));
    const QString path = writeProgram(*m_dir, "nak.ngc", "G91\nG0 X100\nG0 X200\nG0 X300\n");
    device.afterMove(1, [](Simulator* sim) { sim->faults().forceNak = 1; });
    CliRun r = runCli(cliArgs("elab", device.path()) + QStringList{"run", path});
    QVERIFY2(r.exitCode == 4, r.err.constData());
    QVERIFY2(r.err.contains("line 3"), r.err.constData());
    QList<DeviceMove> moves = device.moves();
    QCOMPARE(moves.size(), 1);
    QCOMPARE(moves.at(0).steps, qint64(100));
    QVERIFY(device.still());

    r = runCli(cliArgs("elab", device.path()) + QStringList{"run", path, "--from-line", "3"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    moves = device.moves();
    QCOMPARE(moves.size(), 3);
    QCOMPARE(moves.at(1).steps, qint64(200));
    QCOMPARE(moves.at(2).steps, qint64(300));
    QCOMPARE(device.position(), qint64(600)); // no reference run: the board counts from 0
}

// The port vanishes while a block's move runs: exit 6 naming the line, not a hang.
void TestCliRunDevices::linkLost_duringABlock_exit6NamesTheLine()
{
    RunDevice device(QStringLiteral("elab"));
    const QString path = writeProgram(*m_dir, "lost.ngc", "G91\nG0 X30000\nG0 X100\n");
    QProcess cli;
    cli.start(cliPath(), cliArgs("elab", device.path()) + QStringList{"run", path});
    QVERIFY(cli.waitForStarted(5000));
    QTRY_VERIFY_WITH_TIMEOUT(device.moving(), 20000);
    device.vanish();
    QVERIFY(cli.waitForFinished(20000));
    const QByteArray err = cli.readAllStandardError();
    QVERIFY2(cli.exitCode() == 6, err.constData());
    QVERIFY2(err.contains("line 2"), err.constData());
    QCOMPARE(device.moves().size(), 1);
}

// M66 P5 L3: EMIS' free input 5 goes high 1 s after the start; the move after it comes only
// then. M66 P6 with a Q the input never meets: exit 5, the move after it never arrives.
void TestCliRunDevices::waitInput_goesHighAfterASecond_runOnThenTimeoutExit5()
{
    RunDevice device(QStringLiteral("emis"));
    const QString path = writeProgram(*m_dir, "wait.ngc", "M66 P5 L3 Q10\nG91 G0 X100\n");
    const qint64 started = device.now();
    device.later(1000,
                 [](Simulator* sim) { static_cast<emis::EmisSimulator*>(sim)->setInput(5, true); });
    CliRun r = runCli(cliArgs("emis", device.path()) + QStringList{"run", path});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QList<DeviceMove> moves = device.moves();
    QCOMPARE(moves.size(), 1);
    QVERIFY2(moves.at(0).atMs - started >= 1000,
             qPrintable(QStringLiteral("%1 ms").arg(moves.at(0).atMs - started)));

    const QString timeout = writeProgram(*m_dir, "timeout.ngc", "M66 P6 L3 Q0.5\nG91 G0 X100\n");
    r = runCli(cliArgs("emis", device.path()) + QStringList{"run", timeout});
    QCOMPARE(r.exitCode, 5);
    QVERIFY2(r.err.contains("line 1"), r.err.constData());
    QCOMPARE(device.moves().size(), 1);
}

STEPDECK_TEST_GUILESS_MAIN(TestCliRunDevices)
#include "tst_cli_run_devices.moc"
