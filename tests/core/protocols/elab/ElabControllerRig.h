#pragma once
// Shared by the ElabController tests: the adapter against the real ElabSimulator over an
// in-memory LoopbackTransport pair, plus small value helpers.
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
#include "ElabTestSupport.h"

using namespace stepdeck;
using namespace stepdeck::elab;
using stepdeck::elab::testing::bytes;
namespace elabtest {

inline ParameterValue perAxis(qint64 x, qint64 y, qint64 z)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}};
    return v;
}

inline ParameterValue perAxis(const QString& all)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, all}, {Axis::Y, all}, {Axis::Z, all}};
    return v;
}

inline ParameterValue global(const QVariant& value)
{
    ParameterValue v;
    v.global = value;
    return v;
}

inline ControllerOptions defaultOptions()
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
    // host: a custom host end (e.g. KernelBufferTransport); the rig owns it.
    explicit Rig(const ControllerOptions& options = defaultOptions(), bool resetLine = false,
                 LoopbackTransport* customHost = nullptr)
    {
        LoopbackTransport* host = customHost  ? customHost
                                  : resetLine ? new ResetLineLoopback
                                              : new LoopbackTransport;
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
    // A new adapter on the same link (a restarted host): fresh spies.
    void replaceController(const ControllerOptions& options)
    {
        ctl = std::make_unique<ElabController>(hostEnd.get(), options);
        results = std::make_unique<QSignalSpy>(ctl.get(), &Controller::requestFinished);
        traffic = std::make_unique<QSignalSpy>(ctl.get(), &Controller::traffic);
        errors = std::make_unique<QSignalSpy>(ctl.get(), &Controller::errorOccurred);
        jogRefusals = std::make_unique<QSignalSpy>(ctl.get(), &Controller::jogRefused);
    }
    // closeLink() under the safety contract is asynchronous: waits for closeFinished.
    bool close(int timeoutMs = 5000)
    {
        QSignalSpy closed(ctl.get(), &Controller::closeFinished);
        ctl->closeLink();
        return closed.count() == 1 || closed.wait(timeoutMs);
    }
    // Renews the jog lease every 50 ms until done() or timeoutMs; false on timeout.
    bool jogUntil(const AxisVelocities& rates, const std::function<bool()>& done,
                  int timeoutMs = 5000)
    {
        QElapsedTimer t;
        t.start();
        while (!done()) {
            if (t.elapsed() > timeoutMs)
                return false;
            ctl->setJogVelocity(rates);
            QSignalSpy(ctl.get(), &Controller::statusChanged).wait(50);
        }
        return true;
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
} // namespace elabtest

using namespace elabtest;
