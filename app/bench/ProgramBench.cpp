#include "ProgramBench.h"
#include "BenchDevice.h"
#include "EventWait.h"
#include "Measurements.h"
#include "machine/Machine.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include "protocols/Registry.h"
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMutex>
#include <QTimer>
#include <cstdio>

namespace stepdeck::bench {

namespace {

// The device side of the gap: sampled in the device's thread every kSampleMs, the times a
// move was accepted (the count of accepted moves grew) and the times the axis came to rest.
constexpr int kSampleMs = 1;

class ArrivalSampler
{
public:
    void sample(Simulator* sim, Axis axis)
    {
        const qint64 now = nowNs();
        const int accepted = int(sim->acceptedMoves().size());
        const bool moving = sim->isMoving(axis);
        QMutexLocker lock(&m_mutex);
        if (accepted > m_accepted) {
            if (m_awaitingArrival) // arrived and the next one accepted within one sample
                m_arrivedNs << now;
            m_acceptedNs << now;
            m_awaitingArrival = true;
        } else if (m_awaitingArrival && !moving) {
            m_arrivedNs << now;
            m_awaitingArrival = false;
        }
        m_accepted = accepted;
    }
    // Gaps in ms: arrival of move n to acceptance of move n+1.
    QList<double> gaps() const
    {
        QMutexLocker lock(&m_mutex);
        QList<double> out;
        for (qsizetype i = 0; i + 1 < m_acceptedNs.size() && i < m_arrivedNs.size(); ++i)
            out << double(m_acceptedNs.at(i + 1) - m_arrivedNs.at(i)) / 1e6;
        return out;
    }

private:
    mutable QMutex m_mutex;
    QList<qint64> m_acceptedNs;
    QList<qint64> m_arrivedNs;
    int m_accepted = 0;
    bool m_awaitingArrival = false;
};

struct ProgramFigure
{
    QString model;
    std::optional<double> blocksPerSecond;
    std::optional<double> gapMedianMs;
    std::optional<double> gapP99Ms;
    int pollIntervalMs = 0;
    QString note;
};

BenchDevice::Config deviceConfig(const ModelInfo& model)
{
    BenchDevice::Config config;
    config.paced = true;
    // Multi-drive models: one drive at the first address. A status read asks every drive of
    // the machine, so with three drives on the bus the gap holds three drives' replies.
    if (!model.soak.simulatorAddresses.isEmpty())
        config.addresses = {model.soak.simulatorAddresses.first()};
    config.prepare = [&model](Simulator* sim) {
        SimulatorScenario scenario;
        scenario.setupComplete = true;
        QString ignored;
        if (model.scenario.apply && model.scenario.options.testFlag(ScenarioOption::SetupComplete))
            model.scenario.apply(scenario, sim, &ignored);
    };
    return config;
}

ProgramFigure measure(const ModelInfo& model)
{
    ProgramFigure f;
    f.model = model.id;
    BenchDevice device(model, deviceConfig(model));
    if (!device.start(&f.note))
        return f;
    const Axis axis = model.capabilities.axes.first();
    ArrivalSampler sampler;
    QTimer* timer = nullptr;
    device.withSimulator([&](Simulator* sim) {
        timer = new QTimer(sim);
        timer->setTimerType(Qt::PreciseTimer);
        QObject::connect(timer, &QTimer::timeout, sim,
                         [&sampler, sim, axis] { sampler.sample(sim, axis); });
        timer->start(kSampleMs);
    });
    machine::Machine m;
    QMap<Axis, int> addresses; // multi-drive models: the one simulated drive
    if (model.capabilities.multiDrive && !model.soak.simulatorAddresses.isEmpty())
        addresses.insert(axis, model.soak.simulatorAddresses.first());
    const machine::MachineDescription d =
        machine::MachineDescription::singleController(model, device.slavePath(), addresses);
    if (!m.create(d, &f.note))
        return f;
    m.open();
    if (!waitUntil([&] { return m.state() == machine::MachineState::Idle; }, 5000)) {
        f.note = QStringLiteral("the controller did not connect");
        return f;
    }
    f.pollIntervalMs = m.session(d.controllers.first().id)->spec().options.pollIntervalMs;
    QByteArray text = "G91\n";
    for (int i = 0; i < kProgramBlocks; ++i)
        text += "G0 " + d.axes.first().name.toLatin1() + (i % 2 ? "-10\n" : "10\n");
    QList<program::ProgramError> errors;
    const std::optional<program::Program> p =
        program::ProgramParser::parse(text, {d.axes.first().name}, &errors);
    program::ProgramRunner runner(&m);
    if (!p || !runner.start(*p, 1, &errors)) {
        f.note = errors.isEmpty() ? QStringLiteral("refused") : errors.first().text();
        return f;
    }
    const qint64 startNs = nowNs();
    waitUntil([&] { return program::isEnded(runner.state()); }, 600000);
    const qint64 endNs = nowNs();
    device.withSimulator([&](Simulator*) { timer->stop(); });
    if (runner.state() != program::RunState::Finished) {
        f.note = runner.endMessage();
        return f;
    }
    f.blocksPerSecond = runner.blocksDone() / (double(endNs - startNs) / 1e9);
    const QList<double> gaps = sampler.gaps();
    if (!gaps.isEmpty()) {
        f.gapMedianMs = median(gaps);
        f.gapP99Ms = percentile(gaps, 0.99);
    }
    m.destroy();
    return f;
}

void print(FILE* stream, const QString& text)
{
    const QByteArray bytes = text.toUtf8() + '\n';
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stream);
    std::fflush(stream);
}

QJsonValue rounded(const std::optional<double>& v)
{
    return v ? QJsonValue(std::round(*v * 1000) / 1000) : QJsonValue();
}

QString text(const std::optional<double>& v, const char* unit)
{
    return v ? QStringLiteral("%1 %2").arg(*v, 0, 'f', 2).arg(QLatin1String(unit))
             : QStringLiteral("n/a");
}

} // namespace

