// ElabController against the real ElabSimulator over an in-memory LoopbackTransport pair:
// the line discipline, the manual's rules, NAK/timeout/garbage paths, stop/panic overtaking,
// the DC2 stream with XOFF/XON and link-loss detection.
#include "ElabTestSupport.h"
#include "TestSupport.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabController.h"
#include "protocols/elab/ElabModel.h"
#include "protocols/elab/ElabSimulator.h"
#include "transport/LoopbackTransport.h"
#include <QtTest>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::elab;

namespace {
using stepdeck::elab::testing::bytes;

ParameterValue perAxis(qint64 x, qint64 y, qint64 z)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}};
    return v;
}

ParameterValue perAxis(const QString& all)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, all}, {Axis::Y, all}, {Axis::Z, all}};
    return v;
}

ParameterValue global(const QVariant& value)
{
    ParameterValue v;
    v.global = value;
    return v;
}

ControllerOptions defaultOptions()
{
    ControllerOptions o;
    o.commandTimeoutMs = 1000; // generous: a loaded CI machine must not see false timeouts
    o.pollIntervalMs = 50;
    return o;
}

// A loopback end with an RTS line: records the levels and lets the test act on them.
class ResetLineLoopback : public LoopbackTransport
{
public:
    QList<bool> levels;
    std::function<void(bool)> onLevel;
    bool setResetLine(bool asserted, QString*) override
    {
        levels << asserted;
        if (onLevel)
            onLevel(asserted);
        return true;
    }
};

// Simulator, link and controller; the controller is destroyed first.
struct Rig
{
    explicit Rig(const ControllerOptions& options = defaultOptions(), bool resetLine = false)
    {
        LoopbackTransport* host = resetLine ? new ResetLineLoopback : new LoopbackTransport;
        auto* device = new LoopbackTransport;
        host->setPeer(device);
        device->setPeer(host);
        hostEnd.reset(host);
        deviceEnd.reset(device);
        sim = std::make_unique<ElabSimulator>(SimulatorOptions{});
        sim->attach(deviceEnd.get());
        deviceEnd->open(lineSettings()); // the device end writes the simulator's replies
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            sim->setReferencePosition(a, -500, 10); // short reference runs
        ctl = std::make_unique<ElabController>(hostEnd.get(), options);
        results = std::make_unique<QSignalSpy>(ctl.get(), &Controller::requestFinished);
        traffic = std::make_unique<QSignalSpy>(ctl.get(), &Controller::traffic);
        errors = std::make_unique<QSignalSpy>(ctl.get(), &Controller::errorOccurred);
        jogRefusals = std::make_unique<QSignalSpy>(ctl.get(), &Controller::jogRefused);
    }
    ~Rig() { ctl.reset(); }

    std::unique_ptr<LoopbackTransport> hostEnd;
    std::unique_ptr<LoopbackTransport> deviceEnd;
    std::unique_ptr<ElabSimulator> sim;
    std::unique_ptr<ElabController> ctl;
    std::unique_ptr<QSignalSpy> results;
    std::unique_ptr<QSignalSpy> traffic;
    std::unique_ptr<QSignalSpy> errors;
    std::unique_ptr<QSignalSpy> jogRefusals;
    RequestId nextId = 1;

