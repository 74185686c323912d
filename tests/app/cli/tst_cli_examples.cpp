// Every shipped example runs to its end on its simulator (issue 28, item 2): each program of
// docs/examples for one controller through `stepdeck-cli run` against the model's simulator on a
// real pty (reference, run, exit 0, the device's axes where the program leaves them), and every
// example machine file on its built-in simulators (port "sim"): referenced, moved into its
// travel and back by a program made from its axes, exit 0 and the positions the run reports.
#include "CliRunRig.h"
#include "TestMain.h"
#include "machine/MachineDescription.h"
#include "machine/MachineFile.h"
#include "protocols/elab/ElabSimulator.h"
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::test;

using AxisSteps = QMap<Axis, qint64>;

namespace {
const QString kExamples = QStringLiteral(STEPDECK_SOURCE_DIR "/docs/examples");

// The summary event of `run --json`.
QJsonObject summaryOf(const QByteArray& out)
{
    for (const QByteArray& line : out.split('\n')) {
        const QJsonObject o = QJsonDocument::fromJson(line).object();
        if (o.value("event").toString() == QLatin1String("summary"))
            return o;
    }
    return {};
}
} // namespace

class TestCliExamples : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void exampleProgram_onItsSimulator_runsToItsEnd_data();
    void exampleProgram_onItsSimulator_runsToItsEnd();
    void exampleMachine_onItsSimulators_referencesAndRuns_data();
    void exampleMachine_onItsSimulators_referencesAndRuns();
};

void TestCliExamples::initTestCase()
{
    QVERIFY2(!qEnvironmentVariableIsEmpty("STEPDECK_BIN_DIR"),
             "STEPDECK_BIN_DIR is not set (run through ctest)");
    // Every example is a row below: a new one without a row fails here.
    const QStringList programs =
        QDir(kExamples).entryList({QStringLiteral("*.ngc")}, QDir::Files, QDir::Name);
    QCOMPARE(programs, (QStringList{"elab.ngc", "emis.ngc", "laser.ngc", "nanotec.ngc"}));
    const QStringList machines =
        QDir(kExamples).entryList({QStringLiteral("*.machine.json")}, QDir::Files, QDir::Name);
    QCOMPARE(machines,
             (QStringList{"elab-xyz-nanotec-rotary.machine.json", "emis-xyzu.machine.json",
                          "laser-axes.machine.json", "nanotec-two-buses.machine.json"}));
}

void TestCliExamples::exampleProgram_onItsSimulator_runsToItsEnd_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("file");
    // Where each program leaves the axes, in steps from where its G28 ended (0).
    QTest::addColumn<AxisSteps>("end");
    QTest::newRow("elab") << "elab"
                          << "elab.ngc" << AxisSteps{{Axis::X, 0}, {Axis::Y, 0}, {Axis::Z, 0}};
    QTest::newRow("nanotec") << "nanotec"
                             << "nanotec.ngc" << AxisSteps{{Axis::X, 0}, {Axis::Y, 0}};
    QTest::newRow("emis") << "emis"
                          << "emis.ngc" << AxisSteps{{Axis::X, 0}, {Axis::Y, 0}, {Axis::U, 0}};
    QTest::newRow("laser") << "laser-axis"
                           << "laser.ngc" << AxisSteps{{Axis::X, 0}, {Axis::Y, 0}};
}

void TestCliExamples::exampleProgram_onItsSimulator_runsToItsEnd()
{
    QFETCH(QString, model);
    QFETCH(QString, file);
    QFETCH(AxisSteps, end);
    // The Nanotec example drives X, Y and Z: the model's default addresses 1, 2 and 3.
    RunDevice device(model,
                     model == QLatin1String("nanotec") ? QList<int>{1, 2, 3} : QList<int>{1});
    // The part sensor emis.ngc waits for (M66 P5), as `stepdeck-sim --input 5=1` sets it.
    if (model == QLatin1String("emis"))
        QVERIFY(device.probe([&device] { return device.sim()->setSettableInput(5, true); }));
    QMap<Axis, qint64> switchAt; // E-LAB: the device counts from power-on, not from its switch
    if (model == QLatin1String("elab"))
        switchAt = device.probe([&device] {
            QMap<Axis, qint64> at;
            for (Axis a : {Axis::X, Axis::Y, Axis::Z})
                at.insert(a, static_cast<elab::ElabSimulator*>(device.sim())
                                 ->switchConfig(a)
                                 .referencePosition);
            return at;
        });
    QStringList args = cliArgs(model, device.path());
    if (model == QLatin1String("nanotec"))
        args = QStringList{"--model", model, "--port", device.path(), "--timeout", "10000"};
    const CliRun r = runCli(args + QStringList{"--json", "run", kExamples + "/" + file}, 240000);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(summaryOf(r.out).value("state").toString(), QStringLiteral("finished"));
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 5000);
    for (auto it = end.cbegin(); it != end.cend(); ++it) {
        const qint64 at = device.position(it.key()) - switchAt.value(it.key());
        // The E-LAB's reference run stops within its switch's window (ElabSimSwitchConfig).
        const qint64 slack = model == QLatin1String("elab") ? 10 : 0;
        QVERIFY2(qAbs(at - it.value()) <= slack, qPrintable(QStringLiteral("%1 at %2, not %3")
                                                                .arg(axisName(it.key()))
                                                                .arg(at)
                                                                .arg(it.value())));
    }
}

