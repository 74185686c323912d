#include "MachineStopLatency.h"
#include "BenchDevice.h"
#include "EventWait.h"
#include "machine/Machine.h"
#include "model/ModelInfo.h"
#include "sim/TrafficMeter.h"
#include <QtMath>
#include <algorithm>
#include <memory>
#include <vector>

namespace stepdeck::bench {

namespace {
const char* const kMachineAxes[] = {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"};

// Controller i drives machine axis kMachineAxes[i] with its first axis, counted in steps.
machine::MachineDescription describe(const ModelInfo& model,
                                     const std::vector<std::unique_ptr<BenchDevice>>& devices)
{
    machine::MachineDescription d;
    d.name = QStringLiteral("bench");
    for (size_t i = 0; i < devices.size(); ++i) {
        machine::MachineController c;
        c.id = QStringLiteral("c%1").arg(i + 1);
        c.modelId = model.id;
        c.port = devices[i]->slavePath();
        d.controllers << c;
        machine::MachineAxis a;
        a.name = QLatin1String(kMachineAxes[i]);
        a.controller = c.id;
        a.axis = model.capabilities.axes.first();
        d.axes << a;
    }
    return d;
}

// The simulator powers on as set up (a move needs no parameter writes first). Its thread runs
// real-time where the system allows it, as for the panic figure: N simulated boards stand for
// N boards with CPUs of their own, so the figure shows the host's delay in reaching them, not
// N simulators queueing for the bench machine's two cores behind the host's threads.
BenchDevice::Config deviceConfig(const ModelInfo& model, quint32 seed)
{
    BenchDevice::Config config;
    config.seed = seed;
    config.metered = true;
    config.realtime = true;
    config.prepare = [&model](Simulator* sim) {
        SimulatorScenario scenario;
        scenario.setupComplete = true;
        QString ignored;
        if (model.scenario.apply && model.scenario.options.testFlag(ScenarioOption::SetupComplete))
            model.scenario.apply(scenario, sim, &ignored);
    };
    return config;
}

bool allMoving(const std::vector<std::unique_ptr<BenchDevice>>& devices)
{
    return std::all_of(devices.begin(), devices.end(),
                       [](const auto& d) { return !d->movingAxes().isEmpty(); });
}

bool allStill(const std::vector<std::unique_ptr<BenchDevice>>& devices)
{
    return std::all_of(devices.begin(), devices.end(),
                       [](const auto& d) { return d->movingAxes().isEmpty(); });
}

// One run: every controller in a long move, then Machine::stop(). Milliseconds until the
// last device saw its stop, or a note why there is no sample.
std::optional<double> stopOnce(machine::Machine& m,
                               const std::vector<std::unique_ptr<BenchDevice>>& devices,
                               QString* note)
{
    for (const auto& d : devices)
        d->meter()->reset();
    QMap<QString, double> targets;
    for (const machine::MachineAxis& a : m.description().axes)
        targets.insert(a.name, 1000000);
    QString refusal;
    if (m.move(targets, false, &refusal) == 0) {
        *note = QStringLiteral("move refused: %1").arg(refusal);
        return std::nullopt;
    }
    if (!waitUntil([&] { return allMoving(devices); }, 3000)) {
        *note = QStringLiteral("the devices did not start moving");
        return std::nullopt;
    }
    const qint64 calledNs = nowNs();
    m.stop();
    const auto seen = [&] {
        return std::all_of(devices.begin(), devices.end(),
                           [](const auto& d) { return d->meter()->stopSeenNs() >= 0; });
    };
    if (!waitUntil(seen, 2000)) {
        *note = QStringLiteral("a stop did not arrive within 2 s");
        return std::nullopt;
    }
    qint64 last = 0;
    for (const auto& d : devices)
        last = qMax(last, d->meter()->stopSeenNs());
    waitUntil([&] { return allStill(devices); }, 5000); // the next run starts from rest
    return double(last - calledNs) / 1e6;
}
} // namespace

LatencyFigure measureMachineStopLatency(const ModelInfo& model, int controllers, int repetitions)
{
    LatencyFigure figure;
    std::vector<std::unique_ptr<BenchDevice>> devices;
    for (int i = 0; i < controllers; ++i) {
        devices.push_back(
            std::make_unique<BenchDevice>(model, deviceConfig(model, quint32(i + 1))));
        if (!devices.back()->start(&figure.note))
            return figure;
    }
    machine::Machine m;
    if (!m.create(describe(model, devices), &figure.note))
        return figure;
    m.open();
    if (!waitUntil([&] { return m.state() == machine::MachineState::Idle; }, 5000)) {
        figure.note = QStringLiteral("the controllers did not connect");
        return figure;
    }
    QList<double> samples;
    for (int i = 0; i < repetitions; ++i) {
        if (const std::optional<double> ms = stopOnce(m, devices, &figure.note))
            samples << *ms;
    }
    m.destroy(); // before the devices: every session stops and closes its link
    figure.deviceRealtime =
        std::all_of(devices.begin(), devices.end(), [](const auto& d) { return d->realtime(); });
    figure.samples = int(samples.size());
    if (!samples.isEmpty()) {
        figure.medianMs = median(samples);
        figure.p99Ms = percentile(samples, 0.99);
    }
    return figure;
}

} // namespace stepdeck::bench
