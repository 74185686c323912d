// EmisController against the in-process SMC-IC4 simulator: connect, polling, the refused
// stop, working values, system parameters, outputs, input programs and the console. Every
// test asserts what the simulated board saw.
#include "EmisControllerRig.h"
#include "TestMain.h"
#include "TestSupport.h"

using namespace stepdeck;
using namespace stepdeck::emis;
using stepdeck::test::EmisRig;

class TestEmisController : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void connect_readsVersionStoredValuesAndInputs();
    void stopAndPanic_refusedUnsupported_nothingSent();
    void poll_inputs_referenceSwitchFollowsSwitchType();
    void silentBoard_linkLostByMissedPolls();
    void write_workingValues_commandsAsInManual();
    void write_currentAlone_needsPartner();
    void write_outOfRange_refusedNothingSent();
    void write_bellFromBoard_namesCommand();
    void read_returnsValuesWrittenInSession();
    void store_systemForms_readyParsed_readBack();
    void store_partialEntry_otherMotorsStayKnown();
    void store_notStorable_unsupportedNothingSent();
    void store_missingAcks_timeoutNamesCount();
    void store_entryOfOneMotor_fourAcksRead_nextReplyIsItsOwn();
    void store_boardAcksPerMotor_quietLineEndsWrite();
    void clear_sendsPesys();
    void output_switchedAndTracked();
    void program_sequenceAsInManual_noPollInBetween();
    void program_invalidCommand_refusedNothingSent();
    void program_referenceInput_needsForce();
    void program_lineRefusedByBoard_partialProgramErased();
    void program_erase();
    void console_commandsRoutedThroughBookkeeping();
    void console_mixedVector_eachTargetAsTyped();

private:
    EmisRig m_rig;
};

void TestEmisController::init()
{
    QVERIFY(m_rig.setUp());
}

void TestEmisController::cleanup()
{
    m_rig.tearDown();
}

void TestEmisController::connect_readsVersionStoredValuesAndInputs()
{
    const MachineStatus& s = m_rig.ctl->status();
    QCOMPARE(m_rig.ctl->linkState(), LinkState::Connected);
    QCOMPARE(s.deviceFirmware, QStringLiteral("SMC-IC4 v1.07"));
    QVERIFY(s.inputs.has_value());
    QCOMPARE(s.inputs->size(), 8);
    QCOMPARE(s.outputs.size(), 7);
    QVERIFY(!s.outputs.first().has_value()); // unknown until switched
    QCOMPARE(m_rig.sim->receivedCommands().mid(0, 3), (QList<QByteArray>{"@V", "*PRSYS", "@IG"}));
    const Capabilities caps = m_rig.ctl->capabilities();
    QVERIFY(!caps.stopCommand);
    QCOMPARE(caps.axes.size(), 4);
    QCOMPARE(s.toJson("emis")["device"].toObject()["firmware"].toString(),
             QStringLiteral("SMC-IC4 v1.07"));
    QCOMPARE(s.toJson("emis")["inputs"].toArray().size(), 8);
}

void TestEmisController::stopAndPanic_refusedUnsupported_nothingSent()
{
    const int before = int(m_rig.commands().size());
    const CommandResult stop = m_rig.run([this](RequestId id) { m_rig.ctl->stop(id); });
    QCOMPARE(stop.error, ErrorKind::Unsupported);
    QCOMPARE(stop.message, Controller::noStopCommandText());
    const CommandResult panic = m_rig.run([this](RequestId id) { m_rig.ctl->panic(id); });
    QCOMPARE(panic.error, ErrorKind::Unsupported);
    QCOMPARE(m_rig.commands().size(), before);
}

