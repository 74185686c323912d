// ElabController against the real ElabSimulator over a LoopbackTransport pair: link,
// status, parameters, NAK/timeout/garbage paths, link loss, reset, auxiliaries and console.
#include "ElabControllerRig.h"
#include "TestMain.h"

class TestElabController : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void connect_readsStatus_setupIncomplete();
    void writeParameters_exactBytes();
    void writeParameters_outOfRange_sendsNothing_data();
    void writeParameters_outOfRange_sendsNothing();
    void readParameters_returnsLastWritten_orUnsupported();
    void linkLoss_afterThreeMissedPolls();
    void poll_bothStatusWordsRequestedBeforeTheFirstReply();
    void transportFailure_failsPendingWithLinkDown();
    void reset_withoutModemLines_failsWithReason();
    void reset_pulsesResetLine_andRereadsStatus();
    void sendRaw_returnsReply();
    void closeLink_duringVelocityMove_sendsStopFirst();
    void auxiliaries_validateRange();
};

void TestElabController::connect_readsStatus_setupIncomplete()
{
    Rig rig;
    QSignalSpy links(rig.ctl.get(), &Controller::linkStateChanged);
    QVERIFY(rig.connect());
    QCOMPARE(rig.ctl->linkState(), LinkState::Connected);
    QCOMPARE(rig.hostEnd->lineSettings().baudRate, 57600);
    QCOMPARE(rig.hostEnd->lineSettings().stopBits, 2);
    const MachineStatus& s = rig.ctl->status();
    // A powered-on board: <ENQ>0080# -- tmInvSetup only.
    QVERIFY(s.setupIncomplete);
    QCOMPARE(s.raw.value("machineState").toInt(), 0x80);
    QCOMPARE(s.raw.value("axeState").toInt(), 0);
    QVERIFY(s.temperatureCelsius.has_value());
    QCOMPARE(*s.temperatureCelsius, 25.0);
    QCOMPARE(s.axes.size(), 3);
    for (const AxisStatus& a : s.axes) {
        QVERIFY(!a.referenced);
        QVERIFY(!a.positionKnown);
    }
    QVERIFY(rig.sentFrameStartingWith(ctrl::ENQ));
    QVERIFY(rig.sentFrameStartingWith(ctrl::HT));
    QVERIFY(rig.sentFrameStartingWith(ctrl::ETB));
    // The poller keeps reading both words.
    QTRY_VERIFY_WITH_TIMEOUT(rig.records(TrafficRecord::Direction::Out, true).size() >
                                 rig.records(TrafficRecord::Direction::Out, false).size() + 4,
                             5000);
    QCOMPARE(links.last().at(0).value<LinkState>(), LinkState::Connected);
}

void TestElabController::writeParameters_exactBytes()
{
    Rig rig;
    QVERIFY(rig.connect());
    ParameterSet set;
    set.insert("start-speed", perAxis(100, 100, 100));
    set.insert("max-speed", perAxis(5000, 5000, 5000));
    set.insert("acceleration", perAxis(1000, 1000, 1000));
    set.insert("feed-speed", perAxis(50, 50, 50));
    set.insert("limit-polarity", perAxis(QStringLiteral("low")));
    set.insert("reference-polarity", perAxis(QStringLiteral("high")));
    set.insert("drive-power", global(100));
    set.insert("spindle-rpm", global(1000));
    set.insert("coolant", global(false));
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->writeParameters(id, set, true); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY2(r.message.contains("cannot read parameters back"), qPrintable(r.message));
    // Standstill first ("Sind Positionier- oder Arbeits Kommandos beim Controller in Arbeit, so
    // muss der Host den Status des Controllers abfragen"), then the writes back to back.
    const QList<QByteArray> expected{bytes("<HT>"),
                                     bytes("<ENQ>"),
                                     bytes("<ESC>S0064,0064;0064."),
                                     bytes("<ESC>M1388,1388;1388."),
                                     bytes("<ESC>A03E8,03E8;03E8."),
                                     bytes("<FS>0032,0032;0032."),
                                     bytes("<SO>00,00;00."),
                                     bytes("<DLE>FF,FF;FF."),
                                     bytes("<STX>64"),
                                     bytes("<SOH>000003E8#"),
                                     bytes("<SI>00")};
    QCOMPARE(rig.framesOut(false), expected);
    QCOMPARE(rig.sim->rampParameters(Axis::Y).maxSpeed, quint16(5000));
    QCOMPARE(rig.sim->drivePower(), 100);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.ctl->status().setupIncomplete, 5000);
}

