// MachineStatus::toJson: the `stepdeck-cli status --json` contract (issue #2, section 5).
#include "TestMain.h"
#include "model/MachineStatus.h"
#include <QJsonArray>
#include <QRegularExpression>
#include <QtTest>

using namespace stepdeck;

namespace {
MachineStatus sample()
{
    MachineStatus s;
    s.driveOn = true;
    s.busy = true;
    s.panic = false;
    s.overTemperature = true;
    AxisStatus x;
    x.moving = true;
    x.position = -1234;
    x.positionKnown = true;
    AxisStatus y;
    y.jogging = true;
    y.positionEstimated = true;
    y.position = 5000000000LL; // beyond 32 bits
    AxisStatus z;
    z.limitSwitch = true;
    z.referenceSwitch = true;
    s.axes = {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}};
    s.raw = {{"machineState", 0x41}, {"axeState", 0x05}};
    s.temperatureCelsius = 42.5;
    return s;
}

// Every key at every level is lowerCamelCase (axis names are the exception by contract).
void verifyLowerCamelCase(const QJsonObject& o, const QString& where)
{
    static const QRegularExpression camel(QStringLiteral("^[a-z][a-zA-Z0-9]*$"));
    for (auto it = o.constBegin(); it != o.constEnd(); ++it) {
        const bool axisKey = where.endsWith(QLatin1String("axes"));
        QVERIFY2(axisKey ? axisFromName(it.key()).has_value() : camel.match(it.key()).hasMatch(),
                 qPrintable(where + "/" + it.key()));
        if (it.value().isObject() && !where.endsWith(QLatin1String("raw")))
            verifyLowerCamelCase(it.value().toObject(), where + "/" + it.key());
    }
}
} // namespace

class TestMachineStatus : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void toJson_topLevelKeys();
    void toJson_machineFlags_areBooleans_data();
    void toJson_machineFlags_areBooleans();
    void toJson_axisKeys_areBooleansAndNumbers_data();
    void toJson_axisKeys_areBooleansAndNumbers();
    void toJson_keys_areLowerCamelCase();
    void toJson_temperature_nullWhenUnknown();
    void toJson_raw_keepsTheWords();
    void anyLimitSwitch_anyMoving();
    void toJson_digitalIo_onlyWhenReported();
};

void TestMachineStatus::toJson_topLevelKeys()
{
    const QJsonObject j = sample().toJson("elab");
    QCOMPARE(j.value("model").toString(), QStringLiteral("elab"));
    QVERIFY(j.value("machine").isObject());
    QVERIFY(j.value("axes").isObject());
    QVERIFY(j.value("raw").isObject());
    QVERIFY(j.contains("temperatureCelsius"));
    QCOMPARE(j.value("axes").toObject().keys(), (QStringList{"X", "Y", "Z"}));
}

void TestMachineStatus::toJson_machineFlags_areBooleans_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<bool>("expected");
    QTest::newRow("driveOn") << "driveOn" << true;
    QTest::newRow("spindleOn") << "spindleOn" << false;
    QTest::newRow("busy") << "busy" << true;
    QTest::newRow("overTemperature") << "overTemperature" << true;
    QTest::newRow("setupIncomplete") << "setupIncomplete" << false;
    QTest::newRow("panic") << "panic" << false;
}

void TestMachineStatus::toJson_machineFlags_areBooleans()
{
    QFETCH(QString, key);
    QFETCH(bool, expected);
    const QJsonObject machine = sample().toJson("elab").value("machine").toObject();
    QVERIFY2(machine.value(key).isBool(), qPrintable(key));
    QCOMPARE(machine.value(key).toBool(), expected);
}

