// MachineFile: reading and validating "stepdeck-machine" files (issue 19). Every invalid file
// names the exact field; valid files come back as the description they spell.
#include "machine/MachineFile.h"
#include "protocols/Registry.h"
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::machine;

namespace {

// E-LAB XYZ table + Nanotec rotary A: the first example of docs/machines.md.
QJsonObject tableAndRotary()
{
    const QByteArray json = R"({
  "format": "stepdeck-machine", "version": 1, "name": "Engraver",
  "controllers": [
    {"id": "table", "model": "elab", "port": "/dev/ttyUSB0", "resetLine": "dtr"},
    {"id": "rotary", "model": "nanotec", "port": "/dev/ttyUSB1", "axes": {"X": 1}}
  ],
  "axes": [
    {"name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400,
     "softLimits": [0, 300], "maxJogSpeed": 2, "jogAcceleration": 8,
     "reference": {"direction": -1, "order": 1}},
    {"name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 400,
     "invert": true, "reference": {"order": 1}},
    {"name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 800,
     "reference": {"direction": 1, "order": 0}},
    {"name": "A", "controller": "rotary", "axis": "X", "unit": "deg", "stepsPerUnit": 88.8889}
  ]
})";
    return QJsonDocument::fromJson(json).object();
}

QByteArray bytes(const QJsonObject& o)
{
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

// Sets a value at a path such as "axes.2.stepsPerUnit" ("-" removes the key).
QJsonValue edited(const QJsonValue& at, QStringList path, const QJsonValue& value, bool remove)
{
    const QString key = path.takeFirst();
    if (at.isArray()) {
        QJsonArray array = at.toArray();
        const int index = key.toInt();
        array[index] = path.isEmpty() ? value : edited(array.at(index), path, value, remove);
        return array;
    }
    QJsonObject object = at.toObject();
    if (path.isEmpty()) {
        if (remove)
            object.remove(key);
        else
            object.insert(key, value);
    } else {
        object.insert(key, edited(object.value(key), path, value, remove));
    }
    return object;
}

QByteArray withEdit(const QString& path, const QJsonValue& value, bool remove = false)
{
    return bytes(edited(tableAndRotary(), path.split('.'), value, remove).toObject());
}

bool writeFile(const QString& path, const QByteArray& content)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
}

} // namespace

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
    void version1_busObject_readAsItStandsWrittenAsVersion2();
    void version2_namedBus_readWrittenAndReadBack();
    void version2_namedBus_invalid_namesTheField_data();
    void version2_namedBus_invalid_namesTheField();
    void spindle_maxRpm_roundTripAndOldFilesUnchanged();
    void spindle_maxRpmWithoutASpindleController_refused();
    void crossControllerFeed_roundTripAndOldFilesUnchanged();
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
                                 << "unknown key (known: maxRpm)";
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

// Issue 32: a version 1 bus object {"X": 1} reads as the same axes and addresses and is
// written back as version 2, a list in axis order, which reads back equal.
void TestMachineFile::version1_busObject_readAsItStandsWrittenAsVersion2()
{
    MachineFileError error;
    QJsonObject v1 = tableAndRotary();
    QJsonArray controllers = v1.value("controllers").toArray();
    QJsonObject rotary = controllers.at(1).toObject();
    rotary.insert("axes", QJsonObject{{"Y", 7}, {"X", 1}});
    controllers[1] = rotary;
    v1.insert("controllers", controllers);
    const std::optional<MachineDescription> old = MachineFile::parse(bytes(v1), &error);
    QVERIFY2(old, qPrintable(error.text()));
    QCOMPARE(old->controllers.at(1).busAddresses, (QMap<Axis, int>{{Axis::X, 1}, {Axis::Y, 7}}));
    QVERIFY(old->controllers.at(1).axisNames.isEmpty());
    const QJsonObject written = old->toJson();
    QCOMPARE(written.value("version").toInt(), 2);
    const QJsonArray bus =
        written.value("controllers").toArray().at(1).toObject().value("axes").toArray();
    QCOMPARE(bus, (QJsonArray{QJsonObject{{"name", "X"}, {"address", 1}},
                              QJsonObject{{"name", "Y"}, {"address", 7}}}));
    const std::optional<MachineDescription> back = MachineFile::parse(bytes(written), &error);
    QVERIFY2(back, qPrintable(error.text()));
    QVERIFY(*back == *old);
    // A version 2 file does not take the version 1 object, nor version 1 the list.
    QJsonObject mixed = written;
    mixed.insert("version", 1);
    QVERIFY(!MachineFile::parse(bytes(mixed), &error));
    QCOMPARE(error.field, QStringLiteral("controllers[1].axes"));
    v1.insert("version", 2);
    QVERIFY(!MachineFile::parse(bytes(v1), &error));
    QCOMPARE(error.field, QStringLiteral("controllers[1].axes"));
}