void TestElabController::writeParameters_outOfRange_sendsNothing_data()
{
    QTest::addColumn<ParameterSet>("set");
    QTest::addColumn<QString>("mentions");

    ParameterSet tooFast;
    tooFast.insert("start-speed", perAxis(100, 100, 100));
    tooFast.insert("max-speed", perAxis(5000, 70000, 5000));
    QTest::newRow("max-speed above 16 bits") << tooFast << "Max speed: value '70000'";

    ParameterSet power;
    power.insert("drive-power", global(101));
    QTest::newRow("drive-power 101") << power << "0..100";

    ParameterSet rpm;
    rpm.insert("spindle-rpm", global(1001));
    QTest::newRow("spindle-rpm 1001") << rpm << "0..1000";

    ParameterSet feedAbove;
    feedAbove.insert("start-speed", perAxis(100, 100, 100));
    feedAbove.insert("feed-speed", perAxis(50, 100, 50));
    QTest::newRow("feed not below start")
        << feedAbove << "Feed speed 100 on axis Y must be below Start speed 100";

    ParameterSet feedAlone;
    feedAlone.insert("feed-speed", perAxis(50, 50, 50));
    QTest::newRow("feed without start") << feedAlone << "but Start speed is not known";

    ParameterSet partial;
    ParameterValue onlyX;
    onlyX.perAxis = {{Axis::X, 100}};
    partial.insert("start-speed", onlyX);
    QTest::newRow("one axis, nothing written before") << partial << "axis Y";

    ParameterSet unknown;
    unknown.insert("warp-factor", global(9));
    QTest::newRow("unknown name") << unknown << "warp-factor";
}

void TestElabController::writeParameters_outOfRange_sendsNothing()
{
    QFETCH(ParameterSet, set);
    QFETCH(QString, mentions);
    Rig rig;
    QVERIFY(rig.connect());
    rig.traffic->clear();
    const CommandResult r =
        rig.run([&](RequestId id) { rig.ctl->writeParameters(id, set, false); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY2(r.message.contains(mentions), qPrintable(r.message));
    QVERIFY(rig.framesOut(false).isEmpty());
    QCOMPARE(rig.sim->rampParameters(Axis::X).startSpeed, quint16(0));
}

void TestElabController::readParameters_returnsLastWritten_orUnsupported()
{
    Rig rig;
    QVERIFY(rig.connect());
    CommandResult r = rig.run([&](RequestId id) { rig.ctl->readParameters(id, {"max-speed"}); });
    QCOMPARE(r.error, ErrorKind::Unsupported);
    QVERIFY2(r.message.contains("cannot read parameters back"), qPrintable(r.message));
    QVERIFY(rig.setup());
    // A partial write completes the other axes from the last written values.
    ParameterSet change;
    ParameterValue onlyY;
    onlyY.perAxis = {{Axis::Y, 4000}};
    change.insert("max-speed", onlyY);
    rig.traffic->clear();
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->writeParameters(id, change, false); }).ok());
    QCOMPARE(rig.framesOut(false),
             (QList<QByteArray>{bytes("<HT>"), bytes("<ENQ>"), bytes("<ESC>M1388,0FA0;1388.")}));
    r = rig.run([&](RequestId id) { rig.ctl->readParameters(id, {"max-speed"}); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    const auto values = r.value.value<ParameterSet>();
    QCOMPARE(values.value("max-speed"), perAxis(5000, 4000, 5000));
}

void TestElabController::linkLoss_afterThreeMissedPolls()
{
    ControllerOptions o = defaultOptions();
    o.commandTimeoutMs = 100;
    o.pollIntervalMs = 20;
    Rig rig(o);
    QSignalSpy links(rig.ctl.get(), &Controller::linkStateChanged);
    QVERIFY(rig.connect());
    rig.sim->faults().silent = true;
    QTRY_COMPARE_WITH_TIMEOUT(rig.ctl->linkState(), LinkState::Lost, 10000);
    QCOMPARE(links.last().at(0).value<LinkState>(), LinkState::Lost);
    QVERIFY2(links.last().at(1).toString().contains("3 status polls"),
             qPrintable(links.last().at(1).toString()));
    // The stop went out before the link was declared lost, and the port stays open for PANIC.
    QVERIFY(rig.sim->countReceived(encode::stopMove()) >= 1);
    QVERIFY(rig.hostEnd->isOpen());
    QVERIFY(rig.ctl->status().commFault);
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, 1}});
    });
    QCOMPARE(r.error, ErrorKind::LinkDown);
}

