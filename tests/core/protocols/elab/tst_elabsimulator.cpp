// ElabSimulator: the device side of the E-LAB protocol, driven directly with encoded commands
// (receive()) and observed through transmit() and its test accessors.
#include "ElabTestSupport.h"
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabModel.h"
#include "protocols/elab/ElabSimulator.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::elab;

namespace {
const QByteArray kSimAck(1, ctrl::ACK);
const QByteArray kNak(1, ctrl::NAK);

using stepdeck::elab::testing::bytes;

// A simulator with a spy on its output; ask() returns what one command made it send at once.
struct SimRig
{
    explicit SimRig(const SimulatorOptions& options = {}) : sim(options) {}
    ElabSimulator sim;
    QSignalSpy spy{&sim, &Simulator::transmit};

    QByteArray ask(const QByteArray& command)
    {
        spy.clear();
        sim.receive(command);
        return test::joinedBytes(spy);
    }
    QByteArray ask(const char* mnemonics) { return ask(bytes(mnemonics)); }
    // Start/max speed and acceleration (completes the setup) plus the feed speed.
    bool setup(quint16 start, quint16 max, quint16 accel, quint16 feed = 1000)
    {
        return ask(encode::ramp(RampKind::StartSpeed, {start, start, start})) == kSimAck &&
               ask(encode::ramp(RampKind::MaxSpeed, {max, max, max})) == kSimAck &&
               ask(encode::ramp(RampKind::Acceleration, {accel, accel, accel})) == kSimAck &&
               ask(encode::feedSpeed({feed, feed, feed})) == kSimAck;
    }
    Reply reply(const QByteArray& request)
    {
        ReplyDecoder decoder;
        const QList<Reply> replies = decoder.feed(ask(request));
        return replies.size() == 1 ? replies.first() : Reply{};
    }
    quint16 machineState() { return reply(encode::requestMachineState()).machineState; }
    quint8 axeState() { return reply(encode::requestAxeState()).axeState; }
};
} // namespace

class TestElabSimulator : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void requests_replyFormat_matchesManual_data();
    void requests_replyFormat_matchesManual();
    void setup_incomplete_movesNak_data();
    void setup_incomplete_movesNak();
    void auxiliary_setsMachineBits();
    void malformedHex_naks_data();
    void malformedHex_naks();
    void strayBytes_noReply_nextCommandAnswered();
    void fastMove_reachesTarget_andReportsIdle();
    void fastMove_whileMoving_naks();
    void forceStopMove_ramps_relPositionReportsRemaining();
    void panicStop_stopsAtOnce();
    void limitSwitch_stopsMove_setsBits();
    void limitPolarity_wrong_readsActive();
    void jog_allowedOnLimitSwitch();
    void panicButton_naksMoves();
    void referenceMove_stopsAtSwitch();
    void velocityMove_repeatChangesRate_zeroStops();
    void feedSteps_reachTarget();
    void temperature_overTemp();
    void faults_dropCorruptDelayForceNak();
    void pacing_releasesAtLineRate();
    void powerOnReset_restoresPowerOnState();
};

void TestElabSimulator::requests_replyFormat_matchesManual_data()
{
    QTest::addColumn<int>("temperature");
    QTest::addColumn<bool>("startButton");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("expected");
    QTest::newRow("ENQ at power-on") << 25 << false << bytes("<ENQ>") << bytes("<ENQ>0080#");
    QTest::newRow("HT idle") << 25 << false << bytes("<HT>") << bytes("<HT>00#");
    QTest::newRow("ETB 25 degC") << 25 << false << bytes("<ETB>") << bytes("<ETB>19#");
    QTest::newRow("ETB manual 20 degC") << 20 << false << bytes("<ETB>") << bytes("<ETB>14#");
    QTest::newRow("ETX nothing left")
        << 25 << false << bytes("<ETX>") << bytes("<ETX>00000000,00000000;00000000.");
    QTest::newRow("LF not pressed") << 25 << false << bytes("<LF>") << kNak;
    QTest::newRow("LF pressed") << 25 << true << bytes("<LF>") << kSimAck;
    QTest::newRow("SYN burst: no reply") << 25 << false << encode::requestSync(8) << QByteArray();
    QTest::newRow("SYN then ENQ") << 25 << false << bytes("<SYN><SYN><SYN><ENQ>")
                                  << bytes("<ENQ>0080#");
}

