// End to end: stepdeck-cli against stepdeck-sim over a real pseudo-terminal with QSerialPort
// (issue #2, section 6). Each test gets a fresh simulator process (power-on state); each CLI
// invocation is its own session, so positions are only observable within one invocation
// (move prints where it ended) -- between invocations only the device state persists.
#include "ProcessSupport.h"
#include "TestMain.h"
#include "sim/PtyEndpoint.h"
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using stepdeck::PtyEndpoint;

class TestCliEndToEnd : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();

    void statusJson_atPowerOn_hasContractKeys_data();
    void statusJson_atPowerOn_hasContractKeys();
    void statusJson_atPowerOn_setupIncomplete();
    void status_human_showsFlagsAxesAndUnknownPositions();
    void status_inProcessSim_printsPowerOnState();
    void move_atPowerOn_refusedForIncompleteSetup();
    void set_rampParameters_clearsSetupIncomplete();
    void set_outOfRange_failsNamingParameterAndRange_data();
    void set_outOfRange_failsNamingParameterAndRange();
    void numbers_decimalOnly_nonFiniteIsUsage_data();
    void numbers_decimalOnly_nonFiniteIsUsage();
    void move_afterSetup_printsEndPositionsAndIdle();
    void move_positions_doNotOutliveTheSession();
    void move_timeoutAfterTheCommand_reachesTheMove();
    void exportImport_roundTrip_writesTheSetup();
    void import_brokenFile_refusedAndNothingWritten_data();
    void import_brokenFile_refusedAndNothingWritten();
    void get_writeOnlyParameter_saysItCannot();
    void params_valueWithoutUnit_saysNoUnit();
    void set_writeOnlyModel_saysNothingVerified();
    void scan_modelWithoutBus_unsupportedInOneLine();
    void usageErrors_exitTwoWithOneLine_data();
    void usageErrors_exitTwoWithOneLine();
    void port_missing_failsWithLinkDown();
    void unknownNames_suggestTheNearest_data();
    void unknownNames_suggestTheNearest();
    void resetPositionError_nanotecDrive_orUnsupported();
    void port_silentDevice_failsWithTimeoutNamingPort();
    void help_documentsExitCodes();

private:
    using Run = stepdeck::testing::ProcessRun;
    Run cli(const QStringList& args, int timeoutMs = 20000);
    QJsonObject statusJson();
    QString binary(const QString& name) const;
    QString writeFile(const QString& name, const QByteArray& content);

    QString m_binDir;
    QProcess* m_sim = nullptr;
    QString m_pty;
    QTemporaryDir m_tmp;
};

QString TestCliEndToEnd::binary(const QString& name) const
{
    return QDir(m_binDir).filePath(name);
}

void TestCliEndToEnd::initTestCase()
{
    m_binDir = qEnvironmentVariable("STEPDECK_BIN_DIR");
    QVERIFY2(!m_binDir.isEmpty(), "STEPDECK_BIN_DIR is not set (run through ctest)");
    QVERIFY2(QFileInfo(binary("stepdeck-cli")).isExecutable(), qPrintable(binary("stepdeck-cli")));
    QVERIFY2(QFileInfo(binary("stepdeck-sim")).isExecutable(), qPrintable(binary("stepdeck-sim")));
    QVERIFY(m_tmp.isValid());
}

void TestCliEndToEnd::init()
{
    m_sim = new QProcess(this);
    // The contract: the pty path is the first line of stdout, flushed at once.
    QString error;
    m_pty = stepdeck::testing::startSimulator(m_sim, binary("stepdeck-sim"),
                                              QStringList{"--model", "elab"}, &error);
    QVERIFY2(!m_pty.isEmpty(), qPrintable(error));
    QVERIFY(QFileInfo::exists(m_pty));
}

void TestCliEndToEnd::cleanup()
{
    if (m_sim) {
        m_sim->terminate(); // SIGTERM: the simulator quits cleanly
        if (!m_sim->waitForFinished(5000))
            m_sim->kill();
        QCOMPARE(m_sim->exitStatus(), QProcess::NormalExit);
        delete m_sim;
        m_sim = nullptr;
    }
}

TestCliEndToEnd::Run TestCliEndToEnd::cli(const QStringList& args, int timeoutMs)
{
    QStringList all = args;
    if (!args.contains("--port"))
        all = QStringList{"--model", "elab", "--port", m_pty} + args;
    return stepdeck::testing::runProcess(binary("stepdeck-cli"), all, timeoutMs);
}

