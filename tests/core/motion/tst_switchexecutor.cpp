// The switch executor (issue 49 items 3 and 5): which controller switches the spindle, the
// coolant and output n, what it refuses and why -- and that the check names every refusal the
// run can meet, since both ask this one executor about the command the lowering made of a block.
#include "../program/ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "motion/executors/SwitchExecutor.h"
#include "program/ProgramLowering.h"
#include "program/ProgramReader.h"

using namespace stepdeck;
using namespace stepdeck::motion;
using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

class TestSwitchExecutor : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void spindleSpeed_outsideTheSchemaRange_refused_data();
    void spindleSpeed_outsideTheSchemaRange_refused();
    void spindleValue_maxRpm_mappedOntoTheFullScale_data();
    void spindleValue_maxRpm_mappedOntoTheFullScale();
    void spindleReverse_noModelCanReverse_refusedNamingTheController();
    void spindleRpm_aboveMaxRpm_runsAtMaxRpm_data();
    void spindleRpm_aboveMaxRpm_runsAtMaxRpm();
    void accepts_eachCommand_refusalAsTheMachineWouldGiveIt_data();
    void accepts_eachCommand_refusalAsTheMachineWouldGiveIt();
    void push_refusedCommand_nothingSent();
    void checkAndRun_everySwitchRefusal_namedByTheCheckFirst_data();
    void checkAndRun_everySwitchRefusal_namedByTheCheckFirst();

private:
    // "elab" (table: E-LAB with spindle and coolant, tilt: laser axis), "io" (E-LAB + two EMIS
    // with 7 outputs each), "nanotec" (no spindle, no coolant, no outputs); "Scale": with a
    // spindle scale of 24000 rpm; "Refuse": S above it refused, not limited.
    static MachineFacts facts(const QString& name);
};

MachineFacts TestSwitchExecutor::facts(const QString& name)
{
    QString base = name;
    const bool refuse = base.endsWith(QLatin1String("Refuse"));
    if (refuse)
        base.chop(6);
    const bool scale = base.endsWith(QLatin1String("Scale"));
    if (scale)
        base.chop(5);
    MachineFacts f = machineFacts(base == QLatin1String("elab") ? QString() : base);
    if (scale)
        f.description.spindle.maxRpm = 24000;
    if (refuse)
        f.description.limits = machine::LimitPolicy::Refuse;
    return f;
}

void TestSwitchExecutor::spindleSpeed_outsideTheSchemaRange_refused_data()
{
    QTest::addColumn<double>("maxRpm"); // 0: the machine has no spindle scale
    QTest::addColumn<double>("rpm");
    QTest::addColumn<QString>("refusal");
    QTest::newRow("0") << 0.0 << 0.0 << "";
    QTest::newRow("1000") << 0.0 << 1000.0 << "";
    QTest::newRow("1000.4 rounds to 1000") << 0.0 << 1000.4 << "";
    QTest::newRow("1001") << 0.0 << 1001.0
                          << "Spindle speed: value '1001' is out of range (allowed: 0..1000 rpm)";
    QTest::newRow("12000") << 0.0 << 12000.0
                           << "Spindle speed: value '12000' is out of range (allowed: 0..1000 rpm)";
    // Issue 29: with maxRpm, S is in rpm up to maxRpm, whatever the controller's own range.
    QTest::newRow("maxRpm 24000: S12000") << 24000.0 << 12000.0 << "";
    QTest::newRow("maxRpm 24000: S24000") << 24000.0 << 24000.0 << "";
    QTest::newRow("maxRpm 24000: S0") << 24000.0 << 0.0 << "";
    QTest::newRow("maxRpm 24000: S24000.5")
        << 24000.0 << 24000.5
        << "S24000.5 is above the spindle's maxRpm 24000 (the machine file's spindle scale)";
    QTest::newRow("maxRpm 24000: S30000")
        << 24000.0 << 30000.0
        << "S30000 is above the spindle's maxRpm 24000 (the machine file's spindle scale)";
    QTest::newRow("maxRpm 500: S800") << 500.0 << 800.0
                                      << "S800 is above the spindle's maxRpm 500 (the machine "
                                         "file's spindle scale)";
}

