// The machine file's versions and optional keys: version 1 bus objects read as they stand and
// written as version 2 (issue 32), version 2 named buses, the spindle scale (issue 29) and
// crossControllerFeed (issue 30), each read, written and read back.
#include "MachineFileTestSupport.h"
#include "TestMain.h"
#include "machine/MachineFile.h"
#include "protocols/Registry.h"
#include <QTemporaryDir>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::test;

class TestMachineFileFormat : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void version1_busObject_readAsItStandsWrittenAsVersion2();
    void version2_namedBus_readWrittenAndReadBack();
    void version2_namedBus_invalid_namesTheField_data();
    void version2_namedBus_invalid_namesTheField();
    void spindle_maxRpm_roundTripAndOldFilesUnchanged();
    void spindle_maxRpmWithoutASpindleController_refused();
    void crossControllerFeed_roundTripAndOldFilesUnchanged();
    void limits_readWrittenAndReadBack_data();
    void limits_readWrittenAndReadBack();
    void limits_unknownValue_refusedNamingTheField_data();
    void limits_unknownValue_refusedNamingTheField();
    void subroutineFolder_resolvedAgainstTheFileAndWrittenAsItStands();
    void toolLength_touchOffRoundTripTableLeftOut();
};

// Issue 32: a version 1 bus object {"X": 1} reads as the same axes and addresses and is
// written back as version 2, a list in axis order, which reads back equal.
void TestMachineFileFormat::version1_busObject_readAsItStandsWrittenAsVersion2()
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

void TestMachineFileFormat::version2_namedBus_readWrittenAndReadBack()
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
    QCOMPARE(m->controllerAxisName(*m->axis("A")), QStringLiteral("tilt"));
    QCOMPARE(m->controllerAxisName(*m->axis("X")), QStringLiteral("X")); // the E-LAB's
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

void TestMachineFileFormat::version2_namedBus_invalid_namesTheField_data()
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

void TestMachineFileFormat::version2_namedBus_invalid_namesTheField()
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
void TestMachineFileFormat::spindle_maxRpm_roundTripAndOldFilesUnchanged()
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
    // Issue 50 item 5: "laser" with the scale, read, written and read back; it counts in equality.
    const std::optional<MachineDescription> laser = MachineFile::parse(
        withEdit("spindle", QJsonObject{{"maxRpm", 1000}, {"laser", true}}), &error);
    QVERIFY2(laser, qPrintable(error.text()));
    QVERIFY(laser->spindle.laser);
    QCOMPARE(laser->toJson().value("spindle").toObject(),
             (QJsonObject{{"maxRpm", 1000}, {"laser", true}}));
    QVERIFY(!(*laser == *scaled));
    QVERIFY(!scaled->spindle.laser);

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
void TestMachineFileFormat::crossControllerFeed_roundTripAndOldFilesUnchanged()
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

// Issue 50: "limits" is "clamp" (the default, also without the key: a feed above the machine's
// highest runs at it) or "refuse"; read, written and read back equal. A clamping machine is
// written without the key, so files of before issue 50 stay as they were.
void TestMachineFileFormat::limits_readWrittenAndReadBack_data()
{
    QTest::addColumn<QJsonValue>("value"); // undefined: the key left out
    QTest::addColumn<int>("policy");       // LimitPolicy
    QTest::addColumn<QJsonValue>("written");
    QTest::newRow("no key: clamp") << QJsonValue(QJsonValue::Undefined) << int(LimitPolicy::Clamp)
                                   << QJsonValue(QJsonValue::Undefined);
    QTest::newRow("clamp") << QJsonValue("clamp") << int(LimitPolicy::Clamp)
                           << QJsonValue(QJsonValue::Undefined);
    QTest::newRow("refuse") << QJsonValue("refuse") << int(LimitPolicy::Refuse)
                            << QJsonValue("refuse");
}

void TestMachineFileFormat::limits_readWrittenAndReadBack()
{
    QFETCH(QJsonValue, value);
    QFETCH(int, policy);
    QFETCH(QJsonValue, written);
    MachineFileError error;
    const std::optional<MachineDescription> d = MachineFile::parse(
        value.isUndefined() ? bytes(tableAndRotary()) : withEdit("limits", value), &error);
    QVERIFY2(d, qPrintable(error.text()));
    QCOMPARE(int(d->limits), policy);
    QCOMPARE(d->toJson().value("limits"), written);
    QTemporaryDir dir;
    const QString path = dir.filePath("machine.json");
    QString why;
    QVERIFY2(MachineFile::save(*d, path, &why), qPrintable(why));
    const std::optional<MachineDescription> back = MachineFile::load(path, &error);
    QVERIFY2(back, qPrintable(error.text()));
    QVERIFY(*back == *d);
    MachineDescription other = *d;
    other.limits = other.limits == LimitPolicy::Clamp ? LimitPolicy::Refuse : LimitPolicy::Clamp;
    QVERIFY(!(other == *d));
}