QJsonObject TestCliEndToEnd::statusJson()
{
    const Run run = cli({"status", "--json"});
    if (run.exitCode != 0) {
        qWarning() << "status failed:" << run.err;
        return {};
    }
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(run.out, &error);
    if (!doc.isObject())
        qWarning() << "not one JSON object:" << run.out << error.errorString();
    return doc.object();
}

QString TestCliEndToEnd::writeFile(const QString& name, const QByteArray& content)
{
    const QString path = m_tmp.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size())
        qWarning() << "cannot write" << path;
    return path;
}

void TestCliEndToEnd::statusJson_atPowerOn_hasContractKeys_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("type"); // QJsonValue::Type
    QTest::newRow("model") << "model" << int(QJsonValue::String);
    for (const char* key :
         {"driveOn", "spindleOn", "busy", "overTemperature", "setupIncomplete", "panic"})
        QTest::newRow(key) << QStringLiteral("machine.%1").arg(key) << int(QJsonValue::Bool);
    for (const char* axis : {"X", "Y", "Z"}) {
        for (const char* key :
             {"moving", "jogging", "limitSwitch", "referenceSwitch", "positionEstimated"}) {
            const QString path = QStringLiteral("axes.%1.%2").arg(axis, key);
            QTest::newRow(qPrintable(path)) << path << int(QJsonValue::Bool);
        }
        const QString position = QStringLiteral("axes.%1.position").arg(axis);
        QTest::newRow(qPrintable(position)) << position << int(QJsonValue::Double);
    }
    QTest::newRow("temperatureCelsius") << "temperatureCelsius" << int(QJsonValue::Double);
    QTest::newRow("raw") << "raw" << int(QJsonValue::Object);
}

void TestCliEndToEnd::statusJson_atPowerOn_hasContractKeys()
{
    QFETCH(QString, path);
    QFETCH(int, type);
    QJsonValue value = statusJson();
    for (const QString& key : path.split('.'))
        value = value.toObject().value(key);
    QCOMPARE(int(value.type()), type);
}

