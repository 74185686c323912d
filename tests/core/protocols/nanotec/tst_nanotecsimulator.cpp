// The simulated Nanotec bus: echo, '?' and ignore-invalid exactly as the manual describes,
// records, error memory, motion with the drive's ramp, switches, auto status and faults.
#include "TestMain.h"
#include "protocols/nanotec/NanotecDrive.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::nanotec;

namespace {
SimulatorOptions busOf(QList<int> addresses)
{
    SimulatorOptions o;
    o.addresses = addresses;
    return o;
}
} // namespace

class TestNanotecSimulator : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void reply_manualExamples_data();
    void reply_manualExamples();
    void setting_invalidValue_echoedAndIgnored_data();
    void setting_invalidValue_echoedAndIgnored();
    void setting_positioningMode2_ignoredInSpeedMode();
    void bus_unknownAddress_staysSilent();
    void bus_broadcast_singleDriveAnswers_severalCollide();
    void address_change_echoFromOldAddress();
    void records_saveLoadAndReadBack();
    void errorMemory_ringOf32();
    void positioning_rampsToTarget_andSendsAutoStatus();
    void positioning_manyShortMovesUnevenTicks_encoderStaysOnDemand();
    void speedMode_manyJogsStoppedAtStartFrequency_encoderStaysOnDemand();
    void speedMode_abruptStopAtSpeed_flagsPositionError();
    void reference_external_freesSwitchAndZeroes();
    void limitSwitch_stopBehaviour_haltsOnSwitch();
    void limitSwitch_freeTravel_endsOffTheSwitchAtUnevenTicks();
    void faults_silentGarbledWrongAddress();
    void neverSentCommands_behaveAsManualSays();

private:
    QByteArray ask(const QByteArray& frames);
    NanotecSimulator* m_sim = nullptr;
    QSignalSpy* m_tx = nullptr;
};

void TestNanotecSimulator::init()
{
    m_sim = new NanotecSimulator(busOf({1}));
    m_tx = new QSignalSpy(m_sim, &Simulator::transmit);
}

void TestNanotecSimulator::cleanup()
{
    delete m_tx;
    delete m_sim;
}

QByteArray TestNanotecSimulator::ask(const QByteArray& frames)
{
    m_tx->clear();
    m_sim->receive(frames);
    QByteArray out;
    for (const auto& args : *m_tx)
        out += args.at(0).toByteArray();
    return out;
}

void TestNanotecSimulator::reply_manualExamples_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("reply");
    QTest::newRow("1.1 set travel") << QByteArray("#1s1000\r") << QByteArray("001s1000\r");
    QTest::newRow("1.1 unknown") << QByteArray("#1/\r") << QByteArray("001/?\r");
    QTest::newRow("1.2 read") << QByteArray("#1:CL_motor_pp\r") << QByteArray("1:CL_motor_pp+50\r");
    QTest::newRow("1.2 write") << QByteArray("#1:CL_motor_pp=100\r")
                               << QByteArray("1:CL_motor_pp=100\r");
    QTest::newRow("1.2 unknown") << QByteArray("#1:CL_gibt_es_nicht\r") << QByteArray("1:?\r");
    QTest::newRow("3 read travel")
        << QByteArray("#1s1000\r#1Zs\r") << QByteArray("001s1000\r001Zs1000\r");
    QTest::newRow("5.19 record value") << QByteArray("#1Z5s\r") << QByteArray("001Z5s400\r");
    QTest::newRow("5.22 firmware")
        << QByteArray("#1v\r") << QByteArray("001v SMCI47-S_RS485_04-12-2008\r");
    QTest::newRow("5.24 mask 0") << QByteArray("#1L0\r") << QByteArray("001L0\r");
    QTest::newRow("5.21 status") << QByteArray("#1$\r") << QByteArray("001$19\r"); // at zero
    QTest::newRow("5.20 address") << QByteArray("#1M\r") << QByteArray("001M1\r");
    QTest::newRow("6.4 record") << QByteArray("#1Z|\r")
                                << QByteArray(
                                       "001Zp+1s+400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0\r");
    QTest::newRow("6.4 record 5") << QByteArray("#1Z5|\r")
                                  << QByteArray(
                                         "001Z5p+1s+400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0\r");
    QTest::newRow("plain with value") << QByteArray("#1A5\r") << QByteArray("001A5?\r");
}

void TestNanotecSimulator::reply_manualExamples()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, reply);
    QCOMPARE(ask(request), reply);
}

