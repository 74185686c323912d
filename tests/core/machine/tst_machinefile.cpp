// MachineFile: reading and validating "stepdeck-machine" files (issue 19). Every invalid file
// names the exact field; valid files come back as the description they spell. The format's
// versions and optional keys: tst_machinefileformat.
#include "MachineFileTestSupport.h"
#include "TestMain.h"
#include "machine/MachineFile.h"
#include "protocols/Registry.h"
#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::test;

class TestMachineFile : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_example_givesEveryField();
    void parse_invalid_namesTheField_data();
    void parse_invalid_namesTheField();
    void parse_brokenJson_givesLineAndColumn();
    void parse_emptyFile_saysSo();
    void saveAndLoad_roundTrip_equal();
    void singleController_keepsControllerAxesInSteps_andValidates();
    void toSteps_nearestWholeStep_andBack_data();
    void toSteps_nearestWholeStep_andBack();
    void referenceGroups_lowestOrderFirst();
    void shippedExamples_areValid();
    void load_setupFile_readRelativeToTheMachineFileAndKept();
    void load_setupFile_invalid_namesTheField_data();
    void load_setupFile_invalid_namesTheField();
};

void TestMachineFile::parse_example_givesEveryField()
{
    MachineFileError error;
    const std::optional<MachineDescription> m = MachineFile::parse(bytes(tableAndRotary()), &error);
    QVERIFY2(m, qPrintable(error.text()));
    QCOMPARE(m->name, QStringLiteral("Engraver"));
    QCOMPARE(m->controllers.size(), 2);
    QCOMPARE(m->controllers.at(0).resetLine, LineSettings::ResetLine::Dtr);
    QCOMPARE(m->controllers.at(1).busAddresses, (QMap<Axis, int>{{Axis::X, 1}}));
    QCOMPARE(m->axes.size(), 4);
    const MachineAxis* x = m->axis("X");
    QVERIFY(x);
    QCOMPARE(m->axisIndex("X"), 0); // the file's order
    QCOMPARE(m->axisIndex("A"), 3);
    QCOMPARE(m->axisIndex("B"), -1);
    QCOMPARE(x->unit, AxisUnit::Millimetre);
    QCOMPARE(x->stepsPerUnit, 400.0);
    QCOMPARE(x->softMinimum, 0.0);
    QCOMPARE(x->softMaximum, 300.0);
    QCOMPARE(x->maxJogSpeed, 2.0);
    QCOMPARE(x->jogAcceleration, 8.0);
    QVERIFY(!m->axis("Y")->jogAcceleration); // the default: see tst_jogacceleration
    QCOMPARE(x->referenceDirection, -1);
    QCOMPARE(x->referenceOrder, 1);
    QVERIFY(m->axis("Y")->invert);
    QVERIFY(!m->axis("Y")->hasSoftLimits());
    const MachineAxis* a = m->axis("A");
    QCOMPARE(a->controller, QStringLiteral("rotary"));
    QCOMPARE(a->axis, Axis::X);
    QCOMPARE(a->unit, AxisUnit::Degree);
    QCOMPARE(a->referenceDirection, 0);
}

