// NanotecController's parameter I/O against a simulated bus of drives 1, 2, 3 (axes X, Y, Z)
// over LoopbackTransport: write & verify, read-back, limit-switch groups, motor address, records
// and the error memory. (Link, motion and faults: tst_nanoteccontroller.)
#include "NanotecRig.h"
#include "TestMain.h"
#include "TestSupport.h"

using namespace stepdeck;
using namespace stepdeck::nanotec;
using nanotectest::NanotecRig;

class TestNanotecParameterIo : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void write_verified_reachesEveryDrive();
    void write_ignoredInvalidValue_isCaughtByReadBack();
    void write_valueTheDriveDidNotKeep_notListedAsWritten();
    void write_unverifiedEchoes_listedAsSentNotWritten();
    void write_limitSwitchGroup_keepsOtherGroups();
    void write_undefinedMaskBits_refusedBeforeSending();
    void write_motorAddress_followsTheDrive();
    void read_valuesPerAxis_andLastError();
    void records_writeSaveReadBack();
    void errorMemory_decoded();

private:
    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs = 5000)
    {
        return m_rig->run(call, timeoutMs);
    }
    int countFrames(const QByteArray& frame) const { return m_rig->countFrames(frame); }

    std::unique_ptr<NanotecRig> m_rig;
    NanotecSimulator* m_sim = nullptr;
    NanotecController* m_ctl = nullptr;
};

void TestNanotecParameterIo::init()
{
    m_rig = std::make_unique<NanotecRig>();
    m_sim = m_rig->sim;
    m_ctl = m_rig->ctl;
    QVERIFY(m_rig->connect());
}

void TestNanotecParameterIo::cleanup()
{
    m_rig.reset();
}

