// ParameterSchema: validation, CLI assignments and the JSON file format, using the E-LAB
// schema (issue #2, section 5) as the real-world example.
#include "NumberErrorMetaType.h"
#include "TestMain.h"
#include "model/ParameterSchema.h"
#include "protocols/elab/ElabModel.h"
#include <QJsonDocument>
#include <QtTest>

using namespace stepdeck;

namespace {
const QList<Axis> kXyz{Axis::X, Axis::Y, Axis::Z};

QJsonObject validFile()
{
    return QJsonDocument::fromJson(R"({
        "format": "stepdeck-parameters", "version": 1, "model": "elab",
        "parameters": {
            "start-speed": {"X": 100, "Y": 200, "Z": 300},
            "limit-polarity": {"X": "high", "Y": "low", "Z": "low"},
            "drive-power": 66,
            "coolant": true
        }})")
        .object();
}
} // namespace

class TestParameterSchema : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void elabSchema_hasTheDocumentedNames();
    void elabAcceleration_noUnitInManual_notesItInsteadOfGuessing();
    void validateScalar_ranges_data();
    void validateScalar_ranges();
    void parseAssignment_perAxisValues();
    void parseAssignment_singleValue_broadcastsToEveryAxis();
    void parseAssignment_wrongCount_isError();
    void parseAssignment_errors_data();
    void parseAssignment_errors();
    void parseAssignment_numbersAreDecimal_data();
    void parseAssignment_numbersAreDecimal();
    void json_roundTrip_keepsEveryValue();
    void fromJson_validFile_parses();
    void fromJson_brokenFile_namesTheCause_data();
    void fromJson_brokenFile_namesTheCause();
    void fromJson_numbers_data();
    void fromJson_numbers();

private:
    ParameterSchema m_schema = elab::parameterSchema();
};

void TestParameterSchema::elabSchema_hasTheDocumentedNames()
{
    for (const char* name :
         {"start-speed", "max-speed", "acceleration", "feed-speed", "limit-polarity",
          "reference-polarity", "drive-power", "spindle-rpm", "coolant"})
        QVERIFY2(m_schema.find(QString::fromLatin1(name)), name);
    QVERIFY(!m_schema.find(QStringLiteral("warp-speed")));
}

// Issue 31: the manual gives the acceleration no unit ("Je größer die Werte desto steiler
// ist die Rampe"). The unit column says so, with the manual's words as its tooltip; the unit
// itself stays empty (no guessed unit in messages or files), and a parameter with a unit
// shows only its unit.
void TestParameterSchema::elabAcceleration_noUnitInManual_notesItInsteadOfGuessing()
{
    const ParameterSpec* accel = m_schema.find(QStringLiteral("acceleration"));
    QVERIFY(accel);
    QVERIFY(accel->unit.isEmpty());
    QCOMPARE(ParameterSchema::displayUnitColumn(*accel), QStringLiteral("(no unit)"));
    QVERIFY2(ParameterSchema::displayUnitToolTip(*accel).contains(
                 QStringLiteral("the larger the value, the steeper the ramp")),
             qPrintable(ParameterSchema::displayUnitToolTip(*accel)));
    QCOMPARE(ParameterSchema::displayUnitSuffix(*accel), QString());
    const ParameterSpec* start = m_schema.find(QStringLiteral("start-speed"));
    QCOMPARE(ParameterSchema::displayUnitColumn(*start), QStringLiteral("steps/s"));
    QCOMPARE(ParameterSchema::displayUnitToolTip(*start), QString());
}