    std::optional<CommandResult> find(RequestId id) const
    {
        for (const QList<QVariant>& args : *results) {
            const auto r = args.at(0).value<CommandResult>();
            if (r.id == id)
                return r;
        }
        return std::nullopt;
    }
    int countResults(RequestId id) const
    {
        int n = 0;
        for (const QList<QVariant>& args : *results)
            n += args.at(0).value<CommandResult>().id == id ? 1 : 0;
        return n;
    }
    // Waits on the event loop (never sleeps) for the result of request id.
    CommandResult wait(RequestId id, int timeoutMs = 5000)
    {
        QElapsedTimer t;
        t.start();
        while (!find(id) && t.elapsed() < timeoutMs)
            results->wait(20);
        return find(id).value_or(CommandResult::failure(id, ErrorKind::Timeout, "test: no result"));
    }
    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs = 5000)
    {
        const RequestId id = nextId++;
        call(id);
        return wait(id, timeoutMs);
    }
    bool connect()
    {
        return run([this](RequestId id) { ctl->openLink(id); }).ok();
    }
    // A complete setup: start 3000, max 5000, acceleration 20000 (short ramps), feed 2000.
    bool setup()
    {
        ParameterSet set;
        set.insert("start-speed", perAxis(3000, 3000, 3000));
        set.insert("max-speed", perAxis(5000, 5000, 5000));
        set.insert("acceleration", perAxis(20000, 20000, 20000));
        set.insert("feed-speed", perAxis(2000, 2000, 2000));
        set.insert("drive-power", global(100));
        return run([&](RequestId id) { ctl->writeParameters(id, set, false); }).ok();
    }
    bool connectAndSetup()
    {
        if (!connect() || !setup())
            return false;
        // The next complete status read shows the finished setup.
        const CommandResult r = run([this](RequestId id) { ctl->refreshStatus(id); });
        return r.ok() && !ctl->status().setupIncomplete;
    }

    QList<TrafficRecord> records(TrafficRecord::Direction dir, bool withPolls = false) const
    {
        QList<TrafficRecord> out;
        for (const QList<QVariant>& args : *traffic) {
            const auto rec = args.at(0).value<TrafficRecord>();
            if (rec.direction == dir && (withPolls || !rec.poll))
                out << rec;
        }
        return out;
    }
    QList<QByteArray> framesOut(bool withPolls = false) const
    {
        QList<QByteArray> out;
        for (const TrafficRecord& r : records(TrafficRecord::Direction::Out, withPolls))
            out << r.bytes;
        return out;
    }
    bool sentFrameStartingWith(char code) const
    {
        for (const QByteArray& f : framesOut(true)) {
            if (!f.isEmpty() && f.at(0) == code)
                return true;
        }
        return false;
    }
    int indexOfFrame(const QByteArray& frame, int from = 0) const
    {
        const QList<QByteArray> frames = framesOut(true);
        for (int i = from; i < frames.size(); ++i) {
            if (frames.at(i) == frame)
                return i;
        }
        return -1;
    }
};
} // namespace

