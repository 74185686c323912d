// stepdeck-cli run PROGRAM (issue 20; docs/cli.md "Motion programs"): what happens before a
// program moves anything -- parse errors, the check, M0 without a terminal, --dry-run -- and
// what a run prints. The E-LAB simulator is on a real pty in a thread of this process; every
// test asserts what the DEVICE received.
#include "CliRunRig.h"
#include "TestMain.h"
#include "protocols/elab/ElabSimulator.h"
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>
#include <csignal>

using namespace stepdeck;
using namespace stepdeck::test;

class TestCliRun : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void invalidProgram_everyErrorAsFileLineCol_exit7_nothingSent();
    void unreadableProgram_exit12_nothingSent();
    void checkError_outputTheMachineLacks_exit7_noMotion();
    void pause_withoutTerminal_exit2_nothingSent();
    void pause_skipPauses_runsThrough();
    void pause_onATerminal_waitsForEnter();
    void optionalStop_m1WithoutTerminal_exit2UnlessSwitchedOff_data();
    void optionalStop_m1WithoutTerminal_exit2UnlessSwitchedOff();
    void dryRun_json_previewFiguresNoMotion();
    void dryRun_human_linesExtentsDuration();
    void dryRun_toolTableAndOffsets_appliedToTheCheck();
    void dryRun_canon_motionCommandsAsRs274PrintsThemNoMotion();
    void dryRun_longProgramStderrATerminal_checkProgressShownThenErased();
    void run_progressLinePerBlockOnStderr();
    void run_json_eventPerBlockThenSummary();
    void fromLine_beyondTheFile_exit2();
    void linuxcncLanguage_workedOut_deviceMovesAndFileLines();
    void feedHold_signals_holdOverrideResumeAsJsonEvents();
    void feedAboveTheHighest_runsWithTheNoteOnStderr();
    void touchOff_m6_anotherToolRefusedTheSameGoesOnKeepingZ_data();
    void touchOff_m6_anotherToolRefusedTheSameGoesOnKeepingZ();

private:
    QStringList args(const QString& program, const QStringList& more = {}) const
    {
        return cliArgs(QStringLiteral("elab"), m_device->path()) + QStringList{"run", program} +
               more;
    }

    std::unique_ptr<RunDevice> m_device;
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestCliRun::initTestCase()
{
    QVERIFY2(!qEnvironmentVariableIsEmpty("STEPDECK_BIN_DIR"),
             "STEPDECK_BIN_DIR is not set (run through ctest)");
}

void TestCliRun::init()
{
    m_device = std::make_unique<RunDevice>(QStringLiteral("elab"));
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

void TestCliRun::cleanup()
{
    m_device.reset();
    m_dir.reset();
}

// Every wrong line as FILE:LINE:COL on stderr, before any link is opened: the board received
// not a single byte.
void TestCliRun::invalidProgram_everyErrorAsFileLineCol_exit7_nothingSent()
{
    const QString path =
        writeProgram(*m_dir, "bad.ngc", "G91\nD2\nG0 X10\nG0 X5 Q1\nG0 X1 G1 X2\n");
    const CliRun r = runCli(args(path));
    QCOMPARE(r.exitCode, 7);
    const QList<QByteArray> lines = r.err.trimmed().split('\n');
    QVERIFY2(lines.size() == 4, r.err.constData());
    QVERIFY2(lines.at(0).startsWith(path.toUtf8() + ":2:1: "), r.err.constData());
    QVERIFY2(lines.at(1).startsWith(path.toUtf8() + ":4:"), r.err.constData());
    QVERIFY2(lines.at(2).startsWith(path.toUtf8() + ":5:"), r.err.constData());
    QVERIFY2(lines.at(3).contains("nothing was sent"), r.err.constData());
    QCOMPARE(m_device->receivedCount(), 0);
}

void TestCliRun::unreadableProgram_exit12_nothingSent()
{
    const CliRun r = runCli(args(m_dir->filePath("missing.ngc")));
    QCOMPARE(r.exitCode, 12);
    QVERIFY2(r.err.contains("cannot read"), r.err.constData());
    QCOMPARE(m_device->receivedCount(), 0);
}

// Valid G-code the machine cannot run (E-LAB has no digital outputs): refused by the check
// with its line and column after connecting; the board received no motion.
void TestCliRun::checkError_outputTheMachineLacks_exit7_noMotion()
{
    const QString path = writeProgram(*m_dir, "out.ngc", "G91 G0 X10\nM64 P1\nG0 X10\n");
    const CliRun r = runCli(args(path));
    QCOMPARE(r.exitCode, 7);
    QVERIFY2(r.err.startsWith(path.toUtf8() + ":2:"), r.err.constData());
    QVERIFY(m_device->moves().isEmpty());
    QVERIFY(m_device->still());
}

// stdin of a QProcess is a pipe, not a terminal: M0 would wait for nobody.
void TestCliRun::pause_withoutTerminal_exit2_nothingSent()
{
    const QString path =
        writeProgram(*m_dir, "pause.ngc", "G91 G0 X10\nM0 (check the part)\nG0 X10\n");
    const CliRun r = runCli(args(path));
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("line 2") && r.err.contains("--skip-pauses"), r.err.constData());
    QCOMPARE(m_device->receivedCount(), 0);
}

