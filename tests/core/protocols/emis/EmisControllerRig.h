#pragma once
// EmisController against the in-process EmisSimulator over LoopbackTransport (header-only).
#include "protocols/emis/EmisController.h"
#include "protocols/emis/EmisModel.h"
#include "protocols/emis/EmisSimulator.h"
#include "transport/LoopbackTransport.h"
#include <QDeadlineTimer>
#include <QSignalSpy>
#include <QtTest>

namespace stepdeck::test {

struct EmisRig
{
    QObject* owner = nullptr;
    LoopbackTransport* host = nullptr;
    emis::EmisSimulator* sim = nullptr;
    emis::EmisController* ctl = nullptr;
    RequestId nextId = 0;

    static ControllerOptions defaults()
    {
        ControllerOptions co;
        co.pollIntervalMs = 20;
        co.commandTimeoutMs = 100;
        co.missedPollsForLinkLoss = 3;
        return co;
    }

    // Builds the stack and connects; false when the connect failed.
    bool setUp(const ControllerOptions& co = defaults())
    {
        owner = new QObject;
        auto [h, device] = LoopbackTransport::createPair(owner);
        host = h;
        sim = new emis::EmisSimulator(SimulatorOptions{}, owner);
        device->open(emis::lineSettings());
        sim->attach(device);
        ctl = new emis::EmisController(host, co, owner);
        return run([this](RequestId id) { ctl->openLink(id); }).ok();
    }
    void tearDown()
    {
        delete owner;
        owner = nullptr;
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
        QDeadlineTimer deadline(timeoutMs);
        while (!find() && !deadline.hasExpired())
            spy.wait(int(qMax<qint64>(1, deadline.remainingTime())));
        return find().value_or(CommandResult::failure(id, ErrorKind::Timeout, "test timeout"));
    }
    CommandResult operation(const QString& name, const QVariantMap& args = {})
    {
        return run([&](RequestId id) { ctl->modelOperation(id, name, args); });
    }
    CommandResult write(const QStringList& assignments)
    {
        ParameterSet set;
        const ParameterSchema schema = emis::parameterSchema();
        for (const QString& a : assignments) {
            QString name, error;
            ParameterValue value;
            if (!schema.parseAssignment(a, letterAxes(), &name, &value, &error))
                return CommandResult::failure(0, ErrorKind::InvalidValue, error);
            set.insert(name, value);
        }
        return run([&](RequestId id) { ctl->writeParameters(id, set, true); });
    }

    // What the device saw, without the status polls.
    QList<QByteArray> commands() const
    {
        QList<QByteArray> out;
        for (const QByteArray& c : sim->receivedCommands()) {
            if (c != "@IG")
                out << c;
        }
        return out;
    }
    QList<QByteArray> commandsStartingWith(const QByteArray& prefix) const
    {
        QList<QByteArray> out;
        for (const QByteArray& c : commands()) {
            if (c.startsWith(prefix))
                out << c;
        }
        return out;
    }
    const AxisStatus axis(Axis a) const { return ctl->status().axes.value(a); }
    bool anyMoving() const { return ctl->status().anyMoving(); }
};

} // namespace stepdeck::test