class TestElabController : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void connect_readsStatus_setupIncomplete();
    void writeParameters_exactBytes();
    void writeParameters_outOfRange_sendsNothing_data();
    void writeParameters_outOfRange_sendsNothing();
    void readParameters_returnsLastWritten_orUnsupported();
    void move_picksNarrowestCommand_data();
    void move_picksNarrowestCommand();
    void move_setupIncomplete_refused();
    void move_whileLimitSwitch_refusedWithReason();
    void move_outOfRange_notSent();
    void jog_allowedOnLimitSwitch();
    void jog_lease_expiry_sendsZero();
    void nak_readsBothStatusWords_andReportsDecodedBits();
    void timeout_resyncsWithSynBurst_data();
    void timeout_resyncsWithSynBurst();
    void stop_overtakesQueuedMoves();
    void panic_discardsQueue_andMarksUnreferenced();
    void reference_zeroesPosition_andMarksReferenced();
    void feed_singleAxis_clearPositionThenFeedSteps();
    void dc2Stream_xoffXon_noStepLostOrDuplicated();
    void feed_multiAxis_streamsStraightLine();
    void velocity_reversalWhileRunning_refused();
    void linkLoss_afterThreeMissedPolls();
    void transportFailure_failsPendingWithLinkDown();
    void reset_withoutModemLines_failsWithReason();
    void reset_pulsesResetLine_andRereadsStatus();
    void limitHitDuringMove_marksAxisUnreferenced();
    void dc2Stream_stop_flushesBufferAndEndsFeed();
    void jog_nak_haltsJogAndSaysWhy();
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
    const QList<QByteArray> expected{bytes("<ESC>S0064,0064;0064."),
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
    QTest::newRow("max-speed above 16 bits") << tooFast << "max-speed";

    ParameterSet power;
    power.insert("drive-power", global(101));
    QTest::newRow("drive-power 101") << power << "0..100";

    ParameterSet rpm;
    rpm.insert("spindle-rpm", global(1001));
    QTest::newRow("spindle-rpm 1001") << rpm << "0..1000";

    ParameterSet feedAbove;
    feedAbove.insert("start-speed", perAxis(100, 100, 100));
    feedAbove.insert("feed-speed", perAxis(50, 100, 50));
    QTest::newRow("feed not below start") << feedAbove << "below start-speed";

    ParameterSet feedAlone;
    feedAlone.insert("feed-speed", perAxis(50, 50, 50));
    QTest::newRow("feed without start") << feedAlone << "start-speed";

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
    QCOMPARE(rig.framesOut(false), QList<QByteArray>{bytes("<ESC>M1388,0FA0;1388.")});
    r = rig.run([&](RequestId id) { rig.ctl->readParameters(id, {"max-speed"}); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    const auto values = r.value.value<ParameterSet>();
    QCOMPARE(values.value("max-speed"), perAxis(5000, 4000, 5000));
}

void TestElabController::move_picksNarrowestCommand_data()
{
    QTest::addColumn<AxisVector>("steps");
    QTest::addColumn<QByteArray>("frame");
    QTest::newRow("Z only -> <BS>") << AxisVector{{Axis::Z, 1000}} << bytes("<BS>000003E8.");
    QTest::newRow("X only -> <FF>")
        << AxisVector{{Axis::X, 16}, {Axis::Z, 0}} << bytes("<FF>00000010,00000000;");
    QTest::newRow("XY -> <FF>") << AxisVector{{Axis::X, 1000}, {Axis::Y, -1000}}
                                << bytes("<FF>000003E8,FFFFFC18;");
    QTest::newRow("XYZ -> <EOT>") << AxisVector{{Axis::X, 1000}, {Axis::Y, -1000}, {Axis::Z, 16}}
                                  << bytes("<EOT>000003E8,FFFFFC18;00000010.");
}

void TestElabController::move_picksNarrowestCommand()
{
    QFETCH(AxisVector, steps);
    QFETCH(QByteArray, frame);
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->moveRelative(id, steps); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    // Pre-flight (RequestAxeState, RequestMachineState), then the narrowest FastMove.
    const QList<QByteArray> out = rig.framesOut(false);
    QCOMPARE(out,
             (QList<QByteArray>{encode::requestAxeState(), encode::requestMachineState(), frame}));
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        QTRY_COMPARE_WITH_TIMEOUT(rig.sim->position(it.key()), it.value(), 5000);
        QCOMPARE(rig.ctl->status().axes.value(it.key()).position, it.value());
        QVERIFY(!rig.ctl->status().axes.value(it.key()).positionKnown); // never referenced
    }
}

void TestElabController::move_setupIncomplete_refused()
{
    Rig rig;
    QVERIFY(rig.connect());
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, 100}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("tmInvSetup"), qPrintable(r.message));
    QVERIFY(!rig.sentFrameStartingWith(ctrl::FF));
}

void TestElabController::move_whileLimitSwitch_refusedWithReason()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->setLimitSwitchActuated(Axis::X, true);
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::Y, 100}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("limit switch"), qPrintable(r.message));
    QVERIFY2(r.message.contains("tmLimSwX"), qPrintable(r.message));
    QVERIFY(!rig.sentFrameStartingWith(ctrl::FF));
    QCOMPARE(rig.sim->position(Axis::Y), 0);
}

void TestElabController::move_outOfRange_notSent()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, qint64(1) << 31}});
    });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY2(r.message.contains("2147483647"), qPrintable(r.message));
    r = rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::Z, 2}}); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    r = rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::Y, 40000}}); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY2(r.message.contains("32767"), qPrintable(r.message));
    r = rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::U, 1}}); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY(rig.framesOut(false).isEmpty());
}

void TestElabController::jog_allowedOnLimitSwitch()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->setLimitSwitchActuated(Axis::X, true);
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).limitSwitch, 5000);
    rig.ctl->setJogVelocity({{Axis::X, -300}});
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).jogging, 5000);
    QVERIFY(rig.jogRefusals->isEmpty());
    rig.ctl->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QVERIFY(rig.indexOfFrame(encode::jogSpeed({0, 0, 0})) >= 0);
    QVERIFY(rig.ctl->status().axes.value(Axis::X).positionEstimated);
}

void TestElabController::jog_lease_expiry_sendsZero()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    rig.ctl->setJogVelocity({{Axis::Y, 400}}); // never renewed
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::Y), 5000);
    // The first jog from idle was preceded by the standstill check.
    const QList<QByteArray> out = rig.framesOut(false);
    QVERIFY(out.size() >= 3);
    QCOMPARE(out.at(0), encode::requestAxeState());
    QCOMPARE(out.at(1), encode::requestMachineState());
    QCOMPARE(out.at(2).at(0), ctrl::DC4);
    QTRY_VERIFY_WITH_TIMEOUT(rig.indexOfFrame(encode::jogSpeed({0, 0, 0})) >= 0, 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::Y), 5000);
    QVERIFY(rig.ctl->jogRamp().isIdle());
}