void TestNanotecParameterIo::write_verified_reachesEveryDrive()
{
    ParameterSet set;
    set["phase-current"].perAxis = {{Axis::X, 80}, {Axis::Y, 70}, {Axis::Z, 60}};
    set["step-mode"].perAxis = {{Axis::X, "adaptive"}, {Axis::Y, "16"}, {Axis::Z, "1"}};
    set["cl-motor-pole-pairs"].perAxis = {{Axis::X, "100"}, {Axis::Y, "50"}, {Axis::Z, "50"}};
    const CommandResult r = run([&](RequestId id) { m_ctl->writeParameters(id, set, true); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(m_sim->drive(1)->value('i'), qint64(80));
    QCOMPARE(m_sim->drive(3)->value('i'), qint64(60));
    QCOMPARE(m_sim->drive(1)->value('g'), qint64(255));
    QCOMPARE(m_sim->drive(1)->longValue("CL_motor_pp"), qint64(100));
    QCOMPARE(m_sim->drive(1)->value('a'), qint64(9)); // 8.6: coupled to the step angle
    QCOMPARE(countFrames("#1Zi\r"), 1);               // the read-back
    QCOMPARE(countFrames("#2:CL_motor_pp\r"), 1);
}

void TestNanotecParameterIo::write_ignoredInvalidValue_isCaughtByReadBack()
{
    ParameterSet mode;
    mode["motor-mode"].perAxis = {{Axis::X, "speed"}};
    QVERIFY(run([&](RequestId id) { m_ctl->writeParameters(id, mode, true); }).ok());
    // 6.6: p=2 is "nicht belegt" in speed mode; the drive echoes it and ignores it.
    ParameterSet p;
    p["positioning-mode"].perAxis = {{Axis::X, 2}};
    const CommandResult r = run([&](RequestId id) { m_ctl->writeParameters(id, p, true); });
    QCOMPARE(r.error, ErrorKind::VerifyFailed);
    QVERIFY2(r.message.contains("Positioning mode"), qPrintable(r.message));
    QVERIFY(r.message.contains("drive 1"));
    QCOMPARE(countFrames("#1p2\r"), 1);
    // Without verify the same write "succeeds": that is why verify is the default.
    QVERIFY(run([&](RequestId id) { m_ctl->writeParameters(id, p, false); }).ok());
}

// A drive whose firmware ignores a valid phase current: the read-back catches it, and the
// message lists only what the drives kept as "already written" (issue 18, item 13).
void TestNanotecParameterIo::write_valueTheDriveDidNotKeep_notListedAsWritten()
{
    m_sim->ignoreSetting(1, 'i');
    ParameterSet one;
    one["phase-current"].perAxis = {{Axis::X, 80}};
    CommandResult r = run([&](RequestId id) { m_ctl->writeParameters(id, one, true); });
    QCOMPARE(r.error, ErrorKind::VerifyFailed);
    QVERIFY2(r.message.contains("wrote 80, but the drive kept 50"), qPrintable(r.message));
    QVERIFY2(!r.message.contains("already written"), qPrintable(r.message));
    QVERIFY2(!r.message.contains("not read back"), qPrintable(r.message));
    QCOMPARE(m_sim->drive(1)->value('i'), qint64(50)); // what the device kept

    // Drives are written in axis order: the one that ignores the value comes last here.
    m_sim->drive(1)->faults.ignoredSettings.clear();
    m_sim->ignoreSetting(2, 'i');
    ParameterSet two;
    two["phase-current"].perAxis = {{Axis::X, 70}, {Axis::Y, 80}};
    r = run([&](RequestId id) { m_ctl->writeParameters(id, two, true); });
    QCOMPARE(r.error, ErrorKind::VerifyFailed);
    QCOMPARE(m_sim->drive(1)->value('i'), qint64(70));
    QCOMPARE(m_sim->drive(2)->value('i'), qint64(50));
    const QString written = r.message.section(QStringLiteral("; already written: "), 1);
    QVERIFY2(written == QStringLiteral("Phase current (drive 1 (axis X))"), qPrintable(r.message));
}

// Without verify an echo is all there is: a later failure lists the echoed values as sent,
// never as written (the drive may have ignored them).
void TestNanotecParameterIo::write_unverifiedEchoes_listedAsSentNotWritten()
{
    m_sim->setDriveSilent(2, true);
    ParameterSet set;
    set["phase-current"].perAxis = {{Axis::X, 70}, {Axis::Y, 80}};
    const CommandResult r = run([&](RequestId id) { m_ctl->writeParameters(id, set, false); });
    QVERIFY(!r.ok());
    QVERIFY2(!r.message.contains("already written"), qPrintable(r.message));
    QVERIFY2(r.message.endsWith("; sent but not read back: Phase current (drive 1 (axis X))"),
             qPrintable(r.message));
}

void TestNanotecParameterIo::write_limitSwitchGroup_keepsOtherGroups()
{
    ParameterSet set;
    set["limit-switch-behaviour-external-normal"].perAxis = {{Axis::Y, "stop"}};
    set["limit-switch-behaviour-internal-reference"].perAxis = {{Axis::Y, "free-forward"}};
    QVERIFY(run([&](RequestId id) { m_ctl->writeParameters(id, set, true); }).ok());
    QCOMPARE(m_sim->drive(2)->value('l'), qint64((5154 & ~0x7803) | 0x2000 | 0x0001));
    const CommandResult r = run([&](RequestId id) {
        m_ctl->readParameters(id, {"limit-switch-behaviour-external-normal",
                                   "limit-switch-behaviour-external-reference",
                                   "limit-switch-behaviour-internal-normal"});
    });
    QVERIFY(r.ok());
    const ParameterSet got = r.value.value<ParameterSet>();
    QCOMPARE(got["limit-switch-behaviour-external-normal"].perAxis[Axis::Y].toString(),
             QStringLiteral("stop"));
    QCOMPARE(got["limit-switch-behaviour-external-reference"].perAxis[Axis::Y].toString(),
             QStringLiteral("free-backward"));
    QCOMPARE(got["limit-switch-behaviour-internal-normal"].perAxis[Axis::X].toString(),
             QStringLiteral("ignore"));
}

void TestNanotecParameterIo::write_undefinedMaskBits_refusedBeforeSending()
{
    m_sim->clearReceivedFrames();
    ParameterSet set;
    set["io-mask"].perAxis = {{Axis::X, 64}};
    const CommandResult r = run([&](RequestId id) { m_ctl->writeParameters(id, set, true); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    ParameterSet range;
    range["phase-current"].perAxis = {{Axis::X, 151}};
    QCOMPARE(run([&](RequestId id) { m_ctl->writeParameters(id, range, true); }).error,
             ErrorKind::InvalidValue);
    for (const QByteArray& f : m_sim->receivedFrames())
        QVERIFY2(!f.startsWith("#1L") && !f.startsWith("#1i"), f.constData());
}

void TestNanotecParameterIo::write_motorAddress_followsTheDrive()
{
    ParameterSet clash;
    clash["motor-address"].perAxis = {{Axis::Z, 2}};
    QCOMPARE(run([&](RequestId id) { m_ctl->writeParameters(id, clash, true); }).error,
             ErrorKind::InvalidValue);
    QVERIFY(m_sim->addDrive(9)); // on the bus, but not in the axis map
    ParameterSet taken;
    taken["motor-address"].perAxis = {{Axis::Z, 9}};
    const CommandResult refused =
        run([&](RequestId id) { m_ctl->writeParameters(id, taken, true); });
    QCOMPARE(refused.error, ErrorKind::Refused);
    QCOMPARE(countFrames("#3m9\r"), 0);
    ParameterSet set;
    set["motor-address"].perAxis = {{Axis::Z, 7}};
    const CommandResult r = run([&](RequestId id) { m_ctl->writeParameters(id, set, true); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(m_ctl->addressOf(Axis::Z), 7);
    QVERIFY(m_sim->drive(7));
    QVERIFY(!m_sim->drive(3));
    QVERIFY(run([this](RequestId id) { m_ctl->refreshStatus(id); }).ok());
    QCOMPARE(m_ctl->status().drives[2].address, 7);
    QVERIFY(m_ctl->status().drives[2].responding);
}

void TestNanotecParameterIo::read_valuesPerAxis_andLastError()
{
    m_sim->drive(2)->pushError(error::Temperature);
    const CommandResult r = run([&](RequestId id) {
        m_ctl->readParameters(id, {"phase-current", "cl-motor-pole-pairs", "last-error",
                                   "direction-reversal", "ramp-mode"});
    });
    QVERIFY2(r.ok(), qPrintable(r.message));
    const ParameterSet got = r.value.value<ParameterSet>();
    QCOMPARE(got["phase-current"].perAxis[Axis::Z].toLongLong(), qint64(50));
    QCOMPARE(got["cl-motor-pole-pairs"].perAxis[Axis::X].toString(), QStringLiteral("50"));
    QCOMPARE(got["last-error"].perAxis[Axis::X].toString(), QStringLiteral("none"));
    QCOMPARE(got["last-error"].perAxis[Axis::Y].toString(), QStringLiteral("over-temperature"));
    QCOMPARE(got["direction-reversal"].perAxis[Axis::Y].toBool(), false);
    QCOMPARE(got["ramp-mode"].perAxis[Axis::Y].toString(), QStringLiteral("trapezoid"));
    // Everything readable in one go (the setup pages and export do this).
    const CommandResult all = run([&](RequestId id) { m_ctl->readParameters(id, {}); }, 20000);
    QVERIFY2(all.ok(), qPrintable(all.message));
    QCOMPARE(all.value.value<ParameterSet>().size(), parameterTable().size());
}

void TestNanotecParameterIo::records_writeSaveReadBack()
{
    const QVariantMap values{
        {"travel-distance", -1234}, {"max-frequency", 2000}, {"direction", "right"}};
    CommandResult r = run([&](RequestId id) {
        m_ctl->modelOperation(id, "write-record",
                              {{"axis", "Y"}, {"record", 5}, {"values", values}});
    });
    QVERIFY2(r.ok(), qPrintable(r.message));
    r = run([&](RequestId id) {
        m_ctl->modelOperation(id, "read-record", {{"axis", "Y"}, {"record", 5}});
    });
    QVERIFY(r.ok());
    const QVariantMap got = r.value.toMap()["values"].toMap();
    QCOMPARE(got["travel-distance"].toLongLong(), qint64(-1234));
    QCOMPARE(got["max-frequency"].toLongLong(), qint64(2000));
    QCOMPARE(got["direction"].toString(), QStringLiteral("right"));
    QCOMPARE(got["ramp"].toLongLong(), qint64(2364)); // untouched field kept
    r = run([&](RequestId id) { m_ctl->modelOperation(id, "read-all-records", {{"axis", "Y"}}); });
    QVERIFY(r.ok());
    QCOMPARE(r.value.toList().size(), kRecordCount);
    r = run([&](RequestId id) {
        m_ctl->modelOperation(id, "write-record",
                              {{"axis", "Y"}, {"record", 5}, {"values", QVariantMap{{"ramp", 0}}}});
    });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
}

void TestNanotecParameterIo::errorMemory_decoded()
{
    m_sim->drive(3)->pushError(error::Temperature);
    m_sim->drive(3)->pushError(error::Position);
    const CommandResult r = run([&](RequestId id) {
        m_ctl->modelOperation(id, "read-error-memory", {{"axis", "Z"}});
    });
    QVERIFY2(r.ok(), qPrintable(r.message));
    const QVariantMap m = r.value.toMap();
    QCOMPARE(m["last"].toInt(), 2);
    const QVariantList entries = m["entries"].toList();
    QCOMPARE(entries.size(), kErrorSlots);
    QCOMPARE(entries[0].toMap()["name"].toString(), QStringLiteral("ERROR_TEMP"));
    QCOMPARE(entries[1].toMap()["code"].toInt(), error::Position);
}

STEPDECK_TEST_GUILESS_MAIN(TestNanotecParameterIo)
#include "tst_nanotecparameterio.moc"
