// stepdeck-bench --soak: random commands with injected faults against a simulator on a
// pseudo-terminal, checked at the DEVICE (docs/benchmark.md, "Fault soak").
#include "Soak.h"
#include "BenchDevice.h"
#include "BenchHost.h"
#include "MoveMatching.h"
#include "model/ModelOperations.h"
#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QSet>
#include <cstdio>

namespace stepdeck::bench {

namespace {
constexpr double kFaultProbability = 0.01; // per command
// A ramped stop is over long before this. Models without a stop command (EMIS, laser axes)
// are not stopped at the session end: every target the soak sends (at most 219 steps or
// units, or one jog chunk, at 2000 per second or more) is reached long before this, so an
// axis still moving then is one the host left moving.
constexpr int kLeftMovingGraceMs = 3000;

// STEPDECK_SOAK_TRACE: each command and jog range with the device journal's size.
bool traceEnabled()
{
    static const bool trace = qEnvironmentVariableIsSet("STEPDECK_SOAK_TRACE");
    return trace;
}

// --drives N (issue 32): a bus of N drives at addresses 1..N, axis i at address i+1 (as the
// simulator's probes name them, NanotecSimulator::probeAddress), every per-axis setup value
// of the profile for each of them.
QMap<Axis, int> busAddresses(int drives)
{
    QMap<Axis, int> out;
    for (int i = 0; i < drives; ++i)
        out.insert(Axis::at(i), i + 1);
    return out;
}

BenchDevice::Config busConfig(BenchDevice::Config config, int drives)
{
    if (drives > 0)
        config.addresses = busAddresses(drives).values();
    return config;
}

SoakProfile busProfile(SoakProfile profile, int drives)
{
    if (drives <= 0)
        return profile;
    for (auto it = profile.setup.begin(); it != profile.setup.end(); ++it) {
        if (!it.value().isPerAxis() || it.value().perAxis.isEmpty())
            continue;
        const QVariant value = it.value().perAxis.first();
        it.value().perAxis.clear();
        for (Axis a : busAddresses(drives).keys())
            it.value().perAxis.insert(a, value);
    }
    return profile;
}

QString kindName(ErrorKind kind)
{
    static const char* names[] = {"ok",        "refused",      "nak",         "timeout",
                                  "linkDown",  "invalidValue", "unsupported", "protocol",
                                  "cancelled", "verifyFailed"};
    return QString::fromLatin1(names[int(kind)]);
}

class SoakRun
{
public:
    SoakRun(const ModelInfo& model, int commands, quint32 seed, int drives,
            const std::function<void(const QString&)>& progress)
        : m_model(model), m_profile(busProfile(model.soak, drives)),
          m_device(model, busConfig(BenchDevice::soakConfig(model, seed), drives)), m_rng(seed),
          m_progress(progress)
    {
        m_fig.model = drives > 0 ? QStringLiteral("%1/%2").arg(model.id).arg(drives) : model.id;
        m_fig.commands = commands;
        m_fig.seed = seed;
        if (drives > 0)
            m_host.setAxisAddresses(busAddresses(drives));
    }

    SoakFigures run();

private:
    bool startSession();
    void endSession();
    void oneCommand();
    QString injectFault();
    void clearFaults();
    void record(const BenchHost::Outcome& outcome);
    void recoverIfRefused(const BenchHost::Outcome& outcome, const QList<Axis>& axes);
    QList<Axis> someAxes(const QList<Axis>& axes);
    ParameterSet setupOf(const QList<Axis>& axes) const;
    void cmdMove(bool wait);
    void cmdJog();
    void cmdVelocity();
    void cmdParameters(bool write);
    void checkAxesAtRest();
    void settleAfterLinkLoss();
    void closeJogRange();
    AxisVector whereAxesStand();
    int between(int low, int high) { return low + int(m_rng.bounded(high - low + 1)); }