void TestCliEndToEnd::statusJson_atPowerOn_setupIncomplete()
{
    const Run run = cli({"status", "--json"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    QCOMPARE(run.out.count('\n'), 1); // exactly one JSON object on one line
    const QJsonObject status = QJsonDocument::fromJson(run.out).object();
    QCOMPARE(status.value("model").toString(), QStringLiteral("elab"));
    QCOMPARE(status.value("machine").toObject().value("setupIncomplete").toBool(), true);
    QCOMPARE(status.value("machine").toObject().value("panic").toBool(), false);
    QCOMPARE(status.value("axes").toObject().keys(), (QStringList{"X", "Y", "Z"}));
}

void TestCliEndToEnd::status_human_showsFlagsAxesAndUnknownPositions()
{
    const Run run = cli({"status"});
    QCOMPARE(run.exitCode, 0);
    const QString out = QString::fromUtf8(run.out);
    QVERIFY2(out.contains("SETUP INCOMPLETE"), qPrintable(out));
    QVERIFY2(out.contains("Temperature:"), qPrintable(out));
    for (const char* axis : {"\nX ", "\nY ", "\nZ "})
        QVERIFY2(out.contains(QLatin1String(axis)), qPrintable(out));
    QVERIFY2(out.contains("unknown"), qPrintable(out)); // not referenced in a new session
}

void TestCliEndToEnd::status_inProcessSim_printsPowerOnState()
{
    const Run run = cli({"--model", "elab", "--port", "sim", "status", "--json"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject status = QJsonDocument::fromJson(run.out).object();
    QCOMPARE(status.value("machine").toObject().value("setupIncomplete").toBool(), true);
}

void TestCliEndToEnd::move_atPowerOn_refusedForIncompleteSetup()
{
    const Run run = cli({"move", "X=100"});
    // Refused by the adapter (3) or NAKed by the board (4): either way one line naming setup.
    QVERIFY2(run.exitCode == 3 || run.exitCode == 4, run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.toLower().contains("setup"), run.err.constData());
}

void TestCliEndToEnd::set_rampParameters_clearsSetupIncomplete()
{
    const Run run =
        cli({"set", "start-speed=100", "max-speed=2000,2000,1500", "acceleration=1000"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    QCOMPARE(statusJson().value("machine").toObject().value("setupIncomplete").toBool(), false);
}

void TestCliEndToEnd::set_outOfRange_failsNamingParameterAndRange_data()
{
    QTest::addColumn<QString>("assignment");
    QTest::addColumn<QString>("parameter");
    QTest::addColumn<QString>("range");
    QTest::newRow("speed above 16 bits") << "start-speed=70000"
                                         << "start-speed"
                                         << "0..65535";
    QTest::newRow("one axis negative") << "max-speed=100,-1,100"
                                       << "max-speed"
                                       << "0..65535";
    QTest::newRow("power above 100") << "drive-power=101"
                                     << "drive-power"
                                     << "0..100";
    QTest::newRow("rpm negative") << "spindle-rpm=-1"
                                  << "spindle-rpm"
                                  << "0..1000";
    QTest::newRow("polarity word") << "limit-polarity=sideways"
                                   << "limit-polarity"
                                   << "high|low";
}

void TestCliEndToEnd::set_outOfRange_failsNamingParameterAndRange()
{
    QFETCH(QString, assignment);
    QFETCH(QString, parameter);
    QFETCH(QString, range);
    const Run run = cli({"set", assignment});
    QCOMPARE(run.exitCode, 7);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains(parameter.toUtf8()), run.err.constData());
    QVERIFY2(run.err.contains(range.toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

// Issue 12: "0100" was octal (64 %), "0x40" hex, "jog X=nan" exited 0. Values are decimal;
// anything else is an invalid value (7), a non-finite number a usage error (2).
void TestCliEndToEnd::numbers_decimalOnly_nonFiniteIsUsage_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("needle"); // on stdout for exit 0, else the one stderr line
    QTest::newRow("0100 is one hundred")
        << QStringList{"set", "drive-power=0100"} << 0 << "drive-power=100";
    QTest::newRow("010 is ten") << QStringList{"set", "drive-power=010"} << 0 << "drive-power=10";
    QTest::newRow("per axis with leading zeros")
        << QStringList{"set", "start-speed=0100,020,0003"} << 0 << "start-speed=100,20,3";
    QTest::newRow("hex refused") << QStringList{"set", "drive-power=0x40"} << 7
                                 << "not a decimal integer";
    QTest::newRow("set nan") << QStringList{"set", "drive-power=nan"} << 2 << "not a finite number";
    QTest::newRow("set inf on one axis")
        << QStringList{"set", "max-speed=100,inf,100"} << 2 << "not a finite number";
    QTest::newRow("jog nan") << QStringList{"jog", "X=nan", "--for", "200"} << 2
                             << "not a finite number";
    QTest::newRow("jog inf") << QStringList{"jog", "X=inf", "--for", "200"} << 2
                             << "not a finite number";
    QTest::newRow("jog -Infinity")
        << QStringList{"jog", "Y=-Infinity", "--for", "200"} << 2 << "not a finite number";
    QTest::newRow("jog beyond double")
        << QStringList{"jog", "X=1e400", "--for", "200"} << 7 << "out of range";
    QTest::newRow("velocity nan") << QStringList{"velocity", "X=nan", "--for", "200"} << 2
                                  << "not a finite number";
    QTest::newRow("move hex") << QStringList{"move", "X=0x40"} << 2 << "not a decimal number";
    QTest::newRow("move beyond 64 bits")
        << QStringList{"move", "X=99999999999999999999"} << 7 << "out of range";
    QTest::newRow("power hex") << QStringList{"power", "0x40"} << 7 << "not a decimal integer";
    QTest::newRow("power nan") << QStringList{"power", "nan"} << 2 << "not a finite number";
    QTest::newRow("jog --for hex") << QStringList{"jog", "X=10", "--for", "0x10"} << 2 << "--for";
}

void TestCliEndToEnd::numbers_decimalOnly_nonFiniteIsUsage()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, needle);
    const Run run = cli(args);
    QVERIFY2(run.exitCode == exitCode,
             qPrintable(QStringLiteral("exit %1: %2").arg(run.exitCode).arg(run.err.constData())));
    if (exitCode == 0) {
        QVERIFY2(run.out.contains(needle.toUtf8()), run.out.constData());
    } else {
        QCOMPARE(run.err.count('\n'), 1);
        QVERIFY2(run.err.contains(needle.toUtf8()), run.err.constData());
        QVERIFY(run.out.isEmpty());
    }
}

void TestCliEndToEnd::move_afterSetup_printsEndPositionsAndIdle()
{
    QCOMPARE(cli({"set", "start-speed=200", "max-speed=4000", "acceleration=2000"}).exitCode, 0);
    const Run run = cli({"move", "X=300", "Y=-120", "--json"});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QJsonObject axes = QJsonDocument::fromJson(run.out).object().value("axes").toObject();
    QCOMPARE(axes.value("X").toObject().value("position").toDouble(), 300.0);
    QCOMPARE(axes.value("Y").toObject().value("position").toDouble(), -120.0);
    QCOMPARE(axes.value("Z").toObject().value("position").toDouble(), 0.0);
    for (const QString& axis : axes.keys())
        QCOMPARE(axes.value(axis).toObject().value("moving").toBool(), false); // waited

    const Run human = cli({"move", "Z=40"});
    QCOMPARE(human.exitCode, 0);
    QVERIFY2(human.out.contains("Z=40"), human.out.constData());
}

void TestCliEndToEnd::move_positions_doNotOutliveTheSession()
{
    QCOMPARE(cli({"set", "start-speed=200", "max-speed=4000", "acceleration=2000"}).exitCode, 0);
    QCOMPARE(cli({"move", "X=50"}).exitCode, 0);
    // A new invocation is a reconnect: nothing referenced, positions unknown (issue #2, sec. 2).
    const QJsonObject x = statusJson().value("axes").toObject().value("X").toObject();
    QCOMPARE(x.value("positionKnown").toBool(true), false);
    QCOMPARE(x.value("referenced").toBool(true), false);
    // ... so an absolute move is refused with a reason instead of guessing.
    const Run abs = cli({"move", "--abs", "X=0"});
    QCOMPARE(abs.exitCode, 3);
    QVERIFY2(abs.err.contains("unknown"), abs.err.constData());
}

void TestCliEndToEnd::move_timeoutAfterTheCommand_reachesTheMove()
{
    // `--timeout MS` after move is the motion's (docs/cli.md), not the link's: the move runs
    // into it and the CLI exits 5 naming it.
    QCOMPARE(cli({"set", "start-speed=50", "max-speed=200", "acceleration=4000"}).exitCode, 0);
    const Run run = cli({"move", "X=100000", "--timeout", "300"});
    QCOMPARE(run.exitCode, 5);
    QVERIFY2(run.err.contains("within 300 ms"), run.err.constData());
}

void TestCliEndToEnd::exportImport_roundTrip_writesTheSetup()
{
    const QString path = m_tmp.filePath("setup.json");
    const Run exported = cli({"export", path});
    QCOMPARE(exported.exitCode, 0);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(json.value("format").toString(), QStringLiteral("stepdeck-parameters"));
    QCOMPARE(json.value("model").toString(), QStringLiteral("elab"));
    const QJsonObject startSpeed =
        json.value("parameters").toObject().value("start-speed").toObject();
    QCOMPARE(startSpeed.keys(), (QStringList{"X", "Y", "Z"}));
    // E-LAB cannot read back: the file says its values are schema defaults.
    QCOMPARE(json.value("origin").toObject().value("start-speed").toString(),
             QStringLiteral("default"));

    QCOMPARE(statusJson().value("machine").toObject().value("setupIncomplete").toBool(), true);
    const Run imported = cli({"import", path});
    QVERIFY2(imported.exitCode == 0, imported.err.constData());
    QCOMPARE(statusJson().value("machine").toObject().value("setupIncomplete").toBool(), false);
}

void TestCliEndToEnd::import_brokenFile_refusedAndNothingWritten_data()
{
    QTest::addColumn<QByteArray>("content"); // empty: the file does not exist
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("needle");
    // Valid ramp entries first: if anything were written before validation, setup would
    // become complete and the status check below would catch it.
    const QByteArray head = R"({"format":"stepdeck-parameters","version":1,"model":"elab",
        "parameters":{"start-speed":{"X":100,"Y":100,"Z":100},
                      "max-speed":{"X":2000,"Y":2000,"Z":2000},
                      "acceleration":{"X":1000,"Y":1000,"Z":1000})";
    QTest::newRow("missing file") << QByteArray() << 12 << "Cannot open";
    QTest::newRow("not JSON") << QByteArray("{ \"format\": ") << 12 << "line 1, column";
    QTest::newRow("not a parameter file")
        << QByteArray(R"({"format":"something-else"})") << 7 << "not a StepDeck parameter file";
    QTest::newRow("out of range") << head + R"(,"drive-power":250}})" << 7 << "drive-power";
    QTest::newRow("unknown parameter") << head + R"(,"warp-speed":9}})" << 7 << "warp-speed";
    QTest::newRow("missing axis") << head + R"(,"feed-speed":{"X":50,"Y":50}}})" << 7 << "axis Z";
    QTest::newRow("huge number") << head + R"(,"drive-power":1e300}})" << 7 << "out of range";
    QTest::newRow("hex text") << head + R"(,"drive-power":"0x40"}})" << 7
                              << "not a decimal integer";
    QTest::newRow("other model") << QByteArray(head).replace("\"elab\"", "\"nanotec\"") + "}}" << 7
                                 << "nanotec";
}

void TestCliEndToEnd::import_brokenFile_refusedAndNothingWritten()
{
    QFETCH(QByteArray, content);
    QFETCH(int, exitCode);
    QFETCH(QString, needle);
    const QString path = content.isEmpty() ? m_tmp.filePath("does-not-exist.json")
                                           : writeFile("broken.json", content);
    const Run run = cli({"import", path});
    QCOMPARE(run.exitCode, exitCode);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains(needle.toUtf8()), run.err.constData());
    QCOMPARE(statusJson().value("machine").toObject().value("setupIncomplete").toBool(), true);
}

void TestCliEndToEnd::get_writeOnlyParameter_saysItCannot()
{
    const Run run = cli({"get", "start-speed"});
    QCOMPARE(run.exitCode, 8);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains("cannot be read back"), run.err.constData());
}

// The E-LAB manual gives the acceleration no unit: the listing says so, in its text and JSON.
void TestCliEndToEnd::params_valueWithoutUnit_saysNoUnit()
{
    Run run = cli({"params"});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QList<QByteArray> lines = run.out.split('\n');
    const auto acceleration = std::find_if(lines.cbegin(), lines.cend(), [](const QByteArray& l) {
        return l.startsWith("acceleration ");
    });
    QVERIFY2(acceleration != lines.cend(), run.out.constData());
    QVERIFY2(acceleration->contains("(no unit)"), acceleration->constData());
    run = cli({"--json", "params"});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QJsonArray list = QJsonDocument::fromJson(run.out).object().value("parameters").toArray();
    bool found = false;
    for (const QJsonValue& v : list) {
        const QJsonObject p = v.toObject();
        if (p.value("name").toString() != QLatin1String("acceleration"))
            continue;
        found = true;
        QCOMPARE(p.value("unit").toString(), QString());
        QVERIFY2(p.value("unitNote").toString().contains(QLatin1String("no unit")),
                 qPrintable(p.value("unitNote").toString()));
    }
    QVERIFY(found);
}

void TestCliEndToEnd::set_writeOnlyModel_saysNothingVerified()
{
    // E-LAB cannot read back: write & verify is not attempted, and the output says so.
    const Run run = cli({"set", "start-speed=100"});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.contains("cannot read these back") && run.out.contains("start-speed=100"),
             run.out.constData());
}

void TestCliEndToEnd::scan_modelWithoutBus_unsupportedInOneLine()
{
    const Run run = cli({"scan"});
    QCOMPARE(run.exitCode, 8);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains("no bus to scan"), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

void TestCliEndToEnd::usageErrors_exitTwoWithOneLine_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("needle");
    QTest::newRow("unknown command") << QStringList{"frobnicate"} << "unknown command";
    QTest::newRow("unknown option") << QStringList{"status", "--bogus"} << "unknown option";
    QTest::newRow("option of another command")
        << QStringList{"status", "--for", "5"} << "unknown option '--for'";
    QTest::newRow("option without its value")
        << QStringList{"jog", "X=100", "--for"} << "missing value after '--for'";
    QTest::newRow("no command") << QStringList{} << "no command";
    QTest::newRow("axis value not a number")
        << QStringList{"move", "X=abc"} << "not a decimal number";
    QTest::newRow("jog without duration") << QStringList{"jog", "X=100"} << "--for";
    QTest::newRow("unknown model") << QStringList{"--model", "nope", "status"} << "nope";
    QTest::newRow("set with only --no-verify") << QStringList{"set", "--no-verify"} << "set needs";
    QTest::newRow("scan address out of range")
        << QStringList{"scan", "--first", "0"} << "--first needs an address within 1..254";
    QTest::newRow("scan range reversed")
        << QStringList{"scan", "--first", "9", "--last=3"} << "lies after";
    QTest::newRow("records of two axes") << QStringList{"records", "X", "Y"} << "records needs";
}

void TestCliEndToEnd::usageErrors_exitTwoWithOneLine()
{
    QFETCH(QStringList, args);
    QFETCH(QString, needle);
    const Run run = cli(QStringList{"--port", m_pty} + args);
    QCOMPARE(run.exitCode, 2);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains(needle.toUtf8()), run.err.constData());
}

void TestCliEndToEnd::port_missing_failsWithLinkDown()
{
    // A path that does not exist says so: there never was a link to lose (issue 16).
    const Run run = cli({"--port", "/dev/stepdeck-no-such-port", "status"});
    QCOMPARE(run.exitCode, 6);
    QCOMPARE(run.err, QByteArray("stepdeck-cli: no such port: /dev/stepdeck-no-such-port\n"));
}

void TestCliEndToEnd::unknownNames_suggestTheNearest_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("line");
    QTest::newRow("command") << QStringList{"stauts"} << 2
                             << "unknown command 'stauts' (did you mean status?)";
    QTest::newRow("axis") << QStringList{"move", "X=100", "Q=5"} << 2
                          << "move: this machine has no axis Q (its axes: X, Y, Z)";
    QTest::newRow("model") << QStringList{"--model", "nanotek", "status"} << 2
                           << "unknown controller model 'nanotek' (did you mean nanotec?";
    QTest::newRow("parameter to set") << QStringList{"set", "strat-speed=100"} << 7
                                      << "unknown parameter 'strat-speed' (did you mean "
                                         "start-speed?)";
    QTest::newRow("parameter to get") << QStringList{"get", "max-sped"} << 7
                                      << "unknown parameter 'max-sped' (did you mean max-speed?)";
}

