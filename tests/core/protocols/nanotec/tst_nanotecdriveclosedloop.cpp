// The closed-loop side of a simulated Nanotec drive (manual 8.1; the readings are listed in
// NanotecDriveClosedLoop.h): the calibration run '!101' takes its time and shows its progress
// in 'C' and 'I', fails without an encoder, the closed-loop reference run '!8' ends at the
// index mark, ':CL_enable=1' is ignored until both ran, and 'S' stops either run.
#include "TestMain.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::nanotec;

namespace {
constexpr int kDriveCalibrationMs = 400;
}

class TestNanotecDriveClosedLoop : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void calibration_takesItsTime_progressShowsInPositionAndEncoder();
    void calibration_withoutEncoder_failsWithPositionError();
    void reference_afterCalibration_endsAtIndexMark_enableKept();
    void enable_withoutCalibrationOrReference_ignored_data();
    void enable_withoutCalibrationOrReference_ignored();
    void reference_withoutEncoder_failsWithPositionError();
    void stop_duringCalibration_standsStill_notCalibrated();

private:
    QByteArray ask(const QByteArray& frames);
    qint64 value(const QByteArray& frame, const QByteArray& replyPrefix);
    void calibrate();

    NanotecSimulator* m_sim = nullptr;
    QSignalSpy* m_tx = nullptr;
};

void TestNanotecDriveClosedLoop::init()
{
    SimulatorOptions o;
    o.addresses = {1};
    m_sim = new NanotecSimulator(o);
    m_sim->setCalibrationMs(kDriveCalibrationMs);
    m_tx = new QSignalSpy(m_sim, &Simulator::transmit);
}

void TestNanotecDriveClosedLoop::cleanup()
{
    delete m_tx;
    delete m_sim;
}

QByteArray TestNanotecDriveClosedLoop::ask(const QByteArray& frames)
{
    m_tx->clear();
    m_sim->receive(frames);
    QByteArray out;
    for (const auto& args : *m_tx)
        out += args.at(0).toByteArray();
    return out;
}

qint64 TestNanotecDriveClosedLoop::value(const QByteArray& frame, const QByteArray& replyPrefix)
{
    const QByteArray reply = ask(frame);
    if (!reply.startsWith(replyPrefix) || !reply.endsWith('\r')) {
        qWarning() << frame << "answered" << reply;
        return -999999;
    }
    return reply.mid(replyPrefix.size()).chopped(1).toLongLong();
}

void TestNanotecDriveClosedLoop::calibrate()
{
    ask("#1!101\r");
    QCOMPARE(value("#1Z!\r", "001Z!"), qint64(101)); // the calibration mode, not positioning
    ask("#1A\r");
    QTRY_VERIFY_WITH_TIMEOUT(m_sim->drive(1)->ready(), 10 * kDriveCalibrationMs);
}

void TestNanotecDriveClosedLoop::calibration_takesItsTime_progressShowsInPositionAndEncoder()
{
    NanotecDrive* d = m_sim->drive(1);
    QCOMPARE(ask("#1!101\r"), QByteArray("001!101\r"));
    QCOMPARE(value("#1Z!\r", "001Z!"), qint64(101)); // kept, unlike an invalid mode
    QElapsedTimer clock;
    clock.start();
    QCOMPARE(ask("#1A\r"), QByteArray("001A\r"));
    // Busy (bit 0 clear), at zero (bit 1), mode bits 0: 101 does not fit bits 4-6.
    QCOMPARE(value("#1$\r", "001$"), qint64(2));
    // Progress as the drive shows it: the rotor turns, 'C' and 'I' follow while it is busy.
    QTRY_VERIFY_WITH_TIMEOUT(d->position() > 100, 5000);
    QVERIFY(!d->ready());
    QCOMPARE(value("#1$\r", "001$") & 1, qint64(0));
    QVERIFY(qAbs(value("#1I\r", "001I") - value("#1C\r", "001C")) <= 1);
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    // It cannot end before its time: the rotor went one revolution out and back.
    QVERIFY2(clock.elapsed() >= kDriveCalibrationMs, qPrintable(QString::number(clock.elapsed())));
    QCOMPARE(d->position(), qint64(0));
    QCOMPARE(value("#1$\r", "001$") & 0x05, qint64(1)); // ready, no position error
    QVERIFY(d->closedLoop().calibrated());
    QVERIFY(m_sim->standingStill());
}

