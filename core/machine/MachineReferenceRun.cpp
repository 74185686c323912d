// Machine::reference and MachineReferenceRun: referencing in the machine file's order (issue 19,
// docs/machines.md).
#include "MachineReferenceRun.h"
#include "Machine.h"
#include <algorithm>

namespace stepdeck::machine {

namespace {
// A run that shows no motion this long after its request was accepted did not start.
constexpr qint64 kStartGraceMs = 3000;

} // namespace

// The file's direction is in the machine's sense (like a LinuxCNC home search velocity), so an
// inverted axis searches the other way at the controller; without one the search goes
// negative, as the GUI's default. Models that choose the direction themselves (EMIS 9.9) take
// 1: "reference this axis".
int referenceSearchDirection(const MachineAxis& axis, const Capabilities& capabilities)
{
    if (!capabilities.referenceDirection)
        return 1;
    const int machineDirection = axis.referenceDirection != 0 ? axis.referenceDirection : -1;
    return axis.invert ? -machineDirection : machineDirection;
}

quint64 Machine::reference(const QStringList& axes, QString* refusal, const QObject* owner)
{
    const quint64 id = m_lastMove + 1;
    // The operator's (no owner) holds the motion itself while it runs.
    const QObject* holder = owner ? owner : &m_referenceToken;
    QString why = motionRefusal(holder);
    const bool claims = why.isEmpty() && !owner && m_owner.isFree();
    if (claims)
        claimMotion(holder, tr("a reference run is under way"));
    if (why.isEmpty())
        why = m_references->start(id, axes);
    if (!why.isEmpty() && claims)
        releaseMotion(holder);
    if (!why.isEmpty()) {
        if (refusal)
            *refusal = why;
        return 0;
    }
    m_lastMove = id;
    return id;
}

bool Machine::isReferencing() const
{
    return m_references->isRunning();
}

QString MachineReferenceRun::start(quint64 id, const QStringList& axes)
{
    QList<QList<const MachineAxis*>> groups;
    const QString why = check(axes, &groups);
    if (!why.isEmpty())
        return why;
    m_run = Run{id, groups, {}};
    startGroup();
    return {};
}

QString MachineReferenceRun::check(const QStringList& axes,
                                   QList<QList<const MachineAxis*>>* groups) const
{
    if (m_run)
        return tr("a reference run is going already");
    for (const QString& name : axes) {
        if (!m_machine.description().axis(name))
            return tr("the machine has no axis %1").arg(name);
        if (axes.count(name) > 1)
            return tr("axis %1 is named twice").arg(name);
    }
    for (const QList<const MachineAxis*>& all : m_machine.description().referenceGroups()) {
        QList<const MachineAxis*> group;
        for (const MachineAxis* a : all) {
            if (!axes.isEmpty() && !axes.contains(a->name))
                continue;
            const ControllerSession* s = m_machine.session(a->controller);
            if (s->linkState() != LinkState::Connected)
                return tr("%1: controller \"%2\" is not connected").arg(a->name, a->controller);
            if (!s->capabilities().has(MotionMode::Reference))
                return tr("%1: controller \"%2\" has no reference run").arg(a->name, a->controller);
            group << a;
        }
        if (!group.isEmpty())
            *groups << group;
    }
    if (groups->isEmpty())
        return tr("no axis to reference");
    return {};
}

void MachineReferenceRun::startGroup()
{
    Run& run = *m_run;
    run.parts.clear();
    QStringList names;
    for (const MachineAxis* a : run.groups.constFirst()) {
        ControllerSession* s = m_machine.session(a->controller);
        auto part = std::find_if(run.parts.begin(), run.parts.end(),
                                 [s](const Part& p) { return p.session == s; });
        if (part == run.parts.end()) {
            part = run.parts.insert(run.parts.end(), Part{});
            part->session = s;
        }
        part->directions.insert(a->axis, referenceSearchDirection(*a, s->capabilities()));
        names << a->name;
    }
    // Every controller is checked before any is sent: a link lost since the last group fails
    // the run before anything of this group moves.
    for (const Part& p : std::as_const(run.parts)) {
        if (p.session->linkState() != LinkState::Connected)
            return fail(p.session,
                        tr("controller \"%1\" is not connected: referencing stopped")
                            .arg(m_machine.controllerIdOf(p.session)),
                        true);
    }
    Q_EMIT m_machine.referenceGroupStarted(run.id, names);
    // Back to back, as the parts of a move.
    for (Part& p : run.parts)
        p.request = p.session->reference(p.directions);
}

void MachineReferenceRun::onResult(ControllerSession* session, const CommandResult& result)
{
    if (!m_run || result.id == 0)
        return;
    for (Part& part : m_run->parts) {
        if (part.session != session || result.id != part.request)
            continue;
        if (!result.ok())
            return fail(session,
                        tr("controller \"%1\": referencing failed: %2")
                            .arg(m_machine.controllerIdOf(session), result.message),
                        true);
        part.accepted = true;
        part.acceptedAt.start();
        // Models that report arrival finish the request only when the run is over: the status
        // published before this result is the evidence, and no poll follows.
        if (session->capabilities().reportsArrival)
            part.sawMotion = true;
        onStatus(session);
        return;
    }
}

void MachineReferenceRun::onStatus(ControllerSession* session)
{
    if (!m_run)
        return;
    for (Part& part : m_run->parts) {
        if (part.session != session || part.done)
            continue;
        QString failure;
        if (!evaluate(part, &failure))
            return fail(session, failure, true);
    }
    finishGroupIfDone();
}

// False: the part failed (*failure says why, naming the controller).
bool MachineReferenceRun::evaluate(Part& part, QString* failure)
{
    const MachineStatus& status = part.session->status();
    bool allReferenced = true;
    bool movingNow = status.busy;
    for (auto it = part.directions.cbegin(); it != part.directions.cend(); ++it) {
        const AxisStatus a = status.axes.value(it.key());
        allReferenced = allReferenced && a.referenced;
        movingNow = movingNow || a.moving || a.motionUnknown;
    }
    if (!part.accepted)
        return true;
    part.sawMotion = part.sawMotion || movingNow;
    part.sawUnreferenced = part.sawUnreferenced || !allReferenced;
    // A status from before the run may still say "referenced": evidence of the run first.
    if (allReferenced && !movingNow && (part.sawMotion || part.sawUnreferenced)) {
        part.done = true;
        return true;
    }
    if (!movingNow && (part.sawMotion || part.acceptedAt.elapsed() > kStartGraceMs)) {
        *failure = tr("controller \"%1\": the reference run ended before the reference switch "
                      "was reached")
                       .arg(m_machine.controllerIdOf(part.session));
        return false;
    }
    return true;
}

void MachineReferenceRun::finishGroupIfDone()
{
    if (!m_run)
        return;
    const auto& parts = m_run->parts;
    if (!std::all_of(parts.cbegin(), parts.cend(), [](const Part& p) { return p.done; }))
        return;
    m_run->groups.removeFirst();
    if (!m_run->groups.isEmpty())
        return startGroup();
    const quint64 id = m_run->id;
    m_run.reset();
    Q_EMIT m_machine.referenceFinished(id, true, QString());
}

void MachineReferenceRun::fail(const ControllerSession* session, const QString& message,
                               bool stopAll)
{
    if (!m_run)
        return;
    const quint64 id = m_run->id;
    m_run.reset();
    if (stopAll)
        m_machine.stopAllBut(nullptr); // the failed controller too: its other axes may be running
    if (session)
        Q_EMIT m_machine.controllerFailed(m_machine.controllerIdOf(session), message);
    Q_EMIT m_machine.referenceFinished(id, false, message);
}

} // namespace stepdeck::machine
