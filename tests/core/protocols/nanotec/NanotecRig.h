#pragma once
// Shared by the NanotecController tests: the adapter against a simulated bus of drives
// 1, 2, 3 (axes X, Y, Z) over an in-memory LoopbackTransport pair, connected.
#include "protocols/nanotec/NanotecController.h"
#include "protocols/nanotec/NanotecModel.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include "transport/LoopbackTransport.h"
#include <QDeadlineTimer>
#include <QSignalSpy>
#include <QtTest>
#include <memory>

namespace nanotectest {

using namespace stepdeck;
using namespace stepdeck::nanotec;

inline ControllerOptions fastOptions()
{
    ControllerOptions co;
    co.axisAddresses = {{Axis::X, 1}, {Axis::Y, 2}, {Axis::Z, 3}};
    co.pollIntervalMs = 20;
    co.commandTimeoutMs = 100;
    co.jogLeaseMs = 5000;
    return co;
}

struct NanotecRig
{
    explicit NanotecRig(const ControllerOptions& co = fastOptions())
    {
        owner = std::make_unique<QObject>();
        auto [h, device] = LoopbackTransport::createPair(owner.get());
        host = h;
        SimulatorOptions so;
        so.addresses = {1, 2, 3};
        sim = new NanotecSimulator(so, owner.get());
        device->open(lineSettings());
        sim->attach(device);
        ctl = new NanotecController(host, co, owner.get());
    }
    bool connect()
    {
        return run([this](RequestId id) { ctl->openLink(id); }).ok() &&
               ctl->linkState() == LinkState::Connected;
    }
    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs = 5000)
    {
        const RequestId id = ++nextId;
        QSignalSpy spy(ctl, &Controller::requestFinished);
        call(id);
        auto find = [&]() -> std::optional<CommandResult> {
            for (const auto& args : spy) {
                const auto r = args.at(0).value<CommandResult>();
                if (r.id == id)
                    return r;
            }
            return std::nullopt;
        };
        // QSignalSpy::wait runs an event loop (QTest::qWaitFor would sleep between rounds).
        QDeadlineTimer deadline(timeoutMs);
        while (!find() && !deadline.hasExpired())
            spy.wait(int(qMax<qint64>(1, deadline.remainingTime())));
        return find().value_or(CommandResult::failure(id, ErrorKind::Timeout, "test timeout"));
    }
    int countFrames(const QByteArray& frame) const
    {
        return int(sim->receivedFrames().count(frame));
    }
    // closeLink() under the safety contract is asynchronous: waits for closeFinished.
    bool close(int timeoutMs = 5000)
    {
        QSignalSpy closed(ctl, &Controller::closeFinished);
        ctl->closeLink();
        return closed.count() == 1 || closed.wait(timeoutMs);
    }

    std::unique_ptr<QObject> owner; // owns link, simulator and controller
    LoopbackTransport* host = nullptr;
    NanotecSimulator* sim = nullptr;
    NanotecController* ctl = nullptr;
    RequestId nextId = 0;
};

} // namespace nanotectest