void TestElabSimulator::requests_replyFormat_matchesManual()
{
    QFETCH(int, temperature);
    QFETCH(bool, startButton);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, expected);
    SimRig rig;
    rig.sim.setTemperature(temperature);
    rig.sim.setStartButton(startButton);
    QCOMPARE(rig.ask(request), expected);
}

void TestElabSimulator::setup_incomplete_movesNak_data()
{
    QTest::addColumn<QByteArray>("move");
    QTest::newRow("FastMoveXY") << encode::fastMoveXY(1000, -1000);
    QTest::newRow("FastMoveXYZ") << encode::fastMoveXYZ({1000, -1000, 16});
    QTest::newRow("FastMoveZ") << encode::fastMoveZ(1000);
    QTest::newRow("FeedStepsX") << encode::feedStepsX(1000);
    QTest::newRow("ReferenceMove") << encode::referenceMove({-1, 0, 1});
    QTest::newRow("VelocityMove") << encode::velocityMove({-1000, 0, 1001});
    QTest::newRow("Jog") << encode::jogSpeed({100, 100, -100});
}

void TestElabSimulator::setup_incomplete_movesNak()
{
    QFETCH(QByteArray, move);
    SimRig rig;
    QCOMPARE(rig.ask(move), kNak);
    QVERIFY(rig.sim.lastNakReason().contains(QLatin1String("tmInvSetup")));
    // Start and max speed alone are not enough: the acceleration is part of the setup.
    QCOMPARE(rig.ask("<ESC>S0064,0064;0064."), kSimAck);
    QCOMPARE(rig.ask("<ESC>M1388,1388;1388."), kSimAck);
    QCOMPARE(rig.machineState(), machine::InvSetup);
    QCOMPARE(rig.ask(move), kNak);
    QCOMPARE(rig.ask("<ESC>A03E8,03E8;03E8."), kSimAck);
    QCOMPARE(rig.ask("<FS>0064,0064;0064."), kSimAck);
    QCOMPARE(rig.machineState() & machine::InvSetup, 0);
    QCOMPARE(rig.ask(move), kSimAck);
    QVERIFY(rig.sim.isBusy());
}

void TestElabSimulator::auxiliary_setsMachineBits()
{
    SimRig rig;
    QCOMPARE(rig.ask("<SO>00,00;00."), kSimAck);
    QCOMPARE(rig.ask("<DLE>00,00;00."), kSimAck);
    QCOMPARE(rig.ask("<STX>18"), kSimAck); // 24 %: "<25 = off"
    QCOMPARE(rig.machineState() & machine::DriveOn, 0);
    QCOMPARE(rig.ask("<STX>64"), kSimAck); // manual example: 100 %
    QCOMPARE(rig.sim.drivePower(), 100);
    QCOMPARE(rig.ask("<SOH>000003E8#"), kSimAck); // manual example: spindle on
    QCOMPARE(rig.ask("<SI>FF"), kSimAck);
    QVERIFY(rig.sim.coolant());
    QCOMPARE(rig.machineState(),
             quint16(machine::DriveOn | machine::SpindleOn | machine::InvSetup));
    QCOMPARE(rig.ask("<SOH>00000000#"), kSimAck);
    QCOMPARE(rig.ask("<SI>00"), kSimAck);
    QCOMPARE(rig.machineState(), quint16(machine::DriveOn | machine::InvSetup));
    QVERIFY(!rig.sim.coolant());
}

