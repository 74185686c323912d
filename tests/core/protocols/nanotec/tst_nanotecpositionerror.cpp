// A drive's position error (5.13/5.14) as the operator reads it (issue 16): the adapter says
// what to do in the words of the front end that runs it -- the CLI's command, the GUI's
// button (ControllerOptions::actionNames) -- and in neutral words without one; never a CLI
// word in a GUI. The reset itself reaches the drive and clears the error there.
// STOP of a positioning run ('S' has no ramp, 6.2) keeps the position only where the drive's
// encoder confirms its count (issue 28, item 4), and a reference run clears a position error
// itself instead of being refused.
// A second stop while the first still confirms (issue 47 item 7: a program's abort right behind
// the window's STOP) takes the first over: both end confirmed, never "'I' to drive 1 was
// cancelled", and the encoder check the first was making is made by the second.
#include "NanotecRig.h"
#include "TestMain.h"

using namespace stepdeck;
using namespace stepdeck::nanotec;
using nanotectest::NanotecRig;

class TestNanotecPositionError : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void messages_nameTheFrontEndsAction_data();
    void messages_nameTheFrontEndsAction();
    void reset_clearsTheErrorAtTheDrive();
    void stop_positioningRun_positionKeptWhereTheEncoderAgrees_data();
    void stop_positioningRun_positionKeptWhereTheEncoderAgrees();
    void reference_afterStopWithPositionError_clearsItAndReferences();
    void stop_secondStopBackToBack_bothConfirmed_driveStands();
    void stop_secondStopDuringTheEncoderCheck_firstTakenOver_positionKept();

private:
    // Drive 1 (X) referenced at 0, then a long relative run stopped at full speed.
    bool referenceThenStopAtFullSpeed(NanotecRig& rig);
};

void TestNanotecPositionError::messages_nameTheFrontEndsAction_data()
{
    QTest::addColumn<QString>("action"); // empty: no entry
    QTest::newRow("GUI") << "the \u201cReset position error\u201d button on the Drives page";
    QTest::newRow("CLI") << "`stepdeck-cli reset-position-error AXIS`";
    QTest::newRow("none") << QString();
}

void TestNanotecPositionError::messages_nameTheFrontEndsAction()
{
    QFETCH(QString, action);
    ControllerOptions options = nanotectest::fastOptions();
    if (!action.isEmpty())
        options.actionNames.insert(QStringLiteral("reset-position-error"), action);
    NanotecRig rig(options);
    QSignalSpy errors(rig.ctl, &Controller::errorOccurred);
    QVERIFY(rig.connect());
    rig.sim->drive(2)->injectPositionError();
    QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), 5000);
    const QString reported = errors.last().at(0).toString();
    QVERIFY2(reported.contains(QStringLiteral("position error")), qPrintable(reported));
    // A move of that axis is refused with the same advice.
    const CommandResult refused = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::Y, 10}});
    });
    QCOMPARE(refused.error, ErrorKind::Refused);
    for (const QString& text : {reported, refused.message}) {
        if (action.isEmpty()) {
            QVERIFY2(text.contains(QStringLiteral("reset the position error")), qPrintable(text));
            QVERIFY2(!text.contains(QStringLiteral("reset-position-error")), qPrintable(text));
        } else {
            QVERIFY2(text.endsWith(action), qPrintable(text));
        }
    }
}

void TestNanotecPositionError::reset_clearsTheErrorAtTheDrive()
{
    NanotecRig rig;
    QVERIFY(rig.connect());
    NanotecDrive* drive = rig.sim->drive(2);
    drive->injectPositionError();
    QVERIFY(decodeStatus(drive->statusWord()).positionError);
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->modelOperation(id, QStringLiteral("reset-position-error"), {{"axis", "Y"}});
    });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(rig.countFrames("#2D\r"), 1);
    QVERIFY(!decodeStatus(drive->statusWord()).positionError);
}

