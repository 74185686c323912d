// End to end in one process: the SMC-IC4 simulator on the device side of a real
// pseudo-terminal, the application side through the real QSerialPort (SerialTransport) at
// 115200 8N1 -- also through the registry and ControllerSession, as the GUI and CLI run it.
// The arrival bytes <DC1> and <DC3> are XON and XOFF: they must pass the real port.
#include "TestMain.h"
#include "TestSupport.h"
#include "controller/ControllerSession.h"
#include "protocols/Registry.h"
#include "protocols/emis/EmisController.h"
#include "protocols/emis/EmisModel.h"
#include "protocols/emis/EmisSimulator.h"
#include "sim/PtyEndpoint.h"
#include "transport/SerialTransport.h"
#include <QDeadlineTimer>
#include <QtTest>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::emis;

class TestEmisEndToEnd : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void arrivalsIncludingXonXoff_passTheRealPort();
    void storeProgramAndOutputs_overTheRealPort();
    void peerVanishesWhileMoving_motionUnconfirmedReportedOnce();
    void registrySession_connectsAndMoves();

private:
    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs = 5000);
    void connectController();

    std::unique_ptr<PtyEndpoint> m_device;
    std::unique_ptr<EmisSimulator> m_sim;
    std::unique_ptr<SerialTransport> m_port;
    std::unique_ptr<EmisController> m_ctl;
    RequestId m_nextId = 0;
};

void TestEmisEndToEnd::init()
{
    m_device = std::make_unique<PtyEndpoint>();
    QString error;
    QVERIFY2(m_device->create(&error), qPrintable(error));
    m_sim = std::make_unique<EmisSimulator>(SimulatorOptions{});
    m_device->open(lineSettings());
    m_sim->attach(m_device.get());
    // Quick motion, set on the simulator directly: these tests are about the link.
    m_sim->receive("#R20\r#S500\r#E1,4000\r#E9,4000\r");
}

void TestEmisEndToEnd::cleanup()
{
    m_ctl.reset();
    m_port.reset();
    m_sim.reset();
    m_device.reset();
}

void TestEmisEndToEnd::connectController()
{
    m_port = std::make_unique<SerialTransport>(m_device->slavePath());
    ControllerOptions co;
    co.pollIntervalMs = 20;
    co.commandTimeoutMs = 500; // the machine may be busy: the link is what is tested here
    m_ctl = std::make_unique<EmisController>(m_port.get(), co);
    const CommandResult r = run([this](RequestId id) { m_ctl->openLink(id); });
    QVERIFY2(r.ok(), qPrintable(r.message));
}

CommandResult TestEmisEndToEnd::run(const std::function<void(RequestId)>& call, int timeoutMs)
{
    const RequestId id = ++m_nextId;
    QSignalSpy spy(m_ctl.get(), &Controller::requestFinished);
    call(id);
    auto find = [&]() -> std::optional<CommandResult> {
        for (const auto& args : spy) {
            const auto r = args.at(0).value<CommandResult>();
            if (r.id == id)
                return r;
        }
        return std::nullopt;
    };
    QDeadlineTimer deadline(timeoutMs);
    while (!find() && !deadline.hasExpired())
        spy.wait(int(qMax<qint64>(1, deadline.remainingTime())));
    return find().value_or(CommandResult::failure(id, ErrorKind::Timeout, "test timeout"));
}

void TestEmisEndToEnd::arrivalsIncludingXonXoff_passTheRealPort()
{
    connectController();
    QCOMPARE(m_ctl->status().deviceFirmware, QStringLiteral("SMC-IC4 v1.07"));
    const AxisVector steps{{Axis::X, 120}, {Axis::Y, -80}, {Axis::Z, 60}, {Axis::U, 40}};
    QVERIFY(run([&](RequestId id) { m_ctl->moveRelative(id, steps); }).ok());
    QTRY_VERIFY(!m_ctl->status().anyMoving());
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        QCOMPARE(m_ctl->status().axes.value(it.key()).position, it.value());
        QCOMPARE(m_sim->position(it.key()), it.value());
    }
    QVERIFY(!m_ctl->status().motionUnconfirmed);
    QVERIFY(run([&](RequestId id) { m_ctl->reference(id, {{Axis::X, 1}, {Axis::Z, 1}}); }).ok());
    QTRY_VERIFY(m_ctl->status().axes.value(Axis::Z).positionKnown);
    QVERIFY(run([&](RequestId id) { m_ctl->moveAbsolute(id, {{Axis::Z, -30}}); }).ok());
    QTRY_VERIFY(!m_ctl->status().anyMoving());
    QCOMPARE(m_sim->position(Axis::Z), -30);
    QVERIFY(m_sim->receivedCommands().contains("L1,Z-30"));
}