void TestParameterSchema::validateScalar_ranges_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QVariant>("value");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<QString>("range"); // must appear in the error

    // Unsigned 16-bit speeds (manual: "Word ohne Vorzeichen").
    QTest::newRow("speed 0") << "start-speed" << QVariant(0) << true << "";
    QTest::newRow("speed 65535") << "max-speed" << QVariant(65535) << true << "";
    QTest::newRow("speed 65536") << "max-speed" << QVariant(65536) << false << "0..65535";
    QTest::newRow("speed -1") << "feed-speed" << QVariant(-1) << false << "0..65535";
    QTest::newRow("speed as text") << "start-speed" << QVariant("1200") << true << "";
    QTest::newRow("speed garbage") << "start-speed" << QVariant("fast") << false << "0..65535";
    QTest::newRow("speed fraction") << "start-speed" << QVariant(12.5) << false << "0..65535";
    QTest::newRow("power 100") << "drive-power" << QVariant(100) << true << "";
    QTest::newRow("power 101") << "drive-power" << QVariant(101) << false << "0..100";
    QTest::newRow("rpm 1000") << "spindle-rpm" << QVariant(1000) << true << "";
    QTest::newRow("rpm 1001") << "spindle-rpm" << QVariant(1001) << false << "0..1000";
    QTest::newRow("polarity high") << "limit-polarity" << QVariant("high") << true << "";
    QTest::newRow("polarity HIGH") << "reference-polarity" << QVariant("HIGH") << true << "";
    QTest::newRow("polarity up") << "limit-polarity" << QVariant("up") << false << "high|low";
    QTest::newRow("coolant on") << "coolant" << QVariant("on") << true << "";
    QTest::newRow("coolant bool") << "coolant" << QVariant(false) << true << "";
    QTest::newRow("coolant maybe") << "coolant" << QVariant("maybe") << false << "on|off";
}

void TestParameterSchema::validateScalar_ranges()
{
    QFETCH(QString, name);
    QFETCH(QVariant, value);
    QFETCH(bool, valid);
    QFETCH(QString, range);

    const ParameterSpec* spec = m_schema.find(name);
    QVERIFY(spec);
    const QString error = m_schema.validateScalar(*spec, value);
    QCOMPARE(error.isEmpty(), valid);
    if (!valid) {
        // Named by the label the form shows, not by the key (issue 11).
        QVERIFY2(error.startsWith(spec->label + QLatin1Char(':')), qPrintable(error));
        QVERIFY2(!error.contains(name), qPrintable(error));
        QVERIFY2(error.contains(range), qPrintable(error));
    }
}

void TestParameterSchema::parseAssignment_perAxisValues()
{
    QString name, error;
    ParameterValue value;
    QVERIFY2(m_schema.parseAssignment("start-speed=100,200,300", kXyz, &name, &value, &error),
             qPrintable(error));
    QCOMPARE(name, QStringLiteral("start-speed"));
    QVERIFY(value.isPerAxis());
    QCOMPARE(value.perAxis.value(Axis::X).toLongLong(), 100);
    QCOMPARE(value.perAxis.value(Axis::Y).toLongLong(), 200);
    QCOMPARE(value.perAxis.value(Axis::Z).toLongLong(), 300);
    QCOMPARE(m_schema.formatValue(*m_schema.find(name), value), QStringLiteral("100,200,300"));
}

void TestParameterSchema::parseAssignment_singleValue_broadcastsToEveryAxis()
{
    QString name, error;
    ParameterValue value;
    QVERIFY2(m_schema.parseAssignment("limit-polarity=high", kXyz, &name, &value, &error),
             qPrintable(error));
    QCOMPARE(value.perAxis.size(), 3);
    for (Axis a : kXyz)
        QCOMPARE(value.perAxis.value(a).toString(), QStringLiteral("high"));

    QVERIFY(m_schema.parseAssignment("drive-power=66", kXyz, &name, &value, &error));
    QVERIFY(!value.isPerAxis());
    QCOMPARE(value.global.toLongLong(), 66);
}

void TestParameterSchema::parseAssignment_wrongCount_isError()
{
    QString name, error;
    ParameterValue value;
    QVERIFY(!m_schema.parseAssignment("start-speed=100,200", kXyz, &name, &value, &error));
    QVERIFY2(error.contains("start-speed") && error.contains("X,Y,Z"), qPrintable(error));
    error.clear();
    QVERIFY(!m_schema.parseAssignment("drive-power=10,20,30", kXyz, &name, &value, &error));
    QVERIFY2(error.contains("drive-power"), qPrintable(error));
}