void TestCliEndToEnd::unknownNames_suggestTheNearest()
{
    QFETCH(QStringList, args);
    QFETCH(QString, line);
    const Run run = cli(QStringList{"--port", m_pty} + args);
    QTEST(run.exitCode, "exitCode");
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.startsWith("stepdeck-cli: " + line.toUtf8()), run.err.constData());
}

void TestCliEndToEnd::port_silentDevice_failsWithTimeoutNamingPort()
{
    // A pseudo-terminal nobody answers on: powered off, wrong cable, wrong model.
    PtyEndpoint silent;
    QString error;
    QVERIFY2(silent.create(&error), qPrintable(error));
    const Run run = cli({"--port", silent.slavePath(), "status"});
    QCOMPARE(run.exitCode, 5);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains(silent.slavePath().toUtf8()), run.err.constData());
}

void TestCliEndToEnd::help_documentsExitCodes()
{
    const Run run = cli({"--help"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.contains("Exit codes"));
    for (const char* command : {"ports", "status", "set", "get", "export", "import", "move", "jog",
                                "home", "velocity", "feed", "panic", "spindle"})
        QVERIFY2(run.out.contains(command), command);
}

void TestCliEndToEnd::resetPositionError_nanotecDrive_orUnsupported()
{
    // Issue 16: the command the Nanotec messages name (the GUI names its button instead).
    const Run reset = cli({"--model", "nanotec", "--port", "sim", "reset-position-error", "Y"});
    QVERIFY2(reset.exitCode == 0, reset.err.constData());
    QVERIFY2(reset.out.contains("position error of axis Y reset"), reset.out.constData());
    const Run noAxis = cli({"--model", "nanotec", "--port", "sim", "reset-position-error", "Q"});
    QCOMPARE(noAxis.exitCode, 2);
    const Run elab = cli({"--port", m_pty, "reset-position-error", "X"});
    QCOMPARE(elab.exitCode, 8);
    QCOMPARE(elab.err.count('\n'), 1);
}

STEPDECK_TEST_GUILESS_MAIN(TestCliEndToEnd)
#include "tst_cli_e2e.moc"
