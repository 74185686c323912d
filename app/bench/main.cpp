// stepdeck-bench: figures, never pass/fail (issue #2, section 7; docs/benchmark.md).
#include "BenchOutput.h"
#include "BenchUsage.h"
#include "BusSchedule.h"
#include "BusyLoad.h"
#include "ContourBench.h"
#include "GuiIdle.h"
#include "JogLatency.h"
#include "MachineStopLatency.h"
#include "Measurements.h"
#include "PollWire.h"
#include "PreviewFrameBench.h"
#include "ProgramBench.h"
#include "ProgramScaleBench.h"
#include "SoakMain.h"
#include "WindowProgramBench.h"
#include "protocols/Registry.h"
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <cstdio>

using namespace stepdeck;
using namespace stepdeck::bench;

namespace {

QString text(const std::optional<double>& value, int decimals, const QString& unit,
             const QString& note)
{
    if (!value)
        return QStringLiteral("n/a (%1)").arg(note);
    return QStringLiteral("%1 %2").arg(*value, 0, 'f', decimals).arg(unit);
}

struct Results
{
    Figure poll;
    Figure pollWire;
    QList<PollWireFigure> pollWireByModel; // every model against its wire (issue 21)
    QList<BusScheduleFigure> busSchedule;  // a bus of many drives, one moving (issue 32)
    LatencyFigure panic;
    LatencyFigure panicUnderLoad; // with loadThreads busy threads beside it (issue 21)
    int loadThreads = 0;
    int panicRuns = 0;
    int panicUnderLoadRuns = 0;
    Figure feed;
    Figure feedWire;
    QList<QPair<int, LatencyFigure>> machineStop; // controllers -> Machine::stop() latency
    // `--jog-latency --json` of a child process (JogLatency.h); empty with jogNote otherwise.
    QJsonObject jog;
    QString jogNote;
};

constexpr int kMachineStopControllers[] = {1, 2, 4};
// The under-load panic figure's load unless --load says otherwise: as many busy threads as the
// reference machine has cores (issue 21).
constexpr int kDefaultLoadThreads = 2;

struct RunOptions
{
    int loadThreads = kDefaultLoadThreads;
    int panicRuns = 0; // > 0: both panic figures take this many runs (smoke tests)
    bool panicOnly = false;
    bool pollOnly = false;
    int pollWindowMs = kPollWireWindowMs;
    bool machineStopOnly = false;
    int machineStopRuns = kMachineStopRepetitions;
    bool json = false;
    QStringList jogArgs; // --jog-presses N, --jog-paced: passed on to the jog latency child
    QString benchPath;   // this executable, for that child
};

template <typename Progress>
void measurePolls(const ModelInfo& model, const RunOptions& options, Results& r,
                  const Progress& progress)
{
    progress("poll rate");
    r.poll = measurePollRate(model, false);
    progress("poll rate, paced");
    r.pollWire = measurePollRate(model, true);
    progress("poll rate against the wire, every model");
    r.pollWireByModel = measurePollWire(options.pollWindowMs);
    progress("a Nanotec bus of 8, 32 and 254 drives, one moving");
    // Long enough to see a full bus' idle round (5 s) at the default window.
    r.busSchedule = measureBusSchedule(2 * options.pollWindowMs + 2000);
}

template <typename Progress>
void measurePanicAndWire(const ModelInfo& model, const RunOptions& options, Results& r,
                         const Progress& progress)
{
    progress("panic latency");
    const int quietRuns = options.panicRuns > 0 ? options.panicRuns : kPanicRepetitions;
    const int loadedRuns = options.panicRuns > 0 ? options.panicRuns : kPanicUnderLoadRepetitions;
    r.panicRuns = quietRuns;
    r.panicUnderLoadRuns = loadedRuns;
    r.panic = measurePanicLatency(model, quietRuns, true);
    progress("panic latency under load");
    r.loadThreads = options.loadThreads;
    {
        BusyLoad load(options.loadThreads);
        r.panicUnderLoad = measurePanicLatency(model, loadedRuns, true);
    }
    if (options.panicOnly)
        return;
    measurePolls(model, options, r, progress);
    progress("feed throughput");
    r.feed = measureFeedThroughput(model, false);
    progress("feed throughput, paced");
    r.feedWire = measureFeedThroughput(model, true);
}

Results measureAll(const ModelInfo& model, const RunOptions& options)
{
    const auto progress = [&](const char* what) {
        if (!options.json)
            print(stderr, QStringLiteral("measuring %1 ...").arg(QLatin1String(what)));
    };
    Results r;
    if (options.pollOnly) {
        measurePolls(model, options, r, progress);
        return r;
    }
    if (!options.machineStopOnly) {
        measurePanicAndWire(model, options, r, progress);
        if (options.panicOnly)
            return r;
    }
    for (const int n : kMachineStopControllers) {
        progress("machine STOP latency (1, 2, 4 controllers)");
        r.machineStop << qMakePair(n, measureMachineStopLatency(model, n, options.machineStopRuns));
    }
    if (options.machineStopOnly)
        return r;
    // The jog panel needs a QApplication, this run has a QCoreApplication: a child measures.
    progress("jog latency (a child process with the GUI's jog panel, offscreen)");
    r.jog = jogLatencyFromChild(options.benchPath, options.jogArgs, &r.jogNote);
    return r;
}

QJsonObject latencyJson(const LatencyFigure& figure)
{
    return QJsonObject{{"median", roundedJson(figure.medianMs, 3)},
                       {"p99", roundedJson(figure.p99Ms, 3)},
                       {"samples", figure.samples},
                       {"pausedByXoff", figure.pausedByXoff},
                       {"deviceRealtime", figure.deviceRealtime}};
}

// The jog latency child's figures (JogLatency.h) in this run's object: E-LAB's press -> first
// jog frame as jogLatencyMs, every model's figures under jogLatency by id, its conditions and
// notes beside this run's.
void addJogFigures(const Results& r, QJsonObject* out)
{
    QJsonArray notes = out->value("notes").toArray();
    if (!r.jogNote.isEmpty())
        notes.append(QStringLiteral("jogLatencyMs: %1").arg(r.jogNote));
    for (const QJsonValue& note : r.jog.value("notes").toArray())
        notes.append(note);
    QJsonObject conditions = out->value("conditions").toObject();
    if (r.jog.contains("conditions"))
        conditions.insert("jog", r.jog.value("conditions").toObject().value("jog"));
    out->insert("jogLatencyMs",
                r.jog.contains("jogLatencyMs")
                    ? r.jog.value("jogLatencyMs")
                    : QJsonObject{{"median", QJsonValue()}, {"p99", QJsonValue()}, {"samples", 0}});
    out->insert("jogLatency", r.jog.value("jogLatency").toObject());
    out->insert("conditions", conditions);
    out->insert("notes", notes);
}

void printJson(const Results& r, const ModelInfo& model, const RunOptions& options)
{
    QJsonArray notes;
    for (const auto& [name, note] :
         {std::pair{"pollRateHz", r.poll.note}, std::pair{"pollRateWireMaxHz", r.pollWire.note},
          std::pair{"panicLatencyMs", r.panic.note},
          std::pair{"panicLatencyUnderLoadMs", r.panicUnderLoad.note},
          std::pair{"feedStepsPerSecond", r.feed.note},
          std::pair{"feedWireMaxStepsPerSecond", r.feedWire.note}}) {
        if (!note.isEmpty())
            notes.append(QStringLiteral("%1: %2").arg(QLatin1String(name), note));
    }
    QJsonArray machineStop;
    for (const auto& [controllers, figure] : r.machineStop) {
        machineStop.append(QJsonObject{{"controllers", controllers},
                                       {"median", roundedJson(figure.medianMs, 3)},
                                       {"p99", roundedJson(figure.p99Ms, 3)},
                                       {"samples", figure.samples},
                                       {"deviceRealtime", figure.deviceRealtime}});
        if (!figure.note.isEmpty())
            notes.append(QStringLiteral("machineStopLatencyMs (%1 controllers): %2")
                             .arg(controllers)
                             .arg(figure.note));
    }
    QJsonObject out{
        {"pollRateHz", roundedJson(r.poll.value, 1)},
        {"machineStopLatencyMs", machineStop},
        {"pollRateWireMaxHz", roundedJson(r.pollWire.value, 1)},
        {"pollWire", pollWireJson(r.pollWireByModel)},
        {"busSchedule", busScheduleJson(r.busSchedule)},
        {"panicLatencyMs", latencyJson(r.panic)},
        {"panicLatencyUnderLoadMs", latencyJson(r.panicUnderLoad)},
        {"feedStepsPerSecond", roundedJson(r.feed.value, 0)},
        {"feedWireMaxStepsPerSecond", roundedJson(r.feedWire.value, 0)},
        {"conditions", QJsonObject{{"model", model.id},
                                   {"line", model.line.text()},
                                   {"transport", "QSerialPort on a pseudo-terminal"},
                                   {"pollIntervalMs", kPollIntervalMs},
                                   {"pollWireWindowMs", r.pollWireByModel.isEmpty()
                                                            ? QJsonValue()
                                                            : QJsonValue(options.pollWindowMs)},
                                   {"panicRepetitions", r.panicRuns},
                                   {"panicUnderLoadRepetitions", r.panicUnderLoadRuns},
                                   {"loadThreads", r.loadThreads},
                                   {"feedStreamSteps", kFeedStreamSteps}}},
        {"notes", notes},
    };
    addJogFigures(r, &out);
    print(stdout, QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Compact)));
}