void TestCliRun::pause_skipPauses_runsThrough()
{
    const QString path =
        writeProgram(*m_dir, "pause.ngc", "G91 G0 X10\nM0 (check the part)\nG0 X20\n");
    const CliRun r = runCli(args(path, {"--skip-pauses"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QList<DeviceMove> moves = m_device->moves();
    QCOMPARE(moves.size(), 2);
    QCOMPARE(moves.at(0).steps, qint64(10));
    QCOMPARE(moves.at(1).steps, qint64(20));
}

// Issue 29: M1 holds like M0 with optional stops on (the default), so without a terminal it is
// refused before anything is sent; --optional-stops off runs past it. Anything but on/off is a
// usage error.
void TestCliRun::optionalStop_m1WithoutTerminal_exit2UnlessSwitchedOff_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QByteArray>("says");
    QTest::newRow("default: on") << QStringList{} << 2 << QByteArray("line 2 holds M1");
    QTest::newRow("on") << QStringList{"--optional-stops", "on"} << 2
                        << QByteArray("--optional-stops off passes it");
    QTest::newRow("off") << QStringList{"--optional-stops=off"} << 0 << QByteArray();
    QTest::newRow("maybe") << QStringList{"--optional-stops", "maybe"} << 2
                           << QByteArray("run --optional-stops takes on or off, got 'maybe'");
}

void TestCliRun::optionalStop_m1WithoutTerminal_exit2UnlessSwitchedOff()
{
    QFETCH(QStringList, options);
    QFETCH(int, exitCode);
    QFETCH(QByteArray, says);
    const QString path = writeProgram(*m_dir, "optional.ngc", "G91 G0 X10\nM1 (look)\nG0 X20\n");
    const CliRun r = runCli(args(path, options));
    QVERIFY2(r.exitCode == exitCode, r.err.constData());
    QVERIFY2(r.err.contains(says), r.err.constData());
    if (exitCode != 0) {
        QCOMPARE(m_device->receivedCount(), 0);
        return;
    }
    const QList<DeviceMove> moves = m_device->moves();
    QCOMPARE(moves.size(), 2);
    QCOMPARE(moves.at(0).steps, qint64(10));
    QCOMPARE(moves.at(1).steps, qint64(20));
}

// Issue 50 item 1: a feed far above what the E-LAB's contour stream runs (10^5 steps/s; the
// board's default tick runs 99 a second) is not
// refused: the run says, as FILE:LINE:COL: note, the F it runs at, and the board goes the whole
// way (the ticks at the board: tst_programcontour); with --json the note is an event.
void TestCliRun::feedAboveTheHighest_runsWithTheNoteOnStderr()
{
    const QString path = writeProgram(*m_dir, "fast.ngc", "G91 G1 X200 F6000000\nM2\n");
    const qint64 before = m_device->position(Axis::X);
    const CliRun r = runCli(args(path));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.err.contains(path.toUtf8() + ":1:13: note: F6000000 runs at F"), r.err.constData());
    QVERIFY2(r.err.contains("the highest this move can run at in the contour stream"),
             r.err.constData());
    QTRY_VERIFY_WITH_TIMEOUT(m_device->still(), 5000);
    QCOMPARE(m_device->position(Axis::X) - before, qint64(200));
    const CliRun json = runCli(args(path, {"--dry-run"}) << "--json");
    QVERIFY2(json.exitCode == 0, json.err.constData());
    QVERIFY2(json.out.contains(R"("event":"note")"), json.out.constData());
}

// stdin a terminal (a pty): M0 prints its prompt and holds until Enter; the board gets the
// next block only then.
void TestCliRun::pause_onATerminal_waitsForEnter()
{
    PtyEndpoint terminal;
    QVERIFY(terminal.create());
    const QString path =
        writeProgram(*m_dir, "pause.ngc", "G91 G0 X10\nM0 (load the part)\nG0 X20\n");
    QProcess cli;
    QByteArray err;
    connect(&cli, &QProcess::readyReadStandardError, this,
            [&] { err += cli.readAllStandardError(); });
    cli.setStandardInputFile(terminal.slavePath());
    cli.start(cliPath(), args(path));
    QVERIFY(cli.waitForStarted(5000));
    QTRY_VERIFY2_WITH_TIMEOUT(err.contains("load the part"), err.constData(), 20000);
    QVERIFY2(err.contains("line 2"), err.constData());
    QCOMPARE(m_device->moves().size(), 1); // paused: the block after M0 is not sent
    QVERIFY(cli.state() == QProcess::Running);
    terminal.write("\n");
    QTRY_COMPARE_WITH_TIMEOUT(cli.state(), QProcess::NotRunning, 20000);
    QVERIFY2(cli.exitCode() == 0, err.constData());
    const QList<DeviceMove> moves = m_device->moves();
    QCOMPARE(moves.size(), 2);
    QCOMPARE(moves.at(1).steps, qint64(20));
}

// The preview's figures; the board gets no motion at all (no reference run either).
void TestCliRun::dryRun_json_previewFiguresNoMotion()
{
    const QString path = writeProgram(
        *m_dir, "dry.ngc",
        "G28 X0\nG0 X200\nO1 repeat [3]\n  G0 X50\n  G0 X120\nO1 endrepeat\nG4 P0.5\nM2\n");
    const CliRun r = runCli(args(path, {"--dry-run", "--json"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject preview = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(preview.value("event").toString(), QStringLiteral("preview"));
    QCOMPARE(preview.value("lines").toInt(), 8);
    QVERIFY2(preview.value("blocks").toInteger() >= 9, r.out.constData()); // repeats counted out
    const QJsonObject x = preview.value("extents").toObject().value("X").toObject();
    QCOMPARE(x.value("minimum").toDouble(), 0.0);
    QCOMPARE(x.value("maximum").toDouble(), 200.0);
    QVERIFY(x.value("moved").toBool());
    QCOMPARE(x.value("unit").toString(), QStringLiteral("steps"));
    QVERIFY(preview.value("estimatedSeconds").toDouble() >= 0.5); // at least the dwell
    QVERIFY(m_device->moves().isEmpty());
    QCOMPARE(m_device->position(), qint64(0));
    QVERIFY(m_device->still());
}

// stderr a terminal (a pty): a long program's reading and check say how far they are ("reading
// FILE: n %", "checking FILE: n %", each over the last on one line) and erases that line before
// what follows; with stderr a pipe (a log, a script) it says nothing of the kind.
void TestCliRun::dryRun_longProgramStderrATerminal_checkProgressShownThenErased()
{
    QByteArray text;
    for (int i = 0; i < 200000; ++i)
        text += "G4 P0\n";
    text += "M2\n";
    const QString path = writeProgram(*m_dir, "long.ngc", text);
    PtyEndpoint terminal;
    QVERIFY(terminal.create());
    QByteArray shown;
    connect(&terminal, &Transport::dataReceived, this,
            [&](const QByteArray& bytes) { shown += bytes; });
    QProcess cli;
    cli.setStandardErrorFile(terminal.slavePath());
    cli.start(cliPath(), args(path, {"--dry-run"}));
    QVERIFY(cli.waitForStarted(5000));
    QTRY_COMPARE_WITH_TIMEOUT(cli.state(), QProcess::NotRunning, 60000);
    QCOMPARE(cli.exitCode(), 0);
    QTRY_VERIFY2(shown.contains("\r\033[K"), shown.right(200).constData()); // erased at the end
    // Read first (the parser), then checked against the machine.
    const QByteArray name = QFileInfo(path).fileName().toUtf8();
    QVERIFY2(shown.contains("\rreading ") && shown.contains(name + ": "),
             shown.left(300).constData());
    QVERIFY2(shown.indexOf("\rchecking ") > shown.indexOf("\rreading "),
             shown.left(300).constData());
    int steps = 0; // distinct figures, each written over the last with a carriage return
    for (qsizetype at = shown.indexOf("\rchecking "); at >= 0;
         at = shown.indexOf("\rchecking ", at + 1))
        ++steps;
    QVERIFY2(steps >= 2, shown.left(300).constData());
    // The same check with stderr a pipe: no progress at all.
    const CliRun piped = runCli(args(path, {"--dry-run"}));
    QCOMPARE(piped.exitCode, 0);
    QVERIFY2(!piped.err.contains(" %") && !piped.err.contains('\r'), piped.err.constData());
}

void TestCliRun::dryRun_human_linesExtentsDuration()
{
    const QString path = writeProgram(*m_dir, "dry.ngc", "G28 X0\nG0 X200\nG0 X50\n");
    const CliRun r = runCli(args(path, {"--dry-run"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.out.contains("3 lines"), r.out.constData());
    QVERIFY2(r.out.contains("X: 0.000 .. 200.000 steps"), r.out.constData());
    QVERIFY2(r.out.contains("estimated duration"), r.out.constData());
    QVERIFY(m_device->moves().isEmpty());
}

// Issue 49: --canon prints the motion commands the check's walk lowers, repeats counted out
// (the repeat's G0 twice); Y and Z, never referenced, are not known. Worked out by hand: the
// E-LAB's axes X Y Z in steps, so the program's units change nothing. Nothing reaches the board.
// --canon without --dry-run is a usage error.
void TestCliRun::dryRun_canon_motionCommandsAsRs274PrintsThemNoMotion()
{
    const QString path = writeProgram(
        *m_dir, "canon.ngc", "G28 X0\nO1 repeat [2]\n  G0 X100\nO1 endrepeat\nG4 P0.5\nM2\n");
    const CliRun r = runCli(args(path, {"--dry-run", "--canon"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QByteArray expected = "    1 N00001 USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
                                "    2 N00001 SELECT_PLANE(CANON_PLANE_XY)\n"
                                "    3 N00001 REFERENCE_AXES(X)\n"
                                "    4 N00003 STRAIGHT_TRAVERSE(100.0000, ?, ?)\n"
                                "    5 N00003 STRAIGHT_TRAVERSE(100.0000, ?, ?)\n"
                                "    6 N00005 DWELL(0.5000)\n"
                                "    7 N00006 STOP_SPINDLE_TURNING(0)\n"
                                "    8 N00006 MIST_OFF()\n"
                                "    9 N00006 FLOOD_OFF()\n"
                                "   10 N00006 PROGRAM_END()\n";
    QCOMPARE(r.out, expected);
    QVERIFY(m_device->moves().isEmpty());
    QVERIFY(m_device->still());

    const CliRun alone = runCli(args(path, {"--canon"}));
    QCOMPARE(alone.exitCode, 2);
    QVERIFY2(alone.err.contains("--canon needs --dry-run"), alone.err.constData());
    QVERIFY(m_device->moves().isEmpty());
}

// Issue 29: --offsets gives G55 its work zero and --tool-table G43 its length; without them the
// check refuses the H the table lacks; a malformed table or offset is named, nothing is sent.
void TestCliRun::dryRun_toolTableAndOffsets_appliedToTheCheck()
{
    const QString path =
        writeProgram(*m_dir, "cam.ngc", "G28 X0 Z0\nG55 G0 X100\nG43 H1\nG0 Z0\nM2\n");
    const QString tools = writeProgram(*m_dir, "tool.tbl", "T1 Z-50 ;probe\n");
    const CliRun r =
        runCli(args(path, {"--dry-run", "--json", "--tool-table", tools, "--offsets", "G55:X=20"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject extents = QJsonDocument::fromJson(r.out).object().value("extents").toObject();
    QCOMPARE(extents.value("X").toObject().value("maximum").toDouble(), 120.0);
    QCOMPARE(extents.value("Z").toObject().value("minimum").toDouble(), -50.0);
    const CliRun bare = runCli(args(path, {"--dry-run"}));
    QCOMPARE(bare.exitCode, 7);
    QVERIFY2(bare.err.contains("3:5: G43: the machine's tool table is empty"),
             bare.err.constData());
    const CliRun badOffset = runCli(args(path, {"--dry-run", "--offsets", "G55:Q=20"}));
    QCOMPARE(badOffset.exitCode, 2);
    QVERIFY2(badOffset.err.contains("'Q=20' is not AXIS=NUMBER"), badOffset.err.constData());
    const QString broken = writeProgram(*m_dir, "broken.tbl", "T1 Zx\n");
    const CliRun badTable = runCli(args(path, {"--dry-run", "--tool-table", broken}));
    QCOMPARE(badTable.exitCode, 7);
    QVERIFY2(badTable.err.contains("is not a tool table"), badTable.err.constData());
    QVERIFY(m_device->moves().isEmpty());
}

// Issue 33: a loop with parameters runs its passes (the board saw each move's steps) and the
// progress names the file's lines; a runaway loop is refused before anything is sent.
void TestCliRun::linuxcncLanguage_workedOut_deviceMovesAndFileLines()
{
    const QString path = writeProgram(*m_dir, "loop.ngc",
                                      "G28 X0\n#<step>=40\nG91\no1 repeat [3]\n  G0 X#<step>\n"
                                      "  #<step>=[#<step>+10]\no1 endrepeat\nM2\n");
    const CliRun r = runCli(args(path));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.err.contains("line 5/8: G0 X40\n") && r.err.contains("line 5/8: G0 X50\n") &&
                 r.err.contains("line 5/8: G0 X60\n"),
             r.err.constData());
    QList<qint64> steps;
    for (const DeviceMove& m : m_device->moves())
        if (m.axis == Axis::X)
            steps << m.steps;
    QVERIFY2(steps.size() >= 3, qPrintable(QString::number(steps.size())));
    QCOMPARE(steps.mid(steps.size() - 3), QList<qint64>({40, 50, 60}));

    m_device = std::make_unique<RunDevice>(QStringLiteral("elab"));
    const QString runaway =
        writeProgram(*m_dir, "runaway.ngc", "G91\no7 while [1]\n  #1=[#1+1]\no7 endwhile\n");
    const CliRun refused = runCli(args(runaway));
    QCOMPARE(refused.exitCode, 7);
    QVERIFY2(refused.err.contains(runaway.toUtf8() + ":2:1: O7 while (line 2) has run 1000000"),
             refused.err.constData());
    QCOMPARE(m_device->receivedCount(), 0);
}

void TestCliRun::run_progressLinePerBlockOnStderr()
{
    const QString path = writeProgram(*m_dir, "p.ngc", "; two moves\nG91\nG0 X10\nG0 X-10\n");
    const CliRun r = runCli(args(path));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.err.contains("line 3/4: G0 X10\n"), r.err.constData());
    QVERIFY2(r.err.contains("line 4/4: G0 X-10\n"), r.err.constData());
    QVERIFY2(r.out.startsWith("finished: 2 blocks"), r.out.constData());
    QCOMPARE(m_device->moves().size(), 2);
}

void TestCliRun::run_json_eventPerBlockThenSummary()
{
    const QString path = writeProgram(*m_dir, "j.ngc", "G91\nG0 X10\nG4 P0.05\nG0 X-10\nM2\n");
    const CliRun r = runCli(args(path, {"--json"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY2(r.err.isEmpty(), r.err.constData());
    QList<int> doneLines;
    QJsonObject summary;
    for (const QByteArray& line : r.out.trimmed().split('\n')) {
        const QJsonObject event = QJsonDocument::fromJson(line).object();
        QVERIFY2(!event.isEmpty(), line.constData());
        if (event.value("event").toString() == QLatin1String("block")) {
            QCOMPARE(event.value("state").toString(), QStringLiteral("done"));
            doneLines << event.value("line").toInt();
        } else if (event.value("event").toString() == QLatin1String("summary")) {
            summary = event;
        }
    }
    QVERIFY2(doneLines.mid(0, 3) == QList<int>({2, 3, 4}), r.out.constData());
    QCOMPARE(summary.value("state").toString(), QStringLiteral("finished"));
    QCOMPARE(summary.value("exitCode").toInt(-1), 0);
    QCOMPARE(m_device->moves().size(), 2);
}

void TestCliRun::fromLine_beyondTheFile_exit2()
{
    const QString path = writeProgram(*m_dir, "f.ngc", "G91\nG0 X10\n");
    const CliRun r = runCli(args(path, {"--from-line", "9"}));
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(m_device->receivedCount(), 0);
}

// Issue 30: a contour (G1 in G64: one <DC2> stream) held by Ctrl-Z's SIGTSTP stops on its path
// at the board, the process itself running on (it reports); SIGUSR1 raises the override by
// 10 %; SIGCONT resumes and the contour ends exactly at its end. Each as a JSON event.
void TestCliRun::feedHold_signals_holdOverrideResumeAsJsonEvents()
{
    // 40 steps at 50 steps/s (F3000 steps/min): 0.8 s, below the stream's 99 ticks/s.
    const QString path = writeProgram(*m_dir, "hold.ngc", "G91 G64\nG1 X40 F3000\nM2\n");
    QProcess cli;
    QByteArray out, err;
    connect(&cli, &QProcess::readyReadStandardOutput, this,
            [&] { out += cli.readAllStandardOutput(); });
    connect(&cli, &QProcess::readyReadStandardError, this,
            [&] { err += cli.readAllStandardError(); });
    cli.start(cliPath(), args(path, {"--json", "--feed-override", "100"}));
    QVERIFY(cli.waitForStarted(5000));
    const auto x = [&] {
        return m_device->probe([&] { return m_device->sim()->position(Axis::X); });
    };
    QTRY_VERIFY2_WITH_TIMEOUT(x() >= 3, err.constData(), 20000);
    ::kill(pid_t(cli.processId()), SIGTSTP);
    QTRY_VERIFY2_WITH_TIMEOUT(out.contains("\"event\":\"hold\""), out.constData(), 10000);
    QVERIFY(out.contains("\"contour\":true"));
    // The board runs what it holds, then stands: its buffer empty, X the same twice.
    qint64 stood = -1;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            const qint64 now = x();
            const int buffered = m_device->probe([&] {
                return static_cast<elab::ElabSimulator*>(m_device->sim())->streamBuffered();
            });
            return std::exchange(stood, now) == now && buffered == 0;
        }(),
        5000);
    // The process still runs and reads the board (its status polls arrive); the board stays.
    const int frames = m_device->receivedCount();
    QTRY_VERIFY_WITH_TIMEOUT(m_device->receivedCount() >= frames + 3, 10000);
    QCOMPARE(x(), stood);
    QVERIFY(stood < 40);
    QCOMPARE(cli.state(), QProcess::Running);
    ::kill(pid_t(cli.processId()), SIGUSR1);
    QTRY_VERIFY2_WITH_TIMEOUT(out.contains("\"event\":\"override\",\"percent\":110"),
                              out.constData(), 10000);
    ::kill(pid_t(cli.processId()), SIGCONT);
    QTRY_VERIFY2_WITH_TIMEOUT(out.contains("\"event\":\"resume\""), out.constData(), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(cli.state(), QProcess::NotRunning, 20000);
    QVERIFY2(cli.exitCode() == 0, err.constData());
    QCOMPARE(x(), qint64(40));
    QVERIFY2(out.contains("\"state\":\"finished\""), out.constData());
}

// Issue 50 item 4: with "toolLength": "touchOff" in the machine file an M6 holds until the work Z
// is set for the new tool, which the CLI cannot do: an M6 of another tool than the one before
// it is refused before anything is opened (exit 2, its line and tool named), also with
// --skip-pauses. The run's first M6 and the same tool again go on with Z as it is: passed with
// --skip-pauses, refused without a terminal like M0 (naming the tool too).
void TestCliRun::touchOff_m6_anotherToolRefusedTheSameGoesOnKeepingZ_data()
{
    QTest::addColumn<QByteArray>("program");
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QByteArray>("says");
    QTest::addColumn<QList<qint64>>("moves"); // X's steps at the board
    const QByteArray twoTools =
        "T1 M6 (3 mm drill)\nG91 G0 X10\nT2 M6 (6 mm end mill)\nG0 X20\nM2\n";
    const QByteArray oneTool = "T1 M6 (3 mm drill)\nG91 G0 X10\nT1 M6\nG0 X20\nM2\n";
    const QByteArray refusal = "run: line 3 holds M6 \"Load tool 2 (6 mm end mill)\" with tool "
                               "lengths by touch-off";
    QTest::newRow("another tool, --skip-pauses")
        << twoTools << QStringList{"--skip-pauses"} << 2 << refusal << QList<qint64>{};
    QTest::newRow("another tool, no terminal")
        << twoTools << QStringList{} << 2 << refusal << QList<qint64>{};
    QTest::newRow("the same tool, --skip-pauses")
        << oneTool << QStringList{"--skip-pauses"} << 0
        << QByteArray("line 1: tool change passed with the work Z as it is (--skip-pauses)")
        << QList<qint64>{10, 20};
    QTest::newRow("the same tool, no terminal")
        << oneTool << QStringList{} << 2
        << QByteArray("run: line 1 holds M6 \"Load tool 1 (3 mm drill)\", which waits for Enter")
        << QList<qint64>{};
    // The other families (item 4 at each): the same workflow, the same moves at their devices.
    for (const char* model : {"emis", "nanotec"})
        QTest::newRow(QByteArray("the same tool, --skip-pauses, ").append(model).constData())
            << oneTool << QStringList{"--skip-pauses", "--model-under-test", model} << 0
            << QByteArray("line 1: tool change passed with the work Z as it is (--skip-pauses)")
            << QList<qint64>{10, 20};
    // The laser axes move to targets only: X is homed first so that G91 knows where it starts.
    QTest::newRow("the same tool, --skip-pauses, laser-axis")
        << "G28 X0\n" + oneTool << QStringList{"--skip-pauses", "--model-under-test", "laser-axis"}
        << 0 << QByteArray("line 2: tool change passed with the work Z as it is (--skip-pauses)")
        << QList<qint64>{10, 20};
}

void TestCliRun::touchOff_m6_anotherToolRefusedTheSameGoesOnKeepingZ()
{
    QFETCH(QByteArray, program);
    QFETCH(QStringList, options);
    QFETCH(int, exitCode);
    QFETCH(QByteArray, says);
    QFETCH(QList<qint64>, moves);
    // "--model-under-test M" (this test's own, taken out): the controller family, E-LAB if not.
    QString model = QStringLiteral("elab");
    if (const qsizetype at = options.indexOf(QStringLiteral("--model-under-test")); at >= 0) {
        model = options.at(at + 1);
        options.remove(at, 2);
    }
    const bool nanotec = model == QLatin1String("nanotec");
    std::unique_ptr<RunDevice> own;
    RunDevice* device = m_device.get();
    if (model != QLatin1String("elab")) {
        own = std::make_unique<RunDevice>(model, nanotec ? QList<int>{1, 3} : QList<int>{1});
        device = own.get();
    }
    QJsonObject controller{{"id", "table"}, {"model", model}, {"port", device->path()}};
    if (nanotec)
        controller.insert("axes", QJsonArray{QJsonObject{{"name", "X"}, {"address", 1}},
                                             QJsonObject{{"name", "Z"}, {"address", 3}}});
    const QJsonObject machine{
        {"format", "stepdeck-machine"},
        {"version", 2},
        {"name", "Touch-off mill"},
        {"controllers", QJsonArray{controller}},
        {"axes",
         QJsonArray{
             QJsonObject{{"name", "X"}, {"controller", "table"}, {"axis", "X"}, {"unit", "steps"}},
             QJsonObject{
                 {"name", "Z"}, {"controller", "table"}, {"axis", "Z"}, {"unit", "steps"}}}},
        {"toolLength", "touchOff"}};
    const QString file = writeProgram(*m_dir, "touchoff.json", QJsonDocument(machine).toJson());
    const QString path = writeProgram(*m_dir, "tools.ngc", program);
    QStringList args{"--machine", file, "--timeout", "10000"};
    if (model == QLatin1String("elab"))
        args << "--setup-defaults";
    const CliRun r = runCli(args + QStringList{"run", path} + options);
    QVERIFY2(r.exitCode == exitCode, r.err.constData());
    QVERIFY2(r.err.contains(says), r.err.constData());
    if (exitCode != 0) {
        QCOMPARE(device->receivedCount(), 0);
        return;
    }
    QList<qint64> steps;
    for (const DeviceMove& m : device->moves())
        if (m.axis == Axis::X)
            steps << m.steps;
    QCOMPARE(steps, moves);
    QVERIFY(device->still());
}

STEPDECK_TEST_GUILESS_MAIN(TestCliRun)
#include "tst_cli_run.moc"
