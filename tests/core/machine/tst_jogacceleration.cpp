// A machine axis' jog acceleration (issue 28 item 6): the file's jogAcceleration, or the
// default that stops a release from the axis' top jog speed within one unit, and the one
// ramp per controller (steps/s^2) that keeps every axis of it within its distance.
#include "TestMain.h"
#include "machine/Machine.h"
#include "protocols/Registry.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::machine;

namespace {

MachineAxis axis(const QString& name, Axis on, AxisUnit unit, double stepsPerUnit,
                 std::optional<double> maxJogSpeed = {})
{
    MachineAxis a;
    a.name = name;
    a.controller = QStringLiteral("table");
    a.axis = on;
    a.unit = unit;
    a.stepsPerUnit = stepsPerUnit;
    a.maxJogSpeed = maxJogSpeed;
    return a;
}

MachineDescription table(const QList<MachineAxis>& axes)
{
    MachineDescription d;
    d.name = QStringLiteral("Table");
    d.controllers = {{QStringLiteral("table"),
                      QStringLiteral("elab"),
                      QStringLiteral("sim"),
                      {},
                      {},
                      {},
                      {},
                      {}}};
    d.axes = axes;
    return d;
}

constexpr double kElabCeiling = 5000; // Capabilities::maxJogSpeed of the E-LAB, steps/s

} // namespace

class TestJogAcceleration : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void effective_default_stopsTopSpeedWithinOneUnit_data();
    void effective_default_stopsTopSpeedWithinOneUnit();
    void effective_fileValue_wins();
    void ramp_steepestAxisOfTheController_keepsEveryAxisWithinItsDistance();
    void ramp_singleController_keepsTheModelsDefault();
    void create_rampReachesTheControllersOptions();
};

void TestJogAcceleration::effective_default_stopsTopSpeedWithinOneUnit_data()
{
    QTest::addColumn<int>("unit");
    QTest::addColumn<double>("stepsPerUnit");
    QTest::addColumn<double>("maxJogSpeed"); // 0: none in the file
    QTest::addColumn<double>("expected");    // unit/s^2

    // 10 mm/s: 10^2 / 2 = 50 mm/s^2, 1 mm from 10 mm/s.
    QTest::newRow("mm, maxJogSpeed 10") << int(AxisUnit::Millimetre) << 400.0 << 10.0 << 50.0;
    // No maxJogSpeed: the E-LAB's 5000 steps/s / 400 = 12.5 mm/s.
    QTest::newRow("mm, controller ceiling")
        << int(AxisUnit::Millimetre) << 400.0 << 0.0 << 12.5 * 12.5 / 2;
    // A rotary axis stops within 1 deg.
    QTest::newRow("deg, 90 deg/s") << int(AxisUnit::Degree) << 100.0 << 90.0 << 4050.0;
}

void TestJogAcceleration::effective_default_stopsTopSpeedWithinOneUnit()
{
    QFETCH(int, unit);
    QFETCH(double, stepsPerUnit);
    QFETCH(double, maxJogSpeed);
    QFETCH(double, expected);
    const MachineAxis a = axis("X", Axis::X, AxisUnit(unit), stepsPerUnit,
                               maxJogSpeed > 0 ? std::optional<double>(maxJogSpeed) : std::nullopt);
    const std::optional<double> acc = a.effectiveJogAcceleration(kElabCeiling);
    QVERIFY(acc);
    QCOMPARE(*acc, expected);
    const double top = a.topJogSpeed(kElabCeiling);
    QCOMPARE(top * top / (2 * *acc), 1.0); // one unit from the top speed
}

void TestJogAcceleration::effective_fileValue_wins()
{
    MachineAxis a = axis("X", Axis::X, AxisUnit::Millimetre, 400, 10);
    a.jogAcceleration = 200;
    QCOMPARE(a.effectiveJogAcceleration(kElabCeiling), 200.0);
    // Counted in steps: no default (one step would be no ramp), the file's value if any.
    MachineAxis s = axis("X", Axis::X, AxisUnit::Step, 1);
    QVERIFY(!s.effectiveJogAcceleration(kElabCeiling));
    s.jogAcceleration = 3000;
    QCOMPARE(s.effectiveJogAcceleration(kElabCeiling), 3000.0);
}

void TestJogAcceleration::ramp_steepestAxisOfTheController_keepsEveryAxisWithinItsDistance()
{
    // X: 10 mm/s, 50 mm/s^2 at 400 steps/mm = 20000 steps/s^2. Z: 5 mm/s, 12.5 mm/s^2 at
    // 800 steps/mm = 10000 steps/s^2. Y: 2 mm/s and a file value of 2 mm/s^2 (800 steps/s^2).
    MachineAxis y = axis("Y", Axis::Y, AxisUnit::Millimetre, 400, 2);
    y.jogAcceleration = 2;
    const MachineDescription d = table({axis("X", Axis::X, AxisUnit::Millimetre, 400, 10), y,
                                        axis("Z", Axis::Z, AxisUnit::Millimetre, 800, 5)});
    const double ramp = d.jogRampAcceleration(QStringLiteral("table"), kElabCeiling);
    QCOMPARE(ramp, 20000.0);
    for (const MachineAxis& a : d.axes) {
        // Each axis from its top speed on this one ramp, in its unit.
        const double top = a.topJogSpeed(kElabCeiling);
        const double ownDistance = top * top / (2 * *a.effectiveJogAcceleration(kElabCeiling));
        const double stepsPerS = top * a.stepsPerUnit;
        const double travelled = stepsPerS * stepsPerS / (2 * ramp) / a.stepsPerUnit;
        QVERIFY2(
            travelled <= ownDistance + 1e-12,
            qPrintable(QStringLiteral("%1: %2 > %3").arg(a.name).arg(travelled).arg(ownDistance)));
    }
    QCOMPARE(d.jogRampAcceleration(QStringLiteral("other"), kElabCeiling), 0.0);
}

void TestJogAcceleration::ramp_singleController_keepsTheModelsDefault()
{
    const MachineDescription d =
        MachineDescription::singleController(*findModel(QStringLiteral("elab")), "sim");
    QCOMPARE(d.jogRampAcceleration(d.controllers.at(0).id, kElabCeiling), 0.0);
}

void TestJogAcceleration::create_rampReachesTheControllersOptions()
{
    Machine machine;
    QString error;
    QVERIFY2(machine.create(table({axis("X", Axis::X, AxisUnit::Millimetre, 400, 10)}), &error),
             qPrintable(error));
    QCOMPARE(machine.session("table")->spec().options.jogAccelerationStepsPerS2, 20000.0);
}

STEPDECK_TEST_MAIN(TestJogAcceleration)
#include "tst_jogacceleration.moc"