void TestSwitchExecutor::spindleSpeed_outsideTheSchemaRange_refused()
{
    QFETCH(double, maxRpm);
    QFETCH(double, rpm);
    QFETCH(QString, refusal);
    const ModelInfo* info = findModel(QStringLiteral("elab"));
    const std::optional<double> scale = maxRpm > 0 ? std::optional<double>(maxRpm) : std::nullopt;
    QCOMPARE(SwitchExecutor::spindleSpeed(info->capabilities, info->schema, scale, rpm), refusal);
}

// S / maxRpm x the E-LAB's full scale 1000 (SetSpindleRPM "einen Wert zwischen 0 und 1000"),
// as GRBL's $30 maps S onto its PWM range; an S above 0 is never sent as 0 (relay off).
void TestSwitchExecutor::spindleValue_maxRpm_mappedOntoTheFullScale_data()
{
    QTest::addColumn<double>("maxRpm"); // 0: none
    QTest::addColumn<double>("rpm");
    QTest::addColumn<int>("sent");
    QTest::newRow("no scale: S as written") << 0.0 << 800.0 << 800;
    QTest::newRow("no scale: rounded") << 0.0 << 999.6 << 1000;
    QTest::newRow("no scale: S12000 sent as is") << 0.0 << 12000.0 << 12000;
    QTest::newRow("24000: S0 off") << 24000.0 << 0.0 << 0;
    QTest::newRow("24000: S12000 half scale") << 24000.0 << 12000.0 << 500;
    QTest::newRow("24000: S24000 full scale") << 24000.0 << 24000.0 << 1000;
    QTest::newRow("24000: S6000 a quarter") << 24000.0 << 6000.0 << 250;
    QTest::newRow("24000: S18012 rounded") << 24000.0 << 18012.0 << 751;
    QTest::newRow("24000: S5 at least 1") << 24000.0 << 5.0 << 1;
    QTest::newRow("30000: S10000 a third") << 30000.0 << 10000.0 << 333;
    QTest::newRow("500: S250 scaled up") << 500.0 << 250.0 << 500;
}

void TestSwitchExecutor::spindleValue_maxRpm_mappedOntoTheFullScale()
{
    QFETCH(double, maxRpm);
    QFETCH(double, rpm);
    QFETCH(int, sent);
    const ModelInfo* info = findModel(QStringLiteral("elab"));
    const std::optional<double> scale = maxRpm > 0 ? std::optional<double>(maxRpm) : std::nullopt;
    QCOMPARE(SwitchExecutor::spindleValue(info->capabilities, info->schema, scale, rpm), sent);
}

// M4: no model's capabilities say its spindle can reverse (the E-LAB switches a relay only); on
// a laser (issue 50 item 5) M4 runs as M3, so nothing refuses it.
void TestSwitchExecutor::spindleReverse_noModelCanReverse_refusedNamingTheController()
{
    int spindles = 0;
    for (const ModelInfo& info : models()) {
        QVERIFY2(!SwitchExecutor::spindleReverse(info.capabilities, info.id, {}).isEmpty(),
                 qPrintable(info.id));
        spindles += info.capabilities.spindle ? 1 : 0;
    }
    QVERIFY(spindles > 0);
    const ModelInfo* elab = findModel(QStringLiteral("elab"));
    QCOMPARE(SwitchExecutor::spindleReverse(elab->capabilities, QStringLiteral("table"), {}),
             QStringLiteral("controller \"table\" cannot reverse its spindle: use M3"));
    machine::MachineSpindle laser;
    laser.laser = true;
    QCOMPARE(SwitchExecutor::spindleReverse(elab->capabilities, QStringLiteral("table"), laser),
             QString());
    Capabilities reversible = elab->capabilities;
    reversible.spindleReverse = true;
    QCOMPARE(SwitchExecutor::spindleReverse(reversible, QStringLiteral("table"), {}), QString());
}