void printPanicAndWire(const Results& r)
{
    const QString hz = QStringLiteral("Hz");
    const QString ms = QStringLiteral("ms");
    const QString steps = QStringLiteral("steps/s");
    print(stdout, QStringLiteral("  poll rate                    %1  (poll interval %2 ms)")
                      .arg(text(r.poll.value, 1, hz, r.poll.note))
                      .arg(kPollIntervalMs));
    print(stdout, QStringLiteral("  poll rate, paced (wire max)  %1")
                      .arg(text(r.pollWire.value, 1, hz, r.pollWire.note)));
    for (const QString& line : pollWireText(r.pollWireByModel))
        print(stdout, line);
    if (!r.busSchedule.isEmpty()) {
        for (const QString& line : busScheduleText(r.busSchedule))
            print(stdout, line);
    }
    if (r.panicRuns == 0) // --poll-only
        return;
    print(stdout,
          QStringLiteral("  panic latency                median %1, p99 %2  (%3 runs, %4-step "
                         "DC2 stream queued, host held by XOFF in %5)")
              .arg(text(r.panic.medianMs, 3, ms, r.panic.note),
                   text(r.panic.p99Ms, 3, ms, r.panic.note))
              .arg(r.panic.samples)
              .arg(kFeedStreamSteps)
              .arg(r.panic.pausedByXoff));
    print(stdout, QStringLiteral("  panic latency under load     median %1, p99 %2  (the same "
                                 "with %3 busy threads beside it)")
                      .arg(text(r.panicUnderLoad.medianMs, 3, ms, r.panicUnderLoad.note),
                           text(r.panicUnderLoad.p99Ms, 3, ms, r.panicUnderLoad.note))
                      .arg(r.loadThreads));
    print(stdout, QStringLiteral("  feed throughput              %1")
                      .arg(text(r.feed.value, 0, steps, r.feed.note)));
    print(stdout, QStringLiteral("  feed, paced (wire max)       %1")
                      .arg(text(r.feedWire.value, 0, steps, r.feedWire.note)));
}