void TestEmisController::poll_inputs_referenceSwitchFollowsSwitchType()
{
    m_rig.sim->setPhysicalPosition(Axis::Y, -3); // on its normally open switch: input 2 high
    m_rig.sim->setInput(6, true);
    QTRY_VERIFY(m_rig.axis(Axis::Y).referenceSwitch);
    QVERIFY(!m_rig.axis(Axis::X).referenceSwitch);
    QCOMPARE(m_rig.ctl->status().inputs->at(1), true);
    QCOMPARE(m_rig.ctl->status().inputs->at(5), true);
    QCOMPARE(m_rig.ctl->status().raw.value("inputs").toLongLong(), qint64(0x22));
    // Declared normally closed: a high level now means "not actuated".
    QVERIFY(m_rig.write({"reference-switch-type=NO,NC,NO,NO"}).ok());
    QCOMPARE(m_rig.commands().last(), QByteArray("##REFSW,xNO,yNC,zNO,uNO"));
    QTRY_VERIFY(!m_rig.axis(Axis::Y).referenceSwitch);
}

void TestEmisController::silentBoard_linkLostByMissedPolls()
{
    QSignalSpy lost(m_rig.ctl, &Controller::linkStateChanged);
    m_rig.sim->faults().silent = true;
    QTRY_COMPARE(m_rig.ctl->linkState(), LinkState::Lost);
    QVERIFY(m_rig.ctl->status().commFault);
    QVERIFY(!m_rig.ctl->status().motionUnconfirmed); // nothing was moving
    QVERIFY(m_rig.host->isOpen());                   // the port stays open (base safety contract)
}

void TestEmisController::write_workingValues_commandsAsInManual()
{
    const CommandResult r = m_rig.write({"start-speed=300", "work-speed=1000,1200,1000,1000",
                                         "ramp=150", "step-resolution=32", "interpolation=off",
                                         "reference-offset=5", "reference-speed=450"});
    QVERIFY2(r.ok(), qPrintable(r.message));
    const QList<QByteArray> expected{
        "D,x32",     "D,y32",     "D,z32",   "D,u32", "#R150", "#S300", "#E1,x1000", "#E1,y1200",
        "#E1,z1000", "#E1,u1000", "#E9,450", "#Ox,5", "#Oy,5", "#Oz,5", "#Ou,5",     "IP0"};
    QCOMPARE(m_rig.commands().mid(2), expected);
    const EmisSimulator::Working& w = m_rig.sim->working();
    QCOMPARE(w.startSpeed.value(Axis::U), 300);
    QCOMPARE(w.workSpeed.value(Axis::Y), 1200);
    QCOMPARE(w.ramp, 150);
    QCOMPARE(w.resolution.value(Axis::Z), 32);
    QCOMPARE(w.referenceSpeed, 450);
    QVERIFY(!w.interpolation);
}

void TestEmisController::write_currentAlone_needsPartner()
{
    const int before = int(m_rig.commands().size());
    CommandResult r = m_rig.write({"run-current=80"});
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY2(r.message.startsWith("run-current of axis X needs idle-current"),
             qPrintable(r.message));
    QCOMPARE(m_rig.commands().size(), before);
    QVERIFY(m_rig.write({"run-current=80", "idle-current=10,0,25,5"}).ok());
    QVERIFY(m_rig.commands().contains("c,z80,25"));
    QVERIFY(m_rig.write({"run-current=60"}).ok()); // the idle current is known now
    QCOMPARE(m_rig.commands().last(), QByteArray("c,u60,5"));
    QCOMPARE(m_rig.sim->working().idleCurrent.value(Axis::X), 10);
    QCOMPARE(m_rig.sim->working().runCurrent.value(Axis::X), 60);
}

void TestEmisController::write_outOfRange_refusedNothingSent()
{
    const int before = int(m_rig.commands().size());
    QCOMPARE(m_rig.write({"idle-current=26"}).error, ErrorKind::InvalidValue);
    QCOMPARE(m_rig.write({"step-resolution=3"}).error, ErrorKind::InvalidValue);
    QCOMPARE(m_rig.write({"start-speed=0"}).error, ErrorKind::InvalidValue);
    QCOMPARE(m_rig.write({"ramp=10001"}).error, ErrorKind::InvalidValue);
    QCOMPARE(m_rig.commands().size(), before);
}

