// The SMC-IC4 simulator: replies byte for byte as in chapter 9, time-based motion with ramps,
// reference runs against the switches on inputs 1-4, outputs, the "##" store, input programs,
// <BEL> for invalid values and busy motors, and the faults.
#include "TestMain.h"
#include "protocols/emis/EmisSimAxis.h"
#include "protocols/emis/EmisSimulator.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::emis;

namespace {
constexpr char ACK = 0x06;
constexpr char NAK = 0x15;
constexpr char BEL = 0x07;
} // namespace

class TestEmisSimulator : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void axis_rampsFromStartToWorkSpeedAndBack();
    void axis_reference_searchesSwitchThenLeavesByOffset();
    void queries_answerAsInManual();
    void outputs_setAndReset();
    void vector_nakThenArrival_positionCounted();
    void vector_busyAxis_bell_otherAxisMayJoin();
    void vector_absolute_usesBoardCounter();
    void acceptedMoves_journalsAcceptedVectorsOnly();
    void emergencyStop_axesStandAtOnce_noArrival();
    void vector_interpolation_axesArriveTogether();
    void home_sequential_arrivalsInOrder_counterZero();
    void home_simultaneous_arrivalsAsSwitchesAreReached();
    void home_switchTypeMismatch_endsAtOnce();
    void invalidValues_bell_notExecuted_data();
    void invalidValues_bell_notExecuted();
    void systemWrite_readyAndFourAcks_spacedByFlashWrite_storedForPowerOn();
    void readSystem_listsStoredEntries();
    void clearSystem_erasesSmcFlexOnly();
    void program_writeAndErase();
    void program_invalidLine_bell();
    void faults_silentBellAndLostArrival();

private:
    QByteArray sendAndTake(const QByteArray& bytes);
    EmisSimulator* m_sim = nullptr;
    QByteArray m_out;
};

void TestEmisSimulator::init()
{
    m_sim = new EmisSimulator(SimulatorOptions{});
    m_out.clear();
    connect(m_sim, &Simulator::transmit, this, [this](const QByteArray& b) { m_out += b; });
}

void TestEmisSimulator::cleanup()
{
    delete m_sim;
    m_sim = nullptr;
}

QByteArray TestEmisSimulator::sendAndTake(const QByteArray& bytes)
{
    m_out.clear();
    m_sim->receive(bytes);
    return std::exchange(m_out, QByteArray());
}

void TestEmisSimulator::axis_rampsFromStartToWorkSpeedAndBack()
{
    EmisSimAxis axis;
    axis.setPhysical(0);
    axis.startMove(2000, {200, 1000, 100});
    const auto noSwitch = [](qint64) { return false; };
    QCOMPARE(axis.velocity(), 200.0);
    double peak = 0;
    double last = 0;
    int ticks = 0;
    while (!axis.advance(0.001, noSwitch) && ticks < 100000) {
        peak = qMax(peak, axis.velocity());
        last = axis.velocity();
        ++ticks;
    }
    QCOMPARE(axis.physical(), 2000);
    QCOMPARE(peak, 1000.0);
    QVERIFY2(last < 300, qPrintable(QString::number(last))); // braked towards start speed
    // 2000 steps at 1000 steps/s with 100 ms ramps on each side: 2.0 s + ramp losses.
    QVERIFY(ticks > 2000 && ticks < 2200);
    QVERIFY(!axis.isMoving());
}

void TestEmisSimulator::axis_reference_searchesSwitchThenLeavesByOffset()
{
    EmisSimAxis axis;
    axis.setPhysical(300);
    axis.startReference({200, 400, 100}, 25);
    const auto switchAt0 = [](qint64 p) { return p <= 0; };
    int ticks = 0;
    qint64 lowest = 300;
    while (!axis.advance(0.001, switchAt0) && ticks < 100000) {
        lowest = qMin(lowest, axis.physical());
        ++ticks;
    }
    QVERIFY(lowest <= 0 && lowest >= -1);
    QCOMPARE(axis.physical(), lowest + 25);
}

