// Issue 28, item 1: whatever the run can refuse from what is known before it starts, the check
// refuses first. Programs generated from a fixed seed (relative moves, G0/G1 with feed rates on
// both sides of the E-LAB's start speed and of the Nanotec's rate range, bare G0/G1/F lines,
// spindle speeds in and out of range, dwells) are checked against a machine of an E-LAB table
// (X, Y in mm) and a Nanotec rotary axis (A in degrees), each simulator on a pseudo-terminal.
// Every program the check passes must run to its end: a rule refusal mid-run (after the machine
// moved) fails the test, naming the program. Both sides must occur (some programs refused by
// the check, some run), so the table exercises the rules rather than passing vacuously. Since
// issue 50 a feed above the machine's highest runs at it (FeedLimit, the same function for the
// check and the run): those programs run, noted, and are refused only by the check of a machine
// file with "limits": "refuse".
#include "MachineTestSupport.h"
#include "PtyDevice.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QtTest>
#include <algorithm>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::machine;
using namespace stepdeck::program;

namespace {

constexpr int kPrograms = 30;
constexpr int kBlocks = 6;

// A relative program from seed: the carriage stays within a few mm (and degrees) of where it
// starts, far from every simulated switch (docs/machines.md, "Simulated machines").
QByteArray generated(quint32 seed)
{
    QRandomGenerator rng(seed);
    // 40 steps/mm: the E-LAB's default start speed of 100 steps/s is 150 mm/min, so these rates
    // fall on both sides of its feed rule (feed below start speed).
    static const QList<int> feeds{60, 90, 120, 149, 150, 600, 5400};
    static const QList<int> spindle{0, 500, 1000, 1200, 12000};
    QMap<QString, double> at{{"X", 0}, {"Y", 0}, {"A", 0}};
    auto step = [&](const QString& name, double lo, double hi, double bound) {
        double d = lo + rng.generateDouble() * (hi - lo);
        if (rng.bounded(2))
            d = -d;
        if (qAbs(at[name] + d) > bound)
            d = -d;
        at[name] += d;
        return QStringLiteral("%1%2").arg(name).arg(d, 0, 'f', 3);
    };
    auto feed = [&] { return QStringLiteral("F%1").arg(feeds.at(int(rng.bounded(feeds.size())))); };
    QStringList lines{QStringLiteral("G91")};
    for (int i = 0; i < kBlocks; ++i) {
        switch (rng.bounded(8)) {
        case 0:
            lines << QStringLiteral("G0 ") + step("X", 0.25, 1.0, 4) + QLatin1Char(' ') +
                         step("Y", 0.25, 1.0, 4);
            break;
        case 1:
            lines << QStringLiteral("G1 ") + step("X", 0.25, 1.0, 4) + QLatin1Char(' ') + feed();
            break;
        case 2:
            lines << QStringLiteral("G1 ") + feed(); // modal only (LinuxCNC)
            break;
        case 3:
            lines << QStringLiteral("S%1 M3").arg(spindle.at(int(rng.bounded(spindle.size()))));
            break;
        case 4:
            lines << QStringLiteral("M5");
            break;
        case 5:
            lines << QStringLiteral("G4 P0.05");
            break;
        case 6:
            lines << (rng.bounded(2) ? QStringLiteral("G0") : QStringLiteral("G1"));
            break;
        default:
            lines << QStringLiteral("G1 ") + step("A", 1, 5, 15) + QLatin1Char(' ') +
                         step("Y", 0.25, 1.0, 4) + QLatin1Char(' ') + feed();
            break;
        }
    }
    lines << QStringLiteral("M5") << QStringLiteral("M2");
    return lines.join(QLatin1Char('\n')).toUtf8() + '\n';
}

} // namespace

class TestProgramCheckedRuns : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void checkedClean_runsToItsEnd();

private:
    std::unique_ptr<test::PtyDevice> m_elab;
    std::unique_ptr<test::PtyDevice> m_nanotec;
    std::unique_ptr<Machine> m_machine;
};

void TestProgramCheckedRuns::initTestCase()
{
    m_elab = std::make_unique<test::PtyDevice>("elab");
    m_nanotec = std::make_unique<test::PtyDevice>("nanotec");
    MachineDescription d;
    d.name = QStringLiteral("Table with rotary axis");
    d.controllers = {{"table", "elab", m_elab->path(), {}, {}, {}, {}, {}},
                     {"rotary", "nanotec", m_nanotec->path(), {{Axis::X, 1}}, {}, {}, {}, {}}};
    d.axes = {test::machineAxis("X", "table", Axis::X, AxisUnit::Millimetre, 40),
              test::machineAxis("Y", "table", Axis::Y, AxisUnit::Millimetre, 40),
              test::machineAxis("A", "rotary", Axis::X, AxisUnit::Degree, 100)};
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(d, &error), qPrintable(error));
    m_machine->open();
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    // The board moves only after its ramp setup was written; what was written is what the
    // check's rules judge by (MachineStatus::knownParameters).
    QVERIFY(test::writeSetupBeforeMotion(m_machine->session("table")));
}

void TestProgramCheckedRuns::cleanupTestCase()
{
    m_machine.reset();
    m_elab.reset();
    m_nanotec.reset();
}

void TestProgramCheckedRuns::checkedClean_runsToItsEnd()
{
    int refusedByCheck = 0;
    int refusedWhenRefusing = 0; // by the check of "limits": "refuse" (issue 50)
    int clamped = 0;             // ran with a feed limited to the machine's highest, noted
    int ran = 0;
    for (quint32 seed = 1; seed <= kPrograms; ++seed) {
        const QByteArray text = generated(seed);
        QList<ProgramError> errors;
        const std::optional<Program> program = ProgramParser::parse(
            text, {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("A")}, &errors);
        QVERIFY2(program, qPrintable(QString::fromUtf8(text)));
        // Issue 50: this machine runs a feed above its highest at that highest (the default);
        // the same program checked as "limits": "refuse" is refused as before issue 50.
        MachineFacts facts = factsOf(*m_machine);
        const ProgramCheckResult checked = ProgramCheck::check(*program, facts);
        facts.description.limits = LimitPolicy::Refuse;
        refusedWhenRefusing += ProgramCheck::check(*program, facts).ok() ? 0 : 1;
        if (!checked.ok()) {
            ++refusedByCheck;
            continue;
        }
        clamped += checked.notes.isEmpty() ? 0 : 1;
        ProgramRunner runner(m_machine.get());
        QVERIFY2(runner.start(*program, 1, &errors),
                 qPrintable(QStringLiteral("seed %1: the check passed, start refused: %2\n%3")
                                .arg(seed)
                                .arg(errors.isEmpty() ? QString() : errors.first().text(),
                                     QString::fromUtf8(text))));
        QTRY_VERIFY_WITH_TIMEOUT(isEnded(runner.state()), 60000);
        QVERIFY2(runner.state() == RunState::Finished,
                 qPrintable(QStringLiteral("seed %1: checked clean, then ended mid-run: %2\n%3")
                                .arg(seed)
                                .arg(runner.endMessage(), QString::fromUtf8(text))));
        ++ran;
    }
    qInfo("%d programs: %d refused by the check (%d with \"limits\": \"refuse\"), %d ran to their "
          "end, %d of them with a feed limited",
          kPrograms, refusedByCheck, refusedWhenRefusing, ran, clamped);
    QVERIFY(refusedWhenRefusing >= 3);
    QVERIFY(clamped >= 3);
    QVERIFY(ran >= 3);
}

STEPDECK_TEST_MAIN(TestProgramCheckedRuns)
#include "tst_programcheckedruns.moc"
