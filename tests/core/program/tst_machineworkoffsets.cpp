// The work offsets of a machine (issue 19): zero only at a known position, work <-> machine
// coordinates in the axis' unit, remembered per machine file by its absolute path.
#include "TestMain.h"
#include "machine/Machine.h"
#include "program/MachineWorkOffsets.h"
#include <QDir>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace stepdeck;
using namespace stepdeck::program;

class TestMachineWorkOffsets : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init() { QSettings().clear(); }

    void zero_knownPosition_workIsMachineMinusOffset_data();
    void zero_knownPosition_workIsMachineMinusOffset();
    void zero_unknownOrMoving_refusedWithReasonNothingChanged_data();
    void zero_unknownOrMoving_refusedWithReasonNothingChanged();
    void load_sameFileByAnotherPath_offsetsBack();
    void load_otherFile_noOffsets();
    void clear_everyAxisBackToMachineCoordinates_remembered();
    void load_noFile_keptInMemoryOnly();
    void systems_zeroSetsTheActiveOne_allRemembered();
    void setSystem_programsG10_zerosLeftOutOthersKept();
    void load_fileOfBeforeTheSystems_itsOriginsAreG54();

private:
    static machine::MachineAxisStatus status(double position, machine::PositionKnowledge known,
                                             bool moving = false);
    QTemporaryDir m_dir;
};

void TestMachineWorkOffsets::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    QCoreApplication::setApplicationName(QStringLiteral("StepDeckUnitTest-workoffsets"));
    QVERIFY(m_dir.isValid());
}

machine::MachineAxisStatus
TestMachineWorkOffsets::status(double position, machine::PositionKnowledge known, bool moving)
{
    machine::MachineAxisStatus s;
    s.position = position;
    s.known = known;
    s.moving = moving;
    return s;
}

void TestMachineWorkOffsets::zero_knownPosition_workIsMachineMinusOffset_data()
{
    QTest::addColumn<int>("known");
    QTest::addColumn<double>("zeroAt");
    QTest::addColumn<double>("machinePosition");
    QTest::addColumn<double>("work");
    QTest::addColumn<double>("workTarget");
    QTest::addColumn<double>("machineTarget");
    QTest::newRow("referenced") << int(machine::PositionKnowledge::Referenced) << 12.5 << 13.75
                                << 1.25 << 1.0 << 13.5;
    QTest::newRow("estimated") << int(machine::PositionKnowledge::Estimated) << -4.0 << 0.0 << 4.0
                               << -1.0 << -5.0;
}

void TestMachineWorkOffsets::zero_knownPosition_workIsMachineMinusOffset()
{
    QFETCH(int, known);
    QFETCH(double, zeroAt);
    QFETCH(double, machinePosition);
    QFETCH(double, work);
    QFETCH(double, workTarget);
    QFETCH(double, machineTarget);
    MachineWorkOffsets offsets;
    offsets.load(m_dir.filePath(QStringLiteral("a.machine.json")));
    QSignalSpy changed(&offsets, &MachineWorkOffsets::changed);
    QString refusal;
    QVERIFY(offsets.zero(QStringLiteral("X"), status(zeroAt, machine::PositionKnowledge(known)),
                         &refusal));
    QCOMPARE(changed.size(), 1);
    QVERIFY(offsets.hasOffset(QStringLiteral("X")));
    QVERIFY(!offsets.hasOffset(QStringLiteral("Y")));
    QCOMPARE(offsets.toWork(QStringLiteral("X"), zeroAt), 0.0);
    QCOMPARE(offsets.toWork(QStringLiteral("X"), machinePosition), work);
    QCOMPARE(offsets.toMachine(QStringLiteral("X"), workTarget), machineTarget);
    QCOMPARE(offsets.toWork(QStringLiteral("Y"), machinePosition), machinePosition);
}

void TestMachineWorkOffsets::zero_unknownOrMoving_refusedWithReasonNothingChanged_data()
{
    QTest::addColumn<int>("known");
    QTest::addColumn<bool>("moving");
    QTest::addColumn<QString>("reason");
    QTest::newRow("unknown") << int(machine::PositionKnowledge::Unknown) << false
                             << QStringLiteral("Zero X refused: its position is unknown");
    QTest::newRow("unknown, moving") << int(machine::PositionKnowledge::Unknown) << true
                                     << QStringLiteral("position is unknown");
    QTest::newRow("moving") << int(machine::PositionKnowledge::Referenced) << true
                            << QStringLiteral("Zero X refused: the axis is moving");
}