void TestParameterSchema::parseAssignment_errors_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("mention");

    QTest::newRow("no equals") << "start-speed"
                               << "NAME=VALUE";
    QTest::newRow("no name") << "=5"
                             << "NAME=VALUE";
    QTest::newRow("unknown") << "warp-speed=9"
                             << "warp-speed";
    QTest::newRow("out of range on Y") << "max-speed=1,70000,1"
                                       << "0..65535";
    QTest::newRow("bad choice") << "reference-polarity=sideways"
                                << "high|low";
    QTest::newRow("power over") << "drive-power=150"
                                << "0..100";
}

void TestParameterSchema::parseAssignment_errors()
{
    QFETCH(QString, text);
    QFETCH(QString, mention);
    QString name, error;
    ParameterValue value;
    QVERIFY(!m_schema.parseAssignment(text, kXyz, &name, &value, &error));
    QVERIFY2(error.contains(mention), qPrintable(error));
}

void TestParameterSchema::parseAssignment_numbersAreDecimal_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<qint64>("value");            // -1: refused
    QTest::addColumn<NumberError>("numberError"); // how the text failed to be a number
    QTest::addColumn<QString>("mention");         // in the error
    const auto none = NumberError::None;
    QTest::newRow("leading zero is decimal") << "drive-power=0100" << qint64(100) << none << "";
    QTest::newRow("010 is ten") << "drive-power=010" << qint64(10) << none << "";
    QTest::newRow("plus sign") << "drive-power=+66" << qint64(66) << none << "";
    QTest::newRow("hex refused") << "drive-power=0x40" << qint64(-1) << NumberError::Malformed
                                 << "not a decimal integer";
    QTest::newRow("exponent refused")
        << "drive-power=1e2" << qint64(-1) << NumberError::Malformed << "0..100";
    QTest::newRow("nan") << "drive-power=nan" << qint64(-1) << NumberError::NonFinite
                         << "not a finite number";
    QTest::newRow("inf on one axis")
        << "start-speed=1,inf,1" << qint64(-1) << NumberError::NonFinite << "(Y)";
    QTest::newRow("beyond 64 bits") << "drive-power=99999999999999999999" << qint64(-1)
                                    << NumberError::OutOfRange << "out of range";
    QTest::newRow("in 64 bits, out of the parameter's range")
        << "drive-power=101" << qint64(-1) << none << "0..100";
}

void TestParameterSchema::parseAssignment_numbersAreDecimal()
{
    QFETCH(QString, text);
    QFETCH(qint64, value);
    QFETCH(NumberError, numberError);
    QFETCH(QString, mention);
    QString name, error;
    ParameterValue parsed;
    NumberError why = NumberError::Malformed;
    const bool ok = m_schema.parseAssignment(text, kXyz, &name, &parsed, &error, &why);
    QCOMPARE(ok, value >= 0);
    QCOMPARE(why, numberError);
    if (ok) {
        const QVariant got = parsed.isPerAxis() ? parsed.perAxis.value(Axis::X) : parsed.global;
        QCOMPARE(got.typeId(), int(QMetaType::LongLong));
        QCOMPARE(got.toLongLong(), value);
    } else {
        QVERIFY2(error.contains(mention), qPrintable(error));
    }
}