namespace {
// The rotary controller as a named bus: lift (5), tilt (6); machine axis A is tilt.
QJsonObject namedBus(const QJsonArray& bus, const QString& axisOfA)
{
    QJsonObject o = tableAndRotary();
    o.insert("version", 2);
    QJsonArray controllers = o.value("controllers").toArray();
    QJsonObject rotary = controllers.at(1).toObject();
    rotary.insert("axes", bus);
    controllers[1] = rotary;
    o.insert("controllers", controllers);
    QJsonArray axes = o.value("axes").toArray();
    QJsonObject a = axes.at(3).toObject();
    a.insert("axis", axisOfA);
    axes[3] = a;
    o.insert("axes", axes);
    return o;
}

QJsonArray liftAndTilt()
{
    return {QJsonObject{{"name", "lift"}, {"address", 5}},
            QJsonObject{{"name", "tilt"}, {"address", 6}}};
}
} // namespace

void TestMachineFile::version2_namedBus_readWrittenAndReadBack()
{
    MachineFileError error;
    const std::optional<MachineDescription> m =
        MachineFile::parse(bytes(namedBus(liftAndTilt(), "tilt")), &error);
    QVERIFY2(m, qPrintable(error.text()));
    const MachineController& rotary = m->controllers.at(1);
    QCOMPARE(rotary.busAddresses, (QMap<Axis, int>{{Axis::X, 5}, {Axis::Y, 6}}));
    QCOMPARE(rotary.axisNames.name(Axis::X), QStringLiteral("lift"));
    QCOMPARE(rotary.axisNames.name(Axis::Y), QStringLiteral("tilt"));
    QCOMPARE(m->axis("A")->axis, Axis::Y);
    const QJsonObject written = m->toJson();
    QCOMPARE(written.value("axes").toArray().at(3).toObject().value("axis").toString(),
             QStringLiteral("tilt"));
    QCOMPARE(written.value("controllers").toArray().at(1).toObject().value("axes").toArray(),
             liftAndTilt());
    QTemporaryDir dir;
    const QString path = dir.filePath("named.machine.json");
    QString why;
    QVERIFY2(MachineFile::save(*m, path, &why), qPrintable(why));
    const std::optional<MachineDescription> back = MachineFile::load(path, &error);
    QVERIFY2(back, qPrintable(error.text()));
    QVERIFY(*back == *m);
    // The names are part of the machine: renaming a drive is a change (the editor's
    // "modified"), and Machine passes them to the controller's options.
    MachineDescription renamed = *m;
    QVERIFY(renamed.controllers[1].axisNames.setName(Axis::X, QStringLiteral("raise"), &why));
    QVERIFY(!(renamed == *m));
}

void TestMachineFile::version2_namedBus_invalid_namesTheField_data()
{
    QTest::addColumn<QJsonArray>("bus");
    QTest::addColumn<QString>("axisOfA");
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("says");
    const QJsonArray good = liftAndTilt();
    QTest::newRow("default name of the named axis") << good << "Y"
                                                    << "axes[3].axis"
                                                    << "not an axis of its controller";
    QTest::newRow("name not on the bus") << good << "press"
                                         << "axes[3].axis"
                                         << "not an axis of its controller";
    QTest::newRow("object form") << QJsonArray() << "tilt"
                                 << "controllers[1].axes"
                                 << "must list the controller's axes";
    QTest::newRow("name twice") << QJsonArray{good.at(0),
                                              QJsonObject{{"name", "LIFT"}, {"address", 6}}}
                                << "lift"
                                << "controllers[1].axes"
                                << "LIFT is given twice";
    QTest::newRow("bad name") << QJsonArray{QJsonObject{{"name", "2nd"}, {"address", 5}}} << "X"
                              << "controllers[1].axes[0].name"
                              << "must be X, Y, Z, U or a letter";
    QTest::newRow("fractional address")
        << QJsonArray{QJsonObject{{"name", "lift"}, {"address", 5.5}}} << "lift"
        << "controllers[1].axes[0].address"
        << "whole bus address";
    QTest::newRow("unknown key") << QJsonArray{QJsonObject{{"name", "lift"}, {"adress", 5}}}
                                 << "lift"
                                 << "controllers[1].axes[0].adress"
                                 << "did you mean address";
    QTest::newRow("address twice")
        << QJsonArray{good.at(0), QJsonObject{{"name", "tilt"}, {"address", 5}}} << "tilt"
        << "controllers[1].axes.tilt"
        << "bus address 5 is given to two axes";
}