void TestNanotecSimulator::setting_invalidValue_echoedAndIgnored_data()
{
    QTest::addColumn<QByteArray>("cmd");
    QTest::addColumn<qint64>("invalid");
    QTest::addColumn<qint64>("kept");
    QTest::newRow("5.1 phase current") << QByteArray("i") << qint64(151) << qint64(50);
    QTest::newRow("5.3 step mode") << QByteArray("g") << qint64(3) << qint64(2);
    QTest::newRow("5.6 two internal ref bits") << QByteArray("l") << qint64(5155) << qint64(5154);
    QTest::newRow("5.6 no external normal bit") << QByteArray("l") << qint64(1058) << qint64(5154);
    QTest::newRow("5.8 step angle") << QByteArray("a") << qint64(15) << qint64(18);
    QTest::newRow("5.24 mask bit 6") << QByteArray("L") << qint64(64) << qint64(0x3003F);
    QTest::newRow("6.8 min frequency") << QByteArray("u") << qint64(59) << qint64(400);
    QTest::newRow("6.11 ramp") << QByteArray("b") << qint64(0) << qint64(2364);
    QTest::newRow("6.14 repetitions") << QByteArray("W") << qint64(255) << qint64(1);
}

void TestNanotecSimulator::setting_invalidValue_echoedAndIgnored()
{
    QFETCH(QByteArray, cmd);
    QFETCH(qint64, invalid);
    QFETCH(qint64, kept);
    const QByteArray body = cmd + QByteArray::number(invalid);
    QCOMPARE(ask("#1" + body + "\r"), "001" + body + "\r");
    QCOMPARE(ask("#1Z" + cmd + "\r"), "001Z" + cmd + QByteArray::number(kept) + "\r");
}

void TestNanotecSimulator::setting_positioningMode2_ignoredInSpeedMode()
{
    QCOMPARE(ask("#1!2\r#1p2\r#1Zp\r"), QByteArray("001!2\r001p2\r001Zp1\r"));
    QCOMPARE(ask("#1!1\r#1p2\r#1Zp\r"), QByteArray("001!1\r001p2\r001Zp2\r"));
}

void TestNanotecSimulator::bus_unknownAddress_staysSilent()
{
    QVERIFY(ask("#9A\r#0$\r").isEmpty());
    QVERIFY(ask("garbage without hash\r").isEmpty());
}

void TestNanotecSimulator::bus_broadcast_singleDriveAnswers_severalCollide()
{
    QCOMPARE(ask("#*M\r"), QByteArray("001M1\r"));
    NanotecSimulator bus(busOf({1, 2, 3}));
    QSignalSpy tx(&bus, &Simulator::transmit);
    bus.receive("#*S\r");
    QCOMPARE(tx.count(), 1);
    const QByteArray collision = tx.at(0).at(0).toByteArray();
    QVERIFY(collision.endsWith('\r'));
    QVERIFY(quint8(collision.at(0)) & 0x80); // not a valid reply
    QCOMPARE(bus.receivedFrames(), QList<QByteArray>{"#*S\r"});
}

void TestNanotecSimulator::address_change_echoFromOldAddress()
{
    QCOMPARE(ask("#1m7\r"), QByteArray("001m7\r"));
    QVERIFY(ask("#1$\r").isEmpty());
    QCOMPARE(ask("#7Zm\r"), QByteArray("007Zm7\r"));
    QCOMPARE(ask("#7m255\r#7Zm\r"), QByteArray("007m255\r007Zm7\r")); // 0/255: EEPROM errors
}

void TestNanotecSimulator::records_saveLoadAndReadBack()
{
    ask("#1s-1234\r#1o2000\r#1>5\r");
    QCOMPARE(ask("#1Z5s\r"), QByteArray("001Z5s-1234\r"));
    ask("#1s10\r#1o900\r");
    QCOMPARE(ask("#1y5\r#1Zs\r#1Zo\r"), QByteArray("001y5\r001Zs-1234\r001Zo2000\r"));
    QCOMPARE(ask("#1y33\r#1>0\r"), QByteArray("001y33\r001>0\r")); // echoed, ignored
    QCOMPARE(ask("#1Z33|\r"), QByteArray("001Z33|?\r"));
}

void TestNanotecSimulator::errorMemory_ringOf32()
{
    NanotecDrive* d = m_sim->drive(1);
    QCOMPARE(ask("#1E\r"), QByteArray("001E0\r"));
    d->pushError(error::Temperature);
    QCOMPARE(ask("#1E\r#1ZE1\r"), QByteArray("001E1\r001ZE12\r"));
    for (int i = 0; i < 32; ++i)
        d->pushError(error::LowVoltage);
    QCOMPARE(d->lastErrorSlot(), 1); // wrapped: slot 2 is now the oldest
    QCOMPARE(ask("#1ZE33\r"), QByteArray("001ZE33?\r"));
}

