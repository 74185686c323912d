#include "ProgramBench.h"
#include "BenchDevice.h"
#include "BenchOutput.h"
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
#include <QSet>
#include <QTimer>
#include <cstdio>

namespace stepdeck::bench {

namespace {

constexpr int kSampleMs = 1;
constexpr int kLearnPollFramesMs = 1500;

// The device side of the gap, sampled in the device's thread every kSampleMs:
// - arrival: the axis came to rest after an accepted move;
// - the next block's first byte (issue 20's gap ends there): the first frame after an arrival
//   that is not one of the poller's status reads. The poller's frames are learnt before the
//   program starts (until setLearning(false)), so no model's byte layout is needed. A frame
//   is seen when decoded, i.e. at its last byte; its first byte came (size - 1) character
//   times earlier;
// - acceptance: the device accepted the move (its count of accepted moves grew), which on a
//   Nanotec comes after the drive's set-up and read-back exchanges.
class ArrivalSampler
{
public:
    explicit ArrivalSampler(double characterUs) : m_characterNs(characterUs * 1000.0) {}

    void setLearning(bool learning)
    {
        QMutexLocker lock(&m_mutex);
        m_learning = learning;
    }

    void sample(Simulator* sim, Axis axis)
    {
        const qint64 now = nowNs();
        const QList<QByteArray> frames = sim->receivedFrames();
        sim->clearReceivedFrames();
        const int accepted = int(sim->acceptedMoves().size());
        const bool moving = sim->isMoving(axis);
        QMutexLocker lock(&m_mutex);
        if (m_learning) {
            for (const QByteArray& frame : frames)
                m_pollFrames.insert(frame);
            m_accepted = accepted;
            return;
        }
        if (m_awaitingArrival && !moving && accepted == m_accepted)
            arrive(now); // before this sample's frames: they came after it
        for (const QByteArray& frame : frames) {
            if (m_awaitingBlock && !m_pollFrames.contains(frame)) {
                m_blockStartNs << now - qint64(double(frame.size() - 1) * m_characterNs);
                m_awaitingBlock = false;
            }
        }
        if (accepted > m_accepted) {
            if (m_awaitingArrival) { // arrived and the next one accepted within one sample
                arrive(now);
                if (m_awaitingBlock)
                    m_blockStartNs << now;
                m_awaitingBlock = false;
            }
            m_acceptedNs << now;
            m_awaitingArrival = true;
        }
        m_accepted = accepted;
    }
    // Gaps in ms: arrival of move n to the first byte of block n+1.
    QList<double> gaps() const
    {
        QMutexLocker lock(&m_mutex);
        QList<double> out;
        for (qsizetype i = 0; i < m_arrivedNs.size() && i < m_blockStartNs.size(); ++i)
            out << double(qMax<qint64>(0, m_blockStartNs.at(i) - m_arrivedNs.at(i))) / 1e6;
        return out;
    }
    // Arrival of move n to the device's acceptance of move n+1.
    QList<double> gapsToAcceptance() const
    {
        QMutexLocker lock(&m_mutex);
        QList<double> out;
        for (qsizetype i = 0; i + 1 < m_acceptedNs.size() && i < m_arrivedNs.size(); ++i)
            out << double(m_acceptedNs.at(i + 1) - m_arrivedNs.at(i)) / 1e6;
        return out;
    }

private:
    void arrive(qint64 now)
    {
        // The last arrival has no next block; an arrival whose block start was not seen (a
        // poll frame never learnt) would shift the pairs, so it ends the pairing instead.
        if (m_arrivedNs.size() != m_blockStartNs.size())
            m_paired = false;
        if (m_paired)
            m_arrivedNs << now;
        m_awaitingArrival = false;
        m_awaitingBlock = m_paired;
    }

    mutable QMutex m_mutex;
    const double m_characterNs;
    bool m_learning = true;
    bool m_paired = true;
    QSet<QByteArray> m_pollFrames;
    QList<qint64> m_acceptedNs;
    QList<qint64> m_arrivedNs;
    QList<qint64> m_blockStartNs;
    int m_accepted = 0;
    bool m_awaitingArrival = false;
    bool m_awaitingBlock = false;
};

struct ProgramFigure
{
    QString model;
    std::optional<double> blocksPerSecond;
    std::optional<double> gapMedianMs;
    std::optional<double> gapP99Ms;
    std::optional<double> acceptanceGapMedianMs;
    std::optional<double> acceptanceGapP99Ms;
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
    ArrivalSampler sampler(model.line.characterTimeUs());
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
    // The poller's own frames, learnt at rest: 1.5 s is 30 polls at the default interval,
    // enough for the E-LAB's every-20th start-button read and the Nanotec's every-4th inputs.
    waitUntil([] { return false; }, kLearnPollFramesMs);
    sampler.setLearning(false);
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
    const QList<double> toAcceptance = sampler.gapsToAcceptance();
    if (!toAcceptance.isEmpty()) {
        f.acceptanceGapMedianMs = median(toAcceptance);
        f.acceptanceGapP99Ms = percentile(toAcceptance, 0.99);
    }
    m.destroy();
    return f;
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
            out.append(QJsonObject{
                {"model", f.model},
                {"blocks", kProgramBlocks},
                {"blocksPerSecond", rounded(f.blocksPerSecond)},
                {"gapMs",
                 QJsonObject{{"median", rounded(f.gapMedianMs)}, {"p99", rounded(f.gapP99Ms)}}},
                {"gapToAcceptanceMs", QJsonObject{{"median", rounded(f.acceptanceGapMedianMs)},
                                                  {"p99", rounded(f.acceptanceGapP99Ms)}}},
                {"pollIntervalMs", f.pollIntervalMs},
                {"sampleMs", kSampleMs},
                {"note", f.note}});
        } else {
            print(stdout,
                  QStringLiteral("  %1: %2, gap arrival -> next block's first byte median "
                                 "%3, p99 %4; -> its acceptance median %5, p99 %6 "
                                 "(poll interval %7 ms, sampled every %8 ms)%9")
                      .arg(f.model, text(f.blocksPerSecond, "blocks/s"), text(f.gapMedianMs, "ms"),
                           text(f.gapP99Ms, "ms"), text(f.acceptanceGapMedianMs, "ms"),
                           text(f.acceptanceGapP99Ms, "ms"))
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