void TestElabController::nak_readsBothStatusWords_andReportsDecodedBits()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->forceNak(1);
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, 100}});
    });
    QCOMPARE(r.error, ErrorKind::Nak);
    QVERIFY2(r.message.contains("NAK"), qPrintable(r.message));
    QVERIFY2(r.message.contains("tmDriveOn"), qPrintable(r.message)); // drive power is 100
    QVERIFY2(r.message.contains(describeAxeState(0)), qPrintable(r.message));
    const QList<QByteArray> out = rig.framesOut(false);
    QCOMPARE(out, (QList<QByteArray>{encode::requestAxeState(), encode::requestMachineState(),
                                     bytes("<FF>00000064,00000000;"), encode::requestAxeState(),
                                     encode::requestMachineState()}));
    QCOMPARE(rig.sim->position(Axis::X), 0);
}

void TestElabController::timeout_resyncsWithSynBurst_data()
{
    QTest::addColumn<bool>("corrupt");
    QTest::newRow("dropped reply") << false;
    QTest::newRow("corrupted reply") << true;
}

void TestElabController::timeout_resyncsWithSynBurst()
{
    QFETCH(bool, corrupt);
    ControllerOptions o = defaultOptions();
    o.commandTimeoutMs = 300;
    Rig rig(o);
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    if (corrupt)
        rig.sim->faults().corruptReplies = 1;
    else
        rig.sim->faults().dropReplies = 1;
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().resyncCount >= 1, 5000);
    // A burst of <SYN>, then RequestMachineState.
    const QByteArray burst(16, ctrl::SYN);
    QTRY_VERIFY_WITH_TIMEOUT(rig.indexOfFrame(burst) >= 0, 5000);
    const int at = rig.indexOfFrame(burst);
    QTRY_VERIFY_WITH_TIMEOUT(rig.framesOut(true).size() > at + 1, 5000);
    QCOMPARE(rig.framesOut(true).at(at + 1), encode::requestMachineState());
    QVERIFY(!rig.errors->isEmpty());
    QVERIFY2(rig.errors->first().at(0).toString().contains("resynchronising"),
             qPrintable(rig.errors->first().at(0).toString()));
    // The line works again.
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->refreshStatus(id); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(rig.ctl->linkState(), LinkState::Connected);
}

void TestElabController::stop_overtakesQueuedMoves()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    // A long move: 100000 steps at 5000 steps/s.
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 100000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->position(Axis::X) > 100, 5000);
    rig.traffic->clear();
    const RequestId second = rig.nextId++;
    const RequestId third = rig.nextId++;
    const RequestId stopId = rig.nextId++;
    rig.ctl->moveRelative(second, {{Axis::Y, 500}});
    rig.ctl->feed(third, {{Axis::Z, 500}});
    rig.ctl->stop(stopId);
    QVERIFY(rig.wait(stopId).ok());
    QCOMPARE(rig.wait(second).error, ErrorKind::Cancelled);
    QCOMPARE(rig.wait(third).error, ErrorKind::Cancelled);
    // The stop went out right behind what was already on the line, nothing after it moved.
    const QList<QByteArray> out = rig.framesOut(true);
    const int stopAt = rig.indexOfFrame(encode::stopMove());
    QVERIFY(stopAt >= 0 && stopAt <= 1);
    QCOMPARE(rig.indexOfFrame(bytes("<FF>00000000,000001F4;")), -1);
    QVERIFY(!rig.sentFrameStartingWith(ctrl::VT));
    QVERIFY(!rig.sentFrameStartingWith(ctrl::RS));
    // Braked to standstill, then RequestRelPosition corrected the host position.
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sentFrameStartingWith(ctrl::ETX), 5000);
    QTRY_COMPARE_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).position,
                              rig.sim->position(Axis::X), 5000);
    QVERIFY(rig.sim->position(Axis::X) < 100000);
    QCOMPARE(rig.sim->position(Axis::Y), 0);
    QCOMPARE(rig.countResults(second), 1);
    QCOMPARE(rig.countResults(stopId), 1);
}