namespace {
bool referenceX(NanotecRig& rig)
{
    NanotecDrive* d = rig.sim->drive(1);
    d->setSwitches(-250, 100000);
    if (!rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::X, -1}}); }).ok())
        return false;
    return QTest::qWaitFor([&] { return rig.ctl->status().axes[Axis::X].referenced; }, 5000);
}
} // namespace

bool TestNanotecPositionError::referenceThenStopAtFullSpeed(NanotecRig& rig)
{
    NanotecDrive* d = rig.sim->drive(1);
    if (!referenceX(rig))
        return false;
    if (!rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 20000}}); }).ok())
        return false;
    if (!QTest::qWaitFor([&] { return d->speed() >= 999 && d->position() > 500; }, 5000))
        return false;
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->stop(id); });
    return r.ok() && d->ready();
}

void TestNanotecPositionError::stop_positioningRun_positionKeptWhereTheEncoderAgrees_data()
{
    QTest::addColumn<QByteArray>("setup"); // bodies sent to drive 1 before the run
    QTest::addColumn<bool>("known");
    // 'o' is 1000 steps/s. At or below the start frequency 'u' the motor stops on the spot.
    QTest::newRow("stopped below the start frequency, encoder on") << QByteArray("u1000") << true;
    // Above it the rotor overshoots: the encoder sees steps the count never made (6.2).
    QTest::newRow("stopped above the start frequency") << QByteArray("u400") << false;
    // Without error correction (no encoder, 5.9) nothing confirms the count.
    QTest::newRow("no encoder") << QByteArray("u1000,U0") << false;
}

void TestNanotecPositionError::stop_positioningRun_positionKeptWhereTheEncoderAgrees()
{
    QFETCH(QByteArray, setup);
    QFETCH(bool, known);
    NanotecRig rig;
    QVERIFY(rig.connect());
    NanotecDrive* d = rig.sim->drive(1);
    for (const QByteArray& body : setup.split(','))
        d->handle(body);
    QVERIFY(referenceThenStopAtFullSpeed(rig));
    // At the drive: it stands part-way, its encoder as the scenario says.
    QVERIFY(d->position() > 0 && d->position() < 20000);
    QCOMPARE(qAbs(d->encoderPosition() - d->position()) <= 2, setup != "u400");
    const AxisStatus x = rig.ctl->status().axes.value(Axis::X);
    QCOMPARE(x.positionKnown, known);
    QCOMPARE(x.referenced, known);
    const CommandResult back = rig.run([&](RequestId id) {
        rig.ctl->moveAbsolute(id, {{Axis::X, 100}});
    });
    QCOMPARE(back.ok(), known);
    if (!known) {
        QCOMPARE(back.error, ErrorKind::Refused);
        return;
    }
    // Without re-referencing, the absolute move lands where the drive counts 100.
    QTRY_VERIFY_WITH_TIMEOUT(d->ready() && d->position() == 100, 10000);
    QCOMPARE(d->encoderPosition(), qint64(100));
}

void TestNanotecPositionError::reference_afterStopWithPositionError_clearsItAndReferences()
{
    NanotecRig rig;
    QVERIFY(rig.connect());
    NanotecDrive* d = rig.sim->drive(1);
    QVERIFY(referenceThenStopAtFullSpeed(rig)); // 'u' 400: the stop leaves a position error
    QVERIFY(decodeStatus(d->statusWord()).positionError);
    QTRY_VERIFY(!rig.ctl->status().axes.value(Axis::X).positionKnown);
    const CommandResult r = rig.run(
        [&](RequestId id) {
            rig.ctl->reference(id, {{Axis::X, -1}});
        },
        10000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(rig.countFrames("#1D\r"), 1); // 5.14, before the run
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 10000);
    QVERIFY(!decodeStatus(d->statusWord()).positionError);
    QCOMPARE(d->position(), qint64(0));
    QCOMPARE(d->encoderPosition(), qint64(0));
}