// GRBL's $30: S above maxRpm runs at maxRpm; the spindle's controller gets its full scale and
// takes it, unless the machine file refuses (then the error of issue 29).
void TestSwitchExecutor::spindleRpm_aboveMaxRpm_runsAtMaxRpm_data()
{
    QTest::addColumn<double>("maxRpm"); // 0: none
    QTest::addColumn<double>("rpm");
    QTest::addColumn<double>("runs");
    QTest::addColumn<int>("sent");
    QTest::newRow("below") << 24000.0 << 12000.0 << 12000.0 << 500;
    QTest::newRow("above: maxRpm, full scale") << 24000.0 << 30000.0 << 24000.0 << 1000;
    QTest::newRow("no scale: as written") << 0.0 << 800.0 << 800.0 << 800;
}

void TestSwitchExecutor::spindleRpm_aboveMaxRpm_runsAtMaxRpm()
{
    QFETCH(double, maxRpm);
    QFETCH(double, rpm);
    QFETCH(double, runs);
    QFETCH(int, sent);
    const ModelInfo* info = findModel(QStringLiteral("elab"));
    const std::optional<double> scale = maxRpm > 0 ? std::optional<double>(maxRpm) : std::nullopt;
    QCOMPARE(SwitchExecutor::spindleRpm(rpm, scale), runs);
    QCOMPARE(SwitchExecutor::spindleValue(info->capabilities, info->schema, scale, rpm), sent);
    QCOMPARE(SwitchExecutor::spindleSpeed(info->capabilities, info->schema, scale, rpm,
                                          machine::LimitPolicy::Clamp),
             QString());
    QCOMPARE(SwitchExecutor::spindleSpeed(info->capabilities, info->schema, scale, rpm,
                                          machine::LimitPolicy::Refuse)
                 .isEmpty(),
             runs == rpm);
}

void TestSwitchExecutor::accepts_eachCommand_refusalAsTheMachineWouldGiveIt_data()
{
    QTest::addColumn<QString>("machine");
    QTest::addColumn<MotionCommand>("command");
    QTest::addColumn<QString>("word");    // the refusal's column word
    QTest::addColumn<QString>("refusal"); // empty: accepted
    QTest::newRow("M3 on the E-LAB") << "elab" << MotionCommand(SpindleOn{1, 500, false}) << ""
                                     << "";
    QTest::newRow("M4 on the E-LAB")
        << "elab" << MotionCommand(SpindleOn{1, 500, true}) << ""
        << "M4: controller \"table\" cannot reverse its spindle: use M3";
    QTest::newRow("M3 S above the scale, limited")
        << "elabScale" << MotionCommand(SpindleOn{1, 30000, false}) << ""
        << "";
    QTest::newRow("M3 S above the scale, refused")
        << "elabScaleRefuse" << MotionCommand(SpindleOn{1, 30000, false}) << "S"
        << "controller \"table\": S30000 is above the spindle's maxRpm 24000 (the machine "
           "file's spindle scale)";
    QTest::newRow("S without a spindle") << "nanotec" << MotionCommand(SpindleSpeed{1, 500}) << ""
                                         << "S: no controller of this machine has a spindle";
    QTest::newRow("M5 without a spindle") << "nanotec" << MotionCommand(SpindleOff{1}) << ""
                                          << "M5: no controller of this machine has a spindle";
    QTest::newRow("M8 on the E-LAB")
        << "elab" << MotionCommand(Coolant{1, Coolant::Kind::Flood}) << ""
        << "";
    QTest::newRow("M7 without coolant")
        << "nanotec" << MotionCommand(Coolant{1, Coolant::Kind::Mist}) << ""
        << "M7: no controller of this machine has coolant";
    QTest::newRow("M64 P14: the second EMIS' 7th")
        << "io" << MotionCommand(Output{1, 14, true}) << ""
        << "";
    QTest::newRow("M65 P15: one too many") << "io" << MotionCommand(Output{1, 15, false}) << "P"
                                           << "M65 P15: the machine's outputs are 1..14";
    QTest::newRow("M64 P1 without outputs") << "nanotec" << MotionCommand(Output{1, 1, true}) << "P"
                                            << "M64 P1: the machine has no digital outputs";
}