void TestMachineWorkOffsets::zero_unknownOrMoving_refusedWithReasonNothingChanged()
{
    QFETCH(int, known);
    QFETCH(bool, moving);
    QFETCH(QString, reason);
    const QString file = m_dir.filePath(QStringLiteral("a.machine.json"));
    MachineWorkOffsets offsets;
    offsets.load(file);
    QVERIFY(offsets.zero(QStringLiteral("X"), status(2.0, machine::PositionKnowledge::Referenced),
                         nullptr));
    QSignalSpy changed(&offsets, &MachineWorkOffsets::changed);
    QString refusal;
    QVERIFY(!offsets.zero(QStringLiteral("X"),
                          status(7.0, machine::PositionKnowledge(known), moving), &refusal));
    QVERIFY2(refusal.contains(reason), qPrintable(refusal));
    QVERIFY(!refusal.contains(QLatin1Char('\n')));
    QCOMPARE(changed.size(), 0);
    QCOMPARE(offsets.offset(QStringLiteral("X")), 2.0);
    MachineWorkOffsets reopened;
    reopened.load(file);
    QCOMPARE(reopened.offset(QStringLiteral("X")), 2.0);
}

void TestMachineWorkOffsets::load_sameFileByAnotherPath_offsetsBack()
{
    const QString file = m_dir.filePath(QStringLiteral("table.machine.json"));
    {
        MachineWorkOffsets offsets;
        offsets.load(file);
        QVERIFY(offsets.zero(QStringLiteral("X"),
                             status(12.5, machine::PositionKnowledge::Referenced), nullptr));
        QVERIFY(offsets.zero(QStringLiteral("A"),
                             status(-90.0, machine::PositionKnowledge::Estimated), nullptr));
    }
    // The same file named relative to the current directory: keyed by its absolute path.
    const QString cwd = QDir::currentPath();
    QVERIFY(QDir::setCurrent(m_dir.path()));
    MachineWorkOffsets reopened;
    reopened.load(QStringLiteral("table.machine.json"));
    QDir::setCurrent(cwd);
    QCOMPARE(reopened.machinePath(), QFileInfo(file).absoluteFilePath());
    QCOMPARE(reopened.offset(QStringLiteral("X")), 12.5);
    QCOMPARE(reopened.offset(QStringLiteral("A")), -90.0);
    QVERIFY(!reopened.hasOffset(QStringLiteral("Y")));
}

void TestMachineWorkOffsets::load_otherFile_noOffsets()
{
    MachineWorkOffsets offsets;
    offsets.load(m_dir.filePath(QStringLiteral("a.machine.json")));
    QVERIFY(offsets.zero(QStringLiteral("X"), status(3.0, machine::PositionKnowledge::Referenced),
                         nullptr));
    QSignalSpy changed(&offsets, &MachineWorkOffsets::changed);
    offsets.load(m_dir.filePath(QStringLiteral("b.machine.json")));
    QCOMPARE(changed.size(), 1); // the read-out shows the other machine's offsets
    QVERIFY(!offsets.anyOffset());
    offsets.load(m_dir.filePath(QStringLiteral("a.machine.json")));
    QCOMPARE(offsets.offset(QStringLiteral("X")), 3.0);
}

void TestMachineWorkOffsets::clear_everyAxisBackToMachineCoordinates_remembered()
{
    const QString file = m_dir.filePath(QStringLiteral("a.machine.json"));
    MachineWorkOffsets offsets;
    offsets.load(file);
    for (const char* axis : {"X", "Y"})
        QVERIFY(offsets.zero(QString::fromLatin1(axis),
                             status(5.0, machine::PositionKnowledge::Referenced), nullptr));
    offsets.clear();
    QVERIFY(!offsets.anyOffset());
    QCOMPARE(offsets.toMachine(QStringLiteral("X"), 1.0), 1.0);
    MachineWorkOffsets reopened;
    reopened.load(file);
    QVERIFY(!reopened.anyOffset());
}