void TestNanotecSimulator::positioning_rampsToTarget_andSendsAutoStatus()
{
    ask("#1J1\r#1!1\r#1p1\r#1s800\r#1d1\r");
    QCOMPARE(ask("#1A\r"), QByteArray("001A\r"));
    QCOMPARE(ask("#1$\r"), QByteArray("001$18\r")); // busy, still at zero, positioning
    NanotecDrive* d = m_sim->drive(1);
    QTRY_VERIFY_WITH_TIMEOUT(d->speed() > 400, 2000); // ramps up from 'u'
    m_tx->clear();
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    QCOMPARE(d->position(), qint64(800));
    QTRY_VERIFY(!m_tx->isEmpty());
    QCOMPARE(m_tx->at(0).at(0).toByteArray(), QByteArray("001j17\r")); // 5.31
    // Absolute back to -100.
    ask("#1p2\r#1s-100\r#1A\r");
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    QCOMPARE(d->position(), qint64(-100));
    QCOMPARE(d->encoderPosition(), qint64(-100));
}

void TestNanotecSimulator::positioning_manyShortMovesUnevenTicks_encoderStaysOnDemand()
{
    // stepdeck-bench --program: 1 000 short moves at uneven simulation ticks (a loaded device
    // thread). The fraction of a step a run ends with must reach the encoder as well as the
    // counter, or the two drift apart until the drive reports a position error (5.13, X = 2
    // by default) that no real motor would have made.
    NanotecDrive drive(1);
    QRandomGenerator rng(20);
    for (const char* body : {"!1", "p1", "s10"})
        drive.handle(body);
    for (int move = 0; move < 1000; ++move) {
        drive.handle(move % 2 ? "d0" : "d1");
        drive.handle("A");
        for (int tick = 0; tick < 10000 && !drive.ready(); ++tick)
            drive.advance(0.0005 + rng.bounded(0.02));
        QVERIFY(drive.ready());
        QCOMPARE(drive.position(), qint64(move % 2 ? 0 : 10));
        QCOMPARE(drive.physicalPosition(), double(drive.position()));
        QVERIFY2(!decodeStatus(drive.statusWord()).positionError,
                 qPrintable(QString::number(move)));
    }
}

void TestNanotecSimulator::speedMode_manyJogsStoppedAtStartFrequency_encoderStaysOnDemand()
{
    // stepdeck-bench --jog-latency: short jogs in speed mode, each ended as the adapter ends
    // it ('o' = u, the drive ramps down, then 'S'), at uneven simulation ticks. A run stopped
    // by 'S' ends on a fraction of a step like a positioning run: it must move the encoder as
    // well as the counter, or the drive reports a position error (5.13, X = 2) after a few
    // dozen jogs that no real motor would have made.
    NanotecDrive drive(1);
    QRandomGenerator rng(21);
    for (const char* body : {"!2", "p1", "d1"})
        drive.handle(body);
    for (int jog = 0; jog < 200; ++jog) {
        drive.handle("o1000");
        drive.handle("A");
        for (double t = 0; t < 0.1; t += 0.0005 + rng.bounded(0.005))
            drive.advance(0.0005 + rng.bounded(0.005));
        drive.handle("o400"); // u: the drive ramps down to its start frequency
        for (int tick = 0; tick < 1000 && drive.speed() > 400; ++tick)
            drive.advance(0.0005 + rng.bounded(0.005));
        drive.handle("S");
        for (int tick = 0; tick < 1000 && !drive.ready(); ++tick)
            drive.advance(0.005);
        QVERIFY(drive.ready());
        QCOMPARE(drive.physicalPosition(), double(drive.position()));
        QVERIFY2(!decodeStatus(drive.statusWord()).positionError, qPrintable(QString::number(jog)));
    }
}

