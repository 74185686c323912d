#include "ChordBench.h"
#include "BenchDevice.h"
#include "BenchMachine.h"
#include "BenchOutput.h"
#include "EventWait.h"
#include "Measurements.h"
#include "machine/Machine.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include "protocols/Registry.h"
#include "protocols/emis/EmisSimulator.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>

namespace stepdeck::bench {

namespace {

constexpr double kStepsPerMm = 100;
constexpr double kRadius = 10; // mm
constexpr double kFeed = 1200; // mm/min
// Moves started this close together belong to one chord (the Nanotec's 'A's go out one after
// the other, an exchange of about 6 ms each at 19200 baud).
constexpr qint64 kSameChordUs = 30000;

// One axis' move at the device, in µs of the simulator's clock.
struct DeviceMove
{
    qint64 startUs;
    qint64 arrivedUs;
    // Its share of F was below the lowest rate the device runs and ran at that (Nanotec 'o'
    // 60, 6.9): it arrives early by design; the path error it costs is a few steps.
    bool atLowestRate = false;
};

struct ChordFigure
{
    QString model;
    int chords = 0;
    QList<double> gapsMs;
    QList<double> skewsMs;
    QList<double> skewsAtSharesMs; // chords whose every axis ran at its share
    double seconds = 0;            // first chord's start to the last arrival
    QString note;
};

// A move of no steps is left out: an axis whose chord ends where it stands (the arc's quadrant
// points) is started too, and "arrives" at once; that is no skew of the path.
QList<DeviceMove> deviceMoves(Simulator* sim)
{
    QList<DeviceMove> out;
    if (auto* emis = qobject_cast<emis::EmisSimulator*>(sim))
        for (const auto& m : emis->acceptedMovesWithSpeed())
            if (m.steps != 0)
                out << DeviceMove{m.acceptedUs, m.arrivedUs};
    if (auto* nanotec = qobject_cast<nanotec::NanotecSimulator*>(sim))
        for (const auto& m : nanotec->startedMoves())
            if (m.steps != 0)
                out << DeviceMove{m.startedUs, m.arrivedUs, m.maxFrequency <= 60};
    return out;
}

// The chords of the run (moves grouped by their start), their gaps and skews.
void evaluate(const QList<DeviceMove>& moves, ChordFigure* f)
{
    QList<QList<DeviceMove>> chords;
    for (const DeviceMove& m : moves) {
        if (chords.isEmpty() || m.startUs - chords.last().first().startUs > kSameChordUs)
            chords.append(QList<DeviceMove>{});
        chords.last() << m;
    }
    f->chords = int(chords.size());
    for (qsizetype k = 0; k < chords.size(); ++k) {
        qint64 first = chords[k].first().arrivedUs, last = first;
        bool atShares = true;
        for (const DeviceMove& m : chords[k]) {
            first = std::min(first, m.arrivedUs);
            last = std::max(last, m.arrivedUs);
            atShares = atShares && !m.atLowestRate;
        }
        if (chords[k].size() > 1)
            f->skewsMs << double(last - first) / 1000.0;
        if (chords[k].size() > 1 && atShares)
            f->skewsAtSharesMs << double(last - first) / 1000.0;
        if (k + 1 < chords.size())
            f->gapsMs << double(chords[k + 1].first().startUs - last) / 1000.0;
        else if (!chords.isEmpty())
            f->seconds = double(last - chords.first().first().startUs) / 1e6;
    }
}

// startSpeed (EMIS, 9.4): above the chords' speeds they run without the board's ramp; 0: the
// board's power-on start speed.
bool prepareMachine(machine::Machine& m, const ModelInfo& model, const QString& port,
                    qint64 startSpeed, QString* error)
{
    if (!openTable(m, QStringLiteral("Chord bench"), model.id, port, {Axis::X, Axis::Y},
                   kStepsPerMm, error))
        return false;
    if (model.id != QLatin1String("emis"))
        return true;
    // The EMIS' fast speed (what G0 runs at and a program puts back), as a setup writes it.
    ParameterValue work, start;
    work.perAxis = {{Axis::X, 4000}, {Axis::Y, 4000}};
    start.perAxis = {{Axis::X, startSpeed}, {Axis::Y, startSpeed}};
    ParameterSet setup{{QStringLiteral("work-speed"), work}};
    if (startSpeed > 0)
        setup.insert(QStringLiteral("start-speed"), start);
    ControllerSession* s = m.session("table");
    bool written = false;
    QObject guard;
    const RequestId id = s->writeParameters(setup, false);
    QObject::connect(s, &ControllerSession::requestFinished, &guard,
                     [&](const CommandResult& r) { written = written || (r.id == id && r.ok()); });
    if (!waitUntil([&] { return written; }, 5000)) {
        *error = QStringLiteral("the work speed was not written");
        return false;
    }
    return true;
}

ChordFigure measure(const ModelInfo& model, qint64 startSpeed)
{
    ChordFigure f;
    f.model = startSpeed > 0 ? QStringLiteral("%1, start speed %2").arg(model.id).arg(startSpeed)
                             : model.id;
    BenchDevice::Config config;
    config.paced = true;
    if (model.capabilities.multiDrive)
        config.addresses = {1, 2, 3}; // the adapter greets X, Y and Z (1, 2, 3)
    BenchDevice device(model, config);
    machine::Machine m;
    if (!device.start(&f.note) ||
        !prepareMachine(m, model, device.slavePath(), startSpeed, &f.note))
        return f;
    // Referenced, to the circle's start; the moves from here on are the circle's chords.
    const QByteArray head = "G28 X0 Y0\nG21 G90 G0 X30 Y30\n";
    const QByteArray circle =
        QStringLiteral("G2 X30 Y30 I%1 J0 F%2\nM2\n").arg(kRadius).arg(kFeed).toLatin1();
    for (const QByteArray& text : {head + "M2\n", circle}) {
        QList<program::ProgramError> errors;
        const std::optional<program::Program> p = program::ProgramParser::parse(
            text, {QStringLiteral("X"), QStringLiteral("Y")}, &errors);
        program::ProgramRunner runner(&m);
        if (text == circle)
            device.withSimulator([](Simulator* sim) {
                if (auto* emis = qobject_cast<emis::EmisSimulator*>(sim))
                    emis->clearReceivedCommands();
            });
        const qsizetype before = [&] {
            qsizetype n = 0;
            device.withSimulator([&](Simulator* sim) { n = deviceMoves(sim).size(); });
            return n;
        }();
        if (!p || !runner.start(*p, 1, &errors)) {
            f.note = errors.isEmpty() ? QStringLiteral("refused") : errors.first().text();
            return f;
        }
        waitUntil([&] { return program::isEnded(runner.state()); }, 120000);
        if (runner.state() != program::RunState::Finished) {
            f.note = runner.endMessage();
            return f;
        }
        if (text == circle)
            device.withSimulator(
                [&](Simulator* sim) { evaluate(deviceMoves(sim).mid(before), &f); });
    }
    m.destroy();
    return f;
}

QJsonValue rounded(double v)
{
    return std::round(v * 1000) / 1000;
}

} // namespace

int runChordBench(bool json, const QString& only)
{
    QJsonArray out;
    runChordBench(json, &out, only);
    if (json)
        print(stdout,
              QString::fromUtf8(
                  QJsonDocument(QJsonObject{{"contour", out}}).toJson(QJsonDocument::Compact)));
    return out.isEmpty() && json ? 1 : 0;
}

void runChordBench(bool json, QJsonArray* out, const QString& only)
{
    // The EMIS twice: at its power-on start speed every chord ramps up and down (9.4, 9.6); at a
    // start speed above the chords' 2 000 steps/s they run without a ramp.
    const std::pair<const char*, qint64> runs[] = {{"emis", 0}, {"emis", 2000}, {"nanotec", 0}};
    for (const auto& [id, startSpeed] : runs) {
        const ModelInfo* model = findModel(QLatin1String(id));
        if (!model || (!only.isEmpty() && only != QLatin1String(id)))
            continue;
        if (!json)
            print(stderr, QStringLiteral("running a circle as chords on %1 ...").arg(id));
        const ChordFigure f = measure(*model, startSpeed);
        const double ideal = 2 * M_PI * kRadius / (kFeed / 60);
        const auto stat = [](const QList<double>& v, double fraction) {
            return v.isEmpty() ? 0.0 : percentile(v, fraction);
        };
        if (json) {
            out->append(QJsonObject{
                {"program", QStringLiteral("circle of %1 mm as chords").arg(2 * kRadius)},
                {"model", f.model},
                {"chords", f.chords},
                {"gapMs", QJsonObject{{"median", rounded(stat(f.gapsMs, 0.5))},
                                      {"p99", rounded(stat(f.gapsMs, 0.99))}}},
                {"skewMs", QJsonObject{{"median", rounded(stat(f.skewsMs, 0.5))},
                                       {"max", rounded(stat(f.skewsMs, 1.0))},
                                       {"maxAtShares", rounded(stat(f.skewsAtSharesMs, 1.0))}}},
                {"seconds", rounded(f.seconds)},
                {"idealSeconds", rounded(ideal)},
                {"note", f.note}});
            continue;
        }
        print(stdout, QStringLiteral("  %1, circle of %2 mm at F%3 as %4 chords: gap between "
                                     "chords median %5 ms, p99 %6 ms (goal 10 ms median: %7); "
                                     "arrival skew median %8 ms, largest %9 ms (%10 ms where "
                                     "no share ran at the lowest rate); %11 s "
                                     "(length / F: %12 s)%13")
                          .arg(f.model)
                          .arg(2 * kRadius)
                          .arg(kFeed)
                          .arg(f.chords)
                          .arg(stat(f.gapsMs, 0.5), 0, 'f', 2)
                          .arg(stat(f.gapsMs, 0.99), 0, 'f', 2)
                          .arg(stat(f.gapsMs, 0.5) / 10, 0, 'f', 2)
                          .arg(stat(f.skewsMs, 0.5), 0, 'f', 2)
                          .arg(stat(f.skewsMs, 1.0), 0, 'f', 2)
                          .arg(stat(f.skewsAtSharesMs, 1.0), 0, 'f', 2)
                          .arg(f.seconds, 0, 'f', 2)
                          .arg(ideal, 0, 'f', 2)
                          .arg(f.note.isEmpty() ? QString() : QStringLiteral("  ") + f.note));
    }
}

} // namespace stepdeck::bench