void TestEmisSimulator::queries_answerAsInManual()
{
    QCOMPARE(sendAndTake("@V\r"), QByteArray("@V SMC-IC4 v1.07") + ACK);
    QCOMPARE(sendAndTake("@IG\r"), QByteArray("@IG 00000000") + ACK);
    m_sim->setInput(8, true);
    m_sim->setPhysicalPosition(Axis::X, -5); // on its switch (normally open: high)
    QCOMPARE(sendAndTake("@IG\r"), QByteArray("@IG 10000001") + ACK);
    QCOMPARE(sendAndTake("@I1\r"), QByteArray("@I1 1") + ACK);
    QCOMPARE(sendAndTake("@I2\r"), QByteArray("@I2 0") + ACK);
    m_sim->setSwitchWiring(Axis::Y, true); // a normally closed switch, not actuated: high
    QCOMPARE(sendAndTake("@IG\r"), QByteArray("@IG 11000001") + ACK);
    QCOMPARE(m_sim->receivedCommands(),
             (QList<QByteArray>{"@V", "@IG", "@IG", "@I1", "@I2", "@IG"}));
}

void TestEmisSimulator::outputs_setAndReset()
{
    QCOMPARE(sendAndTake("A1,1\r"), QByteArray(1, ACK));
    QCOMPARE(sendAndTake("A7,1\r"), QByteArray(1, ACK));
    QVERIFY(m_sim->output(1));
    QVERIFY(m_sim->output(7));
    QCOMPARE(sendAndTake("A1,0\r"), QByteArray(1, ACK));
    QVERIFY(!m_sim->output(1));
    QCOMPARE(sendAndTake("A8,1\r"), QByteArray(1, BEL));
}

void TestEmisSimulator::vector_nakThenArrival_positionCounted()
{
    sendAndTake("#R10\r#S500\r#E1,5000\r");
    QCOMPARE(sendAndTake("L1,x100,y-200\r"), QByteArray(1, NAK) + ' ');
    QVERIFY(m_sim->isMoving(Axis::X));
    QTRY_VERIFY(m_out.contains(char(0x11)) && m_out.contains(char(0x12)));
    QCOMPARE(m_out.size(), 2);
    QCOMPARE(m_sim->position(Axis::X), 100);
    QCOMPARE(m_sim->position(Axis::Y), -200);
    QVERIFY(!m_sim->anyMoving());
}

void TestEmisSimulator::vector_busyAxis_bell_otherAxisMayJoin()
{
    sendAndTake("#E1,200\r#S100\r");
    QCOMPARE(sendAndTake("L1,x400\r"), QByteArray(1, NAK) + ' ');
    QCOMPARE(sendAndTake("L1,x10\r"), QByteArray(1, BEL));
    QCOMPARE(sendAndTake("$Hx\r"), QByteArray(1, BEL));
    // 9.11: "Es ist auch möglich, dass während einer Vektorfahrt ein weiterer Motor
    // hinzugeschaltet wird."
    QCOMPARE(sendAndTake("L1,u5\r"), QByteArray(1, NAK) + ' ');
    QTRY_VERIFY(m_out.contains(char(0x14)));
    QVERIFY(m_sim->isMoving(Axis::X));
    QTRY_VERIFY_WITH_TIMEOUT(m_out.contains(char(0x11)), 10000);
    QCOMPARE(m_sim->position(Axis::X), 400);
}

void TestEmisSimulator::vector_absolute_usesBoardCounter()
{
    sendAndTake("#R10\r#E1,5000\r");
    sendAndTake("L1,z300\r");
    QTRY_VERIFY(m_out.contains(char(0x13)));
    QCOMPARE(sendAndTake("L1,Z-100\r"), QByteArray(1, NAK) + ' ');
    QTRY_VERIFY(m_out.contains(char(0x13)));
    QCOMPARE(m_sim->position(Axis::Z), -100);
}