void TestElabSimulator::malformedHex_naks_data()
{
    QTest::addColumn<QByteArray>("command");
    QTest::newRow("non-hex digit") << bytes("<ESC>S00G4,0064;0064.");
    QTest::newRow("wrong separator") << bytes("<FF>000003E8;FFFFFC18,");
    QTest::newRow("interrupted by next command") << bytes("<EOT>000003E8,<HT>");
    QTest::newRow("drive power above 100") << bytes("<STX>65");
    QTest::newRow("spindle above 1000") << bytes("<SOH>000003E9#");
    QTest::newRow("coolant not a boolean") << bytes("<SI>01");
    QTest::newRow("polarity not a boolean") << bytes("<SO>01,00;00.");
    QTest::newRow("reference direction 2") << bytes("<US>0002,0000;0000.");
    QTest::newRow("undocumented <ACK> request") << bytes("<ACK>");
    QTest::newRow("XON is no command") << bytes("<XON>");
}

void TestElabSimulator::malformedHex_naks()
{
    QFETCH(QByteArray, command);
    SimRig rig;
    QVERIFY(rig.setup(100, 5000, 1000));
    const QByteArray reply = rig.ask(command);
    QVERIFY2(reply.startsWith(kNak), reply.toHex().constData());
    QVERIFY(!rig.sim.isBusy());
    QCOMPARE(rig.sim.drivePower(), 0);
    QCOMPARE(rig.ask("<ENQ>"), bytes("<ENQ>0000#")); // still in sync
}

void TestElabSimulator::strayBytes_noReply_nextCommandAnswered()
{
    SimRig rig;
    QCOMPARE(rig.ask(QByteArray("xyz!")), QByteArray());
    QCOMPARE(rig.ask("<HT>"), bytes("<HT>00#"));
}

void TestElabSimulator::fastMove_reachesTarget_andReportsIdle()
{
    SimRig rig;
    QVERIFY(rig.setup(1000, 20000, 60000));
    QVERIFY(!rig.sim.isTicking());                                        // idle costs nothing
    QCOMPARE(rig.ask(encode::fastMoveXYZ({12000, -2000, 500})), kSimAck); // ~0.9 s
    QVERIFY(rig.sim.isTicking());
    QCOMPARE(rig.machineState() & machine::Busy, machine::Busy);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.sim.position(Axis::X), qint64(12000));
    QCOMPARE(rig.sim.position(Axis::Y), qint64(-2000));
    QCOMPARE(rig.sim.position(Axis::Z), qint64(500));
    QCOMPARE(rig.ask("<HT>"), bytes("<HT>00#"));
    QCOMPARE(rig.machineState(), quint16(0));
    QCOMPARE(rig.ask("<ETX>"), bytes("<ETX>00000000,00000000;00000000."));
    QVERIFY(!rig.sim.isTicking());
    // Relative moves: Z only, from where the last one ended.
    QCOMPARE(rig.ask(encode::fastMoveZ(-500)), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.sim.position(Axis::Z), qint64(0));
    QCOMPARE(rig.sim.position(Axis::X), qint64(12000));
}

void TestElabSimulator::fastMove_whileMoving_naks()
{
    SimRig rig;
    QVERIFY(rig.setup(100, 1000, 1000));
    QCOMPARE(rig.ask(encode::fastMoveXY(100000, 0)), kSimAck);
    QCOMPARE(rig.axeState(), axe::XMove);
    QCOMPARE(rig.ask(encode::fastMoveZ(10)), kNak);
    QCOMPARE(rig.ask(encode::jogSpeed({10, 0, 0})), kNak);
    QCOMPARE(rig.ask(encode::velocityMove({1000, 0, 0})), kNak);
    QVERIFY(rig.sim.lastNakReason().contains(QLatin1String("moving")));
    QCOMPARE(rig.ask("<BEL>"), kSimAck);
}

