// LaserBridgeConfig: the axis map, scale, reference directions and door input as typed on the
// command line and in the GUI, checked against the controller behind.
#include "TestMain.h"
#include "bridge/LaserBridgeConfig.h"
#include <QtTest>

using namespace stepdeck;
using stepdeck::bridge::LaserBridgeConfig;

class TestLaserBridgeConfig : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parseMap_valid();
    void parseMap_invalid_data();
    void parseMap_invalid();
    void parseScale_data();
    void parseScale();
    void parseHome_validAndInvalid();
    void referenceRequest_followsController_data();
    void referenceRequest_followsController();
    void parseDoorInput_decimalOnly();
    void validate_againstController();
    void defaults_identityMapScaleOne();
};

void TestLaserBridgeConfig::parseMap_valid()
{
    QMap<Axis, Axis> map;
    QString error;
    QVERIFY(LaserBridgeConfig::parseMap("1=Z,3=x", &map, &error));
    QCOMPARE(map, (QMap<Axis, Axis>{{Axis::X, Axis::Z}, {Axis::Z, Axis::X}}));
    LaserBridgeConfig cfg;
    cfg.axisMap = map;
    QCOMPARE(cfg.mapText(), QStringLiteral("1=Z,3=X"));
}

void TestLaserBridgeConfig::parseMap_invalid_data()
{
    QTest::addColumn<QString>("text");
    QTest::newRow("empty") << "";
    QTest::newRow("laser axis 4") << "4=X";
    QTest::newRow("laser axis 0") << "0=X";
    QTest::newRow("octal-looking") << "01x=X";
    QTest::newRow("hex") << "0x1=X";
    QTest::newRow("nan") << "nan=X";
    QTest::newRow("fraction") << "1.0=X";
    QTest::newRow("huge") << "99999999999999999999=X";
    QTest::newRow("no axis") << "1=";
    QTest::newRow("bad axis") << "1=Q";
    QTest::newRow("twice") << "1=X,1=Y";
    QTest::newRow("no pair") << "X";
}

void TestLaserBridgeConfig::parseMap_invalid()
{
    QFETCH(QString, text);
    QMap<Axis, Axis> map{{Axis::X, Axis::Y}};
    QString error;
    QVERIFY(!LaserBridgeConfig::parseMap(text, &map, &error));
    QVERIFY(error.startsWith("--map"));
    QCOMPARE(map, (QMap<Axis, Axis>{{Axis::X, Axis::Y}})); // untouched
}

void TestLaserBridgeConfig::parseScale_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<double>("value");
    QTest::newRow("integer") << "2" << true << 2.0;
    QTest::newRow("fraction") << "0.5" << true << 0.5;
    QTest::newRow("max") << "1000000" << true << 1e6;
    QTest::newRow("zero") << "0" << false << 0.0;
    QTest::newRow("negative") << "-1" << false << 0.0;
    QTest::newRow("too big") << "1e7" << false << 0.0;
    QTest::newRow("nan") << "nan" << false << 0.0;
    QTest::newRow("inf") << "inf" << false << 0.0;
    QTest::newRow("text") << "two" << false << 0.0;
    // The one notation of NumberParsing: blanks around and a sign are fine, nothing else.
    QTest::newRow("blanks, sign") << " +2.5 " << true << 2.5;
    QTest::newRow("exponent") << "1e3" << true << 1000.0;
    QTest::newRow("hex") << "0x10" << false << 0.0;
    QTest::newRow("hex float") << "0x1p3" << false << 0.0;
    QTest::newRow("comma") << "1,5" << false << 0.0;
    QTest::newRow("beyond double") << "1e400" << false << 0.0;
    QTest::newRow("-inf") << "-Infinity" << false << 0.0;
}

void TestLaserBridgeConfig::parseScale()
{
    QFETCH(QString, text);
    QFETCH(bool, ok);
    QFETCH(double, value);
    double scale = 1;
    QString error;
    QCOMPARE(LaserBridgeConfig::parseScale(text, &scale, &error), ok);
    if (ok)
        QCOMPARE(scale, value);
    else
        QVERIFY(error.contains("--scale"));
}