void TestMachineStatus::toJson_axisKeys_areBooleansAndNumbers_data()
{
    QTest::addColumn<QString>("axis");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QJsonValue>("expected");
    QTest::newRow("X moving") << "X"
                              << "moving" << QJsonValue(true);
    QTest::newRow("X jogging") << "X"
                               << "jogging" << QJsonValue(false);
    QTest::newRow("X position") << "X"
                                << "position" << QJsonValue(-1234);
    QTest::newRow("X positionEstimated") << "X"
                                         << "positionEstimated" << QJsonValue(false);
    QTest::newRow("Y jogging") << "Y"
                               << "jogging" << QJsonValue(true);
    QTest::newRow("Y position 64-bit") << "Y"
                                       << "position" << QJsonValue(5000000000.0);
    QTest::newRow("Y positionEstimated") << "Y"
                                         << "positionEstimated" << QJsonValue(true);
    QTest::newRow("Z limitSwitch") << "Z"
                                   << "limitSwitch" << QJsonValue(true);
    QTest::newRow("Z referenceSwitch") << "Z"
                                       << "referenceSwitch" << QJsonValue(true);
    QTest::newRow("Z moving") << "Z"
                              << "moving" << QJsonValue(false);
}

void TestMachineStatus::toJson_axisKeys_areBooleansAndNumbers()
{
    QFETCH(QString, axis);
    QFETCH(QString, key);
    QFETCH(QJsonValue, expected);
    const QJsonObject a = sample().toJson("elab").value("axes").toObject().value(axis).toObject();
    QVERIFY2(a.contains(key), qPrintable(axis + "/" + key));
    QCOMPARE(a.value(key).type(), expected.type());
    QCOMPARE(a.value(key), expected);
}

void TestMachineStatus::toJson_keys_areLowerCamelCase()
{
    verifyLowerCamelCase(sample().toJson("elab"), QString());
}

void TestMachineStatus::toJson_temperature_nullWhenUnknown()
{
    MachineStatus s = sample();
    QCOMPARE(s.toJson("elab").value("temperatureCelsius").toDouble(), 42.5);
    s.temperatureCelsius.reset();
    QVERIFY(s.toJson("elab").value("temperatureCelsius").isNull());
}

void TestMachineStatus::toJson_raw_keepsTheWords()
{
    const QJsonObject raw = sample().toJson("elab").value("raw").toObject();
    QCOMPARE(raw.value("machineState").toInt(), 0x41);
    QCOMPARE(raw.value("axeState").toInt(), 0x05);
}

void TestMachineStatus::anyLimitSwitch_anyMoving()
{
    MachineStatus s;
    s.axes.insert(Axis::X, AxisStatus{});
    QVERIFY(!s.anyLimitSwitch());
    QVERIFY(!s.anyMoving());
    s.axes[Axis::X].jogging = true;
    QVERIFY(s.anyMoving());
    s.axes[Axis::X].limitSwitch = true;
    QVERIFY(s.anyLimitSwitch());
}

void TestMachineStatus::toJson_digitalIo_onlyWhenReported()
{
    MachineStatus s;
    QJsonObject json = s.toJson("elab");
    QVERIFY(!json.contains("inputs"));
    QVERIFY(!json.contains("outputs"));
    QVERIFY(!json.contains("device"));
    s.inputs = QList<bool>{true, false, false, false, false, false, false, true};
    s.outputs = {true, std::nullopt, false};
    s.deviceFirmware = "SMC-IC4 v1.07";
    json = s.toJson("emis");
    const QJsonArray inputs = json["inputs"].toArray();
    QCOMPARE(inputs.size(), 8);
    QVERIFY(inputs.first().isBool() && inputs.first().toBool());
    QVERIFY(!inputs.at(1).toBool(true));
    const QJsonArray outputs = json["outputs"].toArray();
    QCOMPARE(outputs.size(), 3);
    QVERIFY(outputs.at(0).toBool());
    QVERIFY(outputs.at(1).isNull()); // not switched in this session: unknown
    QCOMPARE(json["device"].toObject()["firmware"].toString(), QStringLiteral("SMC-IC4 v1.07"));
}

STEPDECK_TEST_GUILESS_MAIN(TestMachineStatus)
#include "tst_machinestatus.moc"