void TestElabSimulator::forceStopMove_ramps_relPositionReportsRemaining()
{
    SimRig rig;
    QVERIFY(rig.setup(500, 20000, 20000));
    QCOMPARE(rig.ask(encode::fastMoveXY(100000, -100000)), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim.position(Axis::X) > 1000, 10000);
    const qint64 atStop = rig.sim.position(Axis::X);
    QCOMPARE(rig.ask("<XOFF>"), kSimAck); // ForceStopMove
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    const qint64 x = rig.sim.position(Axis::X);
    QVERIFY2(x > atStop, "the stop ramp still travels");
    const Reply rel = rig.reply(encode::requestRelPosition());
    QCOMPARE(rel.kind, Reply::Kind::RelPosition);
    QCOMPARE(rel.positions[0], qint32(100000 - x));
    QCOMPARE(rel.positions[1], qint32(-100000 - rig.sim.position(Axis::Y)));
    QCOMPARE(rel.positions[2], 0);
    QCOMPARE(rig.ask("<RS>"), kSimAck); // SetClearPosition clears the counters
    QCOMPARE(rig.ask("<ETX>"), bytes("<ETX>00000000,00000000;00000000."));
}

void TestElabSimulator::panicStop_stopsAtOnce()
{
    SimRig rig;
    QVERIFY(rig.setup(500, 20000, 20000));
    QCOMPARE(rig.ask(encode::fastMoveXYZ({100000, 100000, 100000})), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim.position(Axis::X) > 100, 10000);
    QCOMPARE(rig.ask("<BEL>"), kSimAck);
    QCOMPARE(rig.ask("<HT>"), bytes("<HT>00#")); // no stop ramp
    QVERIFY(!rig.sim.isTicking());
}

void TestElabSimulator::limitSwitch_stopsMove_setsBits()
{
    SimRig rig;
    rig.sim.setLimitPositions(Axis::X, -1000, 500);
    QVERIFY(rig.setup(2000, 30000, 60000));
    rig.sim.setStartButton(true);
    QCOMPARE(rig.ask(encode::fastMoveXY(2000, 300)), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.sim.position(Axis::X), qint64(500)); // stopped at the first active step
    QVERIFY(rig.sim.position(Axis::Y) <= 300);        // the whole move was aborted
    QCOMPARE(rig.machineState(), machine::LimSwX);
    QCOMPARE(rig.axeState(), axe::LimSw);
    // Note 1 of the table: NAK while a limit switch is active.
    QCOMPARE(rig.ask(encode::fastMoveXY(-10, 0)), kNak);
    QCOMPARE(rig.ask(encode::referenceMove({-1, 0, 0})), kNak);
    QCOMPARE(rig.ask("<RS>"), kNak);
    QCOMPARE(rig.ask("<LF>"), kNak);                     // even with the start button pressed
    QCOMPARE(rig.ask("<ESC>S07D0,07D0;07D0."), kSimAck); // no note: still accepted
}

void TestElabSimulator::limitPolarity_wrong_readsActive()
{
    SimRig rig;
    rig.sim.setSwitchWiring(Axis::Y, false, false); // low-active switches
    QCOMPARE(rig.machineState(), machine::InvSetup);
    QCOMPARE(rig.ask("<SO>00,FF;00."), kSimAck); // Y configured high-active: reads active at rest
    QVERIFY(rig.sim.limitSwitchLevelHigh(Axis::Y)); // free low-active switch: level high
    QCOMPARE(rig.machineState(), quint16(machine::InvSetup | machine::LimSwY));
    QCOMPARE(rig.ask("<DLE>FF,00;00."), kSimAck);
    QCOMPARE(rig.machineState(), quint16(machine::InvSetup | machine::LimSwY | machine::RefSwX));
    QCOMPARE(rig.axeState(), quint8(axe::LimSw | axe::RefSw));
}

