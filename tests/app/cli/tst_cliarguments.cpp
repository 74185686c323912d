// stepdeck-cli's command line (issue 10): QCommandLineParser for the global options and each
// command's own (the real command table, commandSyntax()), decimal numbers from NumberParsing.
#include "CliArguments.h"
#include "CliCommands.h"
#include "TestMain.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::cli;

namespace {
// The command's own options as "name=value" ("name=" for a flag), sorted.
QStringList ownOptions(const CliOptions& options)
{
    QStringList out;
    for (auto it = options.commandOptions.cbegin(); it != options.commandOptions.cend(); ++it)
        out << it.key() + QLatin1Char('=') + it.value();
    return out;
}
} // namespace

class TestCliArguments : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_goodInvocations_data();
    void parse_goodInvocations();
    void parse_usageErrors_data();
    void parse_usageErrors();
    void parse_globalValues();
    void parse_misspelledNames_suggestNearest_data();
    void parse_misspelledNames_suggestNearest();
    void axisValues_unknownAxis_namesItAndTheAxes_data();
    void axisValues_unknownAxis_namesItAndTheAxes();
    void axisValues_decimalOnly_data();
    void axisValues_decimalOnly();
};

void TestCliArguments::parse_goodInvocations_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QStringList>("positional");
    QTest::addColumn<QStringList>("own");
    QTest::addColumn<QString>("port");
    QTest::addColumn<bool>("json");
    QTest::addColumn<int>("connectTimeoutMs");

    const QStringList none;
    QTest::newRow("command only") << QStringList{"status"} << "status" << none << none << "sim"
                                  << false << 3000;
    QTest::newRow("globals before the command")
        << QStringList{"--port", "/dev/ttyUSB0", "--json", "status"} << "status" << none << none
        << "/dev/ttyUSB0" << true << 3000;
    QTest::newRow("globals after the command, --name=value")
        << QStringList{"status", "--json", "--port=/dev/ttyS1"} << "status" << none << none
        << "/dev/ttyS1" << true << 3000;
    QTest::newRow("later global wins") << QStringList{"--port", "a", "status", "--port", "b"}
                                       << "status" << none << none << "b" << false << 3000;
    QTest::newRow("--timeout before move: the link's")
        << QStringList{"--timeout", "500", "move", "X=1"} << "move" << QStringList{"X=1"} << none
        << "sim" << false << 500;
    QTest::newRow("--timeout after move: the motion's")
        << QStringList{"move", "X=1", "--timeout", "700"} << "move" << QStringList{"X=1"}
        << QStringList{"timeout=700"} << "sim" << false << 3000;
    QTest::newRow("--timeout after status: the link's")
        << QStringList{"status", "--timeout", "700"} << "status" << none << none << "sim" << false
        << 700;
    QTest::newRow("leading zero is decimal") << QStringList{"--timeout", "0100", "status"}
                                             << "status" << none << none << "sim" << false << 100;
    QTest::newRow("move flags between axes")
        << QStringList{"move", "--abs", "X=1", "--no-wait", "Y=-2"} << "move"
        << QStringList{"X=1", "Y=-2"} << QStringList{"abs=", "no-wait="} << "sim" << false << 3000;
    QTest::newRow("jog --for=MS") << QStringList{"jog", "X=1.5e3", "--for=200"} << "jog"
                                  << QStringList{"X=1.5e3"} << QStringList{"for=200"} << "sim"
                                  << false << 3000;
    QTest::newRow("program with a title")
        << QStringList{"program", "8", "--title", "Eingang 8: Vektorfahrt", "L1,x191", "W1500"}
        << "program" << QStringList{"8", "L1,x191", "W1500"}
        << QStringList{"title=Eingang 8: Vektorfahrt"} << "sim" << false << 3000;
    QTest::newRow("scan range") << QStringList{"scan", "--first", "3", "--last=9"} << "scan" << none
                                << QStringList{"first=3", "last=9"} << "sim" << false << 3000;
    QTest::newRow("-- ends the options")
        << QStringList{"power", "--", "-5", "--json"} << "power" << QStringList{"-5", "--json"}
        << none << "sim" << false << 3000;
    QTest::newRow("negative numbers are arguments")
        << QStringList{"output", "-1", "on", "--json", "-.5"} << "output"
        << QStringList{"-1", "on", "-.5"} << none << "sim" << true << 3000;
    QTest::newRow("laser-bridge options")
        << QStringList{"laser-bridge", "/dev/ttyUSB1", "--map", "1=X", "--scale", "10"}
        << "laser-bridge" << QStringList{"/dev/ttyUSB1"} << QStringList{"map=1=X", "scale=10"}
        << "sim" << false << 3000;
    QTest::newRow("run with its options")
        << QStringList{"run",       "part.ngc", "--from-line",  "12",
                       "--dry-run", "--json",   "--skip-pauses"}
        << "run" << QStringList{"part.ngc"}
        << QStringList{"dry-run=", "from-line=12", "skip-pauses="} << "sim" << true << 3000;
    QTest::newRow("run --optional-stops")
        << QStringList{"run", "part.ngc", "--optional-stops", "off", "--from-line=3"} << "run"
        << QStringList{"part.ngc"} << QStringList{"from-line=3", "optional-stops=off"} << "sim"
        << false << 3000;
    QTest::newRow("run --block-delete")
        << QStringList{"run", "part.ngc", "--block-delete", "off"} << "run"
        << QStringList{"part.ngc"} << QStringList{"block-delete=off"} << "sim" << false << 3000;
}

