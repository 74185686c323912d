// The closed-loop workflow of the Nanotec adapter (NanotecClosedLoop, manual 8.1) against the
// simulated bus: what the drive received, how it turned and stands, and what the host says.
#include "NanotecRig.h"
#include "TestMain.h"
#include "model/ClosedLoop.h"

using namespace stepdeck;
using namespace stepdeck::nanotec;
using nanotectest::NanotecRig;
namespace cl = stepdeck::closedloop;

namespace {
constexpr int kClosedLoopCalibrationMs = 300;
}

class TestNanotecClosedLoop : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void check_readsMotorDataAndEncoder_noMotion();
    void check_wrongMotorData_namedAndRunsRefused();
    void calibrate_progressVisible_resultReadBack_modeRestored();
    void calibrate_withoutEncoder_failsNamingTheDrivesError();
    void calibrate_neverSeenBusy_notClaimedAsDone();
    void stop_duringCalibration_driveStandsStill_requestAborted_data();
    void stop_duringCalibration_driveStandsStill_requestAborted();
    void linkLoss_duringCalibration_stopReachesDrive();
    void reference_afterCalibration_axisReferencedAtZero();
    void enable_beforeTheRuns_driveIgnoresIt_explained();
    void enable_afterCalibrationAndReference_keptAndReadBack();
    void enable_wrongMotorData_refusedNothingWritten();

private:
    CommandResult operation(const QString& name, const QVariantMap& args = {});
    RequestId start(const QString& name, const QVariantMap& args = {});
    std::optional<CommandResult> finished(RequestId id) const;
    QVariantMap state() { return operation(cl::kState).value.toMap(); }

    std::unique_ptr<NanotecRig> m_rig;
    std::unique_ptr<QSignalSpy> m_results;
};

void TestNanotecClosedLoop::init()
{
    m_rig = std::make_unique<NanotecRig>();
    m_rig->sim->setCalibrationMs(kClosedLoopCalibrationMs);
    QVERIFY(m_rig->connect());
    m_results = std::make_unique<QSignalSpy>(m_rig->ctl, &Controller::requestFinished);
}

void TestNanotecClosedLoop::cleanup()
{
    m_results.reset();
    m_rig.reset();
}

CommandResult TestNanotecClosedLoop::operation(const QString& name, const QVariantMap& args)
{
    QVariantMap all = args;
    all.insert(QStringLiteral("axis"), QStringLiteral("X"));
    return m_rig->run([&](RequestId id) { m_rig->ctl->modelOperation(id, name, all); }, 10000);
}

RequestId TestNanotecClosedLoop::start(const QString& name, const QVariantMap& args)
{
    QVariantMap all = args;
    all.insert(QStringLiteral("axis"), QStringLiteral("X"));
    const RequestId id = 1000 + ++m_rig->nextId;
    m_rig->ctl->modelOperation(id, name, all);
    return id;
}

std::optional<CommandResult> TestNanotecClosedLoop::finished(RequestId id) const
{
    for (const auto& args : *m_results) {
        const auto r = args.at(0).value<CommandResult>();
        if (r.id == id)
            return r;
    }
    return std::nullopt;
}

void TestNanotecClosedLoop::check_readsMotorDataAndEncoder_noMotion()
{
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = operation(cl::kCheck);
    QVERIFY2(r.ok(), qPrintable(r.message));
    const QVariantMap v = r.value.toMap();
    QCOMPARE(v.value(cl::kMotorPolePairs).toInt(), 50);
    QCOMPARE(v.value(cl::kEncoderIncrements).toInt(), 2000);
    QCOMPARE(v.value(cl::kEncoderRevolutions).toInt(), 1);
    QCOMPARE(v.value(cl::kStepAngle).toString(), QStringLiteral("1.8"));
    QCOMPARE(v.value(cl::kEnabled).toBool(), false);
    QVERIFY(v.contains(cl::kEncoderPosition));
    QVERIFY(v.value(cl::kProblems).toStringList().isEmpty());
    QCOMPARE(v.value(cl::kCalibration).toString(), QString(cl::kResultNone));
    const QList<QByteArray> frames = m_rig->sim->receivedFrames();
    QVERIFY(frames.contains("#1:CL_motor_pp\r"));
    QVERIFY(frames.contains("#1I\r"));
    QVERIFY(!frames.contains("#1A\r"));
}

void TestNanotecClosedLoop::check_wrongMotorData_namedAndRunsRefused()
{
    m_rig->sim->drive(1)->handle(":CL_motor_pp=75");
    m_rig->sim->drive(1)->handle(":CL_rotenc_inc=1000");
    const QStringList problems =
        operation(cl::kCheck).value.toMap().value(cl::kProblems).toStringList();
    QCOMPARE(problems.size(), 2);
    QVERIFY2(problems.join(' ').contains("75") && problems.join(' ').contains("1000"),
             qPrintable(problems.join(' ')));
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = operation(cl::kCalibrate);
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("8.6"), qPrintable(r.message));
    QVERIFY(!m_rig->sim->receivedFrames().contains("#1!101\r")); // nothing started
    QVERIFY(!m_rig->sim->receivedFrames().contains("#1A\r"));
}

