// The poll rate of every model against what its paced wire allows (PollWire.h).
#include "PollWire.h"
#include "BenchDevice.h"
#include "BenchHost.h"
#include "Measurements.h"
#include "protocols/Registry.h"
#include <QJsonValue>
#include <cmath>

namespace stepdeck::bench {

void WireCounter::requestCharArrived()
{
    ++m_requests;
    if (m_repliesQueued.load() > m_repliesDelivered.load())
        ++m_overlapped;
}

WireCounter::Tally WireCounter::tally() const
{
    Tally t;
    t.requestChars = m_requests.load();
    t.replyChars = m_repliesDelivered.load();
    t.overlappedChars = m_overlapped.load();
    return t;
}

std::optional<double> PollWireFigure::ratio() const
{
    if (!hz || !limitHz || *limitHz <= 0)
        return std::nullopt;
    return *hz / *limitHz;
}

namespace {
// The link's own set-up (identification, caches) stays out of the window, and the poller has
// a full second behind its own rate report.
constexpr int kWarmUpMs = 1000;

struct PollWireCase
{
    const char* key;
    const char* modelId;
    int drives; // multi-drive models: drives on the bus, one per axis; else 0
};

// Issue 21 asks for 1, 3 and 8 Nanotec drives (issue 32: a controller's axes are indices, so
// eight drives are eight axes of one link).
constexpr PollWireCase kCases[] = {
    {"elab", "elab", 0},        {"nanotec1", "nanotec", 1}, {"nanotec3", "nanotec", 3},
    {"nanotec4", "nanotec", 4}, {"nanotec8", "nanotec", 8}, {"emis", "emis", 0},
};

// Axis -> bus address for `drives` drives at consecutive addresses from the model's lowest.
QMap<Axis, int> busAddresses(const ModelInfo& model, int drives)
{
    QMap<Axis, int> map;
    const int first = qMax(1, model.capabilities.minBusAddress);
    for (int i = 0; i < drives; ++i)
        map.insert(Axis::at(i), first + i);
    return map;
}

// A completed poll as the host saw it (the adapter publishes its status once per poll) and
// what the wire had carried by then.
struct Completion
{
    qint64 ns = 0;
    WireCounter::Tally tally;
};

// From the first to the last completion of the window: whole polls, and the characters they
// put on the critical path (a poll's last reply has arrived when it completes).
void evaluate(const QList<Completion>& completions, PollWireFigure* f)
{
    if (completions.size() < 3) {
        f->note = QStringLiteral("%1 polls completed in the window").arg(completions.size());
        return;
    }
    const int polls = int(completions.size()) - 1;
    const double seconds = double(completions.last().ns - completions.first().ns) / 1e9;
    const qint64 chars =
        completions.last().tally.criticalChars() - completions.first().tally.criticalChars();
    f->polls = polls;
    f->hz = polls / seconds;
    f->charsPerPoll = double(chars) / polls;
    if (chars > 0)
        f->limitHz = 1e6 / (*f->charsPerPoll * f->characterUs);
}

// The device and host of one case, connected; empty on success, else why not.
QString connectCase(const ModelInfo& model, const QMap<Axis, int>& addresses, BenchDevice* device,
                    BenchHost* host)
{
    QString error;
    if (!device->start(&error))
        return QStringLiteral("simulator: %1").arg(error);
    host->setAxisAddresses(addresses);
    if (!host->connectTo(model, device->slavePath(), {kPollIntervalMs, 0, 5000}, &error))
        return QStringLiteral("connect: %1").arg(error);
    return {};
}

PollWireFigure measureCase(const PollWireCase& c, int windowMs)
{
    PollWireFigure f;
    f.key = QLatin1String(c.key);
    f.drives = c.drives;
    const ModelInfo* model = findModel(QLatin1String(c.modelId));
    if (!model || !model->createSimulator) {
        f.note = QStringLiteral("model %1 is not built in").arg(QLatin1String(c.modelId));
        return f;
    }
    f.line = model->line.text();
    f.characterUs = model->line.characterTimeUs();
    const QMap<Axis, int> addresses = busAddresses(*model, c.drives);
    WireCounter counter; // outlives the device, which counts into it
    BenchDevice::Config config;
    config.paced = true;
    config.wireCounter = &counter;
    config.addresses = addresses.values();
    BenchDevice device(*model, config);
    BenchHost host;
    if (f.note = connectCase(*model, addresses, &device, &host); !f.note.isEmpty())
        return f;
    host.idle(kWarmUpMs);
    QList<Completion> completions;
    const QMetaObject::Connection counting =
        QObject::connect(&host.session(), &ControllerSession::statusChanged, &host, [&] {
            completions << Completion{nowNs(), counter.tally()};
        });
    host.idle(windowMs);
    QObject::disconnect(counting);
    if (host.pollRateReports() > 0 && host.lastPollRateHz() > 0)
        f.pollerHz = host.lastPollRateHz();
    if (!host.connected())
        f.note = QStringLiteral("the link was lost during the window");
    else
        evaluate(completions, &f);
    host.disconnect();
    return f;
}

QString number(const std::optional<double>& value, int decimals)
{
    return value ? QString::number(*value, 'f', decimals) : QStringLiteral("n/a");
}
} // namespace

QList<PollWireFigure> measurePollWire(int windowMs)
{
    QList<PollWireFigure> figures;
    for (const PollWireCase& c : kCases)
        figures << measureCase(c, windowMs);
    return figures;
}

QJsonObject pollWireJson(const QList<PollWireFigure>& figures)
{
    QJsonObject out;
    for (const PollWireFigure& f : figures) {
        QJsonObject o{{"hz", roundedJson(f.hz, 1)},
                      {"limitHz", roundedJson(f.limitHz, 1)},
                      {"ratio", roundedJson(f.ratio(), 3)},
                      {"charsPerPoll", roundedJson(f.charsPerPoll, 2)},
                      {"characterUs", roundedJson(f.characterUs, 2)},
                      {"polls", f.polls},
                      {"pollerHz", roundedJson(f.pollerHz, 1)},
                      {"line", f.line}};
        if (f.drives > 0)
            o.insert("drives", f.drives);
        if (!f.note.isEmpty())
            o.insert("note", f.note);
        out.insert(f.key, o);
    }
    return out;
}

QStringList pollWireText(const QList<PollWireFigure>& figures)
{
    QStringList lines{QStringLiteral("  poll against the paced wire (limit = 1 / (characters per "
                                     "poll x character time), ratio = achieved / limit):")};
    for (const PollWireFigure& f : figures) {
        QString line = QStringLiteral("    %1 %2").arg(f.key, -9).arg(f.line, -11);
        if (f.charsPerPoll && f.limitHz) {
            line += QStringLiteral("%1 chars x %2 us -> limit %3 Hz; achieved %4 Hz = %5 %  "
                                   "(%6 polls; the poller's report %7 Hz)")
                        .arg(number(f.charsPerPoll, 2), number(f.characterUs, 1),
                             number(f.limitHz, 1), number(f.hz, 1))
                        .arg(f.ratio() ? number(*f.ratio() * 100, 1) : QStringLiteral("n/a"))
                        .arg(f.polls)
                        .arg(number(f.pollerHz, 0));
        }
        if (!f.note.isEmpty())
            line += QStringLiteral(" n/a (%1)").arg(f.note);
        lines << line;
    }
    return lines;
}

} // namespace stepdeck::bench