void TestMachineFile::version2_namedBus_invalid_namesTheField()
{
    QFETCH(QJsonArray, bus);
    QFETCH(QString, axisOfA);
    QFETCH(QString, field);
    QFETCH(QString, says);
    MachineFileError error;
    QVERIFY(!MachineFile::parse(bytes(namedBus(bus, axisOfA)), &error));
    QVERIFY2(error.field.startsWith(field), qPrintable(error.text()));
    QVERIFY2(error.message.contains(says), qPrintable(error.text()));
}

// Issue 29: "spindle": {"maxRpm": ...} is read, written and read back; a file without it
// reads as before (no scale) and is written without the key, as older versions read it.
void TestMachineFile::spindle_maxRpm_roundTripAndOldFilesUnchanged()
{
    MachineFileError error;
    const std::optional<MachineDescription> scaled =
        MachineFile::parse(withEdit("spindle", QJsonObject{{"maxRpm", 24000.5}}), &error);
    QVERIFY2(scaled, qPrintable(error.text()));
    QCOMPARE(scaled->spindle.maxRpm, 24000.5);
    QCOMPARE(scaled->toJson().value("spindle").toObject(), (QJsonObject{{"maxRpm", 24000.5}}));
    QTemporaryDir dir;
    const QString path = dir.filePath("machine.json");
    QString why;
    QVERIFY2(MachineFile::save(*scaled, path, &why), qPrintable(why));
    const std::optional<MachineDescription> back = MachineFile::load(path, &error);
    QVERIFY2(back, qPrintable(error.text()));
    QCOMPARE(back->spindle.maxRpm, 24000.5);
    QVERIFY(*back == *scaled);

    const std::optional<MachineDescription> old =
        MachineFile::parse(bytes(tableAndRotary()), &error);
    QVERIFY2(old, qPrintable(error.text()));
    QVERIFY(!old->spindle.maxRpm);
    QVERIFY(!(*old == *scaled)); // the scale counts in equality (the editor's "modified")
    const QJsonObject written = old->toJson();
    QVERIFY(!written.contains("spindle"));
    QCOMPARE(written.value("version").toInt(), 2);
}

// Issue 30: "crossControllerFeed": false is read, written and read back; a file without it
// allows such moves and is written without the key.
void TestMachineFile::crossControllerFeed_roundTripAndOldFilesUnchanged()
{
    MachineFileError error;
    const std::optional<MachineDescription> strict =
        MachineFile::parse(withEdit("crossControllerFeed", false), &error);
    QVERIFY2(strict, qPrintable(error.text()));
    QVERIFY(!strict->crossControllerFeed);
    QCOMPARE(strict->toJson().value("crossControllerFeed"), QJsonValue(false));
    QTemporaryDir dir;
    const QString path = dir.filePath("machine.json");
    QString why;
    QVERIFY2(MachineFile::save(*strict, path, &why), qPrintable(why));
    const std::optional<MachineDescription> back = MachineFile::load(path, &error);
    QVERIFY2(back, qPrintable(error.text()));
    QVERIFY(*back == *strict);
    const std::optional<MachineDescription> old =
        MachineFile::parse(bytes(tableAndRotary()), &error);
    QVERIFY2(old, qPrintable(error.text()));
    QVERIFY(old->crossControllerFeed);
    QVERIFY(!(*old == *strict));
    QVERIFY(!old->toJson().contains("crossControllerFeed"));
}

void TestMachineFile::spindle_maxRpmWithoutASpindleController_refused()
{
    MachineDescription d = MachineDescription::singleController(*findModel("nanotec"), "sim");
    QVERIFY(MachineFile::validate(d, nullptr));
    d.spindle.maxRpm = 24000;
    MachineFileError error;
    QVERIFY(!MachineFile::validate(d, &error));
    QCOMPARE(error.field, QStringLiteral("spindle.maxRpm"));
    QCOMPARE(error.message,
             QStringLiteral("no controller of this machine switches a spindle: leave \"spindle\" "
                            "out"));
    d = MachineDescription::singleController(*findModel("elab"), "sim");
    d.spindle.maxRpm = std::numeric_limits<double>::infinity();
    QVERIFY(!MachineFile::validate(d, &error));
    QCOMPARE(error.field, QStringLiteral("spindle.maxRpm"));
    d.spindle.maxRpm = 24000;
    QVERIFY2(MachineFile::validate(d, &error), qPrintable(error.text()));
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

QTEST_GUILESS_MAIN(TestMachineFile)
#include "tst_machinefile.moc"
