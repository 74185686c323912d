#pragma once
// One registered model's adapter against its own simulator over an in-memory link, for tests
// that run the same scenario through the generic Controller interface on every model
// (tst_faultmatrix, tst_softlimitsmodels).
#include "controller/Controller.h"
#include "protocols/Registry.h"
#include "sim/Simulator.h"
#include "transport/LoopbackTransport.h"
#include <QDeadlineTimer>
#include <QSignalSpy>
#include <functional>
#include <memory>

namespace stepdeck::test {

// The schema defaults of the parameters a model wants written before it moves at all
// (ModelInfo::setupBeforeMotion, E-LAB tmInvSetup), per axis of the model.
inline ParameterSet setupBeforeMotionDefaults(const ModelInfo& info)
{
    ParameterSet set;
    for (const QString& name : info.setupBeforeMotion) {
        const ParameterSpec* spec = info.schema.find(name);
        ParameterValue v;
        for (Axis a : info.capabilities.axes)
            v.perAxis.insert(a, spec->defaultValue);
        set.insert(name, v);
    }
    return set;
}

struct ModelBench
{
    ModelBench(const ModelInfo* model, int commandTimeoutMs) : info(model)
    {
        auto [h, d] = LoopbackTransport::createPair();
        host.reset(h);
        device.reset(d);
        SimulatorOptions so;
        so.line = info->line;
        so.addresses = {1, 2, 3};
        sim.reset(info->createSimulator(so));
        device->open(info->line);
        sim->attach(device.get());
        ControllerOptions co;
        co.pollIntervalMs = 20;
        co.commandTimeoutMs = commandTimeoutMs;
        co.jogLeaseMs = 2000;
        ctl.reset(info->createController(host.get(), co));
        results = std::make_unique<QSignalSpy>(ctl.get(), &Controller::requestFinished);
    }
    ~ModelBench() { ctl.reset(); } // the controller goes before its transport and simulator

    // Calls call(id) and waits for that request's result (a Timeout failure after timeoutMs).
    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs)
    {
        const RequestId rid = ++nextId;
        call(rid);
        QDeadlineTimer deadline(timeoutMs);
        for (;;) {
            for (const QList<QVariant>& args : *results) {
                const auto r = args.at(0).value<CommandResult>();
                if (r.id == rid)
                    return r;
            }
            if (deadline.hasExpired())
                return CommandResult::failure(rid, ErrorKind::Timeout, "test: no result");
            results->wait(20);
        }
    }

    const ModelInfo* info;
    std::unique_ptr<LoopbackTransport> host;
    std::unique_ptr<LoopbackTransport> device;
    std::unique_ptr<Simulator> sim;
    std::unique_ptr<Controller> ctl;
    std::unique_ptr<QSignalSpy> results;
    RequestId nextId = 0;
};

} // namespace stepdeck::test