void TestParameterSchema::json_roundTrip_keepsEveryValue()
{
    ParameterSet set;
    for (const char* text :
         {"start-speed=100,200,300", "max-speed=5000", "acceleration=1000,1500,2000",
          "feed-speed=50", "limit-polarity=high,low,high", "reference-polarity=low",
          "drive-power=33", "spindle-rpm=1000", "coolant=on"}) {
        QString name, error;
        ParameterValue value;
        QVERIFY2(m_schema.parseAssignment(QString::fromLatin1(text), kXyz, &name, &value, &error),
                 qPrintable(error));
        set.insert(name, value);
    }
    const QJsonObject json = m_schema.toJson("elab", set);
    QCOMPARE(json.value("format").toString(), QStringLiteral("stepdeck-parameters"));
    QCOMPARE(json.value("version").toInt(), 1);
    QCOMPARE(json.value("model").toString(), QStringLiteral("elab"));
    // Through text, as a file would be.
    const QJsonObject reread = QJsonDocument::fromJson(QJsonDocument(json).toJson()).object();
    ParameterSet back;
    QString error;
    QVERIFY2(m_schema.fromJson(reread, "elab", kXyz, &back, &error), qPrintable(error));
    QCOMPARE(back.keys(), set.keys());
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = m_schema.find(it.key());
        QCOMPARE(m_schema.formatValue(*spec, back.value(it.key())),
                 m_schema.formatValue(*spec, it.value()));
        QVERIFY2(back.value(it.key()) == it.value(), qPrintable(it.key()));
    }
}

void TestParameterSchema::fromJson_validFile_parses()
{
    ParameterSet set;
    QString error;
    QVERIFY2(m_schema.fromJson(validFile(), "elab", kXyz, &set, &error), qPrintable(error));
    QCOMPARE(set.value("start-speed").perAxis.value(Axis::Z).toLongLong(), 300);
    QCOMPARE(set.value("limit-polarity").perAxis.value(Axis::X).toString(), QStringLiteral("high"));
    QCOMPARE(set.value("drive-power").global.toLongLong(), 66);
    QCOMPARE(set.value("coolant").global.toBool(), true);
}

void TestParameterSchema::fromJson_brokenFile_namesTheCause_data()
{
    QTest::addColumn<QString>("path");     // "parameters/NAME" or a top-level key
    QTest::addColumn<QJsonValue>("value"); // replaces the value at path (undefined: removes)
    QTest::addColumn<QStringList>("mentions");

    QTest::newRow("wrong format") << "format" << QJsonValue("something-else")
                                  << QStringList{"not a StepDeck parameter file"};
    QTest::newRow("no format") << "format" << QJsonValue(QJsonValue::Undefined)
                               << QStringList{"not a StepDeck parameter file"};
    QTest::newRow("wrong model") << "model" << QJsonValue("nanotec")
                                 << QStringList{"nanotec", "elab"};
    QTest::newRow("future version") << "version" << QJsonValue(2) << QStringList{"version 2"};
    QTest::newRow("no parameters")
        << "parameters" << QJsonValue(QJsonValue::Undefined) << QStringList{"parameters"};
    QTest::newRow("unknown name") << "parameters/warp-speed" << QJsonValue(5)
                                  << QStringList{"warp-speed"};
    QTest::newRow("power out of range")
        << "parameters/drive-power" << QJsonValue(150) << QStringList{"drive-power", "0..100"};
    QTest::newRow("speed out of range on Y")
        << "parameters/start-speed" << QJsonValue(QJsonObject{{"X", 1}, {"Y", 70000}, {"Z", 1}})
        << QStringList{"start-speed", "0..65535", "(Y)"};
    QTest::newRow("no such axis") << "parameters/max-speed"
                                  << QJsonValue(QJsonObject{{"X", 1}, {"W", 1}})
                                  << QStringList{"max-speed", "W"};
    QTest::newRow("axis U on a 3-axis machine")
        << "parameters/max-speed" << QJsonValue(QJsonObject{{"U", 1}})
        << QStringList{"max-speed", "axis U"};
    QTest::newRow("per-axis given as one value")
        << "parameters/feed-speed" << QJsonValue(10) << QStringList{"feed-speed", "per axis"};
    QTest::newRow("global given per axis")
        << "parameters/spindle-rpm" << QJsonValue(QJsonObject{{"X", 1}})
        << QStringList{"spindle-rpm", "single value"};
    QTest::newRow("bad choice") << "parameters/limit-polarity"
                                << QJsonValue(QJsonObject{{"X", "sideways"}})
                                << QStringList{"limit-polarity", "high|low"};
    QTest::newRow("text for a number")
        << "parameters/drive-power" << QJsonValue("lots") << QStringList{"drive-power", "0..100"};
}