void TestSwitchExecutor::accepts_eachCommand_refusalAsTheMachineWouldGiveIt()
{
    QFETCH(QString, machine);
    QFETCH(MotionCommand, command);
    QFETCH(QString, word);
    QFETCH(QString, refusal);
    const MachineFacts f = facts(machine);
    const SwitchExecutor switches(f.description, f.capabilities, f.schemas);
    const std::optional<SwitchExecutor::Refusal> got = switches.accepts(command);
    QCOMPARE(got ? got->text : QString(), refusal);
    if (got)
        QCOMPARE(got->word, word);
    QCOMPARE(switches.estimate(command), 0.0);
}

// A command the machine refuses never reaches a controller (here: none exists to reach).
void TestSwitchExecutor::push_refusedCommand_nothingSent()
{
    const MachineFacts f = facts(QStringLiteral("nanotec"));
    const SwitchExecutor switches(f.description, f.capabilities, f.schemas);
    machine::Machine machine;
    QString controller = QStringLiteral("unchanged");
    QCOMPARE(switches.push(SpindleOn{1, 500, false}, machine, &controller), RequestId(0));
    QCOMPARE(controller, QStringLiteral("unchanged"));
}

void TestSwitchExecutor::checkAndRun_everySwitchRefusal_namedByTheCheckFirst_data()
{
    QTest::addColumn<QString>("machine");
    for (const char* m : {"elab", "elabScale", "elabScaleRefuse", "io", "nanotec"})
        QTest::newRow(m) << QString::fromLatin1(m);
}

// Every switch word, as blocks of their own and beside a motion; for each block the command the
// run would hand the executor (ProgramLowering::switchCommand, or speedChange for an S beside a
// motion): where the executor refuses it, the check's error at that line says the same.
void TestSwitchExecutor::checkAndRun_everySwitchRefusal_namedByTheCheckFirst()
{
    QFETCH(QString, machine);
    const MachineFacts f = facts(machine);
    const QString text = QStringLiteral("M3 S500\nM4 S500\nS30000\nM3 S30000\nM5\nM7\nM8\nM9\n"
                                        "M64 P1\nM65 P14\nM64 P15\nG91 G0 X1 S20000\nM2\n");
    const Program program = parsed(text, f);
    const ProgramCheckResult checked = ProgramCheck::check(program, f, 1);
    const SwitchExecutor switches(f.description, f.capabilities, f.schemas);
    ProgramReader reader(program);
    int refusals = 0;
    for (int i = 0; const ProgramBlock* block = reader.at(i); ++i) {
        std::optional<MotionCommand> command = ProgramLowering::switchCommand(*block);
        if (!command)
            command = ProgramLowering::speedChange(*block);
        if (!command)
            continue;
        const std::optional<SwitchExecutor::Refusal> refusal = switches.accepts(*command);
        const bool named =
            std::any_of(checked.errors.cbegin(), checked.errors.cend(), [&](const ProgramError& e) {
                return refusal && e.line == block->line && e.message == refusal->text;
            });
        QVERIFY2(!refusal || named,
                 qPrintable(QStringLiteral("line %1: the run's refusal \"%2\" was not named")
                                .arg(block->line)
                                .arg(refusal ? refusal->text : QString())));
        refusals += refusal ? 1 : 0;
    }
    // Every machine refuses some of these (M4 on the E-LAB, M65 P14 without EMIS, everything on
    // the Nanotec): the walk compared refusals, not only accepted commands.
    QVERIFY(refusals > 0);
}

STEPDECK_TEST_GUILESS_MAIN(TestSwitchExecutor)
#include "tst_switchexecutor.moc"
