// stepdeck-bench --contour (ContourBench.h).
#include "ContourBench.h"
#include "BenchDevice.h"
#include "BenchMachine.h"
#include "BenchOutput.h"
#include "ChordBench.h"
#include "EventWait.h"
#include "machine/Machine.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMutex>
#include <QPointF>
#include <QTimer>
#include <cmath>
#include <functional>

namespace stepdeck::bench {

namespace {

constexpr double kStepsPerMm = 100;
constexpr double kTickRate = 1999;              // below the start speed written (2000)
constexpr double kWirePairs = 57600.0 / 11 / 2; // <DC2> pairs a second on 57600 8N2
constexpr double kFeed = 16;                    // mm/s (F960): 1 600 steps/s along an axis
constexpr double kRadius = 25;                  // the 50 mm circle
constexpr int kZigzagSegments = 2000;
constexpr double kZigzagStep = 0.1; // mm in X and Y per segment
constexpr int kCircleLine = 4;      // circleProgram()'s G2

struct ContourFigure
{
    QString program;
    double lengthMm = 0;
    std::optional<double> pathErrorSteps;
    std::optional<double> speedError; // executed ticks / (length / F x tick) - 1
    std::optional<double> vectorsPerSecond;
    qint64 underruns = 0;
    std::optional<double> holdLatencyMs;
    std::optional<double> overrideLatencyMs;
    QString note;
};

// Samples in the device thread every millisecond: the executed vectors and the board's X, Y.
class BoardSampler
{
public:
    struct Sample
    {
        qint64 ns = 0;
        qint64 executed = 0;
        double x = 0, y = 0;
    };
    void sample(elab::ElabSimulator* sim)
    {
        const Sample s{nowNs(), qint64(sim->executedStepRecord().size()),
                       double(sim->position(Axis::X)), double(sim->position(Axis::Y))};
        QMutexLocker lock(&m_mutex);
        if (m_samples.size() < 2000000)
            m_samples << s;
    }
    QList<Sample> samples() const
    {
        QMutexLocker lock(&m_mutex);
        return m_samples;
    }

private:
    mutable QMutex m_mutex;
    QList<Sample> m_samples;
};

// The largest distance of the executed path (steps from the stream's start) from the ideal
// one: distance(point in mm from the start) gives it in mm.
double worstError(const std::vector<quint8>& record,
                  const std::function<double(double, double)>& distance)
{
    double worst = 0, x = 0, y = 0;
    for (const quint8 byte : record) {
        const elab::Triple<int> s = elab::decodeStepByte(byte);
        x += s[0];
        y += s[1];
        worst = std::max(worst, distance(x / kStepsPerMm, y / kStepsPerMm) * kStepsPerMm);
    }
    return worst;
}

double segmentDistance(double px, double py, double ax, double ay, double bx, double by)
{
    const double dx = bx - ax, dy = by - ay;
    const double t = std::clamp(((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

// The device, a machine of it and the runner; run() one program and measure.
class ContourRig
{
public:
    explicit ContourRig(const ModelInfo& model) : m_model(model) {}
    // The sampler's timer runs in the device's thread and calls into m_sampler: it goes first,
    // or it fires into the destroyed sampler while the device shuts down (a crash at exit).
    ~ContourRig()
    {
        if (m_device && m_timer)
            m_device->withSimulator([this](Simulator*) {
                delete m_timer;
                m_timer = nullptr;
            });
    }
    ContourRig(const ContourRig&) = delete;
    ContourRig& operator=(const ContourRig&) = delete;
    bool open(QString* error);
    void measure(ContourFigure* f, const QByteArray& program,
                 const std::function<double(double, double)>& distance, bool latencies);

private:
    void sampleLatencies(ContourFigure* f, program::ProgramRunner& runner, qint64 before);
    QPointF boardSteps(); // where the board stands, X and Y in steps

    const ModelInfo& m_model;
    std::unique_ptr<BenchDevice> m_device;
    machine::Machine m_machine;
    BoardSampler m_sampler;
    QTimer* m_timer = nullptr;
    QPointF m_circleStart;
};

QPointF ContourRig::boardSteps()
{
    QPointF p;
    m_device->withSimulator([&](Simulator* sim) {
        p = QPointF(double(sim->position(Axis::X)), double(sim->position(Axis::Y)));
    });
    return p;
}

bool ContourRig::open(QString* error)
{
    BenchDevice::Config config;
    config.paced = true;
    config.prepare = [this](Simulator* sim) {
        SimulatorScenario scenario;
        scenario.setupComplete = true;
        QString ignored;
        if (m_model.scenario.apply)
            m_model.scenario.apply(scenario, sim, &ignored);
    };
    m_device = std::make_unique<BenchDevice>(m_model, config);
    if (!m_device->start(error))
        return false;
    if (!openTable(m_machine, QStringLiteral("Contour bench"), m_model.id, m_device->slavePath(),
                   {Axis::X, Axis::Y, Axis::Z}, kStepsPerMm, error))
        return false;
    ParameterValue speed, feed;
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        speed.perAxis.insert(a, 2000);
        feed.perAxis.insert(a, 1000);
    }
    ControllerSession* s = m_machine.session("table");
    bool written = false;
    QObject guard;
    const RequestId id = s->writeParameters({{QStringLiteral("start-speed"), speed},
                                             {QStringLiteral("max-speed"), speed},
                                             {QStringLiteral("acceleration"), speed},
                                             {QStringLiteral("feed-speed"), feed}},
                                            false);
    QObject::connect(s, &ControllerSession::requestFinished, &guard,
                     [&](const CommandResult& r) { written = written || (r.id == id && r.ok()); });
    if (!waitUntil([&] { return written; }, 5000)) {
        *error = QStringLiteral("the setup was not written");
        return false;
    }
    m_device->withSimulator([this](Simulator* sim) {
        m_timer = new QTimer(sim);
        m_timer->setTimerType(Qt::PreciseTimer);
        auto* board = static_cast<elab::ElabSimulator*>(sim);
        QObject::connect(m_timer, &QTimer::timeout, sim,
                         [this, board] { m_sampler.sample(board); });
        m_timer->start(1);
    });
    return true;
}

void ContourRig::measure(ContourFigure* f, const QByteArray& text,
                         const std::function<double(double, double)>& distance, bool latencies)
{
    qint64 before = 0;
    m_device->withSimulator([&](Simulator* sim) {
        auto* board = static_cast<elab::ElabSimulator*>(sim);
        board->clearStreamCounters();
        before = qint64(board->executedStepRecord().size());
    });
    QList<program::ProgramError> errors;
    const std::optional<program::Program> p =
        program::ProgramParser::parse(text, {"X", "Y", "Z"}, &errors);
    program::ProgramRunner runner(&m_machine);
    QObject guard;
    QObject::connect(&runner, &program::ProgramRunner::blockStarted, &guard, [this](int line) {
        if (line == kCircleLine) // the G0 before it arrived: the circle's start
            m_circleStart = boardSteps();
    });
    if (!p || !runner.start(*p, 1, &errors)) {
        f->note = errors.isEmpty() ? QStringLiteral("refused") : errors.first().text();
        return;
    }
    const qint64 startNs = nowNs();
    if (latencies)
        sampleLatencies(f, runner, before);
    waitUntil([&] { return program::isEnded(runner.state()); }, 600000);
    const qint64 endNs = nowNs();
    if (runner.state() != program::RunState::Finished) {
        f->note = runner.endMessage();
        return;
    }
    std::vector<quint8> record;
    m_device->withSimulator([&](Simulator* sim) {
        auto* board = static_cast<elab::ElabSimulator*>(sim);
        record.assign(board->executedStepRecord().begin() + before,
                      board->executedStepRecord().end());
        f->underruns = board->streamUnderruns();
    });
    f->pathErrorSteps = worstError(record, distance);
    if (!latencies) { // a hold or an override changes the time and the ticks
        f->speedError = double(record.size()) / (f->lengthMm / kFeed * kTickRate) - 1;
        // Over the stream's own time at the board: its first executed vector to its last.
        const QList<BoardSampler::Sample> s = m_sampler.samples();
        qsizetype first = -1, last = -1;
        for (qsizetype i = 1; i < s.size(); ++i) {
            if (s.at(i).ns < startNs || s.at(i).ns > endNs ||
                s.at(i).executed <= s.at(i - 1).executed)
                continue;
            if (first < 0)
                first = i - 1;
            last = i;
        }
        if (first >= 0 && last > first)
            f->vectorsPerSecond = double(s.at(last).executed - s.at(first).executed) /
                                  (double(s.at(last).ns - s.at(first).ns) / 1e9);
    }
}

// Half-way round the circle: hold, wait until the board stood 100 ms, resume; then the
// override to 50 %. Both from the sampler's record.
void ContourRig::sampleLatencies(ContourFigure* f, program::ProgramRunner& runner, qint64 before)
{
    const auto executed = [&] {
        qint64 n = 0;
        m_device->withSimulator([&](Simulator* sim) {
            n = qint64(static_cast<elab::ElabSimulator*>(sim)->executedStepRecord().size());
        });
        return n - before;
    };
    const qint64 halfWay = qint64(M_PI * kRadius / kFeed * kTickRate);
    waitUntil(
        [&] {
            return (runner.currentLine() == kCircleLine && executed() >= halfWay) ||
                   program::isEnded(runner.state());
        },
        60000);
    const qint64 holdNs = nowNs();
    if (!runner.holdFeed() || !runner.feedHeld()) {
        f->note = QStringLiteral("the circle was not running at half-way: no latency measured");
        return;
    }
    waitUntil([] { return false; }, 400);
    QList<BoardSampler::Sample> s = m_sampler.samples();
    qint64 lastStepNs = holdNs;
    for (qsizetype i = 1; i < s.size(); ++i)
        if (s.at(i).ns > holdNs && s.at(i).executed != s.at(i - 1).executed)
            lastStepNs = s.at(i).ns;
    f->holdLatencyMs = double(lastStepNs - holdNs) / 1e6;
    runner.resume();
    waitUntil([] { return false; }, 300);
    // The board's angular rate about the circle's centre (X + 25 mm from the start).
    const QList<BoardSampler::Sample> base = m_sampler.samples();
    const double cx = m_circleStart.x() + kRadius * kStepsPerMm;
    const double cy = m_circleStart.y();
    const auto angle = [&](const BoardSampler::Sample& p) {
        return std::atan2(p.y - cy, p.x - cx);
    };
    const auto rateOver = [&](const QList<BoardSampler::Sample>& list, qsizetype i,
                              qint64 windowNs) {
        qsizetype j = i;
        while (j > 0 && list.at(i).ns - list.at(j).ns < windowNs)
            --j;
        double d = angle(list.at(i)) - angle(list.at(j));
        d = std::remainder(d, 2 * M_PI);
        return std::fabs(d) / (double(list.at(i).ns - list.at(j).ns) / 1e9);
    };
    const double fullRate = rateOver(base, base.size() - 1, 50000000);
    const qint64 overrideNs = nowNs();
    runner.setFeedOverride(50);
    waitUntil([] { return false; }, 500);
    s = m_sampler.samples();
    for (qsizetype i = 0; i < s.size(); ++i)
        if (s.at(i).ns > overrideNs + 20000000 && rateOver(s, i, 20000000) < 0.75 * fullRate) {
            f->overrideLatencyMs = double(s.at(i).ns - overrideNs) / 1e6;
            break;
        }
}

QJsonValue rounded(const std::optional<double>& v, double scale = 1000)
{
    return v ? QJsonValue(std::round(*v * scale) / scale) : QJsonValue();
}

QString text(const std::optional<double>& v, const char* unit, int decimals = 2)
{
    return v ? QStringLiteral("%1%2").arg(*v, 0, 'f', decimals).arg(QLatin1String(unit))
             : QStringLiteral("n/a");
}

// Referenced first (an arc needs a known start), then the circle from X40 Y40 (line 4).
QByteArray circleProgram()
{
    return QStringLiteral("G28 X0 Y0\nG0 X40 Y40\nG21 G91 G64\nG2 X0 Y0 I%1 F%2\nM30\n")
        .arg(kRadius)
        .arg(kFeed * 60)
        .toLatin1();
}

QByteArray zigzagProgram()
{
    QByteArray p = "G21 G91 G64\nF" + QByteArray::number(kFeed * 60) + "\n";
    for (int i = 0; i < kZigzagSegments; ++i)
        p += i % 2 == 0 ? "G1 X0.1 Y0.1\n" : "G1 X0.1 Y-0.1\n";
    return p + "M30\n";
}

// An Archimedean spiral of kSpiralTurns turns from radius 5 mm to 20 mm as kSpiralSegments G1
// chords (a CAM post's polyline), relative from its start. *vertices: the chords' ends as the
// program writes them (rounded to 1 µm), in mm from the start: the ideal path the board must
// follow. *length: the polyline's length.
constexpr int kSpiralSegments = 600;
constexpr double kSpiralTurns = 3;
QByteArray spiralProgram(QList<QPointF>* vertices, double* length)
{
    const auto at = [](int k) {
        const double t = double(k) / kSpiralSegments;
        const double r = 5 + 15 * t, a = 2 * M_PI * kSpiralTurns * t;
        return QPointF(r * std::cos(a), r * std::sin(a));
    };
    QByteArray p = "G21 G91 G64\nF" + QByteArray::number(kFeed * 60) + "\n";
    QPointF written(0, 0); // where the program's relative words have put the tool
    *vertices = {written};
    *length = 0;
    for (int k = 1; k <= kSpiralSegments; ++k) {
        const QPointF target = at(k) - at(0);
        const double dx = std::round((target.x() - written.x()) * 1000) / 1000;
        const double dy = std::round((target.y() - written.y()) * 1000) / 1000;
        p += "G1 X" + QByteArray::number(dx, 'f', 3) + " Y" + QByteArray::number(dy, 'f', 3) + "\n";
        written += QPointF(dx, dy);
        *vertices << written;
        *length += std::hypot(dx, dy);
    }
    return p + "M30\n";
}

void report(const ContourFigure& f, bool json, QJsonArray* out)
{
    if (json) {
        out->append(QJsonObject{{"program", f.program},
                                {"lengthMm", rounded(f.lengthMm)},
                                {"pathErrorSteps", rounded(f.pathErrorSteps)},
                                {"pathErrorLimitSteps", 1.0},
                                {"speedError", rounded(f.speedError, 1e5)},
                                {"speedErrorLimit", 0.02},
                                {"vectorsPerSecond", rounded(f.vectorsPerSecond)},
                                {"wirePairsPerSecond", rounded(kWirePairs)},
                                {"underruns", f.underruns},
                                {"holdLatencyMs", rounded(f.holdLatencyMs)},
                                {"overrideLatencyMs", rounded(f.overrideLatencyMs)},
                                {"latencyLimitMs", 250},
                                {"note", f.note}});
        return;
    }
    const auto ratio = [](const std::optional<double>& v, double limit) {
        return v ? QStringLiteral(" (%1 of the limit)").arg(std::fabs(*v) / limit, 0, 'f', 2)
                 : QString();
    };
    print(stdout,
          QStringLiteral("  %1 (%2 mm): path error %3%4, path speed %5%6, %7 vectors/s of the "
                         "wire's %8, %9 underruns")
              .arg(f.program)
              .arg(f.lengthMm, 0, 'f', 1)
              .arg(text(f.pathErrorSteps, " steps", 3), ratio(f.pathErrorSteps, 1.0),
                   text(f.speedError ? std::optional<double>(*f.speedError * 100) : std::nullopt,
                        " %", 3),
                   ratio(f.speedError, 0.02), text(f.vectorsPerSecond, "", 0))
              .arg(kWirePairs, 0, 'f', 0)
              .arg(f.underruns));
    if (f.holdLatencyMs || f.overrideLatencyMs)
        print(stdout, QStringLiteral("    hold latency %1%2, override latency %3%4")
                          .arg(text(f.holdLatencyMs, " ms"), ratio(f.holdLatencyMs, 250),
                               text(f.overrideLatencyMs, " ms"), ratio(f.overrideLatencyMs, 250)));
    if (!f.note.isEmpty())
        print(stdout, QStringLiteral("    %1").arg(f.note));
}

// The E-LAB's programs, each with its length and the distance (mm) of a point (mm from the
// stream's start) from its ideal path.
struct ContourRun
{
    const char* name;
    QByteArray program;
    double length;
    std::function<double(double, double)> distance;
    bool latencies; // hold and override measured on it
};

QList<ContourRun> contourRuns()
{
    const auto onCircle = [](double x, double y) {
        return std::fabs(std::hypot(x - kRadius, y) - kRadius);
    };
    const auto onZigzag = [](double x, double y) {
        const int n = std::clamp(int(x / kZigzagStep), 0, kZigzagSegments - 1);
        double best = 1e9;
        for (int i = std::max(0, n - 1); i <= std::min(kZigzagSegments - 1, n + 1); ++i) {
            const double ay = i % 2 == 0 ? 0 : kZigzagStep, by = kZigzagStep - ay;
            best = std::min(best,
                            segmentDistance(x, y, i * kZigzagStep, ay, (i + 1) * kZigzagStep, by));
        }
        return best;
    };
    QList<QPointF> spiral;
    double spiralLength = 0;
    const QByteArray spiralText = spiralProgram(&spiral, &spiralLength);
    const auto onSpiral = [spiral](double x, double y) {
        double best = 1e9;
        for (qsizetype i = 0; i + 1 < spiral.size(); ++i)
            best = std::min(best, segmentDistance(x, y, spiral[i].x(), spiral[i].y(),
                                                  spiral[i + 1].x(), spiral[i + 1].y()));
        return best;
    };
    return {
        {"circle of 50 mm", circleProgram(), 2 * M_PI * kRadius, onCircle, false},
        {"spiral of 3 turns, 10 to 40 mm, 600 segments", spiralText, spiralLength, onSpiral, false},
        {"zigzag of 2000 segments", zigzagProgram(), kZigzagSegments * std::sqrt(2.0) * kZigzagStep,
         onZigzag, false},
        {"circle of 50 mm, held and overridden", circleProgram(), 2 * M_PI * kRadius, onCircle,
         true},
    };
}

} // namespace

int contourBenchMain(const QStringList& args)
{
    if (!args.contains(QStringLiteral("--contour")))
        return -1;
    const bool json = args.contains(QStringLiteral("--json"));
    // --contour-model ID: only that model's part (elab: the streams; emis, nanotec: chords).
    const qsizetype at = args.indexOf(QStringLiteral("--contour-model"));
    const QString only = at >= 0 ? args.value(at + 1) : QString();
    if (!only.isEmpty() && only != QLatin1String("elab"))
        return runChordBench(json, only);
    const ModelInfo* model = findModel(QStringLiteral("elab"));
    if (!model)
        return 1;
    QJsonArray out;
    {
        // Closed before the chords run: its sampler would take a core's share meanwhile.
        ContourRig rig(*model);
        QString error;
        if (!rig.open(&error)) {
            print(stderr, error);
            return 1;
        }
        if (!json)
            print(stderr, QStringLiteral("running contours on the E-LAB over the paced wire ..."));
        for (const ContourRun& run : contourRuns()) {
            ContourFigure f;
            f.program = QString::fromLatin1(run.name);
            f.lengthMm = run.length;
            rig.measure(&f, run.program, run.distance, run.latencies);
            report(f, json, &out);
        }
    }
    // The EMIS and the Nanotec run their chords one after the other (ChordBench).
    if (only.isEmpty())
        runChordBench(json, &out);
    if (json)
        print(stdout,
              QString::fromUtf8(
                  QJsonDocument(QJsonObject{{"contour", out}}).toJson(QJsonDocument::Compact)));
    return 0;
}

} // namespace stepdeck::bench
