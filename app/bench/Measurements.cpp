#include "Measurements.h"
#include "BenchDevice.h"
#include "BenchHost.h"
#include "sim/TrafficMeter.h"
#include <QtMath>
#include <algorithm>
#include <cmath>

namespace stepdeck::bench {

QJsonValue roundedJson(const std::optional<double>& value, int decimals)
{
    if (!value)
        return QJsonValue();
    const double scale = std::pow(10.0, decimals);
    return std::round(*value * scale) / scale;
}

namespace {
QVector<AxisVector> stepStream(int steps)
{
    const AxisVector oneStep{{Axis::X, 1}}; // shared by every element (implicit sharing)
    return QVector<AxisVector>(steps, oneStep);
}

// A device and a connected, set-up host; empty note on success.
QString prepare(const ModelInfo& model, BenchDevice* device, BenchHost* host, int pollIntervalMs,
                bool setup)
{
    QString error;
    if (!device->start(&error))
        return QStringLiteral("simulator: %1").arg(error);
    if (!host->connectTo(model, device->slavePath(), {pollIntervalMs, 0, 3000}, &error))
        return QStringLiteral("connect: %1").arg(error);
    if (setup) {
        const ParameterSet set = setupParameters(model);
        const CommandResult written =
            host->call([&](ControllerSession& s) { return s.writeParameters(set, false); }, 5000)
                .result;
        if (!written.ok())
            return QStringLiteral("setup: %1").arg(written.message);
    }
    return {};
}

} // namespace

ParameterSet setupParameters(const ModelInfo& model)
{
    ParameterSet set;
    for (const QString& name : model.setupBeforeMotion) {
        const ParameterSpec* spec = model.schema.find(name);
        if (!spec)
            continue;
        ParameterValue value;
        for (Axis axis : model.capabilities.axes)
            value.perAxis.insert(axis, spec->defaultValue);
        set.insert(spec->name, value);
    }
    return set;
}

double percentile(QList<double> samples, double fraction)
{
    std::sort(samples.begin(), samples.end());
    // Nearest rank: with 20 samples p99 is the largest one.
    const int rank = qMax(1, int(qCeil(fraction * samples.size())));
    return samples.at(rank - 1);
}

double median(QList<double> samples)
{
    std::sort(samples.begin(), samples.end());
    const qsizetype n = samples.size();
    return n % 2 ? samples.at(n / 2) : (samples.at(n / 2 - 1) + samples.at(n / 2)) / 2.0;
}

Figure measurePollRate(const ModelInfo& model, bool paced)
{
    BenchDevice::Config config;
    config.paced = paced;
    // The device's scheduling is not the host's (a board has its own CPU), as for the panic.
    config.realtime = true;
    BenchDevice device(model, config);
    BenchHost host;
    if (const QString error = prepare(model, &device, &host, kPollIntervalMs, false);
        !error.isEmpty())
        return {std::nullopt, error};
    host.idle(kPollWindowMs);
    if (host.pollRateReports() == 0 || host.lastPollRateHz() <= 0)
        return {std::nullopt, QStringLiteral("the poller reported no rate")};
    return {host.lastPollRateHz(), {}};
}

LatencyFigure measurePanicLatency(const ModelInfo& model, int repetitions, bool deviceRealtime)
{
    const QVector<AxisVector> stream = stepStream(kFeedStreamSteps);
    QList<double> samples;
    LatencyFigure figure;
    figure.deviceRealtime = deviceRealtime;
    for (int i = 0; i < repetitions; ++i) {
        // A fresh device and session each time: after a panic the machine must be set up
        // and referenced again, which is not what is measured here.
        BenchDevice::Config config;
        config.metered = true;
        config.realtime = deviceRealtime;
        BenchDevice device(model, config);
        BenchHost host;
        if (const QString error = prepare(model, &device, &host, 50, true); !error.isEmpty()) {
            figure.note = error;
            break;
        }
        figure.deviceRealtime = figure.deviceRealtime && device.realtime();
        TrafficMeter* meter = device.meter();
        meter->reset();
        host.session().feedStream(stream);
        if (!host.waitUntil([&] { return meter->stepBytes() >= 32; }, 3000)) {
            figure.note = QStringLiteral("the feed stream did not start");
            break;
        }
        // Until the controller's XOFF holds the host back (the stream is paced by the wire, so
        // filling the board's buffer takes its time), at most 1 s.
        bool paused = false;
        host.waitUntil(
            [&] {
                device.withSimulator(
                    [&](Simulator* sim) { paused = model.streamBench.hostPaused(sim); });
                return paused;
            },
            1000);
        figure.pausedByXoff += paused ? 1 : 0;
        const qint64 calledNs = nowNs();
        host.session().panic();
        if (!host.waitUntil([&] { return meter->panicSeenNs() >= 0; }, 2000)) {
            figure.note = QStringLiteral("a panic byte did not arrive within 2 s");
            continue;
        }
        samples << double(meter->panicSeenNs() - calledNs) / 1e6;
    }
    figure.samples = int(samples.size());
    if (!samples.isEmpty()) {
        figure.medianMs = median(samples);
        figure.p99Ms = percentile(samples, 0.99);
    }
    return figure;
}

Figure measureFeedThroughput(const ModelInfo& model, bool paced)
{
    BenchDevice::Config config;
    config.paced = paced;
    config.metered = true;
    config.prepare = model.streamBench.unlimitBuffer;
    BenchDevice device(model, config);
    BenchHost host;
    if (const QString error = prepare(model, &device, &host, 50, true); !error.isEmpty())
        return {std::nullopt, error};
    const TrafficMeter* meter = device.meter();
    device.meter()->reset();
    host.session().feedStream(stepStream(kFeedStreamSteps));
    if (!host.waitUntil([&] { return meter->stepBytes() > 0; }, 3000))
        return {std::nullopt, QStringLiteral("the feed stream did not start")};
    host.waitUntil(
        [&] {
            return meter->stepBytes() >= kFeedStreamSteps ||
                   nowNs() - meter->firstStepNs() >= qint64(kFeedBudgetMs) * 1000000;
        },
        kFeedBudgetMs + 1000);
    const qint64 steps = meter->stepBytes();
    const double seconds = double(meter->lastStepNs() - meter->firstStepNs()) / 1e9;
    host.call([](ControllerSession& s) { return s.panic(); }, 1000); // end the stream
    if (steps < 2 || seconds <= 0)
        return {std::nullopt, QStringLiteral("too few steps arrived")};
    return {double(steps - 1) / seconds, {}};
}

} // namespace stepdeck::bench