void TestNanotecDriveClosedLoop::calibration_withoutEncoder_failsWithPositionError()
{
    NanotecDrive* d = m_sim->drive(1);
    m_sim->setEncoderConnected(1, false);
    calibrate();
    QVERIFY(!d->closedLoop().calibrated());
    QCOMPARE(value("#1$\r", "001$") & 0x05, qint64(0x05)); // ready, position error (5.21)
    QCOMPARE(value("#1E\r", "001E"), qint64(1));
    QCOMPARE(value("#1ZE1\r", "001ZE1"), qint64(error::Position)); // ERROR_QEI (5.15)
    QCOMPARE(value("#1I\r", "001I"), qint64(0)); // no counts: the encoder is missing
    QVERIFY(d->position() != 0);                 // the rotor turned nevertheless
    QVERIFY(m_sim->standingStill());
}

void TestNanotecDriveClosedLoop::reference_afterCalibration_endsAtIndexMark_enableKept()
{
    NanotecDrive* d = m_sim->drive(1);
    calibrate();
    ask("#1s123\r#1p1\r#1!1\r#1d1\r#1A\r"); // somewhere off the index mark
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    QVERIFY(d->position() != 0);
    QCOMPARE(ask("#1!8\r#1d0\r#1A\r"), QByteArray("001!8\r001d0\r001A\r"));
    QCOMPARE(value("#1$\r", "001$") & 1, qint64(0));
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    QVERIFY(d->closedLoop().referencedSincePowerOn());
    QCOMPARE(value("#1C\r", "001C"), qint64(0)); // the index mark is the reference position
    QCOMPARE(value("#1I\r", "001I"), qint64(0));
    QCOMPARE(value("#1ZY\r", "001ZY") & 0x40, qint64(0)); // bit 6: at the index mark (5.30)
    QCOMPARE(d->physicalPosition(), 0.0); // the mark behind the start, direction 'd'=0
    QCOMPARE(ask("#1:CL_enable=1\r"), QByteArray("1:CL_enable=1\r"));
    QCOMPARE(ask("#1:CL_enable\r"), QByteArray("1:CL_enable+1\r"));
}

void TestNanotecDriveClosedLoop::enable_withoutCalibrationOrReference_ignored_data()
{
    QTest::addColumn<bool>("calibrated");
    QTest::addColumn<bool>("referenced");
    QTest::newRow("neither") << false << false;
    QTest::newRow("calibrated only") << true << false;
    QTest::newRow("referenced only") << false << true;
}

void TestNanotecDriveClosedLoop::enable_withoutCalibrationOrReference_ignored()
{
    QFETCH(bool, calibrated);
    QFETCH(bool, referenced);
    NanotecDrive* d = m_sim->drive(1);
    if (calibrated)
        calibrate();
    if (referenced) {
        ask("#1!8\r#1A\r");
        QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    }
    QCOMPARE(d->closedLoop().calibrated(), calibrated);
    QCOMPARE(d->closedLoop().referencedSincePowerOn(), referenced);
    // 8.1: echoed like every write, and then ignored.
    QCOMPARE(ask("#1:CL_enable=1\r"), QByteArray("1:CL_enable=1\r"));
    QCOMPARE(ask("#1:CL_enable\r"), QByteArray("1:CL_enable+0\r"));
}

void TestNanotecDriveClosedLoop::reference_withoutEncoder_failsWithPositionError()
{
    NanotecDrive* d = m_sim->drive(1);
    calibrate();
    m_sim->setEncoderConnected(1, false);
    ask("#1!8\r#1d1\r#1A\r");
    QTRY_VERIFY_WITH_TIMEOUT(d->ready(), 5000);
    QVERIFY(!d->closedLoop().referencedSincePowerOn());
    QCOMPARE(value("#1$\r", "001$") & 0x04, qint64(0x04));
    QVERIFY(d->position() > 400); // searched beyond one revolution for the index mark
    QVERIFY(m_sim->standingStill());
}

void TestNanotecDriveClosedLoop::stop_duringCalibration_standsStill_notCalibrated()
{
    NanotecDrive* d = m_sim->drive(1);
    calibrate(); // an earlier calibration of this motor
    QVERIFY(d->closedLoop().calibrated());
    ask("#1!101\r#1A\r");
    QTRY_VERIFY_WITH_TIMEOUT(d->speed() != 0.0, 2000);
    QCOMPARE(ask("#1S\r"), QByteArray("001S\r"));
    QVERIFY(m_sim->standingStill());
    QVERIFY(d->ready());
    QVERIFY(!d->closedLoop().calibrated()); // the new run replaced it and did not finish
    QVERIFY(d->closedLoop().running() == DriveClosedLoop::Run::None); // nothing resumes
}

STEPDECK_TEST_MAIN(TestNanotecDriveClosedLoop)
#include "tst_nanotecdriveclosedloop.moc"