void TestMachineFile::parse_invalid_namesTheField_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("says");

    QTest::newRow("wrong format") << withEdit("format", "stepdeck-parameters") << "format"
                                  << "stepdeck-machine";
    QTest::newRow("version 3") << withEdit("version", 3) << "version"
                               << "must be 1 or 2";
    QTest::newRow("no name") << withEdit("name", {}, true) << "name"
                             << "missing";
    QTest::newRow("unknown top key") << withEdit("axis", QJsonArray()) << "axis"
                                     << "did you mean axes?";
    QTest::newRow("no controllers") << withEdit("controllers", QJsonArray()) << "controllers"
                                    << "at least one controller";
    QTest::newRow("controller not object") << withEdit("controllers.0", 5) << "controllers[0]"
                                           << "must be an object";
    QTest::newRow("unknown model")
        << withEdit("controllers.1.model", "nanotek") << "controllers[1].model"
        << "nanotec";
    QTest::newRow("model not text") << withEdit("controllers.1.model", 3) << "controllers[1].model"
                                    << "text";
    QTest::newRow("duplicate id") << withEdit("controllers.1.id", "table") << "controllers[1].id"
                                  << "another controller";
    QTest::newRow("bad id") << withEdit("controllers.0.id", "1 table") << "controllers[0].id"
                            << "short name";
    QTest::newRow("empty port") << withEdit("controllers.0.port", " ") << "controllers[0].port"
                                << "serial port";
    QTest::newRow("reset line word")
        << withEdit("controllers.0.resetLine", "cts") << "controllers[0].resetLine"
        << "rts";
    QTest::newRow("reset line on nanotec")
        << withEdit("controllers.1.resetLine", "rts") << "controllers[1].resetLine"
        << "no reset line";
    QTest::newRow("bus map on elab")
        << withEdit("controllers.0.axes", QJsonObject{{"X", 1}}) << "controllers[0].axes"
        << "no drives on a bus";
    QTest::newRow("address 0") << withEdit("controllers.1.axes", QJsonObject{{"X", 0}})
                               << "controllers[1].axes.X"
                               << "outside 1..254";
    QTest::newRow("address 255") << withEdit("controllers.1.axes", QJsonObject{{"X", 255}})
                                 << "controllers[1].axes.X"
                                 << "outside 1..254";
    QTest::newRow("address twice")
        << withEdit("controllers.1.axes", QJsonObject{{"X", 4}, {"Y", 4}})
        << "controllers[1].axes.Y"
        << "two axes";
    QTest::newRow("address not whole")
        << withEdit("controllers.1.axes", QJsonObject{{"X", 1.5}}) << "controllers[1].axes.X"
        << "whole";
    QTest::newRow("no axes") << withEdit("axes", QJsonArray()) << "axes"
                             << "at least one axis";
    QTest::newRow("unknown axis key") << withEdit("axes.3.stepPerUnit", 4) << "axes[3].stepPerUnit"
                                      << "did you mean stepsPerUnit?";
    QTest::newRow("axis name Q") << withEdit("axes.1.name", "Q") << "axes[1].name"
                                 << "X Y Z A B C U V W";
    QTest::newRow("duplicate axis name") << withEdit("axes.3.name", "X") << "axes[3].name"
                                         << "another axis";
    QTest::newRow("unknown controller")
        << withEdit("axes.3.controller", "rotery") << "axes[3].controller"
        << "did you mean rotary?";
    QTest::newRow("controller axis missing") << withEdit("axes.3.axis", "Y") << "axes[3].axis"
                                             << "has no axis Y";
    QTest::newRow("elab has no U") << withEdit("axes.2.axis", "U") << "axes[2].axis"
                                   << "has no axis U";
    QTest::newRow("axis word") << withEdit("axes.2.axis", "x") << "axes[2].axis"
                               << "not an axis of its controller";
    QTest::newRow("controller axis twice") << withEdit("axes.1.axis", "X") << "axes[1].axis"
                                           << "already drives";
    QTest::newRow("unit inch") << withEdit("axes.0.unit", "inch") << "axes[0].unit"
                               << "mm";
    QTest::newRow("steps per unit missing")
        << withEdit("axes.3.stepsPerUnit", {}, true) << "axes[3].stepsPerUnit"
        << "missing";
    QTest::newRow("steps per unit negative")
        << withEdit("axes.3.stepsPerUnit", -2) << "axes[3].stepsPerUnit"
        << "greater than 0 (is -2)";
    QTest::newRow("steps per unit zero")
        << withEdit("axes.3.stepsPerUnit", 0) << "axes[3].stepsPerUnit"
        << "greater than 0";
    QTest::newRow("steps per unit text")
        << withEdit("axes.3.stepsPerUnit", "400") << "axes[3].stepsPerUnit"
        << "decimal";
    QTest::newRow("steps unit scaled") << withEdit("axes.2", QJsonObject{{"name", "Z"},
                                                                         {"controller", "table"},
                                                                         {"axis", "Z"},
                                                                         {"unit", "steps"},
                                                                         {"stepsPerUnit", 2}})
                                       << "axes[2].stepsPerUnit"
                                       << "must be 1";
    QTest::newRow("invert text") << withEdit("axes.1.invert", "yes") << "axes[1].invert"
                                 << "true or false";
    QTest::newRow("limits reversed")
        << withEdit("axes.0.softLimits", QJsonArray{300, 0}) << "axes[0].softLimits"
        << "below the maximum";
    QTest::newRow("limits equal") << withEdit("axes.0.softLimits", QJsonArray{5, 5})
                                  << "axes[0].softLimits"
                                  << "below the maximum";
    QTest::newRow("limits one value")
        << withEdit("axes.0.softLimits", QJsonArray{5}) << "axes[0].softLimits"
        << "[minimum, maximum]";
    QTest::newRow("jog speed zero") << withEdit("axes.0.maxJogSpeed", 0) << "axes[0].maxJogSpeed"
                                    << "greater than 0";
    // E-LAB jogs at most Capabilities::maxJogSpeed steps/s: 400 steps/mm limit the mm/s.
    QTest::newRow("jog speed above the controller")
        << withEdit("axes.0.maxJogSpeed", 1000) << "axes[0].maxJogSpeed"
        << "steps/s";
    QTest::newRow("jog acceleration zero")
        << withEdit("axes.0.jogAcceleration", 0) << "axes[0].jogAcceleration"
        << "greater than 0 in mm/s\u00b2 (is 0)";
    QTest::newRow("jog acceleration negative")
        << withEdit("axes.3.jogAcceleration", -50) << "axes[3].jogAcceleration"
        << "greater than 0 in deg/s\u00b2 (is -50)";
    QTest::newRow("jog acceleration text")
        << withEdit("axes.0.jogAcceleration", "fast") << "axes[0].jogAcceleration"
        << "decimal";
    QTest::newRow("direction 2") << withEdit("axes.0.reference.direction", 2)
                                 << "axes[0].reference.direction"
                                 << "-1 or 1";
    QTest::newRow("order negative")
        << withEdit("axes.0.reference.order", -1) << "axes[0].reference.order"
        << "0 to 99";
    QTest::newRow("reference key")
        << withEdit("axes.0.reference.speed", 3) << "axes[0].reference.speed"
        << "unknown key";
    // Issue 29: the spindle scale.
    QTest::newRow("spindle not an object") << withEdit("spindle", 24000) << "spindle"
                                           << "must be an object";
    QTest::newRow("spindle key") << withEdit("spindle.maxRPM", 24000) << "spindle.maxRPM"
                                 << "unknown key (known: maxRpm, laser)";
    // Issue 50 item 5: a laser on the spindle output.
    QTest::newRow("laser text") << withEdit("spindle.laser", "yes") << "spindle.laser"
                                << "must be true";
    QTest::newRow("maxRpm zero") << withEdit("spindle.maxRpm", 0) << "spindle.maxRpm"
                                 << "must be a speed greater than 0 in rpm (is 0)";
    QTest::newRow("maxRpm negative") << withEdit("spindle.maxRpm", -100) << "spindle.maxRpm"
                                     << "greater than 0";
    QTest::newRow("maxRpm text") << withEdit("spindle.maxRpm", "24000") << "spindle.maxRpm"
                                 << "must be a decimal number";
    // Issue 30: feed moves across controllers.
    QTest::newRow("crossControllerFeed text")
        << withEdit("crossControllerFeed", "no") << "crossControllerFeed"
        << "must be true or false";
    // Issue 50 item 4: where tool lengths come from.
    QTest::newRow("toolLength unknown")
        << withEdit("toolLength", "probe") << "toolLength"
        << "must be \"table\" (G43 takes the tool table's lengths, the default) or \"touchOff\"";
    QTest::newRow("toolLength in another case")
        << withEdit("toolLength", "touchoff") << "toolLength"
        << "must be \"table\"";
    QTest::newRow("toolLength not a text") << withEdit("toolLength", true) << "toolLength"
                                           << "must be \"table\"";
}

