#include "Machine.h"
#include "MachineFile.h"
#include "MachineReferenceRun.h"
#include "MachineSetup.h"
#include "MachineSimulation.h"
#include "MachineSwitchOff.h"
#include "protocols/Registry.h"
#include <utility>

namespace stepdeck::machine {

namespace {
// A machine's soft limits in units, as the controller enforces them in steps (the session
// checks every move and limits the jog ramp: a GUI or program cannot go around them).
SoftLimits stepLimitsOf(const MachineDescription& d, const QString& controllerId)
{
    SoftLimits limits;
    for (const MachineAxis& a : d.axes) {
        if (a.controller != controllerId || !a.hasSoftLimits())
            continue;
        const qint64 first = a.toSteps(*a.softMinimum);
        const qint64 second = a.toSteps(*a.softMaximum);
        AxisSoftLimit limit;
        limit.rangeSet = true;
        limit.minimum = qMin(first, second); // an inverted axis swaps the ends
        limit.maximum = qMax(first, second);
        limits.set(a.axis, limit);
    }
    return limits;
}

ConnectionSpec specOf(const MachineController& c, const ControllerOptions& base)
{
    ConnectionSpec spec;
    spec.port = c.port;
    spec.options = base;
    spec.options.axisAddresses = c.busAddresses;
    spec.options.axisNames = c.axisNames;
    if (c.resetLine)
        spec.options.resetLine = *c.resetLine;
    spec.simulator.addresses = c.busAddresses.values();
    return spec;
}

// A built-in simulator (port "sim") is the machine of this file (MachineSimulation.h).
void simulateMachine(const MachineDescription& d, const MachineController& c,
                     ControllerSession* session)
{
    const ModelInfo* model = session->model();
    const SimulatorScenario scenario = simulatorScenarioOf(d, c.id, session->capabilities());
    if (!simulatorTakes(*model, scenario))
        return;
    session->withSimulator([model, scenario](Simulator* sim) {
        QString unused;
        model->scenario.apply(scenario, sim, &unused);
    });
}
} // namespace

Machine::Machine(QObject* parent)
    : QObject(parent), m_references(std::make_unique<MachineReferenceRun>(*this)),
      m_switchOff(std::make_unique<MachineSwitchOff>(*this))
{
    // The operator's reference run gives the motion back at its end, before anyone who
    // listens hears of it (connected first).
    connect(this, &Machine::referenceFinished, this, [this] { releaseMotion(&m_referenceToken); });
}

Machine::~Machine()
{
    destroy();
}

bool Machine::create(const MachineDescription& description, QString* error)
{
    destroy();
    MachineFileError invalid;
    if (!MachineFile::validate(description, &invalid)) {
        if (error)
            *error = invalid.text();
        return false;
    }
    m_description = description;
    for (const MachineController& c : m_description.controllers) {
        const bool lent = m_lent && m_sessions.empty();
        std::unique_ptr<ControllerSession> session(lent ? m_lent : new ControllerSession);
        const ModelInfo& model = *findModel(c.modelId);
        ConnectionSpec spec = specOf(c, m_baseOptions);
        // The axes' jogAcceleration as the controller's jog ramp (issue 28 item 6; 0 keeps the
        // model's default ramp). Only where the host ramp is what brakes a jog
        // (Capabilities::hostRampedJog, the E-LAB); a drive that ramps by itself (Nanotec 6.6,
        // EMIS 9.6) stops by its own ramp whatever the host's (docs/machines.md).
        const double ramp = m_description.jogRampAcceleration(c.id, model.capabilities.maxJogSpeed);
        if (ramp > 0 && model.capabilities.hostRampedJog)
            spec.options.jogAccelerationStepsPerS2 = ramp;
        QString why;
        if (!session->create(model, spec, &why)) {
            if (error)
                *error = tr("controller \"%1\": %2").arg(c.id, why);
            if (lent)
                (void)session.release(); // not this machine's to delete
            destroy();
            return false;
        }
        session->setSoftLimits(stepLimitsOf(m_description, c.id));
        if (session->isSimulated())
            simulateMachine(m_description, c, session.get());
        watch(c.id, session.get());
        m_sessions.push_back(std::move(session));
    }
    m_setup = new MachineSetup(this);
    return true;
}

void Machine::destroy()
{
    // Whoever runs motion ends first, its stop posted while the sessions still exist.
    requestAbort();
    // Every session's destroy() stops its controller and flushes the stop before it closes;
    // they are told in turn, but none of them waits for I/O of another.
    for (auto& s : m_sessions)
        s->disconnect(this);
    delete std::exchange(m_setup, nullptr); // before the sessions it listens to
    m_switchOff->cancel();
    m_jogSessions.clear();
    m_targetJogs.clear(); // before the sessions they send to
    for (auto& s : m_sessions) {
        if (s.get() == m_lent) {
            (void)s.release(); // not this machine's to delete
            m_lent->destroy();
        }
    }
    m_sessions.clear();
    for (const PendingMove& m : std::as_const(m_moves))
        Q_EMIT moveFinished(m.id, false, tr("the machine was closed"));
    m_moves.clear();
    m_references->fail(nullptr, tr("the machine was closed"), false);
}

ControllerSession* Machine::session(const QString& controllerId) const
{
    for (qsizetype i = 0; i < m_description.controllers.size(); ++i) {
        if (m_description.controllers.at(i).id == controllerId && i < qsizetype(m_sessions.size()))
            return m_sessions.at(i).get();
    }
    return nullptr;
}

QString Machine::controllerIdOf(const ControllerSession* session) const
{
    for (size_t i = 0; i < m_sessions.size(); ++i) {
        if (m_sessions.at(i).get() == session)
            return m_description.controllers.at(qsizetype(i)).id;
    }
    return {};
}

void Machine::open()
{
    for (auto& s : m_sessions)
        s->open();
}

void Machine::close()
{
    for (auto& s : m_sessions)
        s->close();
}

QMap<QString, RequestId> Machine::stop()
{
    // Posted to every session (urgent: ahead of queued work) before anything is awaited:
    // a slow link never holds back the stop of another controller.
    QMap<QString, RequestId> ids;
    for (auto& s : m_sessions)
        ids.insert(controllerIdOf(s.get()), s->stop());
    releaseTargetJogs(); // no further jog targets (a target under way ends by itself)
    m_references->fail(nullptr, tr("referencing stopped"), false);
    switchOffSpindleAndCoolant(); // LinuxCNC's abort: once the axes stand
    requestAbort();
    return ids;
}

QMap<QString, RequestId> Machine::panic()
{
    QMap<QString, RequestId> ids;
    for (auto& s : m_sessions)
        ids.insert(controllerIdOf(s.get()), s->panic());
    releaseTargetJogs();
    m_references->fail(nullptr, tr("referencing stopped by the panic stop"), false);
    switchOffSpindleAndCoolant(); // LinuxCNC's emergency stop
    requestAbort();
    return ids;
}

void Machine::requestAbort()
{
    // The holder's own abort stops the machine again (ProgramRunner::abort): told once.
    if (std::exchange(m_abortRequesting, true))
        return;
    Q_EMIT abortRequested();
    m_abortRequesting = false;
}

bool Machine::claimMotion(const QObject* owner, const QString& what, QString* why)
{
    const bool wasFree = m_owner.isFree();
    if (!m_owner.claim(owner, what, why))
        return false;
    if (wasFree)
        Q_EMIT motionHolderChanged();
    return true;
}

QString Machine::motionRefusal(const QObject* owner) const
{
    if (m_owner.isHeldBy(owner) || m_owner.admitsManualMotion())
        return {};
    return tr("%1: the machine moves for it alone until it ends or holds").arg(m_owner.holder());
}

void Machine::releaseMotion(const QObject* owner)
{
    if (!m_owner.isHeldBy(owner))
        return;
    m_owner.release(owner);
    Q_EMIT motionHolderChanged();
}

void Machine::switchOffSpindleAndCoolant()
{
    m_switchOff->start();
}

bool Machine::isSwitchingOff() const
{
    return m_switchOff->isRunning();
}

void Machine::watch(const QString& controllerId, ControllerSession* session)
{
    connect(session, &ControllerSession::linkStateChanged, this,
            [this, controllerId](LinkState state, const QString& reason) {
                onLinkState(controllerId, state, reason);
            });
    connect(session, &ControllerSession::statusChanged, this, [this, session] {
        onStatus(session);
        m_references->onStatus(session);
        m_switchOff->onStatus(session);
        Q_EMIT statusChanged();
    });
    connect(session, &ControllerSession::requestFinished, this,
            [this, session, controllerId](const CommandResult& r) {
                onResult(session, r);
                m_references->onResult(session, r);
                m_switchOff->onResult(session, r);
                Q_EMIT requestFinished(controllerId, r);
            });
}

void Machine::onLinkState(const QString& controllerId, LinkState state, const QString& reason)
{
    Q_EMIT statusChanged();
    if (state != LinkState::Lost)
        return;
    ControllerSession* lost = session(controllerId);
    m_switchOff->onLinkLost(lost);
    stopAllBut(lost);
    const QString message = tr("controller \"%1\" lost its link (%2): the other controllers were "
                               "told to stop")
                                .arg(controllerId, reason);
    Q_EMIT controllerFailed(controllerId, message);
    failMovesOf(lost, message);
    m_references->fail(nullptr, message, false);
}

void Machine::stopAllBut(const ControllerSession* failed)
{
    releaseTargetJogs();
    for (auto& s : m_sessions) {
        if (s.get() != failed && s->linkState() == LinkState::Connected &&
            s->capabilities().stopCommand)
            s->stop();
    }
}

MachineAxisStatus Machine::axisStatus(const MachineAxis& axis) const
{
    MachineAxisStatus out;
    out.axis = &axis;
    const ControllerSession* s = session(axis.controller);
    if (!s)
        return out;
    const AxisStatus a = s->status().axes.value(axis.axis);
    out.steps = a.position;
    out.position = axis.toUnits(a.position);
    out.moving = a.moving || a.jogging || a.motionUnknown;
    if (s->linkState() != LinkState::Connected || !a.positionKnown)
        out.known = PositionKnowledge::Unknown;
    else if (a.positionEstimated || a.motionUnknown)
        out.known = PositionKnowledge::Estimated;
    else
        out.known = PositionKnowledge::Referenced;
    return out;
}

MachineState Machine::state(QString* controllerId) const
{
    MachineState worst = MachineState::Idle;
    QString cause;
    for (size_t i = 0; i < m_sessions.size(); ++i) {
        const ControllerSession& s = *m_sessions.at(i);
        MachineState here = MachineState::Idle;
        if (s.linkState() == LinkState::Lost)
            here = MachineState::LinkLost;
        else if (s.linkState() != LinkState::Connected)
            here = MachineState::Disconnected;
        else if (s.status().panic)
            here = MachineState::Fault;
        else if (s.status().anyMoving())
            here = MachineState::Moving;
        if (int(here) > int(worst)) {
            worst = here;
            cause = m_description.controllers.at(qsizetype(i)).id;
        }
    }
    if (controllerId)
        *controllerId = cause;
    return worst;
}

} // namespace stepdeck::machine