void TestEmisSimulator::acceptedMoves_journalsAcceptedVectorsOnly()
{
    // The soak's device journal (stepdeck-bench --soak): relative lengths, absolute targets
    // converted, <BEL>-refused and zero-length moves left out.
    sendAndTake("#R10\r#S500\r#E1,200\r");
    QCOMPARE(sendAndTake("L1,x40,y-30\r"), QByteArray(1, NAK) + ' ');
    QCOMPARE(sendAndTake("L1,x10\r"), QByteArray(1, BEL)); // X still moving
    QTRY_VERIFY_WITH_TIMEOUT(!m_sim->anyMoving(), 5000);
    QCOMPARE(sendAndTake("L1,X25,z0\r"), QByteArray(1, NAK) + ' ');
    QTRY_VERIFY_WITH_TIMEOUT(!m_sim->anyMoving(), 5000);
    const auto moves = m_sim->acceptedMoves();
    QCOMPARE(moves.size(), 3);
    QCOMPARE(moves[0].axis, Axis::X);
    QCOMPARE(moves[0].steps, 40);
    QCOMPARE(moves[1].axis, Axis::Y);
    QCOMPARE(moves[1].steps, -30);
    QCOMPARE(moves[2].axis, Axis::X);
    QCOMPARE(moves[2].steps, -15); // absolute 25 from 40
}

void TestEmisSimulator::emergencyStop_axesStandAtOnce_noArrival()
{
    sendAndTake("#R10\r#S100\r#E1,200\r");
    QCOMPARE(sendAndTake("L1,x100000\r"), QByteArray(1, NAK) + ' ');
    QTRY_VERIFY(m_sim->position(Axis::X) > 0);
    m_sim->emergencyStop();
    QVERIFY(!m_sim->anyMoving());
    const qint64 stoppedAt = m_sim->position(Axis::X);
    QVERIFY(stoppedAt < 100000);
    QVERIFY(!m_out.contains(char(0x11))); // no arrival: the target was never reached
    QCOMPARE(sendAndTake("L1,x10\r"), QByteArray(1, NAK) + ' '); // the board takes new moves
    QTRY_COMPARE(m_sim->position(Axis::X), stoppedAt + 10);
}

void TestEmisSimulator::vector_interpolation_axesArriveTogether()
{
    sendAndTake("#R10\r#S100\r#E1,2000\rIP1\r");
    sendAndTake("L1,x1000,y100\r");
    // Y covers its 100 steps in X's time: when X is half-way, Y is too.
    QTRY_VERIFY(m_sim->position(Axis::X) >= 500);
    QVERIFY2(m_sim->position(Axis::Y) < 90, qPrintable(QString::number(m_sim->position(Axis::Y))));
    QTRY_VERIFY(m_out.contains(char(0x11)) && m_out.contains(char(0x12)));

    sendAndTake("IP0\r");
    sendAndTake("L1,x1000,y100\r");
    QTRY_VERIFY(m_out.contains(char(0x12)));
    QVERIFY(m_sim->isMoving(Axis::X)); // independent: Y was done long before X
    QTRY_VERIFY(m_out.contains(char(0x11)));
}

void TestEmisSimulator::home_sequential_arrivalsInOrder_counterZero()
{
    sendAndTake("#E9,20000\r#Ox,7\r");
    m_sim->setPhysicalPosition(Axis::X, 50);
    m_sim->setPhysicalPosition(Axis::Y, 400); // Y needs far longer than Z
    m_sim->setPhysicalPosition(Axis::Z, 20);
    QCOMPARE(sendAndTake("$Hxyz\r"), QByteArray("$Hxyz") + NAK);
    QVERIFY(m_sim->isMoving(Axis::Z)); // queued: counts as busy
    QTRY_COMPARE(m_out.size(), 3);
    QCOMPARE(m_out, QByteArray("\x11\x12\x13"));
    QCOMPARE(m_sim->position(Axis::X), 0);
    QCOMPARE(m_sim->physicalPosition(Axis::X), 7);
    QVERIFY(m_sim->isReferenced(Axis::Y));
    QVERIFY(!m_sim->isReferenced(Axis::U));
}

void TestEmisSimulator::home_simultaneous_arrivalsAsSwitchesAreReached()
{
    sendAndTake("#E9,5000\r");
    m_sim->setPhysicalPosition(Axis::X, 300);
    m_sim->setPhysicalPosition(Axis::Y, 200);
    m_sim->setPhysicalPosition(Axis::Z, 400);
    m_sim->setPhysicalPosition(Axis::U, 10);
    QCOMPARE(sendAndTake("$Hxyzu,a\r"), QByteArray("$Hxyzu") + NAK);
    QTRY_COMPARE(m_out.size(), 4);
    QCOMPARE(m_out, QByteArray("\x14\x12\x11\x13")); // the manual's own example order
}

