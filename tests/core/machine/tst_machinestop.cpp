// Issue 28, item 4: STOP keeps every position the device vouches for, on every model. A
// machine of one controller (MachineDescription::singleController) on its simulator behind a
// pseudo-terminal: reference X, start a long move, STOP mid-move, then an absolute move
// without referencing again. Asserted at the device: where it stands, and that the absolute
// move lands where the device counts the target (its count at the reference + the target) --
// or, where the device cannot vouch for the position (a Nanotec drive stopped above its start
// frequency: 'S' has no ramp, 6.2), that the position is unknown and the move refused.
#include "MachineTestSupport.h"
#include "PtyDevice.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include <QSignalSpy>
#include <QtTest>
#include <algorithm>

using namespace stepdeck;
using namespace stepdeck::machine;

class TestMachineStop : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void stop_midMove_absoluteMoveLandsWhereTheDeviceSays_data();
    void stop_midMove_absoluteMoveLandsWhereTheDeviceSays();
    void stopOrPanic_spindleAndCoolantOn_boardSwitchesThemOffOnceStanding_data();
    void stopOrPanic_spindleAndCoolantOn_boardSwitchesThemOffOnceStanding();
};

void TestMachineStop::stop_midMove_absoluteMoveLandsWhereTheDeviceSays_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<qint64>("distance");       // steps of the move STOP interrupts
    QTest::addColumn<QByteArray>("driveSetup"); // Nanotec: bodies sent to the drive first
    QTest::addColumn<bool>("known");            // the position after the STOP
    QTest::addColumn<bool>("runsOut");          // no stop command: the move ends by itself
    // ForceStopMove brakes "ohne Schrittverluste"; <ETX> gives the steps not run.
    QTest::newRow("E-LAB") << "elab" << qint64(20000) << QByteArray() << true << false;
    // 'S' without ramp: below the start frequency the encoder confirms the count ...
    QTest::newRow("Nanotec, below its start frequency")
        << "nanotec" << qint64(5000) << QByteArray("u1000") << true << false;
    // ... above it the rotor overshoots and the encoder disagrees: unknown.
    QTest::newRow("Nanotec, above its start frequency")
        << "nanotec" << qint64(5000) << QByteArray() << false << false;
    // No stop command (manual 9): the move runs to its end, read back there.
    QTest::newRow("EMIS") << "emis" << qint64(3000) << QByteArray() << true << true;
    // Only "move to home" and "move to position" exist: the target is reached.
    QTest::newRow("laser axis") << "laser-axis" << qint64(30000) << QByteArray() << true << true;
}