void TestLaserBridgeConfig::parseHome_validAndInvalid()
{
    QMap<Axis, int> dirs;
    QString error;
    QVERIFY(LaserBridgeConfig::parseHome("X=-1,Y=1", &dirs, &error));
    QCOMPARE(dirs, (QMap<Axis, int>{{Axis::X, -1}, {Axis::Y, 1}}));
    QVERIFY(LaserBridgeConfig::parseHome("X=+1,Y=-01", &dirs, &error));
    QCOMPARE(dirs, (QMap<Axis, int>{{Axis::X, 1}, {Axis::Y, -1}}));
    for (const char* bad : {"X=0", "X=2", "X=-1,X=1", "X", "Q=1", "X=+1x", "X=nan", "X=-1.0",
                            "X=0x1", "X=-99999999999999999999"})
        QVERIFY2(!LaserBridgeConfig::parseHome(bad, &dirs, &error), bad);
}

void TestLaserBridgeConfig::referenceRequest_followsController_data()
{
    QTest::addColumn<bool>("directed"); // Capabilities::referenceDirection
    QTest::addColumn<int>("x");
    QTest::addColumn<int>("y");
    QTest::newRow("directed: configured or -1") << true << -1 << 1;
    QTest::newRow("controller chooses: 1") << false << 1 << 1;
}

void TestLaserBridgeConfig::referenceRequest_followsController()
{
    QFETCH(bool, directed);
    QFETCH(int, x);
    QFETCH(int, y);
    Capabilities caps;
    caps.axes = {Axis::X, Axis::Y};
    caps.referenceDirection = directed;
    LaserBridgeConfig cfg;
    cfg.axisMap = {{Axis::X, Axis::X}, {Axis::Y, Axis::Y}};
    if (directed)
        cfg.homeDirections = {{Axis::Y, 1}};
    QCOMPARE(cfg.validate(caps), QString());
    QCOMPARE(cfg.referenceRequest(Axis::X, caps), x);
    QCOMPARE(cfg.referenceRequest(Axis::Y, caps), y);
}

void TestLaserBridgeConfig::parseDoorInput_decimalOnly()
{
    int input = 0;
    QString error;
    QVERIFY(LaserBridgeConfig::parseDoorInput("3", &input, &error));
    QCOMPARE(input, 3);
    QVERIFY(LaserBridgeConfig::parseDoorInput("010", &input, &error));
    QCOMPARE(input, 10); // decimal, not octal
    QVERIFY(LaserBridgeConfig::parseDoorInput(" +4 ", &input, &error));
    QCOMPARE(input, 4);
    for (const char* bad : {"0", "65", "0x3", "-1", "x", "nan", "3.0", "1e1", "99999999999"})
        QVERIFY2(!LaserBridgeConfig::parseDoorInput(bad, &input, &error), bad);
}

void TestLaserBridgeConfig::validate_againstController()
{
    Capabilities twoAxes;
    twoAxes.axes = {Axis::X, Axis::Y};
    LaserBridgeConfig cfg;
    QVERIFY(cfg.validate(twoAxes).contains("no axis Z")); // default map has Z
    cfg.axisMap = {{Axis::X, Axis::X}, {Axis::Y, Axis::Y}};
    QCOMPARE(cfg.validate(twoAxes), QString());
    cfg.axisMap = {{Axis::X, Axis::X}, {Axis::Y, Axis::X}};
    QVERIFY(cfg.validate(twoAxes).contains("two laser axes"));
    cfg.axisMap = {{Axis::X, Axis::X}};
    cfg.homeDirections = {{Axis::Y, 1}};
    QVERIFY(cfg.validate(twoAxes).contains("--home"));
    // A controller that chooses the direction of its reference runs (EMIS): no --home at all.
    Capabilities undirected = twoAxes;
    undirected.referenceDirection = false;
    cfg.homeDirections = {{Axis::X, 1}};
    QVERIFY(cfg.validate(undirected).contains("chooses the direction"));
    cfg.homeDirections.clear();
    QCOMPARE(cfg.validate(undirected), QString());
    cfg.scale = 0;
    QVERIFY(!cfg.validate(twoAxes).isEmpty());
    cfg.axisMap.clear();
    cfg.scale = 1;
    QVERIFY(cfg.validate(twoAxes).contains("empty"));
}

void TestLaserBridgeConfig::defaults_identityMapScaleOne()
{
    const LaserBridgeConfig cfg;
    QCOMPARE(cfg.mapText(), QStringLiteral("1=X,2=Y,3=Z"));
    QCOMPARE(cfg.scale, 1.0);
    QVERIFY(!cfg.doorInput);
}

STEPDECK_TEST_GUILESS_MAIN(TestLaserBridgeConfig)
#include "tst_laserbridgeconfig.moc"