void TestEmisSimulator::home_switchTypeMismatch_endsAtOnce()
{
    m_sim->setSwitchWiring(Axis::X, true); // wired normally closed, board still says NO
    m_sim->setPhysicalPosition(Axis::X, 500);
    sendAndTake("#Ox,0\r");
    sendAndTake("$Hx\r");
    QTRY_VERIFY(m_out.contains(char(0x11)));
    QVERIFY(m_sim->physicalPosition(Axis::X) > 400); // "referenced" far from the switch

    QCOMPARE(sendAndTake("##REFSW,xNC\r"), QByteArray(1, ACK));
    QTRY_COMPARE(m_out.count(ACK), kStoredAcks);
    sendAndTake("#E9,20000\r$Hx\r");
    QTRY_VERIFY(m_out.contains(char(0x11)));
    QVERIFY(qAbs(m_sim->physicalPosition(Axis::X)) <= 1);
}

void TestEmisSimulator::invalidValues_bell_notExecuted_data()
{
    QTest::addColumn<QByteArray>("command");
    QTest::newRow("speed 0") << QByteArray("#S0\r");
    QTest::newRow("idle 30") << QByteArray("c,x100,30\r");
    QTest::newRow("resolution 3") << QByteArray("D,x3\r");
    QTest::newRow("unknown") << QByteArray("XYZ\r");
    QTest::newRow("input 9") << QByteArray("@I9\r");
    QTest::newRow("header outside") << QByteArray("IJ1,1 x\x02");
}

void TestEmisSimulator::invalidValues_bell_notExecuted()
{
    QFETCH(QByteArray, command);
    const EmisSimulator::Working before = m_sim->working();
    QCOMPARE(sendAndTake(command), QByteArray(1, BEL));
    QCOMPARE(m_sim->working().startSpeed, before.startSpeed);
    QCOMPARE(m_sim->working().idleCurrent, before.idleCurrent);
    QCOMPARE(m_sim->working().resolution, before.resolution);
}

void TestEmisSimulator::systemWrite_readyAndFourAcks_spacedByFlashWrite_storedForPowerOn()
{
    // The first <ACK> at once, "Ready!" and the further ones as the flash is written (9.14);
    // a command that comes meanwhile is answered after them.
    QCOMPARE(sendAndTake("##D,x32,y16,z64,u1\r@V\r"), QByteArray(1, ACK));
    QTRY_COMPARE(m_out, QByteArray(" Ready! \x06 \x06 \x06 \x06@V SMC-IC4 v1.07\x06"));
    QCOMPARE(m_sim->receivedCommands().last(), QByteArray("@V"));
    m_sim->setFlashWriteMs(0);
    QCOMPARE(sendAndTake("##R,250\r"), QByteArray("\x06 Ready! \x06 \x06 \x06 \x06"));
    QCOMPARE(sendAndTake("##E,x1800,y1800,z600,u1000\r").count(ACK), 5);
    QCOMPARE(sendAndTake("##E9,x400\r").count(ACK), 5); // four also for an entry of one motor
    m_sim->setStoredAcksPerMotor(true);                 // the other reading of 9.14
    QCOMPARE(sendAndTake("##E9,x400,z200\r"), QByteArray("\x06 Ready! \x06 \x06"));
    QCOMPARE(sendAndTake("##R,250\r").count(ACK), 5); // applies to all four motors
    m_sim->withholdStoredAcks(1);
    QCOMPARE(sendAndTake("##R,250\r").count(ACK), 4);
    QCOMPARE(m_sim->working().resolution.value(Axis::X), 16); // not before the next power-on
    QCOMPARE(m_sim->working().ramp, 100);
    m_sim->powerCycle();
    QCOMPARE(m_sim->working().resolution.value(Axis::X), 32);
    QCOMPARE(m_sim->working().resolution.value(Axis::U), 1);
    QCOMPARE(m_sim->working().ramp, 250);
    QCOMPARE(m_sim->working().workSpeed.value(Axis::Z), 600);
    QCOMPARE(sendAndTake("##c,x101,0\r"), QByteArray(1, BEL));
}

