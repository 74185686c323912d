#pragma once
// The laser bridge end to end: a scripted laser on the master of a real pseudo-terminal, the
// bridge on its slave through QSerialPort (SerialTransport, 9600 8N1), and behind it a model's
// simulator in a ControllerSession: in the session's thread (port "sim", connectController) or
// on a second pseudo-terminal in the test's thread (connectControllerOnPty), so both links run
// through real serial ports. Tests assert the frames the laser got and what the simulated
// device did.
#include "TestSupport.h"
#include "bridge/LaserBridge.h"
#include "controller/ControllerSession.h"
#include "protocols/Registry.h"
#include "protocols/laser/LaserCodec.h"
#include "sim/PtyEndpoint.h"
#include "transport/SerialTransport.h"
#include <QtTest>
#include <atomic>
#include <memory>

namespace stepdeck::test {

using bridge::LaserBridge;
using bridge::LaserBridgeConfig;

class LaserBridgeRig
{
public:
    LaserBridgeRig() = default;
    ~LaserBridgeRig()
    {
        bridge.reset();
        laserPort.reset();
        laserEnd.reset();
        if (ptySim && session) {
            // The simulator answers the close's safety stop from this thread: let it, rather
            // than block in the session's destructor until its wait runs out.
            session->close();
            if (!QTest::qWaitFor([this] { return session->linkState() == LinkState::Disconnected; },
                                 3000))
                qWarning() << "the controller did not close";
        }
        session.reset();
        ptySim.reset();
        controllerEnd.reset();
    }

    // The controller behind, connected (E-LAB: ramps written so it moves at all).
    bool connectController(const QString& modelId, int maxSpeed = 4000,
                           const ControllerOptions& options = {})
    {
        ConnectionSpec spec;
        spec.port = QStringLiteral("sim");
        spec.options = options;
        return connectSession(modelId, spec, maxSpeed);
    }

    // The model's simulator on the device side of a second pseudo-terminal (ptySim, in this
    // thread), the controller on its slave through QSerialPort, connected.
    bool connectControllerOnPty(const QString& modelId, const ControllerOptions& options = {})
    {
        const ModelInfo* model = findModel(modelId);
        if (!model)
            return false;
        controllerEnd = std::make_unique<PtyEndpoint>();
        if (!controllerEnd->create())
            return false;
        SimulatorOptions simOptions;
        simOptions.line = model->line;
        ptySim.reset(model->createSimulator(simOptions));
        controllerEnd->open(model->line);
        ptySim->attach(controllerEnd.get());
        ConnectionSpec spec;
        spec.port = controllerEnd->slavePath();
        spec.options = options;
        return connectSession(modelId, spec, 4000);
    }

    template <typename Sim> Sim* simOnPty() const { return static_cast<Sim*>(ptySim.get()); }

    bool connectSession(const QString& modelId, const ConnectionSpec& spec, int maxSpeed)
    {
        session = std::make_unique<ControllerSession>();
        QString error;
        const ModelInfo* model = findModel(modelId);
        if (!model || !session->create(*model, spec, &error))
            return false;
        QObject::connect(session.get(), &ControllerSession::requestFinished, session.get(),
                         [this](const CommandResult& r) { results.insert(r.id, r); });
        QObject::connect(session.get(), &ControllerSession::traffic, session.get(),
                         [this](const TrafficRecord& r) {
                             if (r.direction == TrafficRecord::Direction::Out)
                                 toController += r.bytes;
                         });
        if (!waitOk(session->open()))
            return false;
        if (modelId == QLatin1String("elab"))
            return waitOk(session->writeParameters(elabRamps(maxSpeed), false));
        return true;
    }

    static ParameterSet elabRamps(qint64 maxSpeed)
    {
        auto perAxis = [](qint64 v) {
            ParameterValue value;
            for (Axis a : {Axis::X, Axis::Y, Axis::Z})
                value.perAxis.insert(a, v);
            return value;
        };
        return {{QStringLiteral("start-speed"), perAxis(200)},
                {QStringLiteral("max-speed"), perAxis(maxSpeed)},
                {QStringLiteral("acceleration"), perAxis(20000)},
                {QStringLiteral("feed-speed"), perAxis(50)}};
    }

    bool waitOk(RequestId id, int timeoutMs = 5000)
    {
        QElapsedTimer t;
        t.start();
        while (!results.contains(id) && t.elapsed() < timeoutMs)
            QTest::qWait(5);
        if (results.contains(id) && !results.value(id).ok())
            qWarning() << "request failed:" << results.value(id).message;
        return results.contains(id) && results.value(id).ok();
    }

    // Runs fn on the in-process simulator in the controller thread and waits for it.
    template <typename Sim> bool onSim(std::function<void(Sim*)> fn)
    {
        auto done = std::make_shared<std::atomic_bool>(false);
        session->withSimulator([fn, done](Simulator* s) {
            fn(static_cast<Sim*>(s));
            *done = true;
        });
        QElapsedTimer t;
        t.start();
        while (!*done && t.elapsed() < 5000)
            QTest::qWait(2);
        return *done;
    }

    // The laser's pty and the bridge on its other end.
    bool startBridge(const LaserBridgeConfig& config = {})
    {
        laserEnd = std::make_unique<PtyEndpoint>();
        QString error;
        if (!laserEnd->create(&error))
            return false;
        laserEnd->open({});
        QObject::connect(laserEnd.get(), &Transport::dataReceived, laserEnd.get(),
                         [this](const QByteArray& b) { fromBridge += b; });
        laserPort = std::make_unique<SerialTransport>(laserEnd->slavePath());
        bridge = std::make_unique<LaserBridge>(session.get(), laserPort.get(), config);
        QObject::connect(bridge.get(), &LaserBridge::logged, bridge.get(),
                         [this](const LaserBridge::LogEntry& e) { log << e; });
        QSignalSpy started(bridge.get(), &LaserBridge::started);
        bridge->start();
        return started.count() > 0 || started.wait(5000);
    }

    void laserSends(const QByteArray& bytes) { laserEnd->write(bytes); }

    // True if the bridge sent the laser nothing within ms.
    bool laserQuiet(int ms)
    {
        QSignalSpy spy(laserEnd.get(), &Transport::dataReceived);
        return test::staysQuiet(spy, ms);
    }

    QList<laser::StatusFrame> answers() const
    {
        laser::StatusDecoder decoder;
        QList<laser::StatusFrame> out;
        for (const laser::DecodedStatus& d : decoder.feed(fromBridge)) {
            if (d.ok())
                out << *d.frame;
        }
        return out;
    }

    bool waitAnswers(int count, int timeoutMs = 15000)
    {
        QElapsedTimer t;
        t.start();
        while (answers().size() < count && t.elapsed() < timeoutMs)
            QTest::qWait(10);
        return answers().size() >= count;
    }

    int logCount(LaserBridge::LogEntry::Kind kind, const QString& containing = {}) const
    {
        int n = 0;
        for (const LaserBridge::LogEntry& e : log)
            n += e.kind == kind && e.text.contains(containing) ? 1 : 0;
        return n;
    }

    std::unique_ptr<PtyEndpoint> controllerEnd; // connectControllerOnPty
    std::unique_ptr<Simulator> ptySim;
    std::unique_ptr<ControllerSession> session;
    std::unique_ptr<PtyEndpoint> laserEnd;
    std::unique_ptr<SerialTransport> laserPort;
    std::unique_ptr<LaserBridge> bridge;
    QHash<RequestId, CommandResult> results;
    QByteArray fromBridge;
    QByteArray toController;
    QList<LaserBridge::LogEntry> log;
};

} // namespace stepdeck::test