void TestEmisEndToEnd::storeProgramAndOutputs_overTheRealPort()
{
    connectController();
    ParameterSet set{{"ramp", ParameterValue{150, {}}}};
    QVERIFY(run([&](RequestId id) {
                m_ctl->modelOperation(id, "store-parameters",
                                      {{"parameters", QVariant::fromValue(set)}});
            }).ok());
    QCOMPARE(m_sim->storedEntries().size(), 1);
    QVERIFY(run([&](RequestId id) {
                m_ctl->modelOperation(id, "write-input-program",
                                      {{"input", 7},
                                       {"title", "Eingang 7: Referenzfahrt X-Motor"},
                                       {"commands", QStringList{"$H,x"}}});
            }).ok());
    QCOMPARE(m_sim->program(7)->title, QByteArray("Eingang 7: Referenzfahrt X-Motor"));
    QVERIFY(run([&](RequestId id) {
                m_ctl->modelOperation(id, "set-output", {{"output", 7}, {"on", true}});
            }).ok());
    QVERIFY(m_sim->output(7));
    const CommandResult stored =
        run([&](RequestId id) { m_ctl->modelOperation(id, "read-stored-parameters", {}); });
    QVERIFY(stored.ok());
    QCOMPARE(stored.value.toMap().value("parameters").value<ParameterSet>().value("ramp").global,
             QVariant(qint64(150)));
}

void TestEmisEndToEnd::peerVanishesWhileMoving_motionUnconfirmedReportedOnce()
{
    connectController();
    // Slow, so the move is still running when the cable goes.
    QVERIFY(run([&](RequestId id) { m_ctl->sendRaw(id, "#E1,200\r"); }).ok());
    QSignalSpy errors(m_ctl.get(), &Controller::errorOccurred);
    QVERIFY(run([&](RequestId id) { m_ctl->moveRelative(id, {{Axis::Y, 2000}}); }).ok());
    m_device->vanish();
    QTRY_COMPARE(m_ctl->linkState(), LinkState::Lost);
    QVERIFY(m_ctl->status().motionUnconfirmed);
    QVERIFY(!m_ctl->status().axes.value(Axis::Y).positionKnown);
    QTRY_COMPARE(errors.size(), 1);
    QVERIFY(stepdeck::test::staysQuiet(errors, 200)); // reported once
    QVERIFY(!m_port->isOpen());
}

void TestEmisEndToEnd::registrySession_connectsAndMoves()
{
    const ModelInfo* model = findModel("emis");
    QVERIFY(model);
    QCOMPARE(model->line.baudRate, 115200);
    QVERIFY(!model->capabilities.stopCommand);
    ControllerSession session;
    ConnectionSpec spec;
    spec.port = m_device->slavePath();
    spec.options.pollIntervalMs = 20;
    QString error;
    QVERIFY2(session.create(*model, spec, &error), qPrintable(error));
    QSignalSpy finished(&session, &ControllerSession::requestFinished);
    session.open();
    QTRY_COMPARE(session.linkState(), LinkState::Connected);
    const RequestId stop = session.stop();
    QTRY_VERIFY(std::any_of(finished.cbegin(), finished.cend(), [stop](const QList<QVariant>& a) {
        const auto r = a.at(0).value<CommandResult>();
        return r.id == stop && r.error == ErrorKind::Unsupported;
    }));
    session.moveRelative({{Axis::U, 50}});
    QTRY_COMPARE(session.status().axes.value(Axis::U).position, 50);
    QCOMPARE(m_sim->position(Axis::U), 50);
    QVERIFY(session.status().inputs.has_value());
    session.close();
    session.destroy();
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisEndToEnd)
#include "tst_emis_e2e.moc"