void TestNanotecSimulator::speedMode_abruptStopAtSpeed_flagsPositionError()
{
    ask("#1!2\r#1p1\r#1o3000\r#1d0\r#1A\r");
    NanotecDrive* d = m_sim->drive(1);
    QTRY_VERIFY_WITH_TIMEOUT(d->speed() <= -2999, 3000);
    ask("#1o1500\r"); // 6.6: ramped at once while running
    QTRY_VERIFY_WITH_TIMEOUT(d->speed() >= -1501, 3000);
    QCOMPARE(ask("#1S\r"), QByteArray("001S\r"));
    QVERIFY(d->ready());
    QVERIFY(d->encoderPosition() != d->position()); // overshoot the counter never saw
    QVERIFY(decodeStatus(d->statusWord()).positionError);
    QCOMPARE(ask("#1E\r#1ZE1\r"), QByteArray("001E1\r001ZE116\r"));
    ask("#1D\r"); // 5.14
    QVERIFY(!decodeStatus(d->statusWord()).positionError);
    QCOMPARE(d->position(), d->encoderPosition());
}

void TestNanotecSimulator::reference_external_freesSwitchAndZeroes()
{
    NanotecDrive* d = m_sim->drive(1);
    d->setSwitches(-300, 100000);
    // l = 5154 (factory): "free backward" backs off the switch after the reference run.
    QCOMPARE(d->value('l'), qint64(5154));
    ask("#1!1\r#1p4\r#1d0\r#1A\r");
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    QVERIFY(d->physicalPosition() < -290); // it ran into the switch ...
    QVERIFY(!d->externalSwitchActuated()); // ... and freed it
    QCOMPARE(d->position(), qint64(0));
    QVERIFY(decodeStatus(d->statusWord()).zeroReached);
    QCOMPARE(ask("#1ZY\r"), QByteArray("001ZY96\r")); // NC switch released: input 6 high
}

void TestNanotecSimulator::limitSwitch_stopBehaviour_haltsOnSwitch()
{
    NanotecDrive* d = m_sim->drive(1);
    d->setSwitches(-100000, 250);
    ask("#1l9250\r"); // external normal: stop (bit 13)
    ask("#1!1\r#1p1\r#1s5000\r#1d1\r#1A\r");
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    QVERIFY(d->externalSwitchActuated()); // "Der Schalter bleibt dabei gedrueckt"
    QVERIFY(d->position() >= 250 && d->position() < 300);
    QCOMPARE(ask("#1e1\r#1ZY\r"), QByteArray("001e1\r001ZY96\r")); // NO switch: high = pressed
}

// The factory behaviour frees a limit switch after stopping on it. The run then ends on a whole
// step: completed in the free travel's direction, never taken back onto the switch (a move
// ended short was reported "on its limit switch" now and then in tst_machine).
void TestNanotecSimulator::limitSwitch_freeTravel_endsOffTheSwitchAtUnevenTicks()
{
    QRandomGenerator rng(21);
    for (int run = 0; run < 50; ++run) {
        NanotecDrive drive(1);
        drive.setSwitches(-100000, 3000);
        for (const char* body : {"!1", "p1", "s9000", "d1", "A"})
            drive.handle(body);
        for (int tick = 0; tick < 100000 && !drive.ready(); ++tick)
            drive.advance(0.0005 + rng.bounded(0.02));
        QVERIFY(drive.ready());
        QVERIFY2(!drive.externalSwitchActuated(),
                 qPrintable(QStringLiteral("run %1 ended on the switch at %2")
                                .arg(run)
                                .arg(drive.physicalPosition())));
        QVERIFY(drive.position() < 3000);
    }
}

void TestNanotecSimulator::faults_silentGarbledWrongAddress()
{
    m_sim->setDriveSilent(1, true);
    QVERIFY(ask("#1$\r").isEmpty());
    m_sim->setDriveSilent(1, false);
    m_sim->garbleReplies(1, 1);
    const QByteArray garbled = ask("#1$\r");
    QVERIFY(garbled.endsWith('\r'));
    QCOMPARE(ReplyDecoder::parse(garbled.chopped(1)).kind, Reply::Kind::Invalid);
    QCOMPARE(ask("#1$\r"), QByteArray("001$19\r"));
    m_sim->replyFromWrongAddress(1, 1, 2);
    QCOMPARE(ask("#1$\r"), QByteArray("002$19\r"));
    QCOMPARE(ask("#1$\r"), QByteArray("001$19\r"));
}

void TestNanotecSimulator::neverSentCommands_behaveAsManualSays()
{
    QVERIFY(ask("#1@A\r").isEmpty()); // 5.32: the firmware does not answer
    QVERIFY(ask("#1|0\r").isEmpty()); // 6.4: no answer any more ...
    QVERIFY(ask("#1s5\r").isEmpty());
    QCOMPARE(m_sim->drive(1)->value('s'), qint64(5)); // ... but commands still execute
    QCOMPARE(ask("#1|1\r"), QByteArray("001|1\r"));
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecSimulator)
#include "tst_nanotecsimulator.moc"
