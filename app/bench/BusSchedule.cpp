// A Nanotec bus of many drives, one moving (BusSchedule.h).
#include "BusSchedule.h"
#include "BenchDevice.h"
#include "BenchHost.h"
#include "Measurements.h"
#include "PollWire.h"
#include "protocols/Registry.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include <QJsonValue>
#include <QMutex>
#include <QRegularExpression>
#include <atomic>
#include <cmath>

namespace stepdeck::bench {

namespace {
constexpr int kDriveCounts[] = {8, 32, 254};
constexpr int kPollIntervalMs = 50;      // ControllerOptions' default: what an operator gets
constexpr int kConnectTimeoutMs = 60000; // 254 drives are identified one after the other
constexpr qint64 kMoveSteps = 10000000;  // runs through the whole window

// '$' requests as the device received them, per address, with the time they arrived.
class StatusReads
{
public:
    void record(Simulator* sim, qint64 arrivedNs)
    {
        static const QRegularExpression status(QStringLiteral("^#(\\d+)\\$\\r$"));
        const QList<QByteArray> frames = sim->receivedFrames();
        sim->clearReceivedFrames();
        if (!m_on.load())
            return;
        const QMutexLocker lock(&m_mutex);
        for (const QByteArray& f : frames) {
            const QRegularExpressionMatch m = status.match(QString::fromLatin1(f));
            if (m.hasMatch())
                m_reads[m.captured(1).toInt()] << arrivedNs;
        }
    }
    void setRecording(bool on) { m_on = on; }
    QMap<int, QList<qint64>> reads() const
    {
        const QMutexLocker lock(&m_mutex);
        return m_reads;
    }

private:
    mutable QMutex m_mutex;
    std::atomic<bool> m_on{false};
    QMap<int, QList<qint64>> m_reads;
};

QList<double> gapsMs(const QList<qint64>& times)
{
    QList<double> gaps;
    for (qsizetype i = 1; i < times.size(); ++i)
        gaps << double(times.at(i) - times.at(i - 1)) / 1e6;
    return gaps;
}

void evaluate(const QMap<int, QList<qint64>>& reads, BusScheduleFigure* f)
{
    const QList<double> moving = gapsMs(reads.value(f->movingAddress));
    f->movingReads = int(reads.value(f->movingAddress).size());
    if (moving.size() >= 2) {
        f->movingMedianMs = median(moving);
        f->movingP99Ms = percentile(moving, 0.99);
        f->movingMaxMs = *std::max_element(moving.cbegin(), moving.cend());
    }
    QList<double> rounds;
    for (auto it = reads.cbegin(); it != reads.cend(); ++it) {
        const QList<double> gaps = gapsMs(it.value());
        if (it.key() == f->movingAddress || gaps.isEmpty())
            continue;
        rounds << *std::max_element(gaps.cbegin(), gaps.cend());
    }
    f->idleDrivesRead = int(rounds.size());
    if (!rounds.isEmpty()) {
        f->idleRoundMedianMs = median(rounds);
        f->idleRoundMaxMs = *std::max_element(rounds.cbegin(), rounds.cend());
    }
}

// The paced bus, counting its characters and recording its '$' reads.
BenchDevice::Config deviceConfig(const QList<int>& addresses, WireCounter* counter,
                                 StatusReads* reads)
{
    BenchDevice::Config config;
    config.paced = true;
    config.wireCounter = counter;
    config.addresses = addresses;
    config.received = [reads](Simulator* sim, qint64 ns) { reads->record(sim, ns); };
    // The simulated drives' switches sit at +-3000 steps: far away, the move runs through the
    // window.
    config.prepare = [](Simulator* sim) {
        if (auto* bus = qobject_cast<nanotec::NanotecSimulator*>(sim)) {
            for (nanotec::NanotecDrive* d : bus->drives())
                d->setSwitches(-1e9, 1e9);
        }
    };
    return config;
}

BusScheduleFigure measureBus(const ModelInfo& model, int drives, int windowMs)
{
    BusScheduleFigure f;
    f.drives = drives;
    f.movingAddress = drives / 2;
    QMap<Axis, int> addresses;
    for (int i = 0; i < drives; ++i)
        addresses.insert(Axis::at(i), i + 1);
    WireCounter counter; // outlives the device, which counts into it
    StatusReads reads;
    BenchDevice device(model, deviceConfig(addresses.values(), &counter, &reads));
    BenchHost host;
    QString error;
    if (!device.start(&error)) {
        f.note = QStringLiteral("simulator: %1").arg(error);
        return f;
    }
    host.setAxisAddresses(addresses);
    if (!host.connectTo(model, device.slavePath(), {kPollIntervalMs, 0, kConnectTimeoutMs},
                        &error)) {
        f.note = QStringLiteral("connect: %1").arg(error);
        return f;
    }
    const Axis moving = Axis::at(f.movingAddress - 1);
    const BenchHost::Outcome started = host.call(
        [&](ControllerSession& s) {
            return s.moveRelative({{moving, kMoveSteps}});
        },
        BenchHost::kRequestBoundMs);
    if (!started.finished || !started.result.ok()) {
        f.note = QStringLiteral("the move did not start");
        return f;
    }
    host.idle(500); // the move under way, the poller expedited
    const WireCounter::Tally before = counter.tally();
    const qint64 fromNs = nowNs();
    reads.setRecording(true);
    host.idle(windowMs);
    reads.setRecording(false);
    const WireCounter::Tally after = counter.tally();
    const AxisStatus end = host.session().status().axes.value(moving);
    if (!end.moving)
        f.note = QStringLiteral("the moving drive stood still before the window ended (at %1)")
                     .arg(end.position);
    f.windowMs = double(nowNs() - fromNs) / 1e6;
    const double chars =
        double(after.requestChars + after.replyChars - before.requestChars - before.replyChars);
    f.wireUse = chars / (f.windowMs / 1000.0) / (1e6 / model.line.characterTimeUs());
    evaluate(reads.reads(), &f);
    host.call([](ControllerSession& s) { return s.stop(); }, BenchHost::kRequestBoundMs);
    host.disconnect();
    return f;
}

QString ms(const std::optional<double>& value)
{
    return value ? QString::number(*value, 'f', 1) : QStringLiteral("n/a");
}
} // namespace

QList<BusScheduleFigure> measureBusSchedule(int windowMs)
{
    QList<BusScheduleFigure> figures;
    const ModelInfo* model = findModel(QStringLiteral("nanotec"));
    for (int drives : kDriveCounts) {
        if (!model || !model->createSimulator) {
            BusScheduleFigure f;
            f.drives = drives;
            f.note = QStringLiteral("model nanotec is not built in");
            figures << f;
            continue;
        }
        figures << measureBus(*model, drives, windowMs);
    }
    return figures;
}

QJsonObject busScheduleJson(const QList<BusScheduleFigure>& figures)
{
    QJsonObject out;
    for (const BusScheduleFigure& f : figures) {
        QJsonObject o{{"drives", f.drives},
                      {"movingAddress", f.movingAddress},
                      {"movingReads", f.movingReads},
                      {"movingMedianMs", roundedJson(f.movingMedianMs, 1)},
                      {"movingP99Ms", roundedJson(f.movingP99Ms, 1)},
                      {"movingMaxMs", roundedJson(f.movingMaxMs, 1)},
                      {"idleDrivesRead", f.idleDrivesRead},
                      {"idleRoundMedianMs", roundedJson(f.idleRoundMedianMs, 0)},
                      {"idleRoundMaxMs", roundedJson(f.idleRoundMaxMs, 0)},
                      {"wireUse", roundedJson(f.wireUse, 3)},
                      {"windowMs", roundedJson(f.windowMs, 0)}};
        if (!f.note.isEmpty())
            o.insert("note", f.note);
        out.insert(QStringLiteral("nanotec%1").arg(f.drives), o);
    }
    return out;
}

QStringList busScheduleText(const QList<BusScheduleFigure>& figures)
{
    QStringList lines{QStringLiteral("  a Nanotec bus, one drive moving, 50 ms poll interval "
                                     "(read intervals at the device):")};
    for (const BusScheduleFigure& f : figures) {
        QString line = QStringLiteral("    %1 drives: ").arg(f.drives, 3);
        if (!f.note.isEmpty()) {
            lines << line + QStringLiteral("n/a (%1)").arg(f.note);
            continue;
        }
        line +=
            QStringLiteral("moving drive %1 read every %2 ms (median), p99 %3, longest %4 "
                           "(%5 reads); idle round median %6 ms, longest %7 (%8 of %9 idle "
                           "drives read twice); wire %10 %")
                .arg(f.movingAddress)
                .arg(ms(f.movingMedianMs), ms(f.movingP99Ms), ms(f.movingMaxMs))
                .arg(f.movingReads)
                .arg(ms(f.idleRoundMedianMs), ms(f.idleRoundMaxMs))
                .arg(f.idleDrivesRead)
                .arg(f.drives - 1)
                .arg(f.wireUse ? QString::number(*f.wireUse * 100, 'f', 1) : QStringLiteral("n/a"));
        lines << line;
    }
    return lines;
}

} // namespace stepdeck::bench