void TestMachineWorkOffsets::load_noFile_keptInMemoryOnly()
{
    MachineWorkOffsets offsets;
    offsets.load(QString());
    QVERIFY(offsets.zero(QStringLiteral("X"), status(5.0, machine::PositionKnowledge::Referenced),
                         nullptr));
    QCOMPARE(offsets.offset(QStringLiteral("X")), 5.0);
    QVERIFY(QSettings().value(MachineWorkOffsets::settingsKey()).toMap().isEmpty());
}

// Issue 29: G54..G59. Zero, the read-out and clear act on the active system; the table and the
// active system come back with the machine file.
void TestMachineWorkOffsets::systems_zeroSetsTheActiveOne_allRemembered()
{
    const QString file = m_dir.filePath(QStringLiteral("s.machine.json"));
    {
        MachineWorkOffsets offsets;
        offsets.load(file);
        QVERIFY(offsets.zero(QStringLiteral("X"),
                             status(10.0, machine::PositionKnowledge::Referenced), nullptr));
        QSignalSpy changed(&offsets, &MachineWorkOffsets::changed);
        offsets.setActive(2); // G56
        QCOMPARE(changed.size(), 1);
        QVERIFY(!offsets.hasOffset(QStringLiteral("X")));
        QVERIFY(offsets.zero(QStringLiteral("X"),
                             status(30.0, machine::PositionKnowledge::Referenced), nullptr));
        QCOMPARE(offsets.toWork(QStringLiteral("X"), 31.0), 1.0);
        QCOMPARE(offsets.systems()[0].value(QStringLiteral("X")), 10.0);
    }
    MachineWorkOffsets reopened;
    reopened.load(file);
    QCOMPARE(reopened.active(), 2);
    QCOMPARE(reopened.offset(QStringLiteral("X")), 30.0);
    QCOMPARE(reopened.systems()[0].value(QStringLiteral("X")), 10.0);
    reopened.clear(); // G56 only
    QCOMPARE(reopened.systems()[0].value(QStringLiteral("X")), 10.0);
    QVERIFY(!reopened.anyOffset());
    reopened.setActive(0);
    QCOMPARE(reopened.offset(QStringLiteral("X")), 10.0);
}

void TestMachineWorkOffsets::setSystem_programsG10_zerosLeftOutOthersKept()
{
    MachineWorkOffsets offsets;
    offsets.load(m_dir.filePath(QStringLiteral("g10.machine.json")));
    QVERIFY(offsets.zero(QStringLiteral("Y"), status(4.0, machine::PositionKnowledge::Referenced),
                         nullptr));
    offsets.setSystem(1, {{QStringLiteral("X"), 6.0}, {QStringLiteral("Y"), 0.0}});
    QCOMPARE(offsets.systems()[1], (QMap<QString, double>{{QStringLiteral("X"), 6.0}}));
    QCOMPARE(offsets.offset(QStringLiteral("Y")), 4.0); // G54 still active and kept
    offsets.setSystem(7, {{QStringLiteral("X"), 1.0}}); // no such system: nothing
    MachineWorkOffsets reopened;
    reopened.load(m_dir.filePath(QStringLiteral("g10.machine.json")));
    QCOMPARE(reopened.systems()[1].value(QStringLiteral("X")), 6.0);
}

// A file's origins stored before the systems came (only "machine/workOffsets") are G54's.
void TestMachineWorkOffsets::load_fileOfBeforeTheSystems_itsOriginsAreG54()
{
    const QString file =
        QFileInfo(m_dir.filePath(QStringLiteral("old.machine.json"))).absoluteFilePath();
    QVariantMap axes{{QStringLiteral("Z"), -3.5}};
    QSettings().setValue(MachineWorkOffsets::settingsKey(), QVariantMap{{file, axes}});
    MachineWorkOffsets offsets;
    offsets.load(file);
    QCOMPARE(offsets.active(), 0);
    QCOMPARE(offsets.offset(QStringLiteral("Z")), -3.5);
}

STEPDECK_TEST_GUILESS_MAIN(TestMachineWorkOffsets)
#include "tst_machineworkoffsets.moc"