void TestMachineFile::parse_invalid_namesTheField()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, field);
    QFETCH(QString, says);
    MachineFileError error;
    QVERIFY(!MachineFile::parse(json, &error));
    QCOMPARE(error.field, field);
    QVERIFY2(error.message.contains(says), qPrintable(error.text()));
    QVERIFY(error.text().startsWith(field + QStringLiteral(": ")));
    // The editor's reading names the same field; whatever it returns breaks the same rule.
    MachineFileError draftError;
    const std::optional<MachineDescription> draft = MachineFile::parseDraft(json, &draftError);
    QCOMPARE(draftError.field, error.field);
    QCOMPARE(draftError.message, error.message);
    if (draft) {
        MachineFileError again;
        QVERIFY(!MachineFile::validate(*draft, &again));
        QCOMPARE(again.field, field);
    }
}

void TestMachineFile::parse_brokenJson_givesLineAndColumn()
{
    MachineFileError error;
    QVERIFY(!MachineFile::parse("{\n  \"format\": \"stepdeck-machine\",\n  \"version\": 1,,\n}",
                                &error));
    QCOMPARE(error.line, 3);
    QVERIFY2(error.column >= 15 && error.column <= 17, qPrintable(error.text()));
    QVERIFY(error.text().startsWith(QStringLiteral("line 3, column")));
}

