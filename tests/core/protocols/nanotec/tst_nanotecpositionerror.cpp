// A drive's position error (5.13/5.14) as the operator reads it (issue 16): the adapter says
// what to do in the words of the front end that runs it -- the CLI's command, the GUI's
// button (ControllerOptions::actionNames) -- and in neutral words without one; never a CLI
// word in a GUI. The reset itself reaches the drive and clears the error there.
#include "NanotecRig.h"

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

QTEST_GUILESS_MAIN(TestNanotecPositionError)
#include "tst_nanotecpositionerror.moc"