void TestMachineStop::stop_midMove_absoluteMoveLandsWhereTheDeviceSays()
{
    QFETCH(QString, model);
    QFETCH(qint64, distance);
    QFETCH(QByteArray, driveSetup);
    QFETCH(bool, known);
    QFETCH(bool, runsOut);
    const ModelInfo* info = findModel(model);
    QVERIFY(info);
    test::PtyDevice device(model);
    if (!driveSetup.isEmpty())
        device.probe([&] {
            static_cast<nanotec::NanotecSimulator*>(device.sim())->drive(1)->handle(driveSetup);
            return true;
        });
    QMap<Axis, int> addresses;
    if (info->capabilities.multiDrive)
        addresses.insert(Axis::X, 1);
    Machine m;
    QString error;
    QVERIFY2(
        m.create(MachineDescription::singleController(*info, device.path(), addresses), &error),
        qPrintable(error));
    m.open();
    QTRY_COMPARE_WITH_TIMEOUT(m.state(), MachineState::Idle, 10000);
    ControllerSession* s = m.session(m.description().controllers.first().id);
    if (!info->setupBeforeMotion.isEmpty())
        QVERIFY(test::writeSetupBeforeMotion(s));
    const MachineAxis& x = *m.description().axis(QStringLiteral("X"));
    if (m.axisStatus(x).known != PositionKnowledge::Referenced) {
        QSignalSpy referenced(&m, &Machine::referenceFinished);
        QVERIFY2(m.reference({QStringLiteral("X")}, &error) != 0, qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(!referenced.isEmpty(), 30000);
        QVERIFY2(referenced.first().at(1).toBool(),
                 qPrintable(referenced.first().at(2).toString()));
    }
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(m.axisStatus(x).known, PositionKnowledge::Referenced, 10000);
    // The device's count where the host counts 0 (the E-LAB counts from power-on).
    const qint64 zero = device.position(Axis::X) - m.axisStatus(x).steps;

    QSignalSpy moved(&m, &Machine::moveFinished);
    QVERIFY2(m.move({{QStringLiteral("X"), double(distance)}}, false, &error) != 0,
             qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(device.position(Axis::X) - zero > distance / 5, 10000);
    QVERIFY(device.moving(Axis::X));
    m.stop();
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(!moved.isEmpty(), 20000);
    const qint64 stoppedAt = device.position(Axis::X) - zero;
    if (runsOut)
        QCOMPARE(stoppedAt, distance);
    else
        QVERIFY2(stoppedAt < distance, qPrintable(QString::number(stoppedAt)));

    const PositionKnowledge expected =
        known ? PositionKnowledge::Referenced : PositionKnowledge::Unknown;
    QTRY_COMPARE_WITH_TIMEOUT(m.axisStatus(x).known, expected, 10000);
    moved.clear();
    const quint64 back = m.move({{QStringLiteral("X"), 100.0}}, true, &error);
    if (!known) {
        QCOMPARE(back, quint64(0));
        QVERIFY2(error.contains(QStringLiteral("not referenced")), qPrintable(error));
        return;
    }
    QVERIFY2(back != 0, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(!moved.isEmpty(), 30000);
    QVERIFY2(moved.first().at(1).toBool(), qPrintable(moved.first().at(2).toString()));
    QTRY_VERIFY_WITH_TIMEOUT(device.still(), 10000);
    QCOMPARE(device.position(Axis::X) - zero,
             qint64(100)); // at the device, without a new reference
    QCOMPARE(m.axisStatus(x).steps, qint64(100));
}

// Issue 47, item 1: STOP and PANIC switch spindle and coolant off, as LinuxCNC's abort and
// emergency stop do, after the axes stand (the board takes <SOH> and <SI> only at standstill).
// Asserted at the simulated board: its relays, and that the switch-off frames came after the
// stop and while nothing moved.
void TestMachineStop::stopOrPanic_spindleAndCoolantOn_boardSwitchesThemOffOnceStanding_data()
{
    QTest::addColumn<bool>("panic");
    QTest::newRow("STOP") << false;
    QTest::newRow("PANIC") << true;
}

void TestMachineStop::stopOrPanic_spindleAndCoolantOn_boardSwitchesThemOffOnceStanding()
{
    QFETCH(bool, panic);
    test::PtyDevice device("elab");
    const auto board = [&] { return static_cast<elab::ElabSimulator*>(device.sim()); };
    Machine m;
    QString error;
    QVERIFY2(m.create(MachineDescription::singleController(*findModel("elab"), device.path(), {}),
                      &error),
             qPrintable(error));
    m.open();
    QTRY_COMPARE_WITH_TIMEOUT(m.state(), MachineState::Idle, 10000);
    ControllerSession* s = m.session(m.description().controllers.first().id);
    QVERIFY(test::writeSetupBeforeMotion(s));
    QSignalSpy results(s, &ControllerSession::requestFinished);
    const RequestId spindle = s->setSpindle(1000);
    const RequestId coolant = s->setCoolant(true);
    QTRY_VERIFY_WITH_TIMEOUT(
        device.probe([&] { return board()->spindleRpm() == 1000 && board()->coolant(); }), 10000);
    QVERIFY(spindle != 0 && coolant != 0);

    QVERIFY2(m.move({{QStringLiteral("X"), 20000.0}}, false, &error) != 0, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(device.moving(Axis::X), 10000);
    const int before = device.frames().size();
    QSignalSpy off(&m, &Machine::spindleAndCoolantOff);
    panic ? m.panic() : m.stop();
    QVERIFY(m.isSwitchingOff());
    QTRY_VERIFY_WITH_TIMEOUT(!off.isEmpty(), 20000);
    QVERIFY2(off.first().at(0).toBool(), qPrintable(off.first().at(1).toString()));
    QVERIFY(device.still());
    QCOMPARE(device.probe([&] { return board()->spindleRpm(); }), quint32(0));
    QVERIFY(!device.probe([&] { return board()->coolant(); }));
    // The stop first, then <SOH>00000000# and <SI>00: never the other way round.
    const QList<QByteArray> frames = device.frames().mid(before);
    const auto first = [&](const QByteArray& part) {
        for (int i = 0; i < frames.size(); ++i)
            if (frames.at(i).startsWith(part))
                return i;
        return -1;
    };
    const int stopAt = first(panic ? elab::encode::panicStop() : elab::encode::stopMove());
    const int spindleAt = first(elab::encode::spindleRpm(0));
    const int coolantAt = first(elab::encode::coolant(false));
    QVERIFY2(stopAt >= 0 && spindleAt > stopAt && coolantAt > stopAt,
             qPrintable(QStringLiteral("%1 %2 %3").arg(stopAt).arg(spindleAt).arg(coolantAt)));
    QVERIFY(!m.isSwitchingOff());
}

STEPDECK_TEST_MAIN(TestMachineStop)
#include "tst_machinestop.moc"