void TestElabSimulator::jog_allowedOnLimitSwitch()
{
    SimRig rig;
    QVERIFY(rig.setup(100, 5000, 1000));
    rig.sim.setLimitSwitchActuated(Axis::X, true);
    QCOMPARE(rig.ask(encode::fastMoveXY(-100, 0)), kNak);
    QCOMPARE(rig.ask("<DC4>FC18,0000;0000."), kSimAck); // X -1000 steps/s
    QCOMPARE(rig.axeState(), quint8(axe::XJog | axe::LimSw));
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim.position(Axis::X) < -50, 10000);
    QCOMPARE(rig.ask("<DC4>FC18,0064;0000."), kSimAck); // Y joins, no standstill needed
    QCOMPARE(rig.axeState(), quint8(axe::XJog | axe::YJog | axe::LimSw));
    rig.sim.setLimitSwitchActuated(Axis::X, false);
    QCOMPARE(rig.ask(encode::jogSpeed({0, 0, 0})), kSimAck); // all zero: jog mode left
    QCOMPARE(rig.axeState(), quint8(0));
    QVERIFY(!rig.sim.isTicking());
    QCOMPARE(rig.ask(encode::fastMoveXY(10, 0)), kSimAck);
}

void TestElabSimulator::panicButton_naksMoves()
{
    SimRig rig;
    QVERIFY(rig.setup(100, 5000, 1000));
    QCOMPARE(rig.ask(encode::fastMoveXY(100000, 0)), kSimAck);
    rig.sim.setPanicButton(true);
    QVERIFY(!rig.sim.isBusy());
    QCOMPARE(rig.machineState(), machine::PanicStop);
    QCOMPARE(rig.ask(encode::fastMoveXY(10, 0)), kNak);
    QCOMPARE(rig.ask(encode::jogSpeed({10, 0, 0})), kNak);
    QCOMPARE(rig.ask("<STX>64"), kNak);
    QCOMPARE(rig.ask("<SOH>00000001#"), kNak);
    QVERIFY(rig.sim.lastNakReason().contains(QLatin1String("panic")));
    QCOMPARE(rig.ask("<XOFF>"), kSimAck); // stop commands carry no note
    QCOMPARE(rig.ask("<BEL>"), kSimAck);
    rig.sim.setPanicButton(false);
    QCOMPARE(rig.ask(encode::jogSpeed({10, 0, 0})), kSimAck);
}

void TestElabSimulator::referenceMove_stopsAtSwitch()
{
    SimRig rig;
    rig.sim.setReferencePosition(Axis::X, -300, 5);
    rig.sim.setReferencePosition(Axis::Z, 400, 5);
    QVERIFY(rig.setup(200, 20000, 2000));              // slow enough to still run at the next poll
    QCOMPARE(rig.ask("<US>FFFF,0000;0001."), kSimAck); // manual example: X -dir, Z +dir
    QCOMPARE(rig.axeState(), quint8(axe::XMove | axe::ZMove));
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.sim.position(Axis::X), qint64(-295));
    QCOMPARE(rig.sim.position(Axis::Y), qint64(0));
    QCOMPARE(rig.sim.position(Axis::Z), qint64(395));
    QCOMPARE(rig.machineState(), quint16(machine::RefSwX | machine::RefSwZ));
    QCOMPARE(rig.axeState(), axe::RefSw);
}

void TestElabSimulator::velocityMove_repeatChangesRate_zeroStops()
{
    SimRig rig;
    QVERIFY(rig.setup(200, 5000, 20000));
    QCOMPARE(rig.ask(encode::velocityMove({150, 0, 0})), kSimAck); // below start: no move
    QVERIFY(!rig.sim.isBusy());
    QCOMPARE(rig.ask(encode::velocityMove({-3000, 0, 0})), kSimAck);
    QCOMPARE(rig.axeState(), axe::XMove);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim.position(Axis::X) < -200, 10000);
    QCOMPARE(rig.ask(encode::velocityMove({4000, 0, 0})), kSimAck); // sign ignored
    QCOMPARE(rig.ask(encode::fastMoveZ(10)), kNak);
    const qint64 before = rig.sim.position(Axis::X);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim.position(Axis::X) < before - 200, 10000);
    QCOMPARE(rig.ask(encode::velocityMove({0, 0, 0})), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.ask("<HT>"), bytes("<HT>00#"));
}

