// stepdeck-bench --soak N --machine: the fault soak over a machine of two controllers, checked
// at the DEVICES (docs/benchmark.md, "Fault soak").
#include "MachineSoak.h"
#include "BenchDevice.h"
#include "EventWait.h"
#include "MoveMatching.h"
#include "machine/Machine.h"
#include "protocols/Registry.h"
#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QSet>
#include <algorithm>
#include <cstdio>
#include <memory>

namespace stepdeck::bench {

namespace {
constexpr double kFaultProbability = 0.01; // per command
constexpr int kLeftMovingGraceMs = 3000;   // a ramped stop is over long before this
constexpr int kMoveBoundMs = 15000;        // a machine move without its end: a hang
constexpr int kRequestBoundMs = 10000;

// One controller of the soaked machine: its simulator and what the soak commanded on it.
struct Link
{
    QString id;
    const ModelInfo* model = nullptr;
    std::unique_ptr<BenchDevice> device;
    QMap<QString, Axis> axes; // machine axis -> controller axis
    QList<CommandedMove> commanded;
};

class MachineSoakRun
{
public:
    MachineSoakRun(int commands, quint32 seed, const std::function<void(const QString&)>& progress);
    SoakFigures run();

private:
    bool startSession();
    void endSession();
    machine::MachineDescription describe() const;
    bool connected() const;
    void oneCommand();
    Link* injectFault();
    void clearFaults(Link* link);
    void record(bool finished, const CommandResult& result);
    bool call(ControllerSession* session,
              const std::function<RequestId(ControllerSession&)>& start);
    void cmdMove();
    void cmdJog();
    void cmdRead();
    void checkAxesAtRest(const QSet<Link*>& unreachable);
    int between(int low, int high) { return low + int(m_rng.bounded(high - low + 1)); }