// Issue 21: a poll's RequestAxeState and RequestMachineState (and every few polls the
// temperature and start button requests) go out back to back, all before the first reply; the
// words are still matched to the right requests.
void TestElabController::poll_bothStatusWordsRequestedBeforeTheFirstReply()
{
    ControllerOptions o = defaultOptions();
    o.pollIntervalMs = 10;
    Rig rig(o);
    QVERIFY(rig.connect());
    rig.traffic->clear();
    QTRY_VERIFY_WITH_TIMEOUT(rig.records(TrafficRecord::Direction::In, true).size() >= 20, 5000);
    QList<QByteArray> sequence; // "out:<HT>", "in:<HT>00#", ... in the adapter's order
    for (const QList<QVariant>& args : *rig.traffic) {
        const auto rec = args.at(0).value<TrafficRecord>();
        const bool out = rec.direction == TrafficRecord::Direction::Out;
        sequence << (out ? "out:" : "in:") + rec.bytes.left(1);
    }
    const QByteArray ht = "out:" + encode::requestAxeState();
    const QByteArray enq = "out:" + encode::requestMachineState();
    int pairs = 0;
    for (int i = 0; i + 3 < sequence.size(); ++i) {
        if (sequence.at(i) != ht)
            continue;
        QCOMPARE(sequence.at(i + 1), enq);
        int reply = i + 2; // behind the temperature and start button requests of some polls
        while (reply + 1 < sequence.size() && sequence.at(reply).startsWith("out:"))
            ++reply;
        QCOMPARE(sequence.at(reply), QByteArray("in:") + char(ctrl::HT));
        QCOMPARE(sequence.at(reply + 1), QByteArray("in:") + char(ctrl::ENQ));
        ++pairs;
    }
    QVERIFY2(pairs >= 5, qPrintable(QString::number(pairs)));
    QCOMPARE(rig.ctl->linkState(), LinkState::Connected);
    QVERIFY(rig.ctl->status().setupIncomplete); // the fresh board's tmInvSetup, read right
}

void TestElabController::transportFailure_failsPendingWithLinkDown()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->faults().silent = true; // the pending request gets no answer
    const RequestId id = rig.nextId++;
    rig.ctl->refreshStatus(id);
    rig.hostEnd->simulateFailure(QStringLiteral("device vanished"));
    const CommandResult r = rig.wait(id);
    QCOMPARE(r.error, ErrorKind::LinkDown);
    QCOMPARE(rig.ctl->linkState(), LinkState::Lost);
    QCOMPARE(rig.countResults(id), 1);
}