void TestEmisSimulator::readSystem_listsStoredEntries()
{
    QCOMPARE(sendAndTake("*PRSYS\r"), QByteArray("*PRSYS:") + ACK);
    m_sim->setFlashWriteMs(0); // the whole "##" replies at once
    sendAndTake("##D,x32,y16,z64,u1\r##REFSW,xNO,yNO,zNO,uNC\r##D,x8\r");
    const QByteArray reply = sendAndTake("*PRSYS\r");
    QCOMPARE(reply, QByteArray("*PRSYS:##D,x8,y16,z64,u1\r\n##REFSW,xNO,yNO,zNO,uNC") + ACK);
}

void TestEmisSimulator::clearSystem_erasesSmcFlexOnly()
{
    m_sim->setFlashWriteMs(0);
    sendAndTake("##S,200,1800,100\r##R,100\r");
    QCOMPARE(m_sim->storedEntries().size(), 2);
    QCOMPARE(sendAndTake("*PESYS\r"), QByteArray("*PESYS ") + ACK);
    QCOMPARE(m_sim->storedEntries().size(), 1);
    QCOMPARE(m_sim->storedEntries().first().key, SystemEntry::Key::Ramp);
}

void TestEmisSimulator::program_writeAndErase()
{
    QCOMPARE(sendAndTake("*PWIN8\r"), QByteArray(1, ACK));
    QCOMPARE(sendAndTake("IJ8,1 Eingang 8: Vektorfahrt X-Motor\x02"), QByteArray(1, ACK));
    QCOMPARE(sendAndTake("L1,x191\r"), QByteArray(1, ACK));
    QCOMPARE(sendAndTake("W1500\r"), QByteArray(1, ACK));
    QCOMPARE(sendAndTake("\x03"), QByteArray(1, ACK));
    QVERIFY(!m_sim->anyMoving()); // stored, not executed
    const auto program = m_sim->program(8);
    QVERIFY(program.has_value());
    QCOMPARE(program->title, QByteArray("Eingang 8: Vektorfahrt X-Motor"));
    QCOMPARE(program->commands, (QList<QByteArray>{"L1,x191", "W1500"}));
    QCOMPARE(sendAndTake("*PEIN8\r"), QByteArray("*PEIN8 ") + ACK);
    QVERIFY(!m_sim->program(8).has_value());
}

void TestEmisSimulator::program_invalidLine_bell()
{
    sendAndTake("*PWIN5\r");
    QCOMPARE(sendAndTake("L1,x1\r"), QByteArray(1, BEL)); // the header must come first
    QCOMPARE(sendAndTake("IJ5,1 t\x02"), QByteArray(1, ACK));
    QCOMPARE(sendAndTake("@IG\r"), QByteArray(1, BEL));
    QCOMPARE(sendAndTake("W-1\r"), QByteArray(1, BEL));
    QCOMPARE(sendAndTake("\x03"), QByteArray(1, ACK));
    QVERIFY(m_sim->program(5)->commands.isEmpty());
}

void TestEmisSimulator::faults_silentBellAndLostArrival()
{
    m_sim->faults().silent = true;
    QCOMPARE(sendAndTake("@V\r"), QByteArray());
    m_sim->faults().silent = false;
    m_sim->faults().forceNak = 1;
    QCOMPARE(sendAndTake("A2,1\r"), QByteArray(1, BEL));
    QVERIFY(!m_sim->output(2));
    QCOMPARE(sendAndTake("A2,1\r"), QByteArray(1, ACK));

    sendAndTake("#R10\r#E1,5000\r");
    m_sim->dropArrivals(1);
    QCOMPARE(sendAndTake("L1,x50\r"), QByteArray(1, NAK) + ' ');
    QTRY_VERIFY(!m_sim->isMoving(Axis::X));
    QCOMPARE(m_sim->arrivalsDropped(), 1);
    QVERIFY(m_out.isEmpty());
    QCOMPARE(m_sim->position(Axis::X), 50);
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisSimulator)
#include "tst_emissimulator.moc"