    const ModelInfo& m_model;
    const SoakProfile m_profile;
    BenchDevice m_device;
    BenchHost m_host;
    QRandomGenerator m_rng;
    std::function<void(const QString&)> m_progress;
    SoakFigures m_fig;
    QList<CommandedMove> m_commanded;
    QList<QPair<int, int>> m_jogRanges; // device journal indices [first, end) made by jogs
    int m_jogJournalStart = -1;         // journal size when the last jog began; -1: closed
    int m_moveIndex = 0;
    int m_done = 0;
    bool m_vanishing = false;
};

SoakFigures SoakRun::run()
{
    QElapsedTimer clock;
    clock.start();
    QString error;
    if (!m_device.start(&error)) {
        m_fig.results.insert(QStringLiteral("deviceFailed: ") + error, 1);
        return m_fig;
    }
    int failedConnects = 0;
    while (m_done < m_fig.commands && failedConnects < 20) {
        if (!startSession()) {
            ++failedConnects;
            continue;
        }
        failedConnects = 0;
        const int length = between(20, 200);
        for (int i = 0; i < length && m_done < m_fig.commands && m_host.connected(); ++i)
            oneCommand();
        endSession();
        if (m_progress && m_fig.sessions % 10 == 0)
            m_progress(QStringLiteral("%1: %2/%3 commands")
                           .arg(m_model.id)
                           .arg(m_done)
                           .arg(m_fig.commands));
    }
    closeJogRange();
    const QList<SimulatedMove> deviceMoves = m_device.moves();
    matchMoves(deviceMoves, m_commanded, m_jogRanges, &m_fig);
    QSet<Axis> moved;
    for (const SimulatedMove& move : deviceMoves)
        moved.insert(move.axis);
    m_fig.axesMoved = moved.size();
    m_fig.seconds = clock.elapsed() / 1000.0;
    return m_fig;
}

bool SoakRun::startSession()
{
    QString error;
    if (!m_device.present() && !m_device.reappear(&error))
        return false;
    m_fig.movingAtReconnect += m_device.movingAxes().size(); // left by an unplugged host
    if (!m_host.connectTo(m_model, m_device.slavePath(), BenchHost::soakOptions(), &error)) {
        ++m_fig.connectFailures;
        m_host.disconnect();
        return false;
    }
    ++m_fig.sessions;
    m_vanishing = false;
    if (!m_profile.setup.isEmpty()) {
        record(m_host.call(
            [&](ControllerSession& s) { return s.writeParameters(m_profile.setup, false); }));
    }
    if (m_profile.anchorPositions) {
        const AxisVector here = whereAxesStand();
        record(m_host.call([&](ControllerSession& s) { return s.moveAbsolute(here); }));
    }
    return true;
}

// Every axis where the device says it stands (SoakProfile::anchorPositions).
AxisVector SoakRun::whereAxesStand()
{
    AxisVector out;
    m_device.withSimulator([&](Simulator* s) {
        for (Axis a : m_model.capabilities.axes)
            out.insert(a, s->position(a));
    });
    return out;
}

void SoakRun::endSession()
{
    closeJogRange();
    if (m_vanishing || !m_device.present()) {
        // The peer vanished: wait until the host noticed, then start over on a new terminal.
        m_host.waitUntil([&] { return !m_host.connected(); }, 2000);
        ++m_fig.vanishes;
        m_host.disconnect();
        return;
    }
    const bool lost = !m_host.connected();
    m_host.disconnect();
    if (lost) {
        ++m_fig.linkLosses;
        settleAfterLinkLoss();
        return;
    }
    checkAxesAtRest();
}

// After an orderly close the adapter must have stopped everything it started.
void SoakRun::checkAxesAtRest()
{
    QElapsedTimer clock;
    clock.start();
    QList<Axis> moving = m_device.movingAxes();
    while (!moving.isEmpty() && clock.elapsed() < kLeftMovingGraceMs) {
        m_host.idle(20);
        moving = m_device.movingAxes();
    }
    if (moving.isEmpty())
        return;
    m_fig.axesLeftMoving += moving.size();
    m_device.halt(); // so the next session starts at rest and is judged on its own
    m_host.waitUntil([&] { return m_device.movingAxes().isEmpty(); }, kLeftMovingGraceMs);
}

// Nobody could stop the axes over a dead link: the model's stop at the device; a model
// without a stop command gets the time its targets need, then the machine's emergency stop.
void SoakRun::settleAfterLinkLoss()
{
    if (m_model.capabilities.stopCommand) {
        m_device.halt();
        return;
    }
    if (m_host.waitUntil([&] { return m_device.movingAxes().isEmpty(); }, kLeftMovingGraceMs))
        return;
    ++m_fig.emergencyStops;
    m_device.halt();
}

QString SoakRun::injectFault()
{
    if (m_rng.generateDouble() >= kFaultProbability)
        return {};
    static const QStringList kinds{"drop", "corrupt", "delay", "noise", "vanish"};
    const QString kind = kinds.at(int(m_rng.bounded(int(kinds.size()))));
    ++m_fig.faults[kind];
    if (kind == QLatin1String("drop")) {
        m_device.withSimulator([](Simulator* s) { s->faults().dropReplies = 1; });
    } else if (kind == QLatin1String("corrupt")) {
        m_device.withSimulator([](Simulator* s) { s->faults().corruptReplies = 1; });
    } else if (kind == QLatin1String("delay")) {
        m_device.withSimulator([](Simulator* s) {
            s->faults().delayProbability = 1.0;
            s->faults().delayMaxMs = 800;
        });
    } else if (kind == QLatin1String("noise")) {
        m_device.noiseBurst(between(1, 16));
    } else {
        m_vanishing = true;
        m_device.vanishLater(between(0, 60)); // lands within the command
    }
    return kind;
}

void SoakRun::clearFaults()
{
    m_device.withSimulator([](Simulator* s) {
        s->faults().dropReplies = 0;
        s->faults().corruptReplies = 0;
        s->faults().delayProbability = 0;
    });
}

// Models that jog by targets (EMIS, laser axes) leave moves in the device journal that no
// commanded move stands for: everything the device accepts from the start of a jog burst to
// the start of the next command (late chunks included) is counted apart and left out of the
// matching. Other models journal no jog moves.
void SoakRun::closeJogRange()
{
    if (m_jogJournalStart < 0)
        return;
    const int end = int(m_device.moves().size());
    if (end > m_jogJournalStart)
        m_jogRanges.append({m_jogJournalStart, end});
    if (traceEnabled())
        std::fprintf(stderr, "jog range %d..%d\n", m_jogJournalStart, end);
    m_jogJournalStart = -1;
}

void SoakRun::oneCommand()
{
    closeJogRange();
    const QString fault = injectFault();
    const Capabilities caps = m_host.session().capabilities();
    const int pick = int(m_rng.bounded(100));
    if (traceEnabled())
        std::fprintf(stderr, "cmd %d pick %d fault '%s' journal %d\n", m_done, pick,
                     qPrintable(fault), int(m_device.moves().size()));
    if (pick < 20) {
        record(m_host.call([](ControllerSession& s) { return s.refreshStatus(); }));
    } else if (pick < 45) {
        cmdMove(true);
    } else if (pick < 50) {
        cmdMove(false);
    } else if (pick < 65) {
        cmdJog();
    } else if (pick < 75 && caps.motionModes.contains(MotionMode::Velocity)) {
        cmdVelocity();
    } else if (pick < 80 && caps.stopCommand) {
        record(m_host.call([](ControllerSession& s) { return s.stop(); }));
    } else if (pick < 80) {
        // No velocity move or no stop command (EMIS, laser axes): a status request instead.
        record(m_host.call([](ControllerSession& s) { return s.refreshStatus(); }));
    } else if (pick < 90) {
        cmdParameters(true);
    } else {
        cmdParameters(false);
    }
    ++m_done;
    if (!fault.isEmpty()) {
        clearFaults();
        if (fault == QLatin1String("vanish")) // give it time to land if the command was quick
            m_host.waitUntil([&] { return !m_host.connected(); }, 500);
    }
}

void SoakRun::record(const BenchHost::Outcome& outcome)
{
    if (!outcome.finished) {
        ++m_fig.hangs;
        return;
    }
    ++m_fig.results[kindName(outcome.result.error)];
    static const bool verbose = qEnvironmentVariableIsSet("STEPDECK_SOAK_VERBOSE");
    if (verbose && !outcome.result.ok()) {
        const QByteArray line =
            QStringLiteral("%1: %2: %3\n")
                .arg(m_model.id, kindName(outcome.result.error), outcome.result.message)
                .toUtf8();
        std::fwrite(line.constData(), 1, size_t(line.size()), stderr);
    }
}

// A random non-empty subset: any of a few axes; on a bus of many drives one to three of them,
// as a plant moves a few drives at a time.
QList<Axis> SoakRun::someAxes(const QList<Axis>& axes)
{
    constexpr int kFewAxes = 4;
    QList<Axis> out;
    if (axes.size() <= kFewAxes) {
        for (Axis a : axes) {
            if (out.isEmpty() || m_rng.bounded(2))
                out << a;
        }
        return out;
    }
    const int count = between(1, 3);
    while (out.size() < count) {
        const Axis a = axes.at(int(m_rng.bounded(int(axes.size()))));
        if (!out.contains(a))
            out << a;
    }
    return out;
}

// The profile's setup for `axes` only (global values as they are).
ParameterSet SoakRun::setupOf(const QList<Axis>& axes) const
{
    ParameterSet out = m_profile.setup;
    for (auto it = out.begin(); it != out.end(); ++it) {
        if (!it.value().isPerAxis())
            continue;
        for (Axis a : it.value().perAxis.keys()) {
            if (!axes.contains(a))
                it.value().perAxis.remove(a);
        }
    }
    return out;
}

// What an operator does after a refusal the model's manual says how to clear, for the axes of
// the refused command.
void SoakRun::recoverIfRefused(const BenchHost::Outcome& outcome, const QList<Axis>& axes)
{
    if (!outcome.finished || outcome.result.error != ErrorKind::Refused)
        return;
    if (m_profile.anchorPositions) {
        // "home it or move it to an absolute target first": where the device says it stands.
        ++m_fig.recoveries;
        const AxisVector here = whereAxesStand();
        record(m_host.call([&](ControllerSession& s) { return s.moveAbsolute(here); }));
    }
    for (const QString& operation : m_profile.recovery) {
        for (Axis a : axes) {
            ++m_fig.recoveries;
            record(m_host.call([&](ControllerSession& s) {
                return s.modelOperation(operation, {{operation::arg::kAxis, axisName(a)}});
            }));
        }
    }
}

void SoakRun::cmdMove(bool wait)
{
    // Sizes unique within kMoveWindow moves, so the device's journal can be matched.
    const qint64 size = 20 + (m_moveIndex++ % kMoveWindow);
    AxisVector steps;
    for (Axis a : someAxes(m_host.session().capabilities().axes))
        steps.insert(a, m_rng.bounded(2) ? size : -size);
    const int journalBefore = int(m_device.moves().size());
    const BenchHost::Outcome out =
        m_host.call([&](ControllerSession& s) { return s.moveRelative(steps); });
    record(out);
    recoverIfRefused(out, steps.keys());
    const bool ok = out.finished && out.result.ok();
    for (auto it = steps.cbegin(); it != steps.cend(); ++it)
        m_commanded.append({it.key(), it.value(), ok, journalBefore});
    if (ok && wait)
        m_host.waitIdle(5000);
}

void SoakRun::cmdJog()
{
    AxisVelocities rates;
    const Capabilities caps = m_host.session().capabilities();
    const double ceiling = qMin(2000.0, caps.maxJogSpeed);
    rates.insert(caps.axes.at(int(m_rng.bounded(int(caps.axes.size())))),
                 (m_rng.bounded(2) ? 1 : -1) * between(100, int(ceiling)));
    const int ms = between(100, 400);
    m_jogJournalStart = int(m_device.moves().size());
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms && m_host.connected()) {
        m_host.session().setJogVelocity(rates);
        m_host.idle(100);
    }
    m_host.session().endJog();
    m_host.waitIdle(3000);
}

void SoakRun::cmdVelocity()
{
    const Capabilities caps = m_host.session().capabilities();
    AxisVector rates;
    rates.insert(caps.axes.at(int(m_rng.bounded(int(caps.axes.size())))),
                 (m_rng.bounded(2) ? 1 : -1) * between(100, 2000));
    const BenchHost::Outcome out =
        m_host.call([&](ControllerSession& s) { return s.velocityMove(rates); });
    record(out);
    recoverIfRefused(out, rates.keys());
    if (!out.finished || !out.result.ok())
        return;
    m_host.idle(between(50, 300));
    record(m_host.call([](ControllerSession& s) { return s.stop(); }));
    m_host.waitIdle(3000);
}

void SoakRun::cmdParameters(bool write)
{
    if (m_profile.setup.isEmpty() && m_profile.readable.isEmpty()) {
        // No parameters at all (the laser axes): a status request instead.
        record(m_host.call([](ControllerSession& s) { return s.refreshStatus(); }));
        return;
    }
    if (write && !m_profile.setup.isEmpty()) {
        const bool verify = !m_profile.readable.isEmpty() && m_rng.bounded(2);
        // A bus of many drives: the setup of a few of them, as a technician rewrites one drive.
        const ParameterSet set = m_host.session().capabilities().axes.size() > 4
                                     ? setupOf(someAxes(m_host.session().capabilities().axes))
                                     : m_profile.setup;
        record(m_host.call([&](ControllerSession& s) { return s.writeParameters(set, verify); }));
    } else {
        const QStringList names = m_profile.readable.isEmpty()
                                      ? QStringList{m_profile.setup.firstKey()}
                                      : m_profile.readable;
        record(m_host.call([&](ControllerSession& s) { return s.readParameters(names); }));
    }
}

} // namespace

SoakFigures runSoak(const ModelInfo& model, int commands, quint32 seed, int drives,
                    const std::function<void(const QString&)>& progress)
{
    SoakRun run(model, commands, seed, drives, progress);
    return run.run();
}

} // namespace stepdeck::bench