void TestElabSimulator::feedSteps_reachTarget()
{
    SimRig rig;
    QVERIFY(rig.setup(100, 5000, 1000, 4000));
    QCOMPARE(rig.ask("<EM>000003E8,"), kSimAck); // manual example: X +1000 steps, 0.25 s
    QCOMPARE(rig.axeState(), axe::XMove);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.ask("<SUB>FFFFFC18;"), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.ask("<VT>00000010."), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    QCOMPARE(rig.sim.position(Axis::X), qint64(1000));
    QCOMPARE(rig.sim.position(Axis::Y), qint64(-1000));
    QCOMPARE(rig.sim.position(Axis::Z), qint64(16));
}

void TestElabSimulator::temperature_overTemp()
{
    SimRig rig;
    rig.sim.setTemperature(50);
    QCOMPARE(rig.machineState() & machine::OverTemp, 0);
    rig.sim.setTemperature(51);
    QCOMPARE(rig.ask("<ETB>"), bytes("<ETB>33#"));
    QCOMPARE(rig.machineState(), quint16(machine::OverTemp | machine::InvSetup));
}

void TestElabSimulator::faults_dropCorruptDelayForceNak()
{
    SimRig rig;
    rig.sim.faults().dropReplies = 1;
    QCOMPARE(rig.ask("<ENQ>"), QByteArray());
    QCOMPARE(rig.ask("<ENQ>"), bytes("<ENQ>0080#"));

    rig.sim.faults().corruptReplies = 1;
    const QByteArray corrupted = rig.ask("<ENQ>");
    QCOMPARE(corrupted.size(), 6);
    QVERIFY(corrupted != bytes("<ENQ>0080#"));

    rig.sim.forceNak(2);
    QCOMPARE(rig.ask("<HT>"), bytes("<HT>00#")); // requests are not affected
    QCOMPARE(rig.ask("<ESC>S0064,0064;0064."), kNak);
    QCOMPARE(rig.ask("<STX>64"), kNak);
    QCOMPARE(rig.sim.drivePower(), 0); // a refused command is not executed
    QCOMPARE(rig.sim.forcedNaksPending(), 0);
    QCOMPARE(rig.ask("<STX>64"), kSimAck);

    rig.sim.faults().delayMs = 30;
    QCOMPARE(rig.ask("<HT>"), QByteArray());
    QTRY_COMPARE(test::joinedBytes(rig.spy), bytes("<HT>00#"));
    rig.sim.faults().delayMs = 0;

    rig.sim.faults().silent = true;
    QCOMPARE(rig.ask("<ENQ>"), QByteArray());
    QVERIFY(test::staysQuiet(rig.spy, 50));
}

void TestElabSimulator::pacing_releasesAtLineRate()
{
    SimulatorOptions options;
    options.paceOutput = true;
    options.line = lineSettings(); // 57600 8N2: ~191 us per character
    SimRig rig(options);
    QCOMPARE(rig.ask("<ETX>"), QByteArray()); // 27 characters need ~5 ms on the wire
    QVERIFY(rig.sim.bytesPending() > 0);
    QTRY_COMPARE(test::joinedBytes(rig.spy), bytes("<ETX>00000000,00000000;00000000."));
}

void TestElabSimulator::powerOnReset_restoresPowerOnState()
{
    SimRig rig;
    QVERIFY(rig.setup(1000, 20000, 60000));
    QCOMPARE(rig.ask("<STX>64"), kSimAck);
    QCOMPARE(rig.ask(encode::fastMoveXY(500, 500)), kSimAck);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim.isBusy(), 10000);
    rig.sim.powerOnReset();
    QCOMPARE(rig.ask("<ENQ>"), bytes("<ENQ>0080#"));
    QCOMPARE(rig.sim.position(Axis::X), qint64(0));
    QCOMPARE(rig.ask(encode::fastMoveXY(500, 500)), kNak);
}

STEPDECK_TEST_GUILESS_MAIN(TestElabSimulator)
#include "tst_elabsimulator.moc"