void TestEmisController::write_bellFromBoard_namesCommand()
{
    m_rig.sim->bellOn("#R100");
    const CommandResult r = m_rig.write({"ramp=100"});
    QCOMPARE(r.error, ErrorKind::Nak);
    QVERIFY2(r.message.contains("#R100") && r.message.contains("<BEL>"), qPrintable(r.message));
}

void TestEmisController::read_returnsValuesWrittenInSession()
{
    CommandResult r = m_rig.run([this](RequestId id) { m_rig.ctl->readParameters(id, {"ramp"}); });
    QCOMPARE(r.error, ErrorKind::Unsupported);
    QVERIFY(m_rig.write({"ramp=120"}).ok());
    r = m_rig.run([this](RequestId id) { m_rig.ctl->readParameters(id, {"ramp"}); });
    QVERIFY(r.ok());
    QCOMPARE(r.value.value<ParameterSet>().value("ramp").global.toLongLong(), 120);
}

void TestEmisController::store_systemForms_readyParsed_readBack()
{
    const ParameterSchema schema = parameterSchema();
    ParameterSet set;
    QString name, error;
    ParameterValue v;
    for (const char* a :
         {"step-resolution=32,16,64,1", "ramp=100", "reference-speed=400",
          "reference-switch-type=NO,NO,NO,NC", "run-current=100", "idle-current=0,0,20,0"}) {
        QVERIFY(schema.parseAssignment(a, letterAxes(), &name, &v, &error));
        set.insert(name, v);
    }
    const CommandResult r =
        m_rig.operation("store-parameters", {{"parameters", QVariant::fromValue(set)}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    const QList<QByteArray> sent = m_rig.commandsStartingWith("##");
    QCOMPARE(sent,
             (QList<QByteArray>{"##D,x32,y16,z64,u1", "##c,x100,0,y100,0,z100,20,u100,0", "##R,100",
                                "##E9,x400,y400,z400,u400", "##REFSW,xNO,yNO,zNO,uNC"}));
    QCOMPARE(m_rig.sim->storedEntries().size(), 5);
    m_rig.sim->clearReceivedCommands();
    const CommandResult read = m_rig.operation("read-stored-parameters");
    QVERIFY(read.ok());
    QCOMPARE(m_rig.commands(), QList<QByteArray>{"*PRSYS"});
    const ParameterSet stored = read.value.toMap().value("parameters").value<ParameterSet>();
    QCOMPARE(stored.value("step-resolution").perAxis.value(Axis::Z).toString(), QString("64"));
    QCOMPARE(stored.value("idle-current").perAxis.value(Axis::Z).toLongLong(), 20);
    QCOMPARE(stored.value("reference-switch-type").perAxis.value(Axis::U).toString(),
             QString("NC"));
    QCOMPARE(stored.value("ramp").global.toLongLong(), 100);
    QCOMPARE(read.value.toMap().value("entries").toList().size(), 5);
}

void TestEmisController::store_partialEntry_otherMotorsStayKnown()
{
    // A later "##c" for X alone must not hide Y's stored currents from the host: a store of
    // Y's run current takes its idle current from the first, full entry.
    const auto store = [this](const ParameterSet& set) {
        return m_rig.operation("store-parameters", {{"parameters", QVariant::fromValue(set)}});
    };
    const auto perAxis = [](qint64 x, qint64 y, qint64 z, qint64 u) {
        return ParameterValue{{}, {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}, {Axis::U, u}}};
    };
    ParameterSet all{{"run-current", perAxis(100, 100, 100, 100)},
                     {"idle-current", perAxis(0, 5, 20, 0)}};
    const CommandResult first = store(all);
    QVERIFY2(first.ok(), qPrintable(first.message));
    ParameterSet xOnly{{"run-current", ParameterValue{{}, {{Axis::X, 50}}}},
                       {"idle-current", ParameterValue{{}, {{Axis::X, 10}}}}};
    QVERIFY(store(xOnly).ok());
    const CommandResult r = store({{"run-current", ParameterValue{{}, {{Axis::Y, 80}}}}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(m_rig.commandsStartingWith("##c"),
             (QList<QByteArray>{"##c,x100,0,y100,5,z100,20,u100,0", "##c,x50,10", "##c,y80,5"}));
    const QList<SystemEntry> stored = m_rig.sim->storedEntries();
    QCOMPARE(stored.size(), 1);
    QCOMPARE(stored.first().values.value(Axis::Y), 80);
    QCOMPARE(stored.first().idle.value(Axis::Y), 5);
    QCOMPARE(stored.first().values.value(Axis::X), 50);
}

void TestEmisController::store_notStorable_unsupportedNothingSent()
{
    ParameterSet set{{"interpolation", ParameterValue{true, {}}}};
    const int before = int(m_rig.commands().size());
    const CommandResult r =
        m_rig.operation("store-parameters", {{"parameters", QVariant::fromValue(set)}});
    QCOMPARE(r.error, ErrorKind::Unsupported);
    QVERIFY(r.message.contains("interpolation"));
    ParameterSet runOnly{{"run-current", ParameterValue{{}, {{Axis::X, 50}}}}};
    QCOMPARE(
        m_rig.operation("store-parameters", {{"parameters", QVariant::fromValue(runOnly)}}).error,
        ErrorKind::InvalidValue); // no idle current stored or given
    QCOMPARE(m_rig.commands().size(), before);
}

void TestEmisController::store_missingAcks_timeoutNamesCount()
{
    m_rig.sim->withholdStoredAcks(1); // the last <ACK> of the reply never comes
    ParameterSet set{{"ramp", ParameterValue{200, {}}}};
    const CommandResult r =
        m_rig.operation("store-parameters", {{"parameters", QVariant::fromValue(set)}});
    QCOMPARE(r.error, ErrorKind::Timeout);
    QVERIFY2(r.message.contains("3 of 4"), qPrintable(r.message));
}

void TestEmisController::store_entryOfOneMotor_fourAcksRead_nextReplyIsItsOwn()
{
    // "##REFSW,xNC" names one motor; the board sends four <ACK>s after "Ready!" as every
    // example of 9.14 shows, a flash write apart. None may be taken for the next reply: the
    // move queued behind the write gets its own <NAK>.
    const int resyncs = m_rig.ctl->status().resyncCount;
    QSignalSpy finished(m_rig.ctl, &Controller::requestFinished);
    const ParameterSet nc{{"reference-switch-type", ParameterValue{{}, {{Axis::X, "NC"}}}}};
    const RequestId writeId = 1000;
    const CommandResult move = m_rig.run([&](RequestId id) {
        m_rig.ctl->writeParameters(writeId, nc, false);
        m_rig.ctl->moveRelative(id, {{Axis::X, 20}});
    });
    QVERIFY2(move.ok(), qPrintable(move.message));
    QVERIFY(!finished.isEmpty());
    QCOMPARE(finished.first().at(0).value<CommandResult>().id, writeId);
    QVERIFY(finished.first().at(0).value<CommandResult>().ok());
    QCOMPARE(m_rig.commandsStartingWith("##"), QList<QByteArray>{"##REFSW,xNC"});
    QCOMPARE(m_rig.commandsStartingWith("L1"), QList<QByteArray>{"L1,x20"});
    QTRY_VERIFY(!m_rig.anyMoving());
    QCOMPARE(m_rig.axis(Axis::X).position, 20);
    QCOMPARE(m_rig.sim->position(Axis::X), 20);
    QVERIFY(!m_rig.ctl->status().motionUnconfirmed);
    QCOMPARE(m_rig.ctl->status().resyncCount, resyncs); // no reply went astray
}

void TestEmisController::store_boardAcksPerMotor_quietLineEndsWrite()
{
    // The other reading of 9.14: one <ACK> per motor the entry names. The write ends when
    // the line stays quiet after them.
    m_rig.sim->setStoredAcksPerMotor(true);
    const int resyncs = m_rig.ctl->status().resyncCount;
    const ParameterSet speeds{{"work-speed", ParameterValue{{}, {{Axis::X, 800}, {Axis::Y, 900}}}}};
    const CommandResult r =
        m_rig.operation("store-parameters", {{"parameters", QVariant::fromValue(speeds)}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(m_rig.commandsStartingWith("##"), QList<QByteArray>{"##E,x800,y900"});
    QCOMPARE(m_rig.sim->storedEntries().first().values.value(Axis::Y), 900);
    QVERIFY(m_rig.operation("set-output", {{"output", 2}, {"on", true}}).ok());
    QVERIFY(m_rig.sim->output(2));
    QCOMPARE(m_rig.ctl->status().resyncCount, resyncs);
}

void TestEmisController::clear_sendsPesys()
{
    m_rig.sim->setFlashWriteMs(0);
    m_rig.sim->receive("##S,200,1800,100\r"); // an SMCflex entry from elsewhere
    QVERIFY(m_rig.operation("clear-stored-parameters").ok());
    QCOMPARE(m_rig.commands().last(), QByteArray("*PESYS"));
    QVERIFY(m_rig.sim->storedEntries().isEmpty());
}

void TestEmisController::output_switchedAndTracked()
{
    QVERIFY(m_rig.operation("set-output", {{"output", 3}, {"on", true}}).ok());
    QVERIFY(m_rig.sim->output(3));
    QCOMPARE(m_rig.ctl->status().outputs.at(2), std::optional<bool>(true));
    QVERIFY(m_rig.operation("set-output", {{"output", 3}, {"on", false}}).ok());
    QVERIFY(!m_rig.sim->output(3));
    QCOMPARE(m_rig.commandsStartingWith("A"), (QList<QByteArray>{"A3,1", "A3,0"}));
    QCOMPARE(m_rig.operation("set-output", {{"output", 8}, {"on", true}}).error,
             ErrorKind::InvalidValue);
    QCOMPARE(m_rig.ctl->status().toJson("emis")["outputs"].toArray().at(2).toBool(true), false);
}

void TestEmisController::program_sequenceAsInManual_noPollInBetween()
{
    m_rig.sim->clearReceivedCommands();
    const CommandResult r =
        m_rig.operation("write-input-program", {{"input", 8},
                                                {"title", "Eingang 8: Vektorfahrt X-Motor"},
                                                {"commands", QStringList{"L1,x191", "W1500"}}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    QList<QByteArray> seen = m_rig.sim->receivedCommands();
    const qsizetype start = seen.indexOf("*PWIN8");
    QVERIFY(start >= 0);
    QCOMPARE(seen.mid(start, 5),
             (QList<QByteArray>{"*PWIN8", "IJ8,1 Eingang 8: Vektorfahrt X-Motor", "L1,x191",
                                "W1500", "<ETX>"}));
    QCOMPARE(m_rig.sim->program(8)->commands, (QList<QByteArray>{"L1,x191", "W1500"}));
    QVERIFY(!m_rig.sim->anyMoving());
    QTRY_VERIFY(m_rig.sim->receivedCommands().last() == "@IG"); // polling goes on afterwards
}

void TestEmisController::program_invalidCommand_refusedNothingSent()
{
    const int before = int(m_rig.commands().size());
    CommandResult r =
        m_rig.operation("write-input-program",
                        {{"input", 6}, {"title", "t"}, {"commands", QStringList{"L1,x10", "FOO"}}});
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY2(r.message.contains("2") && r.message.contains("FOO"), qPrintable(r.message));
    r = m_rig.operation("write-input-program",
                        {{"input", 6}, {"title", "Türöffner"}, {"commands", QStringList{"W1"}}});
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    r = m_rig.operation("write-input-program",
                        {{"input", 6}, {"title", "t"}, {"commands", QStringList{"@IG"}}});
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QCOMPARE(m_rig.commands().size(), before);
}

void TestEmisController::program_referenceInput_needsForce()
{
    const QVariantMap args{{"input", 2}, {"title", "t"}, {"commands", QStringList{"A1,1"}}};
    const CommandResult refused = m_rig.operation("write-input-program", args);
    QCOMPARE(refused.error, ErrorKind::Refused);
    QVERIFY(refused.message.contains("5.2.2"));
    QVERIFY(m_rig.commandsStartingWith("*PWIN").isEmpty());
    QVariantMap forced = args;
    forced.insert("force", true);
    QVERIFY(m_rig.operation("write-input-program", forced).ok());
    QVERIFY(m_rig.sim->program(2).has_value());
}

void TestEmisController::program_lineRefusedByBoard_partialProgramErased()
{
    m_rig.sim->bellOn("L1,x10");
    const CommandResult r = m_rig.operation(
        "write-input-program",
        {{"input", 7}, {"title", "t"}, {"commands", QStringList{"A1,1", "L1,x10", "W5"}}});
    QCOMPARE(r.error, ErrorKind::Nak);
    QVERIFY2(r.message.contains("*PEIN7"), qPrintable(r.message));
    const QList<QByteArray> seen = m_rig.commands();
    QCOMPARE(seen.mid(seen.indexOf("*PWIN7")),
             (QList<QByteArray>{"*PWIN7", "IJ7,1 t", "A1,1", "L1,x10", "<ETX>", "*PEIN7"}));
    QVERIFY(!m_rig.sim->program(7).has_value());
}

void TestEmisController::program_erase()
{
    QVERIFY(m_rig
                .operation("write-input-program",
                           {{"input", 5}, {"title", "x"}, {"commands", QStringList{"W1"}}})
                .ok());
    QVERIFY(m_rig.operation("erase-input-program", {{"input", 5}}).ok());
    QCOMPARE(m_rig.commands().last(), QByteArray("*PEIN5"));
    QVERIFY(!m_rig.sim->program(5).has_value());
}

void TestEmisController::console_commandsRoutedThroughBookkeeping()
{
    CommandResult r = m_rig.run([this](RequestId id) { m_rig.ctl->sendRaw(id, "@V\r"); });
    QVERIFY(r.ok());
    QCOMPARE(r.value.toString(), QStringLiteral("@V SMC-IC4 v1.07"));
    r = m_rig.run([this](RequestId id) { m_rig.ctl->sendRaw(id, "L1,z25\r"); });
    QVERIFY(r.ok());
    QTRY_COMPARE(m_rig.axis(Axis::Z).position, 25);
    QCOMPARE(m_rig.sim->position(Axis::Z), 25);
    r = m_rig.run([this](RequestId id) { m_rig.ctl->sendRaw(id, "*PWIN1\r"); });
    QCOMPARE(r.error, ErrorKind::Refused);
    r = m_rig.run([this](RequestId id) { m_rig.ctl->sendRaw(id, "#S0\r"); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
}

void TestEmisController::console_mixedVector_eachTargetAsTyped()
{
    const auto console = [this](const QByteArray& line) {
        return m_rig.run([&](RequestId id) { m_rig.ctl->sendRaw(id, line + "\r"); });
    };
    // Z is not referenced: its absolute target is refused, whatever comes first.
    CommandResult r = console("L1,x10,Z5");
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("axis Z"), qPrintable(r.message));
    QVERIFY(m_rig.commandsStartingWith("L1").isEmpty());
    QVERIFY(m_rig.operation("reference", {{"axes", "XY"}, {"simultaneous", true}}).ok());
    QTRY_VERIFY(m_rig.axis(Axis::X).referenced && m_rig.axis(Axis::Y).referenced);
    QVERIFY(console("L1,y30").ok());
    QTRY_VERIFY(!m_rig.anyMoving());
    // X absolute, Y relative (9.11): the board moves Y by 50 more.
    r = console("L1,X100,y50");
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(m_rig.commandsStartingWith("L1").last(), QByteArray("L1,X100,y50"));
    QTRY_VERIFY(!m_rig.anyMoving());
    QCOMPARE(m_rig.sim->position(Axis::X), 100);
    QCOMPARE(m_rig.sim->position(Axis::Y), 80);
    QCOMPARE(m_rig.axis(Axis::X).position, 100);
    QCOMPARE(m_rig.axis(Axis::Y).position, 80);
    QVERIFY(m_rig.axis(Axis::Y).positionKnown);
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisController)
#include "tst_emiscontroller.moc"