void TestParameterSchema::fromJson_brokenFile_namesTheCause()
{
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    QFETCH(QStringList, mentions);

    QJsonObject file = validFile();
    if (path.startsWith("parameters/")) {
        QJsonObject params = file.value("parameters").toObject();
        params.insert(path.mid(11), value);
        file.insert("parameters", params);
    } else if (value.isUndefined()) {
        file.remove(path);
    } else {
        file.insert(path, value);
    }
    ParameterSet set;
    set.insert("untouched", ParameterValue{});
    QString error;
    QVERIFY(!m_schema.fromJson(file, "elab", kXyz, &set, &error));
    for (const QString& m : mentions)
        QVERIFY2(error.contains(m), qPrintable(QStringLiteral("'%1' lacks '%2'").arg(error, m)));
    // Validated before anything is returned: the output is left alone.
    QCOMPARE(set.keys(), QStringList{"untouched"});
}

// Numbers in files: JSON numbers are range-checked as doubles before any conversion (1e300 was
// undefined behaviour), text is decimal only.
void TestParameterSchema::fromJson_numbers_data()
{
    QTest::addColumn<QByteArray>("value"); // JSON text of "drive-power"
    QTest::addColumn<qint64>("expected");  // -1: refused
    QTest::addColumn<QString>("mention");
    QTest::newRow("integer") << QByteArray("66") << qint64(66) << "";
    QTest::newRow("whole double") << QByteArray("66.0") << qint64(66) << "";
    QTest::newRow("exponent that is whole") << QByteArray("6.6e1") << qint64(66) << "";
    QTest::newRow("decimal text") << QByteArray("\"0100\"") << qint64(100) << "";
    QTest::newRow("hex text") << QByteArray("\"0x40\"") << qint64(-1) << "not a decimal integer";
    QTest::newRow("octal-looking text") << QByteArray("\"010\"") << qint64(10) << "";
    QTest::newRow("1e300") << QByteArray("1e300") << qint64(-1) << "out of range";
    QTest::newRow("-1e300") << QByteArray("-1e300") << qint64(-1) << "out of range";
    QTest::newRow("2^63") << QByteArray("9223372036854775808") << qint64(-1) << "out of range";
    QTest::newRow("fraction") << QByteArray("12.5") << qint64(-1) << "not a decimal integer";
    QTest::newRow("nan text") << QByteArray("\"nan\"") << qint64(-1) << "not a finite number";
    QTest::newRow("boolean") << QByteArray("true") << qint64(-1) << "drive-power";
    QTest::newRow("null") << QByteArray("null") << qint64(-1) << "drive-power";
}

void TestParameterSchema::fromJson_numbers()
{
    QFETCH(QByteArray, value);
    QFETCH(qint64, expected);
    QFETCH(QString, mention);
    const QByteArray text = R"({"format":"stepdeck-parameters","version":1,"model":"elab",)"
                            R"("parameters":{"drive-power":)" +
                            value + "}}";
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(text, &parseError);
    QVERIFY2(doc.isObject(), qPrintable(parseError.errorString()));
    ParameterSet set;
    QString error;
    const bool ok = m_schema.fromJson(doc.object(), "elab", kXyz, &set, &error);
    QCOMPARE(ok, expected >= 0);
    if (ok)
        QCOMPARE(set.value("drive-power").global.toLongLong(), expected);
    else
        QVERIFY2(error.contains(mention), qPrintable(error));
}

STEPDECK_TEST_GUILESS_MAIN(TestParameterSchema)
#include "tst_parameterschema.moc"