void TestNanotecClosedLoop::calibrate_progressVisible_resultReadBack_modeRestored()
{
    NanotecDrive* drive = m_rig->sim->drive(1);
    m_rig->sim->clearReceivedFrames();
    const RequestId id = start(cl::kCalibrate);
    // Progress as the drive shows it: the run is on, the position read back moves.
    QTRY_VERIFY_WITH_TIMEOUT(state().value(cl::kPosition).toLongLong() > 50, 5000);
    QCOMPARE(state().value(cl::kRun).toString(), QString(cl::kRunCalibration));
    QVERIFY(!finished(id));
    QVERIFY(m_rig->ctl->status().axes[Axis::X].moving);
    QVERIFY(m_rig->ctl->status().drives[0].detail.contains("calibration run"));
    const CommandResult move = m_rig->run([&](RequestId mid) {
        m_rig->ctl->moveRelative(mid, {{Axis::X, 100}});
    });
    QCOMPARE(move.error, ErrorKind::Refused); // the drive is busy with its run
    QTRY_VERIFY_WITH_TIMEOUT(finished(id).has_value(), 5000);
    const CommandResult r = *finished(id);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY(r.value.toMap().value(cl::kDurationMs).toLongLong() >= kClosedLoopCalibrationMs);
    QVERIFY(drive->closedLoop().calibrated());
    QVERIFY(m_rig->sim->standingStill());
    const QList<QByteArray> f = m_rig->sim->receivedFrames();
    QVERIFY(f.indexOf("#1!101\r") >= 0 && f.indexOf("#1A\r") > f.indexOf("#1!101\r"));
    QCOMPARE(drive->value('!'), qint64(1)); // the mode of before, set again
    QCOMPARE(state().value(cl::kCalibration).toString(), QString(cl::kResultDone));
    QVERIFY(!m_rig->ctl->status().axes[Axis::X].referenced); // turned, not a reference run
    QVERIFY(!m_rig->ctl->status().axes[Axis::X].moving);
}

void TestNanotecClosedLoop::calibrate_withoutEncoder_failsNamingTheDrivesError()
{
    m_rig->sim->setEncoderConnected(1, false);
    const CommandResult r = operation(cl::kCalibrate);
    QCOMPARE(r.error, ErrorKind::Nak);
    QVERIFY2(r.message.contains("ERROR_QEI") && r.message.contains("encoder"),
             qPrintable(r.message));
    QVERIFY(!m_rig->sim->drive(1)->closedLoop().calibrated());
    QCOMPARE(m_rig->sim->drive(1)->value('!'), qint64(1));
    QCOMPARE(state().value(cl::kCalibration).toString(), QString(cl::kResultFailed));
    QVERIFY(m_rig->sim->standingStill());
}

void TestNanotecClosedLoop::calibrate_neverSeenBusy_notClaimedAsDone()
{
    // A drive that keeps '!101' but does not run it on 'A': ready at once, nothing proves
    // that a calibration ran.
    m_rig->sim->drive(1)->faults.closedLoopRunsIgnored = true;
    const CommandResult r = operation(cl::kCalibrate);
    QCOMPARE(r.error, ErrorKind::VerifyFailed);
    QVERIFY2(r.message.contains("not confirmed"), qPrintable(r.message));
    QCOMPARE(state().value(cl::kCalibration).toString(), QString(cl::kResultFailed));
}

void TestNanotecClosedLoop::stop_duringCalibration_driveStandsStill_requestAborted_data()
{
    QTest::addColumn<bool>("panic");
    QTest::newRow("stop") << false;
    QTest::newRow("panic") << true;
}

void TestNanotecClosedLoop::stop_duringCalibration_driveStandsStill_requestAborted()
{
    QFETCH(bool, panic);
    m_rig->sim->setCalibrationMs(5000);
    NanotecDrive* drive = m_rig->sim->drive(1);
    const RequestId id = start(cl::kCalibrate);
    QTRY_VERIFY_WITH_TIMEOUT(drive->speed() != 0.0, 3000);
    m_rig->sim->clearReceivedFrames();
    const CommandResult stopped = m_rig->run([&](RequestId sid) {
        if (panic)
            m_rig->ctl->panic(sid);
        else
            m_rig->ctl->stop(sid);
    });
    QVERIFY2(stopped.ok(), qPrintable(stopped.message));
    QVERIFY(m_rig->sim->receivedFrames().contains(panic ? "#*S\r" : "#1S\r"));
    QVERIFY(m_rig->sim->standingStill()); // at the device
    QVERIFY(!drive->closedLoop().calibrated());
    QTRY_VERIFY(finished(id).has_value());
    QCOMPARE(finished(id)->error, ErrorKind::Cancelled);
    QVERIFY2(finished(id)->message.contains("not calibrated"), qPrintable(finished(id)->message));
    QCOMPARE(state().value(cl::kCalibration).toString(), QString(cl::kResultAborted));
    QVERIFY(!m_rig->ctl->status().axes[Axis::X].positionKnown);
    QVERIFY(!m_rig->ctl->status().axes[Axis::X].moving);
}