void TestCliExamples::exampleMachine_onItsSimulators_referencesAndRuns_data()
{
    QTest::addColumn<QString>("file");
    for (const char* f : {"elab-xyz-nanotec-rotary.machine.json", "emis-xyzu.machine.json",
                          "laser-axes.machine.json", "nanotec-two-buses.machine.json"})
        QTest::newRow(f) << QString::fromLatin1(f);
}

// The file with every port "sim"; a program that references every axis, moves each 5 units
// into its travel (from the end its reference run ends at) and reports where it stands.
void TestCliExamples::exampleMachine_onItsSimulators_referencesAndRuns()
{
    QFETCH(QString, file);
    machine::MachineFileError invalid;
    std::optional<machine::MachineDescription> d =
        machine::MachineFile::load(kExamples + "/" + file, &invalid);
    QVERIFY2(d, qPrintable(invalid.text()));
    // Ports "sim"; a controller's setup file (controllers[i].setup) by its absolute path,
    // since the copy is written elsewhere.
    for (machine::MachineController& c : d->controllers)
        c.port = QStringLiteral("sim");
    machine::MachineFile::anchorSetupFiles(&*d, kExamples + "/" + file);
    QTemporaryDir dir;
    const QString machinePath = dir.filePath("machine.json");
    {
        QFile out(machinePath);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(d->toJson()).toJson());
    }
    QByteArray program = "G90\nG28\n";
    QMap<QString, double> targets;
    for (const machine::MachineAxis& a : d->axes) {
        const double inward = a.softMaximum && *a.softMaximum > 0   ? 5
                              : a.softMinimum && *a.softMinimum < 0 ? -5
                              : a.referenceDirection > 0            ? -5
                                                                    : 5;
        targets.insert(a.name, inward);
        program += QStringLiteral("G0 %1%2\n").arg(a.name).arg(inward).toUtf8();
    }
    program += "M2\n";
    const QString programPath = writeProgram(dir, "travel.ngc", program);
    // A board that refuses motion until its setup is written (E-LAB) gets it from the machine
    // file (controllers[i].setup, written on connect), else the schema's defaults.
    QStringList args{"--machine", machinePath, "--timeout", "10000", "run", programPath};
    for (const machine::MachineController& c : d->controllers)
        if (!findModel(c.modelId)->setupBeforeMotion.isEmpty() && c.setup.isEmpty() &&
            !args.contains("--setup-defaults"))
            args.prepend("--setup-defaults");
    const CliRun r = runCli(args, 240000);
    QVERIFY2(r.exitCode == 0, (program + r.err).constData());
    // "finished: N blocks in T; X=5.000 Y=5.000 Z=-5.000 A=5.000": every axis referenced
    // (no mark) and where the program left it.
    const QString out = QString::fromUtf8(r.out);
    const qsizetype at = out.indexOf(QStringLiteral("finished: "));
    QVERIFY2(at >= 0, r.out.constData());
    const QStringList words = out.mid(at).section(QLatin1Char(';'), 1).simplified().split(' ');
    QCOMPARE(words.size(), targets.size());
    for (const QString& word : words) {
        const QString name = word.section(QLatin1Char('='), 0, 0);
        QVERIFY2(targets.contains(name), qPrintable(word));
        // The nearest whole step (docs/machines.md "Units"): 5 deg at 88.8889 steps/deg is 444.
        const double shown = word.section(QLatin1Char('='), 1).toDouble();
        QVERIFY2(qAbs(shown - targets.value(name)) <= 1.0 / d->axis(name)->stepsPerUnit + 1e-3,
                 qPrintable(word));
    }
}

STEPDECK_TEST_GUILESS_MAIN(TestCliExamples)
#include "tst_cli_examples.moc"
