// LaserBridge end to end with every model behind it, both links through real serial ports:
// the scripted laser on one pseudo-terminal, the model's simulator on a second one. Each laser
// axis is homed and moved; the test asserts the frames the laser got and where the simulated
// device stands.
#include "LaserBridgeRig.h"
#include "TestMain.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/emis/EmisSimulator.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "protocols/nanotec/NanotecSimulator.h"

using namespace stepdeck;
using namespace stepdeck::laser;
using stepdeck::test::LaserBridgeRig;
using Kind = stepdeck::bridge::LaserBridge::LogEntry::Kind;

namespace {
constexpr qint64 kModelsElabReference = -300; // E-LAB reference switches (device steps)

// The device behind made quick and given reference switches, as a machine would have them.
void prepareDevice(LaserBridgeRig& rig, const QString& model)
{
    if (model == QLatin1String("elab")) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            rig.simOnPty<elab::ElabSimulator>()->setReferencePosition(a, kModelsElabReference, 5);
    } else if (model == QLatin1String("nanotec")) {
        for (nanotec::NanotecDrive* d : rig.simOnPty<nanotec::NanotecSimulator>()->drives())
            d->setSwitches(-150, 50000);
    } else if (model == QLatin1String("emis")) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            rig.simOnPty<emis::EmisSimulator>()->setSwitchPosition(a, -20);
    } else if (model == QLatin1String("laser-axis")) {
        rig.simOnPty<LaserAxisSimulator>()->setSpeed(20000);
    }
}

// Where the device stands, in its own steps from the point its reference run made zero.
qint64 deviceFromReference(LaserBridgeRig& rig, const QString& model, Axis axis)
{
    if (model == QLatin1String("elab"))
        return rig.simOnPty<elab::ElabSimulator>()->position(axis) - kModelsElabReference;
    if (model == QLatin1String("nanotec"))
        return rig.simOnPty<nanotec::NanotecSimulator>()->drive(axis.index() + 1)->position();
    if (model == QLatin1String("emis"))
        return rig.simOnPty<emis::EmisSimulator>()->position(axis);
    return rig.simOnPty<LaserAxisSimulator>()->position(axis);
}

bool deviceStands(LaserBridgeRig& rig)
{
    return rig.ptySim->standingStill();
}
} // namespace

class TestLaserBridgeModels : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void everyModel_homeAndMovePerAxis_answeredAndDeviceThere_data();
    void everyModel_homeAndMovePerAxis_answeredAndDeviceThere();
};

void TestLaserBridgeModels::everyModel_homeAndMovePerAxis_answeredAndDeviceThere_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<qint64>("tolerance"); // device steps (E-LAB: its reference window)
    QTest::newRow("E-LAB") << QStringLiteral("elab") << qint64(5);
    QTest::newRow("Nanotec") << QStringLiteral("nanotec") << qint64(0);
    QTest::newRow("EMIS") << QStringLiteral("emis") << qint64(0);
    QTest::newRow("laser axes") << QStringLiteral("laser-axis") << qint64(0);
}

// With the bridge's default settings: the reference direction follows what the controller
// behind can do (EMIS chooses its own), every home is answered '2', every move '0' at its
// target, and the device stands there.
void TestLaserBridgeModels::everyModel_homeAndMovePerAxis_answeredAndDeviceThere()
{
    QFETCH(QString, model);
    QFETCH(qint64, tolerance);
    LaserBridgeRig rig;
    QVERIFY(rig.connectControllerOnPty(model));
    prepareDevice(rig, model);
    QVERIFY(rig.startBridge());
    const QMap<Axis, int> targets{{Axis::X, 120}, {Axis::Y, 80}, {Axis::Z, 40}};
    QList<StatusFrame> expected;
    for (auto it = targets.cbegin(); it != targets.cend(); ++it) {
        const Axis axis = it.key();
        rig.laserSends(encodeHome(axis));
        expected << StatusFrame{axis, 0, Status::HomeSwitch};
        QVERIFY2(rig.waitAnswers(int(expected.size())), qPrintable(rig.fromBridge));
        QCOMPARE(rig.answers(), expected);
        QVERIFY2(qAbs(deviceFromReference(rig, model, axis)) <= tolerance,
                 qPrintable(QString::number(deviceFromReference(rig, model, axis))));
        rig.laserSends(encodeMove(axis, it.value()));
        expected << StatusFrame{axis, it.value(), Status::TargetReached};
        QVERIFY2(rig.waitAnswers(int(expected.size())), qPrintable(rig.fromBridge));
        QCOMPARE(rig.answers(), expected);
        QVERIFY(deviceStands(rig));
        const qint64 at = deviceFromReference(rig, model, axis);
        QVERIFY2(qAbs(at - it.value()) <= tolerance, qPrintable(QString::number(at)));
    }
    QCOMPARE(rig.logCount(Kind::Error), 0);
    QCOMPARE(rig.logCount(Kind::Note, "referencing it first"), 0);
}

STEPDECK_TEST_MAIN(TestLaserBridgeModels)
#include "tst_laserbridge_models.moc"