void TestCliArguments::parse_goodInvocations()
{
    QFETCH(QStringList, args);
    CliOptions options;
    QString error;
    QVERIFY2(parseArguments(QStringList{"stepdeck-cli"} + args, commandSyntax(), &options, &error),
             qPrintable(error));
    QTEST(options.command, "command");
    QTEST(options.args, "positional");
    QTEST(ownOptions(options), "own");
    QTEST(options.port, "port");
    QTEST(options.json, "json");
    QTEST(options.connectTimeoutMs, "connectTimeoutMs");
}

void TestCliArguments::parse_usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("needle");

    QTest::newRow("no command") << QStringList{} << "no command given";
    QTest::newRow("unknown command") << QStringList{"frobnicate"} << "unknown command 'frobnicate'";
    QTest::newRow("unknown option before the command")
        << QStringList{"--bogus", "status"} << "unknown option '--bogus'";
    QTest::newRow("unknown option after the command")
        << QStringList{"status", "--bogus=1"} << "unknown option '--bogus'";
    QTest::newRow("unknown short option") << QStringList{"status", "-x"} << "unknown option '-x'";
    QTest::newRow("option of another command: status --for")
        << QStringList{"status", "--for", "5"} << "unknown option '--for'";
    QTest::newRow("option of another command: home --abs")
        << QStringList{"home", "--abs", "X=1"} << "unknown option '--abs'";
    QTest::newRow("command option before the command")
        << QStringList{"--no-wait", "move", "X=1"} << "unknown option '--no-wait'";
    QTest::newRow("missing value of a global option")
        << QStringList{"status", "--port"} << "missing value after '--port'";
    QTest::newRow("missing value of a command option")
        << QStringList{"jog", "X=1", "--for"} << "missing value after '--for'";
    QTest::newRow("run --from-line without its line")
        << QStringList{"run", "part.ngc", "--from-line"} << "missing value after '--from-line'";
    QTest::newRow("value for a flag") << QStringList{"--json=yes", "status"} << "--json";
    QTest::newRow("timeout not a number")
        << QStringList{"--timeout", "x", "status"} << "--timeout needs a positive number";
    QTest::newRow("timeout hex") << QStringList{"status", "--timeout", "0x10"}
                                 << "--timeout needs a positive number";
    QTest::newRow("timeout zero") << QStringList{"--timeout", "0", "status"}
                                  << "--timeout needs a positive number";
    QTest::newRow("arrival-timeout nan") << QStringList{"--arrival-timeout", "nan", "status"}
                                         << "--arrival-timeout needs a positive number";
    QTest::newRow("arrival-timeout inf") << QStringList{"--arrival-timeout", "inf", "status"}
                                         << "--arrival-timeout needs a positive number";
    QTest::newRow("address negative")
        << QStringList{"--address", "-1", "status"} << "--address needs a non-negative number";
    QTest::newRow("address -1 after the command")
        << QStringList{"status", "--address", "-1"}
        << "--address needs a non-negative number, got '-1'";
    QTest::newRow("dash word is no number") << QStringList{"output", "-x"} << "unknown option '-x'";
    QTest::newRow("address fraction")
        << QStringList{"--address", "2.5", "status"} << "--address needs a non-negative number";
    QTest::newRow("axes not a number") << QStringList{"--axes", "X=abc", "status"}
                                       << "--axes: X: 'abc' is not a whole bus address";
    QTest::newRow("axes nan") << QStringList{"--axes", "X=nan", "status"} << "--axes: X:";
    QTest::newRow("axes unknown axis")
        << QStringList{"--axes", "Q=1", "status"} << "--axes: 'Q' is not an axis name";
    QTest::newRow("axes not an assignment")
        << QStringList{"--axes", "feeder", "status"} << "expected NAME=ADDRESS";
    QTest::newRow("axes name twice")
        << QStringList{"--axes", "feeder=5,FEEDER=6", "status"} << "--axes: FEEDER is given twice";
    QTest::newRow("address and axes")
        << QStringList{"--address", "2", "--axes", "X=1", "status"} << "either --address or --axes";
    QTest::newRow("reset line") << QStringList{"--reset-line", "cts", "reset"}
                                << "--reset-line needs rts or dtr";
    QTest::newRow("machine and port")
        << QStringList{"--machine", "m.json", "--port", "/dev/ttyUSB0", "status"}
        << "either --machine or --model";
    QTest::newRow("machine and model after the command")
        << QStringList{"--machine", "m.json", "status", "--model", "nanotec"}
        << "either --machine or --model";
    QTest::newRow("machine and axes")
        << QStringList{"--machine", "m.json", "--axes", "X=1", "status"} << "either --machine";
    QTest::newRow("controller without machine")
        << QStringList{"--controller", "table", "get", "speed"} << "--controller needs --machine";
}