void printHuman(const Results& r, const ModelInfo& model)
{
    const QString ms = QStringLiteral("ms");
    print(stdout, QStringLiteral("stepdeck-bench: %1 adapter + simulator, QSerialPort on a "
                                 "pseudo-terminal; paced = %2 in both directions")
                      .arg(model.id, model.line.text()));
    if (r.panicRuns > 0 || !r.pollWireByModel.isEmpty()) // not with --machine-stop-only
        printPanicAndWire(r);
    for (const auto& [controllers, figure] : r.machineStop) {
        print(stdout, QStringLiteral("  machine STOP, %1 controller%2  median %3, p99 %4  (%5 "
                                     "runs, Machine::stop() to the stop at the last device)")
                          .arg(controllers)
                          .arg(controllers == 1 ? QStringLiteral(" ") : QStringLiteral("s"))
                          .arg(text(figure.medianMs, 3, ms, figure.note),
                               text(figure.p99Ms, 3, ms, figure.note))
                          .arg(figure.samples));
    }
    if (!r.jog.isEmpty())
        print(stdout, jogLatencyText(r.jog).join(QLatin1Char('\n')));
    else if (!r.jogNote.isEmpty())
        print(stdout, QStringLiteral("  jog latency                  n/a (%1)").arg(r.jogNote));
}
// One option at args[*i] (and its value, advancing *i); false when unknown or out of range.
bool parseOption(const QStringList& args, int* i, RunOptions* o)
{
    const QString& arg = args.at(*i);
    const bool hasValue = *i + 1 < args.size();
    bool ok = true;
    if (arg == QLatin1String("--load") && hasValue)
        o->loadThreads = args.at(++*i).toInt(&ok, 10);
    else if (arg == QLatin1String("--panic-runs") && hasValue)
        o->panicRuns = args.at(++*i).toInt(&ok, 10);
    else if (arg == QLatin1String("--panic-only"))
        o->panicOnly = true;
    else if (arg == QLatin1String("--poll-only"))
        o->pollOnly = true;
    else if (arg == QLatin1String("--poll-window") && hasValue)
        o->pollWindowMs = args.at(++*i).toInt(&ok, 10);
    else if (arg == QLatin1String("--machine-stop-only"))
        o->machineStopOnly = true;
    else if (arg == QLatin1String("--machine-stop-runs") && hasValue)
        o->machineStopRuns = args.at(++*i).toInt(&ok, 10);
    else if (arg == QLatin1String("--json"))
        o->json = true;
    else if (arg == QLatin1String("--jog-paced"))
        o->jogArgs << arg;
    else if (arg == QLatin1String("--jog-presses") && hasValue) {
        const int presses = args.at(++*i).toInt(&ok, 10);
        ok = ok && presses > 0 && presses <= 10000;
        o->jogArgs << arg << QString::number(presses);
    } else
        return false;
    return ok && o->loadThreads >= 0 && o->loadThreads <= 64 && o->panicRuns >= 0 &&
           o->panicRuns <= 10000 && o->machineStopRuns > 0 && o->machineStopRuns <= 10000 &&
           o->pollWindowMs >= 100 && o->pollWindowMs <= 600000;
}

} // namespace

