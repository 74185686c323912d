#include "Replug.h"
#include "BenchDevice.h"
#include "BenchHost.h"
#include <QElapsedTimer>
#include <QJsonArray>
#include <QRandomGenerator>
#include <algorithm>

namespace stepdeck::bench {

namespace {
const QStringList kPhases{"poll", "jog", "stream", "write"};
constexpr int kNoticeBoundMs = 2000;

struct Stats
{
    double min = 0, median = 0, max = 0;
    int over100 = 0;
};

Stats stats(QList<double> v)
{
    Stats s;
    if (v.isEmpty())
        return s;
    std::sort(v.begin(), v.end());
    s.min = v.first();
    s.max = v.last();
    s.median = v.at(v.size() / 2);
    s.over100 = int(std::count_if(v.cbegin(), v.cend(), [](double x) { return x > 100; }));
    return s;
}

// Starts the phase's activity on a connected host; the vanish follows while it runs.
void startActivity(const QString& phase, BenchHost& host, const SoakProfile& profile,
                   QRandomGenerator& rng)
{
    ControllerSession& s = host.session();
    const Capabilities caps = s.capabilities();
    if (phase == QLatin1String("poll")) {
        host.idle(50 + int(rng.bounded(100))); // the poller runs; nothing else
    } else if (phase == QLatin1String("jog")) {
        for (int i = 0; i < 2; ++i) {
            s.setJogVelocity({{caps.axes.first(), 1500.0}});
            host.idle(60);
        }
        s.setJogVelocity({{caps.axes.first(), 1500.0}});
    } else if (phase == QLatin1String("stream")) {
        if (caps.motionModes.contains(MotionMode::FeedStream)) {
            s.feedStream(QVector<AxisVector>(20000, AxisVector{{caps.axes.first(), 1}}));
        } else {
            s.moveRelative({{caps.axes.first(), 200000}});
        }
        host.idle(30 + int(rng.bounded(50)));
    } else {
        s.writeParameters(profile.setup, !profile.readable.isEmpty());
    }
}
} // namespace

ReplugFigures runReplug(const ModelInfo& model, int cycles, quint32 seed,
                        const std::function<void(const QString&)>& progress)
{
    ReplugFigures fig;
    fig.model = model.id;
    fig.cycles = cycles;
    QElapsedTimer clock;
    clock.start();
    QRandomGenerator rng(seed);
    BenchDevice device(model, BenchDevice::soakConfig(model, seed));
    BenchHost host;
    QString error;
    if (!device.start(&error)) {
        ++fig.reconnectFailures;
        return fig;
    }
    for (int i = 0; i < cycles; ++i) {
        const QString phase = kPhases.at(i % kPhases.size());
        if ((!device.present() && !device.reappear(&error)) ||
            !host.connectTo(model, device.slavePath(), BenchHost::soakOptions(), &error)) {
            ++fig.reconnectFailures;
            host.disconnect();
            continue;
        }
        fig.axesMovingAfterReconnect += device.movingAxes().size();
        device.halt();
        if (!model.soak.setup.isEmpty()) {
            host.call(
                [&](ControllerSession& s) { return s.writeParameters(model.soak.setup, false); });
        }
        startActivity(phase, host, model.soak, rng);
        if (phase == QLatin1String("write"))
            device.vanishLater(int(rng.bounded(3))); // while the write is on the line
        else
            device.vanish();
        if (host.waitUntil([&] { return host.linkLeftNs() >= 0 && device.lastVanishNs() >= 0; },
                           kNoticeBoundMs)) {
            fig.latencyMs[phase] << (host.linkLeftNs() - device.lastVanishNs()) / 1e6;
        } else {
            ++fig.notNoticed;
        }
        host.disconnect(); // the device keeps what it was told; the next cycle counts it
        if (progress && (i + 1) % 20 == 0)
            progress(QStringLiteral("%1: %2/%3 replugs").arg(model.id).arg(i + 1).arg(cycles));
    }
    fig.seconds = clock.elapsed() / 1000.0;
    return fig;
}

QJsonObject ReplugFigures::toJson() const
{
    QJsonObject phases;
    QList<double> all;
    for (auto it = latencyMs.cbegin(); it != latencyMs.cend(); ++it) {
        const Stats s = stats(it.value());
        all += it.value();
        phases.insert(it.key(), QJsonObject{{"samples", it.value().size()},
                                            {"minMs", s.min},
                                            {"medianMs", s.median},
                                            {"maxMs", s.max},
                                            {"over100Ms", s.over100}});
    }
    const Stats s = stats(all);
    return QJsonObject{{"model", model},
                       {"cycles", cycles},
                       {"samples", all.size()},
                       {"minMs", s.min},
                       {"medianMs", s.median},
                       {"maxMs", s.max},
                       {"over100Ms", s.over100},
                       {"notNoticed", notNoticed},
                       {"reconnectFailures", reconnectFailures},
                       {"axesMovingAfterReconnect", axesMovingAfterReconnect},
                       {"byPhase", phases},
                       {"seconds", seconds}};
}

QString ReplugFigures::toText() const
{
    QStringList lines;
    QList<double> all;
    for (auto it = latencyMs.cbegin(); it != latencyMs.cend(); ++it) {
        const Stats s = stats(it.value());
        all += it.value();
        lines << QStringLiteral("  mid-%1: %2 samples, disconnected shown after min %3 / median "
                                "%4 / max %5 ms, %6 over 100 ms")
                     .arg(it.key())
                     .arg(it.value().size())
                     .arg(s.min, 0, 'f', 2)
                     .arg(s.median, 0, 'f', 2)
                     .arg(s.max, 0, 'f', 2)
                     .arg(s.over100);
    }
    const Stats s = stats(all);
    lines.prepend(QStringLiteral("%1: %2 replugs in %3 s; disconnected shown after min %4 / "
                                 "median %5 / max %6 ms, %7 over 100 ms; not noticed %8; "
                                 "reconnect failures %9; axes found moving at reconnect %10")
                      .arg(model)
                      .arg(cycles)
                      .arg(seconds, 0, 'f', 1)
                      .arg(s.min, 0, 'f', 2)
                      .arg(s.median, 0, 'f', 2)
                      .arg(s.max, 0, 'f', 2)
                      .arg(s.over100)
                      .arg(notNoticed)
                      .arg(reconnectFailures)
                      .arg(axesMovingAfterReconnect));
    return lines.join(QLatin1Char('\n'));
}

} // namespace stepdeck::bench