int programBenchMain(const QStringList& args)
{
    if (!args.contains(QStringLiteral("--program")))
        return -1;
    const bool json = args.contains(QStringLiteral("--json"));
    QJsonArray out;
    for (const char* id : {"elab", "nanotec"}) {
        const ModelInfo* model = findModel(QLatin1String(id));
        if (!model)
            continue;
        if (!json)
            print(stderr, QStringLiteral("measuring a %1-block program on %2 ...")
                              .arg(kProgramBlocks)
                              .arg(model->id));
        const ProgramFigure f = measure(*model);
        if (json) {
            out.append(QJsonObject{{"model", f.model},
                                   {"blocks", kProgramBlocks},
                                   {"blocksPerSecond", rounded(f.blocksPerSecond)},
                                   {"gapMs", QJsonObject{{"median", rounded(f.gapMedianMs)},
                                                         {"p99", rounded(f.gapP99Ms)}}},
                                   {"pollIntervalMs", f.pollIntervalMs},
                                   {"sampleMs", kSampleMs},
                                   {"note", f.note}});
        } else {
            print(stdout, QStringLiteral("  %1: %2, gap arrival -> next move median %3, p99 %4 "
                                         "(poll interval %5 ms, sampled every %6 ms)%7")
                              .arg(f.model, text(f.blocksPerSecond, "blocks/s"),
                                   text(f.gapMedianMs, "ms"), text(f.gapP99Ms, "ms"))
                              .arg(f.pollIntervalMs)
                              .arg(kSampleMs)
                              .arg(f.note.isEmpty() ? QString() : QStringLiteral("  ") + f.note));
        }
    }
    if (json)
        print(stdout,
              QString::fromUtf8(
                  QJsonDocument(QJsonObject{{"program", out}}).toJson(QJsonDocument::Compact)));
    return 0;
}

} // namespace stepdeck::bench
