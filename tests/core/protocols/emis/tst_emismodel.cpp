// The SMC-IC4 model data: line settings, capabilities, the schema's ranges and the console
// notation (that every schema word has a German translation: tst_translations).
#include "TestMain.h"
#include "protocols/emis/EmisModel.h"
#include <QtTest>

using namespace stepdeck;

class TestEmisModel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void line_115200_8N1();
    void capabilities_noStop_fourAxes_io();
    void schema_rangesFromManual();
    void traffic_controlNames_roundTrip();
    void traffic_badNotation_refused();
    void presentation_checksProgramCommands();
};

void TestEmisModel::line_115200_8N1()
{
    const LineSettings line = emis::lineSettings();
    QCOMPARE(line.baudRate, 115200);
    QCOMPARE(line.dataBits, 8);
    QCOMPARE(line.stopBits, 1);
    QCOMPARE(line.parity, LineSettings::Parity::None);
}

void TestEmisModel::capabilities_noStop_fourAxes_io()
{
    const Capabilities caps = emis::capabilities();
    QVERIFY(!caps.stopCommand);
    QVERIFY(!caps.panic);
    QCOMPARE(caps.axes, (QList<Axis>{Axis::X, Axis::Y, Axis::Z, Axis::U}));
    QVERIFY(!caps.has(MotionMode::Velocity)); // nothing that does not end by itself
    QVERIFY(!caps.has(MotionMode::Feed));
    QVERIFY(caps.has(MotionMode::Jog));
    QCOMPARE(caps.digitalInputs, 8);
    QCOMPARE(caps.digitalOutputs, 7);
    QVERIFY(caps.storedParameters && caps.inputPrograms);
    QVERIFY(!caps.referenceDirection);
    QVERIFY(!caps.positionReadback);
}

void TestEmisModel::schema_rangesFromManual()
{
    const ParameterSchema schema = emis::parameterSchema();
    const ParameterSpec* idle = schema.find("idle-current");
    QVERIFY(idle);
    QCOMPARE(idle->maximum, 25); // manual 6: 0 % to 25 %
    QVERIFY(!schema.validateScalar(*idle, 26).isEmpty());
    const ParameterSpec* resolution = schema.find("step-resolution");
    QCOMPARE(resolution->choices.size(), 9); // 1 .. 256 (9.7)
    QVERIFY(!schema.validateScalar(*resolution, "3").isEmpty());
    QVERIFY(schema.validateScalar(*resolution, "256").isEmpty());
    QVERIFY(!schema.find("reference-speed")->perAxis); // "#E9,400": one value (9.5)
    QVERIFY(schema.find("reference-switch-type")->perAxis);
    for (const ParameterSpec& spec : schema.specs())
        QVERIFY2(!spec.readable, qPrintable(spec.name)); // working values: no read command
}

void TestEmisModel::traffic_controlNames_roundTrip()
{
    const QByteArray wire("$Hx\x15\x11\x06 Ready! \x06\x07IJ7,1 t\x02\x03<\xff");
    const QString text = emis::formatTraffic(wire);
    QCOMPARE(text,
             QStringLiteral("$Hx<NAK><DC1><ACK> Ready! <ACK><BEL>IJ7,1 t<STX><ETX><x3C><xFF>"));
    QByteArray back;
    QString error;
    QVERIFY(emis::parseTraffic(text, &back, &error));
    QCOMPARE(back, wire + '\r'); // not ended by <CR>, <STX> or <ETX>: a <CR> is added
    QVERIFY(emis::parseTraffic("@V", &back, &error));
    QCOMPARE(back, QByteArray("@V\r"));
    QVERIFY(emis::parseTraffic("IJ8,1 x<stx>", &back, &error));
    QCOMPARE(back, QByteArray("IJ8,1 x\x02"));
}

void TestEmisModel::traffic_badNotation_refused()
{
    QByteArray bytes;
    QString error;
    QVERIFY(!emis::parseTraffic("A1,1<FOO>", &bytes, &error));
    QVERIFY2(error.contains("5"), qPrintable(error)); // the column of the "<"
    QVERIFY(!emis::parseTraffic(QStringLiteral("A1,1 \u00e4"), &bytes, &error));
}

void TestEmisModel::presentation_checksProgramCommands()
{
    const ModelPresentation p = emis::presentation();
    QVERIFY(p.checkProgramCommand);
    QVERIFY(p.checkProgramCommand("L1,x191").isEmpty());
    QVERIFY(p.checkProgramCommand(" W1500 ").isEmpty());
    QVERIFY(!p.checkProgramCommand("@IG").isEmpty());
    QVERIFY(!p.checkProgramCommand("W-5").isEmpty());
    QVERIFY(!p.checkProgramCommand(QStringLiteral("L1,x\u00e41")).isEmpty());
    QCOMPARE(p.statusWords({}).first().key, QStringLiteral("inputs"));
    QCOMPARE(p.statusWords({}).first().bits.size(), 8);
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisModel)
#include "tst_emismodel.moc"