void TestElabController::panic_discardsQueue_andMarksUnreferenced()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::X, -1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 50000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    rig.traffic->clear();
    const RequestId queued = rig.nextId++;
    const RequestId panicId = rig.nextId++;
    rig.ctl->moveRelative(queued, {{Axis::Y, 10}});
    rig.ctl->panic(panicId);
    QVERIFY(rig.wait(panicId).ok());
    QCOMPARE(rig.wait(queued).error, ErrorKind::Cancelled);
    QVERIFY(rig.indexOfFrame(encode::panicStop()) >= 0);
    QVERIFY(!rig.sim->isMoving(Axis::X)); // no brake ramp
    const MachineStatus& s = rig.ctl->status();
    QVERIFY(s.panic);
    for (const AxisStatus& a : s.axes) {
        QVERIFY(!a.referenced);
        QVERIFY(!a.positionKnown);
    }
    // Jog stays refused until the machine is re-initialised; the line still works.
    rig.ctl->setJogVelocity({{Axis::X, 100}});
    QCOMPARE(rig.jogRefusals->size(), 1);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->refreshStatus(id); }).ok());
    QVERIFY(rig.ctl->status().panic);
}

void TestElabController::reference_zeroesPosition_andMarksReferenced()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    QVERIFY(rig.run([&](RequestId id) {
                   rig.ctl->reference(id, {{Axis::X, -1}, {Axis::Y, 0}, {Axis::Z, 0}});
               })
                .ok());
    QVERIFY(rig.indexOfFrame(bytes("<US>FFFF,0000;0000.")) >= 0);
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    const AxisStatus x = rig.ctl->status().axes.value(Axis::X);
    QVERIFY(x.positionKnown);
    QCOMPARE(x.position, 0);
    QVERIFY(!rig.ctl->status().axes.value(Axis::Y).referenced);
    // An absolute move now works from the referenced origin.
    const qint64 origin = rig.sim->position(Axis::X);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveAbsolute(id, {{Axis::X, 300}}); }).ok());
    QTRY_COMPARE_WITH_TIMEOUT(rig.sim->position(Axis::X), origin + 300, 5000);
    QCOMPARE(rig.ctl->status().axes.value(Axis::X).position, 300);
}

void TestElabController::feed_singleAxis_clearPositionThenFeedSteps()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->feed(id, {{Axis::Y, 200}}); }).ok());
    QCOMPARE(rig.framesOut(false),
             (QList<QByteArray>{encode::requestAxeState(), encode::requestMachineState(),
                                bytes("<RS>"), bytes("<SUB>000000C8;")}));
    QTRY_COMPARE_WITH_TIMEOUT(rig.sim->position(Axis::Y), 200, 5000);
}

void TestElabController::dc2Stream_xoffXon_noStepLostOrDuplicated()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    // A small buffer so the board says XOFF/XON many times during the stream.
    rig.sim->setStreamBuffer(64, 32, 8);
    QVector<AxisVector> steps;
    qint64 expected[3] = {0, 0, 0};
    for (int i = 0; i < 600; ++i) {
        AxisVector s{
            {Axis::X, i % 2 ? 1 : 0}, {Axis::Y, i % 3 ? -1 : 1}, {Axis::Z, i % 5 ? 0 : -1}};
        for (auto it = s.cbegin(); it != s.cend(); ++it)
            expected[int(it.key())] += it.value();
        steps << s;
    }
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->feedStream(id, steps); }, 20000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.value.toLongLong(), 600);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 20000);
    QCOMPARE(rig.sim->executedStepBytes(), 600);
    QCOMPARE(rig.sim->streamOverflows(), 0);
    QCOMPARE(rig.sim->streamRejected(), 0);
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        QCOMPARE(rig.sim->position(a), expected[int(a)]);
        QCOMPARE(rig.ctl->status().axes.value(a).position, expected[int(a)]);
    }
    // The board did throttle the host.
    int xoff = 0;
    int xon = 0;
    for (const TrafficRecord& rec : rig.records(TrafficRecord::Direction::In, true)) {
        xoff += rec.bytes == QByteArray(1, ctrl::XOFF) ? 1 : 0;
        xon += rec.bytes == QByteArray(1, ctrl::XON) ? 1 : 0;
    }
    QVERIFY(xoff >= 2);
    QVERIFY(xon >= 2);
    QVERIFY(rig.indexOfFrame(encode::endOfFeed()) >= 0);
}