// Any other value is refused at the field, naming the two words: a typo must not leave a shop
// that wants refusals clamping.
void TestMachineFileFormat::limits_unknownValue_refusedNamingTheField_data()
{
    QTest::addColumn<QJsonValue>("value");
    QTest::newRow("another word") << QJsonValue("clip");
    QTest::newRow("wrong case") << QJsonValue("Refuse");
    QTest::newRow("a boolean") << QJsonValue(true);
    QTest::newRow("a number") << QJsonValue(1);
}

void TestMachineFileFormat::limits_unknownValue_refusedNamingTheField()
{
    QFETCH(QJsonValue, value);
    MachineFileError error;
    QVERIFY(!MachineFile::parse(withEdit("limits", value), &error));
    QCOMPARE(error.field, QStringLiteral("limits"));
    QVERIFY2(error.message.contains("\"clamp\"") && error.message.contains("\"refuse\""),
             qPrintable(error.message));
}

// Issue 33: "subroutineFolder" is read as written, resolved against the machine file's folder,
// written back as written; a file without it has none.
void TestMachineFileFormat::subroutineFolder_resolvedAgainstTheFileAndWrittenAsItStands()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("machine.json");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(withEdit("subroutineFolder", "subs"));
    file.close();
    MachineFileError error;
    const std::optional<MachineDescription> d = MachineFile::load(path, &error);
    QVERIFY2(d, qPrintable(error.text()));
    QCOMPARE(d->subroutineFolder, QStringLiteral("subs"));
    QCOMPARE(d->subroutineFolderPath, QDir(dir.path()).filePath("subs"));
    QCOMPARE(d->toJson().value("subroutineFolder"), QJsonValue("subs"));
    const std::optional<MachineDescription> old =
        MachineFile::parse(bytes(tableAndRotary()), &error);
    QVERIFY2(old, qPrintable(error.text()));
    QVERIFY(old->subroutineFolderPath.isEmpty());
    QVERIFY(!old->toJson().contains("subroutineFolder"));
    QVERIFY(!(*old == *d));
    QVERIFY(!MachineFile::parse(withEdit("subroutineFolder", 3), &error));
    QCOMPARE(error.field, QStringLiteral("subroutineFolder"));
}

// Issue 50 item 4: "toolLength": "touchOff" is read, written and read back; "table" is the
// default, the same as no key, and is written without it (older versions still read the file).
void TestMachineFileFormat::toolLength_touchOffRoundTripTableLeftOut()
{
    MachineFileError error;
    const std::optional<MachineDescription> touchOff =
        MachineFile::parse(withEdit("toolLength", "touchOff"), &error);
    QVERIFY2(touchOff, qPrintable(error.text()));
    QCOMPARE(touchOff->toolLength, ToolLength::TouchOff);
    QCOMPARE(touchOff->toJson().value("toolLength"), QJsonValue("touchOff"));
    QTemporaryDir dir;
    const QString path = dir.filePath("machine.json");
    QString why;
    QVERIFY2(MachineFile::save(*touchOff, path, &why), qPrintable(why));
    const std::optional<MachineDescription> back = MachineFile::load(path, &error);
    QVERIFY2(back, qPrintable(error.text()));
    QVERIFY(*back == *touchOff);
    const std::optional<MachineDescription> table =
        MachineFile::parse(withEdit("toolLength", "table"), &error);
    QVERIFY2(table, qPrintable(error.text()));
    QCOMPARE(table->toolLength, ToolLength::Table);
    QVERIFY(!table->toJson().contains("toolLength"));
    const std::optional<MachineDescription> old =
        MachineFile::parse(bytes(tableAndRotary()), &error);
    QVERIFY2(old, qPrintable(error.text()));
    QCOMPARE(old->toolLength, ToolLength::Table);
    QVERIFY(*old == *table);
    QVERIFY(!(*old == *touchOff));
}

void TestMachineFileFormat::spindle_maxRpmWithoutASpindleController_refused()
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
    d.spindle.maxRpm.reset();
    d.spindle.laser = true; // a laser needs the spindle output as well (issue 50 item 5)
    QVERIFY(!MachineFile::validate(d, &error));
    QCOMPARE(error.field, QStringLiteral("spindle.laser"));
    d = MachineDescription::singleController(*findModel("elab"), "sim");
    d.spindle.maxRpm = std::numeric_limits<double>::infinity();
    QVERIFY(!MachineFile::validate(d, &error));
    QCOMPARE(error.field, QStringLiteral("spindle.maxRpm"));
    d.spindle.maxRpm = 24000;
    QVERIFY2(MachineFile::validate(d, &error), qPrintable(error.text()));
}

STEPDECK_TEST_GUILESS_MAIN(TestMachineFileFormat)
#include "tst_machinefileformat.moc"
