// "The jog stops where the operator lets go" (issue 28 item 6), asserted at the device: an
// E-LAB simulator on a pseudo-terminal jogs an axis at its full machine jog speed, the input
// is released, and the distance the simulated board travelled after the release is compared
// with the axis' stopping distance (jogAcceleration, or the default: 1 unit from maxJogSpeed).
// The E-LAB brakes a jog only by the rates the host sends ("Befehle im Jogbetrieb": zero
// stops the motor, the host makes the ramps); its own acceleration parameter (1000 steps/s^2,
// written below) is for positioning moves and plays no part.
#include "ModelBench.h"
#include "PtyDevice.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "protocols/elab/ElabCodec.h"
#include <QSignalSpy>
#include <QtTest>
#include <algorithm>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::machine;

namespace {

MachineDescription jogStopMachine(const QString& port, double maxJogSpeed,
                                  std::optional<double> jogAcceleration)
{
    MachineDescription d;
    d.name = QStringLiteral("Jog table");
    d.controllers = {{QStringLiteral("table"), QStringLiteral("elab"), port, {}, {}, {}, {}, {}}};
    MachineAxis x;
    x.name = QStringLiteral("X");
    x.controller = QStringLiteral("table");
    x.axis = Axis::X;
    x.unit = AxisUnit::Millimetre;
    x.stepsPerUnit = 400;
    x.maxJogSpeed = maxJogSpeed;
    x.jogAcceleration = jogAcceleration;
    d.axes = {x};
    return d;
}

} // namespace

class TestMachineJogStop : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void release_fromMaxJogSpeed_boardStandsWithinTheStoppingDistance_data();
    void release_fromMaxJogSpeed_boardStandsWithinTheStoppingDistance();
};

void TestMachineJogStop::release_fromMaxJogSpeed_boardStandsWithinTheStoppingDistance_data()
{
    QTest::addColumn<double>("maxJogSpeed");     // mm/s
    QTest::addColumn<double>("jogAcceleration"); // mm/s^2, 0: the default
    QTest::addColumn<double>("bound");           // mm

    // The case: 10 mm/s on 400 steps/mm coasted about 10 mm; the default stops it
    // within 1 mm.
    QTest::newRow("default, 10 mm/s") << 10.0 << 0.0 << 1.0;
    // The E-LAB's ceiling, 5000 steps/s = 12.5 mm/s: still within 1 mm.
    QTest::newRow("default, 12.5 mm/s") << 12.5 << 0.0 << 1.0;
    // The file's value: 10^2 / (2 x 100) = 0.5 mm.
    QTest::newRow("jogAcceleration 100, 10 mm/s") << 10.0 << 100.0 << 0.5;
}

void TestMachineJogStop::release_fromMaxJogSpeed_boardStandsWithinTheStoppingDistance()
{
    QFETCH(double, maxJogSpeed);
    QFETCH(double, jogAcceleration);
    QFETCH(double, bound);

    test::PtyDevice board("elab");
    Machine machine;
    QString error;
    QVERIFY2(
        machine.create(jogStopMachine(board.path(), maxJogSpeed,
                                      jogAcceleration > 0 ? std::optional<double>(jogAcceleration)
                                                          : std::nullopt),
                       &error),
        qPrintable(error));
    ControllerSession* session = machine.session(QStringLiteral("table"));
    machine.open();
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Connected, 10000);
    // The board moves only after its setup was written; its acceleration is the schema's
    // default, 1000 steps/s^2.
    QSignalSpy done(session, &ControllerSession::requestFinished);
    const RequestId id =
        session->writeParameters(test::setupBeforeMotionDefaults(*session->model()), false);
    QTRY_VERIFY_WITH_TIMEOUT(std::any_of(done.cbegin(), done.cend(),
                                         [id](const QList<QVariant>& args) {
                                             return args.at(0).value<CommandResult>().id == id;
                                         }),
                             10000);

    // Held at full deflection (renewed) until the board runs at the full rate.
    const qint16 full = qint16(qRound(maxJogSpeed * 400));
    const QByteArray fullRate = elab::encode::jogSpeed({full, 0, 0});
    QString refusal;
    QTRY_VERIFY_WITH_TIMEOUT(machine.jog({{QStringLiteral("X"), maxJogSpeed}}, &refusal) &&
                                 board.frames().contains(fullRate),
                             10000);
    QVERIFY2(refusal.isEmpty(), qPrintable(refusal));
    // ... and a tenth of a second more at that rate: the operator jogs at full speed, then
    // lets go (JogRamp::heldRates: a release within the first tick after reaching the rate
    // may run up to half a tick further).
    auto position = [&board] {
        return board.probe([&] { return board.sim()->position(Axis::X); });
    };
    const qint64 atFullRate = position();
    QTRY_VERIFY_WITH_TIMEOUT(machine.jog({{QStringLiteral("X"), maxJogSpeed}}, &refusal) &&
                                 position() >= atFullRate + full / 10,
                             10000);
    // Let go: the position at the board just before the release, then where it comes to rest.
    const qint64 atRelease = position();
    machine.endJog();
    QTRY_VERIFY_WITH_TIMEOUT(board.probe([&] { return board.sim()->standingStill(); }), 10000);
    const qint64 atRest = position();
    const double travelled = double(atRest - atRelease) / 400.0;
    qInfo("%.3f mm after the release (bound %.3f mm)", travelled, bound);
    QVERIFY2(travelled <= bound,
             qPrintable(QStringLiteral("the board travelled %1 mm after the release, more than "
                                       "the %2 mm stopping distance")
                            .arg(travelled)
                            .arg(bound)));
    QVERIFY(travelled > 0); // it did run at full speed when let go
}

STEPDECK_TEST_MAIN(TestMachineJogStop)
#include "tst_machinejogstop.moc"