void TestMachineFile::parse_emptyFile_saysSo()
{
    MachineFileError error;
    QVERIFY(!MachineFile::parse(" \n", &error));
    QVERIFY2(error.message.contains("empty"), qPrintable(error.text()));
    QVERIFY(!MachineFile::parse("[1, 2]", &error));
    QVERIFY2(error.message.contains("no JSON object"), qPrintable(error.text()));
}

void TestMachineFile::saveAndLoad_roundTrip_equal()
{
    const std::optional<MachineDescription> m =
        MachineFile::parse(bytes(tableAndRotary()), nullptr);
    QVERIFY(m);
    QTemporaryDir dir;
    const QString path = dir.filePath("machine.json");
    QString why;
    QVERIFY2(MachineFile::save(*m, path, &why), qPrintable(why));
    MachineFileError error;
    const std::optional<MachineDescription> back = MachineFile::load(path, &error);
    QVERIFY2(back, qPrintable(error.text()));
    QVERIFY(*back == *m);
    QVERIFY(!MachineFile::load(dir.filePath("missing.json"), &error));
    QVERIFY(error.message.contains("missing.json"));
}

void TestMachineFile::singleController_keepsControllerAxesInSteps_andValidates()
{
    for (const ModelInfo& model : models()) {
        const MachineDescription m = MachineDescription::singleController(model, "/dev/ttyS0");
        MachineFileError error;
        QVERIFY2(MachineFile::validate(m, &error), qPrintable(model.id + ": " + error.text()));
        QCOMPARE(m.controllers.size(), 1);
        QCOMPARE(m.axes.size(), model.capabilities.axes.size());
        for (const MachineAxis& a : m.axes) {
            QCOMPARE(a.name, axisName(a.axis));
            QCOMPARE(a.unit, AxisUnit::Step);
            QCOMPARE(a.toSteps(123), qint64(123));
        }
    }
    const MachineDescription bus = MachineDescription::singleController(
        *findModel("nanotec"), "/dev/ttyS0", {{Axis::X, 7}, {Axis::U, 9}});
    QCOMPARE(bus.axes.size(), 2);
    QCOMPARE(bus.axes.at(1).name, QStringLiteral("U"));
    QVERIFY(MachineFile::validate(bus, nullptr));
}

void TestMachineFile::toSteps_nearestWholeStep_andBack_data()
{
    QTest::addColumn<double>("stepsPerUnit");
    QTest::addColumn<bool>("invert");
    QTest::addColumn<double>("units");
    QTest::addColumn<qint64>("steps");
    QTest::addColumn<double>("shown");
    QTest::newRow("400/mm") << 400.0 << false << 2.5 << qint64(1000) << 2.5;
    QTest::newRow("100/deg") << 100.0 << false << 90.0 << qint64(9000) << 90.0;
    QTest::newRow("rounded up") << 88.8889 << false << 1.0 << qint64(89) << 89 / 88.8889;
    QTest::newRow("rounded down") << 3.0 << false << 0.1 << qint64(0) << 0.0;
    QTest::newRow("inverted") << 400.0 << true << 2.5 << qint64(-1000) << 2.5;
    QTest::newRow("negative") << 400.0 << false << -0.00126 << qint64(-1) << -0.0025;
}

void TestMachineFile::toSteps_nearestWholeStep_andBack()
{
    QFETCH(double, stepsPerUnit);
    QFETCH(bool, invert);
    QFETCH(double, units);
    QFETCH(qint64, steps);
    QFETCH(double, shown);
    MachineAxis a;
    a.stepsPerUnit = stepsPerUnit;
    a.invert = invert;
    QCOMPARE(a.toSteps(units), steps);
    // What is shown is the step count the device holds, converted back.
    QCOMPARE(a.toUnits(a.toSteps(units)), shown);
}

void TestMachineFile::referenceGroups_lowestOrderFirst()
{
    const std::optional<MachineDescription> m =
        MachineFile::parse(bytes(tableAndRotary()), nullptr);
    QVERIFY(m);
    const QList<QList<const MachineAxis*>> groups = m->referenceGroups();
    QCOMPARE(groups.size(), 2);
    QCOMPARE(groups.at(0).size(), 2); // Z and A (order 0: A has no reference entry)
    QCOMPARE(groups.at(0).at(0)->name, QStringLiteral("Z"));
    QCOMPARE(groups.at(0).at(1)->name, QStringLiteral("A"));
    QCOMPARE(groups.at(1).at(0)->name, QStringLiteral("X"));
    QCOMPARE(groups.at(1).at(1)->name, QStringLiteral("Y"));
}