void TestElabController::reset_withoutModemLines_failsWithReason()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::X, -1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->reset(id); });
    QCOMPARE(r.error, ErrorKind::Unsupported);
    QVERIFY2(r.message.contains("modem control"), qPrintable(r.message));
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).referenced);
}

void TestElabController::auxiliaries_validateRange()
{
    Rig rig;
    QVERIFY(rig.connect());
    rig.traffic->clear();
    QCOMPARE(rig.run([&](RequestId id) { rig.ctl->setSpindle(id, 1001); }).error,
             ErrorKind::InvalidValue);
    QCOMPARE(rig.run([&](RequestId id) { rig.ctl->setDrivePower(id, -1); }).error,
             ErrorKind::InvalidValue);
    QVERIFY(rig.framesOut(false).isEmpty());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->setSpindle(id, 1000); }).ok());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->setCoolant(id, true); }).ok());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->setDrivePower(id, 66); }).ok());
    // Each output write is preceded by the standstill read (<HT><ENQ>).
    QCOMPARE(rig.framesOut(false),
             (QList<QByteArray>{bytes("<HT>"), bytes("<ENQ>"), bytes("<SOH>000003E8#"),
                                bytes("<HT>"), bytes("<ENQ>"), bytes("<SI>FF"), bytes("<HT>"),
                                bytes("<ENQ>"), bytes("<STX>42")}));
    QCOMPARE(rig.sim->spindleRpm(), quint32(1000));
    QVERIFY(rig.sim->coolant());
    QCOMPARE(rig.sim->drivePower(), 66);
}

void TestElabController::reset_pulsesResetLine_andRereadsStatus()
{
    Rig rig(defaultOptions(), true);
    auto* line = static_cast<ResetLineLoopback*>(rig.hostEnd.get());
    line->onLevel = [&](bool high) {
        if (high)
            rig.sim->powerOnReset(); // RTS high resets the board (jumper J7)
    };
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::X, -1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->reset(id); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(line->levels, (QList<bool>{true, false}));
    // Status re-read after the reset: the board lost its setup, nothing is referenced.
    QVERIFY(rig.sentFrameStartingWith(ctrl::ENQ));
    QVERIFY(rig.ctl->status().setupIncomplete);
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).referenced);
    QCOMPARE(rig.run([&](RequestId id) { rig.ctl->readParameters(id, {"start-speed"}); }).error,
             ErrorKind::Unsupported);
}

void TestElabController::sendRaw_returnsReply()
{
    Rig rig;
    QVERIFY(rig.connect());
    CommandResult r = rig.run([&](RequestId id) { rig.ctl->sendRaw(id, bytes("<ENQ>")); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.value.toByteArray(), bytes("<ENQ>0080#"));
    r = rig.run([&](RequestId id) { rig.ctl->sendRaw(id, bytes("<ESC>S0064,0064;0064.")); });
    QCOMPARE(r.value.toByteArray(), bytes("<ACK>"));
    r = rig.run([&](RequestId id) { rig.ctl->sendRaw(id, bytes("<SYN>")); });
    QVERIFY2(r.ok(), qPrintable(r.message));
}

void TestElabController::closeLink_duringVelocityMove_sendsStopFirst()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::Z, -3500}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::Z), 5000);
    rig.sim->clearReceivedFrames();
    QSignalSpy closed(rig.ctl.get(), &Controller::closeFinished);
    rig.ctl->closeLink();
    QVERIFY(closed.count() == 1 || closed.wait(3000));
    QCOMPARE(rig.ctl->linkState(), LinkState::Disconnected);
    // What the device saw: the stop, nothing else, and it was acknowledged before the close.
    QCOMPARE(rig.sim->receivedFrames(), QList<QByteArray>{encode::stopMove()});
    QVERIFY(!rig.ctl->status().motionUnconfirmed);
    // Nothing keeps running unattended: the board brakes to standstill.
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->standingStill(), 5000);
}

STEPDECK_TEST_GUILESS_MAIN(TestElabController)
#include "tst_elabcontroller.moc"