void TestNanotecClosedLoop::linkLoss_duringCalibration_stopReachesDrive()
{
    m_rig->sim->setCalibrationMs(5000);
    const RequestId id = start(cl::kCalibrate);
    QTRY_VERIFY_WITH_TIMEOUT(m_rig->sim->drive(1)->speed() != 0.0, 3000);
    m_rig->sim->faults().silent = true; // every reply lost on the way back; drives still listen
    m_rig->sim->clearReceivedFrames();
    QTRY_COMPARE_WITH_TIMEOUT(m_rig->ctl->linkState(), LinkState::Lost, 10000);
    QVERIFY(m_rig->sim->receivedFrames().contains("#1S\r"));
    QVERIFY(m_rig->sim->standingStill());
    QTRY_VERIFY(finished(id).has_value());
    // Whichever came first: the drive's silence (its 'S' then) or the link verdict.
    const ErrorKind e = finished(id)->error;
    QVERIFY2(e == ErrorKind::LinkDown || e == ErrorKind::Timeout,
             qPrintable(finished(id)->message));
    QVERIFY(m_rig->ctl->status().motionUnconfirmed); // no echo: not claimed
}

void TestNanotecClosedLoop::reference_afterCalibration_axisReferencedAtZero()
{
    QVERIFY(operation(cl::kCalibrate).ok());
    QVERIFY(m_rig->run([&](RequestId id) { m_rig->ctl->moveRelative(id, {{Axis::X, 123}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig->ctl->status().axes[Axis::X].moving, 5000);
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = operation(cl::kReference, {{QStringLiteral("direction"), -1}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    const QList<QByteArray> f = m_rig->sim->receivedFrames();
    QVERIFY(f.contains("#1!8\r") && f.contains("#1d0\r"));
    QVERIFY(m_rig->sim->drive(1)->closedLoop().referencedSincePowerOn());
    const AxisStatus x = m_rig->ctl->status().axes[Axis::X];
    QVERIFY(x.referenced && x.positionKnown);
    QCOMPARE(x.position, qint64(0));
    QCOMPARE(m_rig->sim->drive(1)->position(), qint64(0));
    QCOMPARE(state().value(cl::kReferenceRun).toString(), QString(cl::kResultDone));
}

void TestNanotecClosedLoop::enable_beforeTheRuns_driveIgnoresIt_explained()
{
    const CommandResult r = operation(cl::kEnable, {{QStringLiteral("on"), true}});
    QCOMPARE(r.error, ErrorKind::VerifyFailed);
    QVERIFY2(r.message.contains("!101") && r.message.contains("!8"), qPrintable(r.message));
    QCOMPARE(m_rig->sim->drive(1)->longValue("CL_enable"), qint64(0));
    QVERIFY(m_rig->sim->receivedFrames().contains("#1:CL_enable=1\r")); // written, ignored
}

void TestNanotecClosedLoop::enable_afterCalibrationAndReference_keptAndReadBack()
{
    QVERIFY(operation(cl::kCalibrate).ok());
    QVERIFY(operation(cl::kReference, {{QStringLiteral("direction"), 1}}).ok());
    const CommandResult r = operation(cl::kEnable, {{QStringLiteral("on"), true}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.value.toMap().value(cl::kEnabled).toBool(), true);
    QCOMPARE(r.value.toMap().value(cl::kParameter).toString(), QStringLiteral("cl-enable"));
    QCOMPARE(m_rig->sim->drive(1)->longValue("CL_enable"), qint64(1));
    QCOMPARE(state().value(cl::kEnabled).toBool(), true);
    const CommandResult off = operation(cl::kEnable, {{QStringLiteral("on"), false}});
    QVERIFY2(off.ok(), qPrintable(off.message));
    QCOMPARE(m_rig->sim->drive(1)->longValue("CL_enable"), qint64(0));
}

void TestNanotecClosedLoop::enable_wrongMotorData_refusedNothingWritten()
{
    m_rig->sim->drive(1)->handle(":CL_rotenc_rev=2");
    m_rig->sim->clearReceivedFrames();
    const CommandResult r = operation(cl::kEnable, {{QStringLiteral("on"), true}});
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("mechanical limits"), qPrintable(r.message));
    QVERIFY(!m_rig->sim->receivedFrames().contains("#1:CL_enable=1\r"));
}

STEPDECK_TEST_MAIN(TestNanotecClosedLoop)
#include "tst_nanotecclosedloop.moc"
