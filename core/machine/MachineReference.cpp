// Machine::reference: referencing in the machine file's order (issue 19, docs/machines.md).
#include "Machine.h"
#include <algorithm>

namespace stepdeck::machine {

namespace {
// A run that shows no motion this long after its request was accepted did not start (as the
// GUI's ReferenceRunner judges a single controller's run).
constexpr qint64 kStartGraceMs = 3000;

// The controller direction of an axis' reference run. The file's direction is in the
// machine's sense (like a LinuxCNC home search velocity), so an inverted axis searches the
// other way at the controller; without one the search goes negative, as the GUI's default.
// Models that choose the direction themselves (EMIS 9.9) take 1: "reference this axis".
int controllerDirection(const MachineAxis& axis, const Capabilities& capabilities)
{
    if (!capabilities.referenceDirection)
        return 1;
    const int machineDirection = axis.referenceDirection != 0 ? axis.referenceDirection : -1;
    return axis.invert ? -machineDirection : machineDirection;
}
} // namespace

quint64 Machine::reference(const QStringList& axes, QString* refusal)
{
    QList<QList<const MachineAxis*>> groups;
    const QString why = checkReference(axes, &groups);
    if (!why.isEmpty()) {
        if (refusal)
            *refusal = why;
        return 0;
    }
    m_reference = PendingReference{++m_lastMove, groups, {}};
    const quint64 id = m_reference->id;
    startReferenceGroup();
    return id;
}

QString Machine::checkReference(const QStringList& axes,
                                QList<QList<const MachineAxis*>>* groups) const
{
    if (m_reference)
        return tr("a reference run is going already");
    for (const QString& name : axes) {
        if (!m_description.axis(name))
            return tr("the machine has no axis %1").arg(name);
        if (axes.count(name) > 1)
            return tr("axis %1 is named twice").arg(name);
    }
    for (const QList<const MachineAxis*>& all : m_description.referenceGroups()) {
        QList<const MachineAxis*> group;
        for (const MachineAxis* a : all) {
            if (!axes.isEmpty() && !axes.contains(a->name))
                continue;
            const ControllerSession* s = session(a->controller);
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

void Machine::startReferenceGroup()
{
    PendingReference& run = *m_reference;
    run.parts.clear();
    QStringList names;
    for (const MachineAxis* a : run.groups.constFirst()) {
        ControllerSession* s = session(a->controller);
        auto part = std::find_if(run.parts.begin(), run.parts.end(),
                                 [s](const ReferencePart& p) { return p.session == s; });
        if (part == run.parts.end()) {
            part = run.parts.insert(run.parts.end(), ReferencePart{});
            part->session = s;
        }
        part->directions.insert(a->axis, controllerDirection(*a, s->capabilities()));
        names << a->name;
    }
    // Every controller is checked before any is sent: a link lost since the last group fails
    // the run before anything of this group moves.
    for (const ReferencePart& p : std::as_const(run.parts)) {
        if (p.session->linkState() != LinkState::Connected)
            return failReference(p.session,
                                 tr("controller \"%1\" is not connected: referencing stopped")
                                     .arg(controllerIdOf(p.session)),
                                 true);
    }
    Q_EMIT referenceGroupStarted(run.id, names);
    // Back to back, as the parts of a move.
    for (ReferencePart& p : run.parts)
        p.request = p.session->reference(p.directions);
}

void Machine::onReferenceResult(ControllerSession* session, const CommandResult& result)
{
    if (!m_reference || result.id == 0)
        return;
    for (ReferencePart& part : m_reference->parts) {
        if (part.session != session || result.id != part.request)
            continue;
        if (!result.ok())
            return failReference(session,
                                 tr("controller \"%1\": referencing failed: %2")
                                     .arg(controllerIdOf(session), result.message),
                                 true);
        part.accepted = true;
        part.acceptedAt.start();
        // Models that report arrival finish the request only when the run is over: the status
        // published before this result is the evidence, and no poll follows.
        if (session->capabilities().reportsArrival)
            part.sawMotion = true;
        onReferenceStatus(session);
        return;
    }
}

void Machine::onReferenceStatus(ControllerSession* session)
{
    if (!m_reference)
        return;
    for (ReferencePart& part : m_reference->parts) {
        if (part.session != session || part.done)
            continue;
        QString failure;
        if (!evaluateReferencePart(part, &failure))
            return failReference(session, failure, true);
    }
    finishReferenceGroupIfDone();
}

// False: the part failed (*failure says why, naming the controller).
bool Machine::evaluateReferencePart(ReferencePart& part, QString* failure)
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
                       .arg(controllerIdOf(part.session));
        return false;
    }
    return true;
}

void Machine::finishReferenceGroupIfDone()
{
    if (!m_reference)
        return;
    const auto& parts = m_reference->parts;
    if (!std::all_of(parts.cbegin(), parts.cend(), [](const ReferencePart& p) { return p.done; }))
        return;
    m_reference->groups.removeFirst();
    if (!m_reference->groups.isEmpty())
        return startReferenceGroup();
    const quint64 id = m_reference->id;
    m_reference.reset();
    Q_EMIT referenceFinished(id, true, QString());
}

void Machine::failReference(const ControllerSession* session, const QString& message, bool stopAll)
{
    if (!m_reference)
        return;
    const quint64 id = m_reference->id;
    m_reference.reset();
    if (stopAll)
        stopAllBut(nullptr); // the failed controller too: its other axes may be running
    if (session)
        Q_EMIT controllerFailed(controllerIdOf(session), message);
    Q_EMIT referenceFinished(id, false, message);
}

} // namespace stepdeck::machine