void TestMachineFile::shippedExamples_areValid()
{
    const QDir examples(QStringLiteral(STEPDECK_SOURCE_DIR "/docs/examples"));
    const QStringList files = examples.entryList({"*.machine.json"}, QDir::Files);
    QVERIFY2(files.size() >= 2, qPrintable(examples.path()));
    for (const QString& name : files) {
        MachineFileError error;
        QVERIFY2(MachineFile::load(examples.filePath(name), &error),
                 qPrintable(name + ": " + error.text()));
    }
}

// Issue 28, item 1: controllers[i].setup names a parameter file (as `export` writes it),
// read relative to the machine file's folder and validated against the controller's model;
// the description keeps the name as written (saved back unchanged) and the values.
void TestMachineFile::load_setupFile_readRelativeToTheMachineFileAndKept()
{
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("setups"));
    QVERIFY(writeFile(dir.filePath("setups/table.json"),
                      R"({"format": "stepdeck-parameters", "version": 1, "model": "elab",
                   "parameters": {"start-speed": {"X": 150, "Y": 120, "Z": 100}}})"));
    const QString path = dir.filePath("machine.json");
    QVERIFY(writeFile(path, withEdit("controllers.0.setup", QStringLiteral("setups/table.json"))));
    MachineFileError error;
    const std::optional<MachineDescription> m = MachineFile::load(path, &error);
    QVERIFY2(m, qPrintable(error.text()));
    const MachineController& table = m->controllers.at(0);
    QCOMPARE(table.setupFile, QStringLiteral("setups/table.json"));
    QCOMPARE(table.setup.value("start-speed").perAxis.value(Axis::Y).toLongLong(), 120);
    QVERIFY(m->controllers.at(1).setup.isEmpty());
    QCOMPARE(m->toJson()["controllers"].toArray().at(0).toObject()["setup"].toString(),
             QStringLiteral("setups/table.json"));
    // Saved beside its setup and read again: equal.
    QString why;
    QVERIFY2(MachineFile::save(*m, dir.filePath("again.json"), &why), qPrintable(why));
    const std::optional<MachineDescription> back =
        MachineFile::load(dir.filePath("again.json"), &error);
    QVERIFY2(back, qPrintable(error.text()));
    QVERIFY(*back == *m);
    QCOMPARE(back->controllers.at(0).setup, table.setup);
}

void TestMachineFile::load_setupFile_invalid_namesTheField_data()
{
    QTest::addColumn<QByteArray>("setup"); // the file's text; empty: no file
    QTest::addColumn<QString>("contains");
    QTest::newRow("missing file") << QByteArray() << "table.json";
    QTest::newRow("not JSON") << QByteArray("{ start-speed") << "table.json";
    QTest::newRow("another model's file")
        << QByteArray(R"({"format": "stepdeck-parameters", "version": 1, "model": "nanotec",
                         "parameters": {}})")
        << "nanotec";
    QTest::newRow("value out of range")
        << QByteArray(R"({"format": "stepdeck-parameters", "version": 1, "model": "elab",
                         "parameters": {"start-speed": {"X": 99999999, "Y": 1, "Z": 1}}})")
        << "start-speed";
    QTest::newRow("no parameter")
        << QByteArray(R"({"format": "stepdeck-parameters", "version": 1, "model": "elab",
                         "parameters": {}})")
        << "no parameter";
}

void TestMachineFile::load_setupFile_invalid_namesTheField()
{
    QFETCH(QByteArray, setup);
    QFETCH(QString, contains);
    QTemporaryDir dir;
    if (!setup.isEmpty())
        QVERIFY(writeFile(dir.filePath("table.json"), setup));
    const QString path = dir.filePath("machine.json");
    QVERIFY(writeFile(path, withEdit("controllers.0.setup", QStringLiteral("table.json"))));
    MachineFileError error;
    QVERIFY(!MachineFile::load(path, &error));
    QCOMPARE(error.field, QStringLiteral("controllers[0].setup"));
    QVERIFY2(error.message.contains(contains, Qt::CaseInsensitive), qPrintable(error.text()));
}

STEPDECK_TEST_GUILESS_MAIN(TestMachineFile)
#include "tst_machinefile.moc"