void TestElabController::feed_multiAxis_streamsStraightLine()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    const CommandResult r = rig.run(
        [&](RequestId id) {
            rig.ctl->feed(id, {{Axis::X, 300}, {Axis::Y, -120}, {Axis::Z, 7}});
        },
        20000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 20000);
    QCOMPARE(rig.sim->position(Axis::X), 300);
    QCOMPARE(rig.sim->position(Axis::Y), -120);
    QCOMPARE(rig.sim->position(Axis::Z), 7);
    QCOMPARE(rig.sim->executedStepBytes(), 300);
}

void TestElabController::velocity_reversalWhileRunning_refused()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, 4000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    CommandResult r = rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, -4000}}); });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("reverse"), qPrintable(r.message));
    // A rate change in the same direction needs no standstill.
    r = rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, 3500}}); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->stop(id); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).positionKnown);
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
    QVERIFY(!rig.hostEnd->isOpen());
    QVERIFY(rig.ctl->status().commFault);
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, 1}});
    });
    QCOMPARE(r.error, ErrorKind::LinkDown);
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
    QCOMPARE(rig.framesOut(false),
             (QList<QByteArray>{bytes("<SOH>000003E8#"), bytes("<SI>FF"), bytes("<STX>42")}));
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

void TestElabController::limitHitDuringMove_marksAxisUnreferenced()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::X, -1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    rig.sim->setLimitPositions(Axis::X, -100000, rig.sim->position(Axis::X) + 400);
    rig.errors->clear();
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 3000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).positionKnown);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.errors->isEmpty(), 5000);
    QVERIFY2(rig.errors->last().at(0).toString().contains("limit switch"),
             qPrintable(rig.errors->last().at(0).toString()));
    // Further moves are refused while the switch is active; jog is the way out.
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, -100}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
}

void TestElabController::dc2Stream_stop_flushesBufferAndEndsFeed()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVector<AxisVector> steps(4000, AxisVector{{Axis::X, 1}});
    const RequestId streamId = rig.nextId++;
    rig.ctl->feedStream(streamId, steps);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->executedStepBytes() > 100, 5000);
    rig.traffic->clear();
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->stop(id); }).ok());
    const CommandResult streamResult = rig.wait(streamId);
    QCOMPARE(streamResult.error, ErrorKind::Cancelled);
    const int stopAt = rig.indexOfFrame(encode::stopMove());
    const int flushAt = rig.indexOfFrame(encode::flushBuffer());
    const int endAt = rig.indexOfFrame(encode::endOfFeed());
    QVERIFY(stopAt >= 0 && stopAt < flushAt && flushAt < endAt);
    const QList<QByteArray> out = rig.framesOut(true);
    for (int i = stopAt + 1; i < out.size(); ++i)
        QVERIFY(out.at(i).at(0) != ctrl::DC2);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QCOMPARE(rig.sim->streamBuffered(), 0);
    QVERIFY(rig.sim->executedStepBytes() < 4000);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.ctl->status().axes.value(Axis::X).moving, 5000);
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).positionKnown);
}

void TestElabController::jog_nak_haltsJogAndSaysWhy()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->forceNak(1);
    rig.ctl->setJogVelocity({{Axis::Z, 300}});
    QTRY_COMPARE_WITH_TIMEOUT(rig.jogRefusals->size(), 1, 5000);
    QVERIFY2(rig.jogRefusals->first().at(0).toString().contains("NAK"),
             qPrintable(rig.jogRefusals->first().at(0).toString()));
    QVERIFY(rig.ctl->jogRamp().isIdle());
    QVERIFY(!rig.sim->isMoving(Axis::Z));
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
    rig.traffic->clear();
    rig.ctl->closeLink();
    QCOMPARE(rig.ctl->linkState(), LinkState::Disconnected);
    QCOMPARE(rig.framesOut(true), QList<QByteArray>{encode::stopMove()});
    // Nothing keeps running unattended: the board brakes to standstill.
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::Z), 5000);
}

QTEST_GUILESS_MAIN(TestElabController)
#include "tst_elabcontroller.moc"