void TestCliArguments::parse_usageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QString, needle);
    CliOptions options;
    QString error;
    QVERIFY(!parseArguments(QStringList{"stepdeck-cli"} + args, commandSyntax(), &options, &error));
    QVERIFY2(error.contains(needle), qPrintable(error));
    QVERIFY2(!error.contains(QLatin1Char('\n')), qPrintable(error));
}

void TestCliArguments::parse_globalValues()
{
    CliOptions options;
    QString error;
    QVERIFY2(
        parseArguments({"stepdeck-cli", "--model", "nanotec", "--axes", "X=1,Y=02", "-v", "status",
                        "--reset-line", "dtr", "--arrival-timeout=900", "--setup-defaults"},
                       commandSyntax(), &options, &error),
        qPrintable(error));
    QCOMPARE(options.model, QStringLiteral("nanotec"));
    QCOMPARE(options.axisAddresses, (QMap<Axis, int>{{Axis::X, 1}, {Axis::Y, 2}}));
    QVERIFY(options.verbose);
    QVERIFY(options.setupDefaults);
    QCOMPARE(options.resetLine, LineSettings::ResetLine::Dtr);
    QCOMPARE(options.arrivalTimeoutMs, 900);
    QVERIFY(!options.address);
    QVERIFY(options.axisNames.isEmpty());

    // Issue 32: names for the drives, in order.
    CliOptions named;
    QVERIFY2(parseArguments({"stepdeck-cli", "--model", "nanotec", "--axes",
                             "feeder=5,gate=6,axis5=9", "status"},
                            commandSyntax(), &named, &error),
             qPrintable(error));
    QCOMPARE(named.axisAddresses, (QMap<Axis, int>{{Axis::X, 5}, {Axis::Y, 6}, {Axis::at(4), 9}}));
    QCOMPARE(named.axisNames.name(Axis::X), QStringLiteral("feeder"));
    QCOMPARE(named.axisNames.name(Axis::Y), QStringLiteral("gate"));
    QCOMPARE(named.axisNames.name(Axis::at(4)), QStringLiteral("axis5"));

    for (const QStringList& args :
         {QStringList{"--help"}, QStringList{"status", "-h"}, QStringList{"--version"}}) {
        CliOptions shown;
        QVERIFY2(
            parseArguments(QStringList{"stepdeck-cli"} + args, commandSyntax(), &shown, &error),
            qPrintable(error));
        QVERIFY2(shown.help || shown.version, qPrintable(args.join(' ')));
    }
}

void TestCliArguments::parse_misspelledNames_suggestNearest_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected"); // the whole message

    QTest::newRow("command, swapped letters")
        << QStringList{"stauts"} << "unknown command 'stauts' (did you mean status?)";
    QTest::newRow("command, letter missing")
        << QStringList{"mve", "X=1"} << "unknown command 'mve' (did you mean move?)";
    QTest::newRow("command, prefix") << QStringList{"laser", "/dev/ttyS0"}
                                     << "unknown command 'laser' (did you mean laser-bridge?)";
    QTest::newRow("command, nothing close")
        << QStringList{"frobnicate"} << "unknown command 'frobnicate' (try --help)";
    QTest::newRow("global option before the command")
        << QStringList{"--modle", "elab", "status"}
        << "unknown option '--modle' (did you mean --model?)";
    QTest::newRow("global option after the command")
        << QStringList{"status", "--josn"} << "unknown option '--josn' (did you mean --json?)";
    QTest::newRow("the command's own option")
        << QStringList{"move", "X=1", "--no-wiat"}
        << "unknown option '--no-wiat' (did you mean --no-wait?)";
    // Another command's option is not offered: it would be refused just the same.
    QTest::newRow("option of another command")
        << QStringList{"status", "--abs"} << "unknown option '--abs' (try --help)";
}