    QList<Link*> m_links;
    std::vector<std::unique_ptr<Link>> m_owned;
    machine::Machine m_machine;
    QHash<quint64, QPair<bool, QString>> m_movesEnded;
    QHash<RequestId, CommandResult> m_results;
    QRandomGenerator m_rng;
    std::function<void(const QString&)> m_progress;
    SoakFigures m_fig;
    int m_moveIndex = 0;
    int m_done = 0;
    bool m_vanishing = false;
    bool m_failed = false; // a controller failed in this session (Machine::controllerFailed)
};

MachineSoakRun::MachineSoakRun(int commands, quint32 seed,
                               const std::function<void(const QString&)>& progress)
    : m_rng(seed), m_progress(progress)
{
    m_fig.model = QStringLiteral("machine");
    m_fig.commands = commands;
    m_fig.seed = seed;
    const struct
    {
        const char* id;
        const char* model;
        QList<QPair<QString, Axis>> axes;
    } parts[] = {{"table", "elab", {{"X", Axis::X}, {"Y", Axis::Y}, {"Z", Axis::Z}}},
                 {"rotary", "nanotec", {{"A", Axis::X}}}};
    quint32 offset = 0;
    for (const auto& p : parts) {
        auto link = std::make_unique<Link>();
        link->id = QLatin1String(p.id);
        link->model = findModel(QLatin1String(p.model));
        link->device = std::make_unique<BenchDevice>(
            *link->model, BenchDevice::soakConfig(*link->model, seed + offset++));
        for (const auto& [name, axis] : p.axes)
            link->axes.insert(name, axis);
        m_links << link.get();
        m_owned.push_back(std::move(link));
    }
    QObject::connect(&m_machine, &machine::Machine::moveFinished, &m_machine,
                     [this](quint64 id, bool ok, const QString& message) {
                         m_movesEnded.insert(id, {ok, message});
                     });
    QObject::connect(&m_machine, &machine::Machine::controllerFailed, &m_machine,
                     [this] { m_failed = true; });
}

machine::MachineDescription MachineSoakRun::describe() const
{
    machine::MachineDescription d;
    d.name = QStringLiteral("soak");
    for (const Link* link : m_links) {
        machine::MachineController c;
        c.id = link->id;
        c.modelId = link->model->id;
        c.port = link->device->slavePath();
        const QList<int>& addresses = link->model->soak.simulatorAddresses;
        if (!addresses.isEmpty())
            c.busAddresses.insert(Axis::X, addresses.first());
        d.controllers << c;
        for (auto it = link->axes.cbegin(); it != link->axes.cend(); ++it) {
            machine::MachineAxis a;
            a.name = it.key();
            a.controller = link->id;
            a.axis = it.value();
            d.axes << a;
        }
    }
    return d;
}

SoakFigures MachineSoakRun::run()
{
    QElapsedTimer clock;
    clock.start();
    for (Link* link : m_links) {
        QString error;
        if (!link->device->start(&error)) {
            m_fig.results.insert(QStringLiteral("deviceFailed: ") + error, 1);
            return m_fig;
        }
    }
    int failedConnects = 0;
    while (m_done < m_fig.commands && failedConnects < 20) {
        if (!startSession()) {
            ++failedConnects;
            continue;
        }
        failedConnects = 0;
        const int length = between(20, 200);
        for (int i = 0; i < length && m_done < m_fig.commands && connected(); ++i)
            oneCommand();
        endSession();
        if (m_progress && m_fig.sessions % 10 == 0)
            m_progress(QStringLiteral("machine: %1/%2 commands").arg(m_done).arg(m_fig.commands));
    }
    for (Link* link : m_links)
        matchMoves(link->device->moves(), link->commanded, {}, &m_fig);
    m_fig.seconds = clock.elapsed() / 1000.0;
    return m_fig;
}

bool MachineSoakRun::connected() const
{
    return m_machine.state() != machine::MachineState::LinkLost &&
           m_machine.state() != machine::MachineState::Disconnected;
}

bool MachineSoakRun::startSession()
{
    QString error;
    for (Link* link : m_links) {
        if (!link->device->present() && !link->device->reappear(&error))
            return false;
        m_fig.movingAtReconnect += link->device->movingAxes().size();
    }
    m_failed = false;
    m_vanishing = false;
    if (!m_machine.create(describe(), &error)) {
        m_fig.results.insert(QStringLiteral("machineRefused: ") + error, 1);
        return false;
    }
    m_machine.open();
    if (!waitUntil([&] { return m_machine.state() == machine::MachineState::Idle; }, 5000)) {
        ++m_fig.connectFailures;
        m_machine.destroy();
        return false;
    }
    ++m_fig.sessions;
    for (Link* link : m_links) {
        const ParameterSet setup = link->model->soak.setup;
        if (!setup.isEmpty())
            call(m_machine.session(link->id),
                 [&](ControllerSession& s) { return s.writeParameters(setup, false); });
    }
    return true;
}

void MachineSoakRun::endSession()
{
    const bool vanished = m_vanishing || std::any_of(m_links.begin(), m_links.end(),
                                                     [](Link* l) { return !l->device->present(); });
    const bool lost = !vanished && !connected();
    QSet<Link*> unreachable; // a dead link: nobody could stop that device
    for (Link* link : m_links) {
        if (m_machine.session(link->id)->linkState() != LinkState::Connected)
            unreachable.insert(link);
    }
    m_machine.close();
    waitUntil(
        [&] {
            return m_machine.state() == machine::MachineState::Disconnected ||
                   m_machine.state() == machine::MachineState::LinkLost;
        },
        3000);
    m_machine.destroy(); // every session stops its controller and closes
    if (vanished) {
        ++m_fig.vanishes;
    } else if (lost) {
        ++m_fig.linkLosses;
    }
    // The machine is one machine: whatever happened to one link, no axis of the other may be
    // left moving (Machine stops the others when one fails).
    checkAxesAtRest(unreachable);
}

void MachineSoakRun::checkAxesAtRest(const QSet<Link*>& unreachable)
{
    for (Link* link : m_links) {
        if (!link->device->present())
            continue; // gone: movingAtReconnect counts what it kept doing meanwhile
        if (unreachable.contains(link)) {
            link->device->halt(); // as the single soak after a lost link
            continue;
        }
        const bool still =
            waitUntil([&] { return link->device->movingAxes().isEmpty(); }, kLeftMovingGraceMs);
        if (still)
            continue;
        m_fig.axesLeftMoving += link->device->movingAxes().size();
        link->device->halt(); // the next session starts at rest and is judged on its own
        waitUntil([&] { return link->device->movingAxes().isEmpty(); }, kLeftMovingGraceMs);
    }
}

Link* MachineSoakRun::injectFault()
{
    if (m_rng.generateDouble() >= kFaultProbability)
        return nullptr;
    Link* link = m_links.at(int(m_rng.bounded(int(m_links.size()))));
    static const QStringList kinds{"drop", "corrupt", "delay", "noise", "vanish"};
    const QString kind = kinds.at(int(m_rng.bounded(int(kinds.size()))));
    ++m_fig.faults[QStringLiteral("%1 %2").arg(link->id, kind)];
    if (kind == QLatin1String("drop")) {
        link->device->withSimulator([](Simulator* s) { s->faults().dropReplies = 1; });
    } else if (kind == QLatin1String("corrupt")) {
        link->device->withSimulator([](Simulator* s) { s->faults().corruptReplies = 1; });
    } else if (kind == QLatin1String("delay")) {
        link->device->withSimulator([](Simulator* s) {
            s->faults().delayProbability = 1.0;
            s->faults().delayMaxMs = 800;
        });
    } else if (kind == QLatin1String("noise")) {
        link->device->noiseBurst(between(1, 16));
    } else {
        m_vanishing = true;
        link->device->vanishLater(between(0, 60)); // lands within the command
    }
    return link;
}

void MachineSoakRun::clearFaults(Link* link)
{
    link->device->withSimulator([](Simulator* s) {
        s->faults().dropReplies = 0;
        s->faults().corruptReplies = 0;
        s->faults().delayProbability = 0;
    });
}

void MachineSoakRun::oneCommand()
{
    Link* faulted = injectFault();
    const int pick = int(m_rng.bounded(100));
    if (pick < 45) {
        cmdMove();
    } else if (pick < 65) {
        cmdJog();
    } else if (pick < 75) {
        m_machine.stop(); // every controller; no axis may move afterwards (checked at the end)
        waitUntil(
            [&] { return !connected() || m_machine.state() != machine::MachineState::Moving; },
            kLeftMovingGraceMs);
    } else {
        cmdRead();
    }
    ++m_done;
    if (faulted) {
        clearFaults(faulted);
        if (m_vanishing) // give it time to land if the command was quick
            waitUntil([&] { return !connected(); }, 500);
    }
}

void MachineSoakRun::record(bool finished, const CommandResult& result)
{
    if (!finished) {
        ++m_fig.hangs;
        return;
    }
    static const char* names[] = {"ok",        "refused",      "nak",         "timeout",
                                  "linkDown",  "invalidValue", "unsupported", "protocol",
                                  "cancelled", "verifyFailed"};
    ++m_fig.results[QString::fromLatin1(names[int(result.error)])];
}

bool MachineSoakRun::call(ControllerSession* session,
                          const std::function<RequestId(ControllerSession&)>& start)
{
    RequestId id = 0;
    const QMetaObject::Connection c =
        QObject::connect(session, &ControllerSession::requestFinished, session,
                         [&](const CommandResult& r) { m_results.insert(r.id, r); });
    id = start(*session);
    const bool finished = waitUntil([&] { return m_results.contains(id); }, kRequestBoundMs);
    QObject::disconnect(c);
    const CommandResult result = m_results.take(id);
    record(finished, result);
    return finished && result.ok();
}

// A relative move of one to all four machine axes, sizes unique within kMoveWindow so each
// device's journal can be matched; the host's verdict is the machine's moveFinished.
void MachineSoakRun::cmdMove()
{
    const qint64 size = 20 + (m_moveIndex++ % kMoveWindow);
    QMap<QString, double> targets;
    QHash<Link*, int> journalBefore;
    for (Link* link : m_links) {
        journalBefore.insert(link, int(link->device->moves().size()));
        for (const QString& name : link->axes.keys()) {
            if (targets.isEmpty() || m_rng.bounded(2))
                targets.insert(name, m_rng.bounded(2) ? size : -size);
        }
    }
    QString refusal;
    const quint64 id = m_machine.move(targets, false, &refusal);
    bool ok = false;
    if (id == 0) {
        ++m_fig.results[QStringLiteral("refused")];
    } else {
        const bool ended = waitUntil([&] { return m_movesEnded.contains(id); }, kMoveBoundMs);
        ok = ended && m_movesEnded.value(id).first;
        m_fig.hangs += ended ? 0 : 1;
        ++m_fig.results[ok ? QStringLiteral("ok") : QStringLiteral("moveFailed")];
        static const bool verbose = qEnvironmentVariableIsSet("STEPDECK_SOAK_VERBOSE");
        if (verbose && ended && !ok)
            std::fprintf(stderr, "machine move failed: %s\n",
                         qPrintable(m_movesEnded.value(id).second));
    }
    for (Link* link : m_links) {
        for (auto it = link->axes.cbegin(); it != link->axes.cend(); ++it) {
            if (targets.contains(it.key()))
                link->commanded.append(
                    {it.value(), qint64(targets.value(it.key())), ok, journalBefore.value(link)});
        }
    }
}

// One input jogs an axis of each controller for a moment; every lease is renewed together.
void MachineSoakRun::cmdJog()
{
    QMap<QString, double> rates;
    for (Link* link : m_links) {
        const QStringList names = link->axes.keys();
        rates.insert(names.at(int(m_rng.bounded(int(names.size())))),
                     (m_rng.bounded(2) ? 1 : -1) * between(100, 2000));
    }
    const int ms = between(100, 400);
    QElapsedTimer clock;
    clock.start();
    QString refusal;
    while (clock.elapsed() < ms && connected()) {
        if (!m_machine.jog(rates, &refusal))
            break;
        waitUntil([] { return false; }, 100);
    }
    m_machine.endJog();
    waitUntil([&] { return !connected() || m_machine.state() != machine::MachineState::Moving; },
              kLeftMovingGraceMs);
}

void MachineSoakRun::cmdRead()
{
    Link* link = m_links.at(int(m_rng.bounded(int(m_links.size()))));
    ControllerSession* session = m_machine.session(link->id);
    const QStringList readable = link->model->soak.readable;
    if (readable.isEmpty() || m_rng.bounded(2))
        call(session, [](ControllerSession& s) { return s.refreshStatus(); });
    else
        call(session, [&](ControllerSession& s) { return s.readParameters(readable); });
}
} // namespace

SoakFigures runMachineSoak(int commands, quint32 seed,
                           const std::function<void(const QString&)>& progress)
{
    MachineSoakRun run(commands, seed, progress);
    return run.run();
}

} // namespace stepdeck::bench