int main(int argc, char** argv)
{
    // With a QApplication of its own (the GUI's jog panel), so before the QCoreApplication.
    if (const int code = jogLatencyMain(argc, argv); code >= 0)
        return code;
    if (const int code = previewFrameBenchMain(argc, argv); code >= 0)
        return code;
    if (const int code = windowProgramBenchMain(argc, argv); code >= 0)
        return code;
    QCoreApplication application(argc, argv);
    const QStringList args = application.arguments().mid(1);
    if (qEnvironmentVariableIsEmpty("QT_LOGGING_RULES"))
        qInstallMessageHandler(quiet);
    if (const int code = guiIdleMain(QCoreApplication::applicationDirPath(), args); code >= 0)
        return code;
    if (const int code = soakMain(application.applicationFilePath(), args); code >= 0)
        return code;
    if (const int code = programBenchMain(args); code >= 0)
        return code;
    if (const int code = programScaleBenchMain(args); code >= 0)
        return code;
    if (const int code = contourBenchMain(args); code >= 0)
        return code;
    // The figures need a stream to queue behind and to meter: the first registered model
    // whose descriptor has one (ModelInfo::streamBench).
    const ModelInfo* model = nullptr;
    for (const ModelInfo& m : models()) {
        if (!model && m.streamBench.supported())
            model = &m;
    }
    RunOptions options;
    options.benchPath = application.applicationFilePath();
    if (args.contains(QLatin1String("--help")) || args.contains(QLatin1String("-h"))) {
        printUsage(model);
        return 0;
    }
    for (int i = 0; i < args.size(); ++i) {
        const QString& arg = args.at(i);
        if (!parseOption(args, &i, &options)) {
            print(stderr, QStringLiteral("stepdeck-bench: bad argument '%1'").arg(arg));
            return 2;
        }
    }
    if (!model) {
        print(stderr, QStringLiteral("stepdeck-bench: no model with a stream to measure is "
                                     "built in"));
        return 1;
    }
    const Results results = measureAll(*model, options);
    if (options.json)
        printJson(results, *model, options);
    else
        printHuman(results, *model);
    return 0;
}