namespace {
std::optional<CommandResult> resultOf(const QSignalSpy& finished, RequestId id)
{
    for (const QList<QVariant>& args : finished) {
        const auto r = args.at(0).value<CommandResult>();
        if (r.id == id)
            return r;
    }
    return std::nullopt;
}
} // namespace

void TestNanotecPositionError::stop_secondStopBackToBack_bothConfirmed_driveStands()
{
    NanotecRig rig;
    QVERIFY(rig.connect());
    NanotecDrive* d = rig.sim->drive(1);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 20000}}); }).ok());
    QVERIFY(QTest::qWaitFor([&] { return d->speed() >= 999 && d->position() > 500; }, 5000));
    QSignalSpy finished(rig.ctl, &Controller::requestFinished);
    const RequestId first = ++rig.nextId;
    const RequestId second = ++rig.nextId;
    // As MainWindow::stopAll posts them: the window's STOP, then the program's abort. The
    // second cancels the first's 'S' on the bus.
    rig.ctl->stop(first);
    rig.ctl->stop(second);
    QTRY_VERIFY_WITH_TIMEOUT(resultOf(finished, first) && resultOf(finished, second), 10000);
    const CommandResult r1 = *resultOf(finished, first);
    const CommandResult r2 = *resultOf(finished, second);
    QVERIFY2(r1.ok(), qPrintable(r1.message));
    QVERIFY2(r2.ok(), qPrintable(r2.message));
    // At the drive: it stands short of its target, and stays there.
    QVERIFY(d->ready());
    const qint64 stoppedAt = d->position();
    QVERIFY(stoppedAt > 0 && stoppedAt < 20000);
    QTest::qWait(200);
    QVERIFY(d->ready());
    QCOMPARE(d->position(), stoppedAt);
    QVERIFY(!rig.ctl->status().motionUnconfirmed);
}

void TestNanotecPositionError::stop_secondStopDuringTheEncoderCheck_firstTakenOver_positionKept()
{
    NanotecRig rig;
    QVERIFY(rig.connect());
    NanotecDrive* d = rig.sim->drive(1);
    d->handle("u1000"); // stopped on the spot: the encoder agrees with the count
    QVERIFY(referenceX(rig));
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 20000}}); }).ok());
    QVERIFY(QTest::qWaitFor([&] { return d->speed() >= 999 && d->position() > 500; }, 5000));
    QSignalSpy finished(rig.ctl, &Controller::requestFinished);
    const RequestId first = ++rig.nextId;
    const RequestId second = ++rig.nextId;
    // The second stop comes the moment the first asks drive 1 for its encoder count ('I'):
    // it cancels that read on the bus, as in issue 47's report.
    bool posted = false;
    QObject::connect(rig.ctl, &Controller::traffic, rig.ctl, [&](const TrafficRecord& r) {
        if (posted || r.direction != TrafficRecord::Direction::Out || r.bytes != "#1I\r")
            return;
        posted = true;
        QMetaObject::invokeMethod(
            rig.ctl, [&] { rig.ctl->stop(second); }, Qt::QueuedConnection);
    });
    rig.ctl->stop(first);
    QTRY_VERIFY_WITH_TIMEOUT(resultOf(finished, first) && resultOf(finished, second), 10000);
    QVERIFY(posted);
    const CommandResult r1 = *resultOf(finished, first);
    const CommandResult r2 = *resultOf(finished, second);
    QVERIFY2(r1.ok(), qPrintable(r1.message));
    QVERIFY2(r2.ok(), qPrintable(r2.message));
    // At the drive: it stands; the second stop asked 'I' again, and the count the encoder
    // confirmed is kept (no reference run needed).
    QVERIFY(d->ready());
    QVERIFY(rig.countFrames("#1I\r") >= 2);
    QVERIFY(qAbs(d->encoderPosition() - d->position()) <= 2);
    const AxisStatus x = rig.ctl->status().axes.value(Axis::X);
    QVERIFY(x.referenced);
    QVERIFY(x.positionKnown);
    QCOMPARE(x.position, d->position());
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecPositionError)
#include "tst_nanotecpositionerror.moc"