void TestCliArguments::parse_misspelledNames_suggestNearest()
{
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    CliOptions options;
    QString error;
    QVERIFY(!parseArguments(QStringList{"stepdeck-cli"} + args, commandSyntax(), &options, &error));
    QCOMPARE(error, expected);
}

void TestCliArguments::axisValues_unknownAxis_namesItAndTheAxes_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected");
    QTest::newRow("letter that is no axis")
        << QStringList{"X=100", "Q=5"} << "move: this machine has no axis Q (its axes: X, Y, Z)";
    QTest::newRow("lower case") << QStringList{"q=5"}
                                << "move: this machine has no axis Q (its axes: X, Y, Z)";
    QTest::newRow("axis of another machine")
        << QStringList{"U=1"} << "move: this machine has no axis U (its axes: X, Y, Z)";
    QTest::newRow("not an assignment")
        << QStringList{"speed=5"} << "move: expected AXIS=VALUE (e.g. X=100), got 'speed=5'";
}

void TestCliArguments::axisValues_unknownAxis_namesItAndTheAxes()
{
    QFETCH(QStringList, args);
    AxisVector steps;
    const Outcome outcome =
        parseAxisIntegers(QStringLiteral("move"), args, {Axis::X, Axis::Y, Axis::Z}, &steps);
    QCOMPARE(outcome.code, int(ExitUsage));
    QTEST(outcome.message, "expected");
}

void TestCliArguments::axisValues_decimalOnly_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("rates"); // parseAxisDoubles, else parseAxisIntegers
    QTest::addColumn<int>("exitCode");

    QTest::newRow("integers") << QStringList{"X=100", "Z=-5"} << false << int(ExitOk);
    QTest::newRow("leading zero") << QStringList{"X=010"} << false << int(ExitOk);
    QTest::newRow("hex") << QStringList{"X=0x10"} << false << int(ExitUsage);
    QTest::newRow("fraction for steps") << QStringList{"X=1.5"} << false << int(ExitUsage);
    QTest::newRow("beyond 64 bits")
        << QStringList{"X=99999999999999999999"} << false << int(ExitInvalidValue);
    QTest::newRow("no such axis") << QStringList{"U=1"} << false << int(ExitUsage);
    QTest::newRow("axis twice") << QStringList{"X=1", "X=2"} << false << int(ExitUsage);
    QTest::newRow("no axis") << QStringList{} << false << int(ExitUsage);
    QTest::newRow("rate with exponent") << QStringList{"X=1.5e3"} << true << int(ExitOk);
    QTest::newRow("rate nan") << QStringList{"X=nan"} << true << int(ExitUsage);
    QTest::newRow("rate -inf") << QStringList{"Y=-Infinity"} << true << int(ExitUsage);
    QTest::newRow("rate beyond double") << QStringList{"X=1e400"} << true << int(ExitInvalidValue);
}

void TestCliArguments::axisValues_decimalOnly()
{
    QFETCH(QStringList, args);
    QFETCH(bool, rates);
    const QList<Axis> axes{Axis::X, Axis::Y, Axis::Z};
    AxisVector steps;
    AxisVelocities velocities;
    const Outcome outcome = rates ? parseAxisDoubles(QStringLiteral("jog"), args, axes, &velocities)
                                  : parseAxisIntegers(QStringLiteral("move"), args, axes, &steps);
    QTEST(outcome.code, "exitCode");
    if (!outcome.ok())
        QVERIFY2(outcome.message.startsWith(rates ? "jog: " : "move: "),
                 qPrintable(outcome.message));
    else if (rates)
        QCOMPARE(velocities.value(Axis::X), 1500.0);
    else
        QCOMPARE(steps.value(Axis::X), args.first() == "X=010" ? 10 : 100);
}

STEPDECK_TEST_GUILESS_MAIN(TestCliArguments)
#include "tst_cliarguments.moc"
