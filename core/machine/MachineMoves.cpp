// Machine::move: a positioning of axes on several controllers, checked as a whole, sent back
// to back, finished when every controller has confirmed arrival (issue 19).
#include "Machine.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::machine {

namespace {
bool restsAt(const MachineStatus& status, const QList<Axis>& axes)
{
    for (Axis axis : axes) {
        const AxisStatus a = status.axes.value(axis);
        if (a.moving || a.jogging || a.motionUnknown)
            return false;
    }
    return true;
}
} // namespace

quint64 Machine::move(const QMap<QString, double>& units, bool absolute, QString* refusal,
                      MoveKind kind, const QObject* owner)
{
    QList<StepTargets> plan;
    QString why = motionRefusal(owner);
    if (why.isEmpty())
        why = checkMove(units, absolute, kind, &plan);
    if (!why.isEmpty()) {
        if (refusal)
            *refusal = why;
        return 0;
    }
    PendingMove pending{++m_lastMove, {}};
    // Back to back: every part is posted before any result is looked at.
    for (const StepTargets& t : std::as_const(plan)) {
        Part part;
        part.session = t.session;
        part.axes = t.steps.keys();
        if (t.session->capabilities().positionReadback) {
            for (auto it = t.steps.cbegin(); it != t.steps.cend(); ++it) {
                const qint64 from = t.session->status().axes.value(it.key()).position;
                part.expected.insert(it.key(), absolute ? it.value() : from + it.value());
            }
        }
        if (kind == MoveKind::Feed && t.session->capabilities().feedRateUsesFeedMode) {
            // A feed move counts from where the axes stand (absolute targets made relative).
            AxisVector relative = t.steps;
            if (absolute)
                for (auto it = relative.begin(); it != relative.end(); ++it)
                    it.value() -= t.session->status().axes.value(it.key()).position;
            part.request = t.session->feed(relative);
        } else {
            part.request =
                absolute ? t.session->moveAbsolute(t.steps) : t.session->moveRelative(t.steps);
        }
        pending.parts << part;
    }
    m_moves << pending;
    return pending.id;
}

QString Machine::checkMove(const QMap<QString, double>& units, bool absolute, MoveKind kind,
                           QList<StepTargets>* plan) const
{
    if (units.isEmpty())
        return tr("no axis to move");
    for (auto it = units.cbegin(); it != units.cend(); ++it) {
        const MachineAxis* axis = m_description.axis(it.key());
        if (!axis)
            return tr("the machine has no axis %1").arg(it.key());
        ControllerSession* s = session(axis->controller);
        if (s->linkState() != LinkState::Connected)
            return tr("%1: controller \"%2\" is not connected").arg(axis->name, axis->controller);
        if (kind == MoveKind::Feed && !s->capabilities().feedRateParameter)
            return tr("%1: controller \"%2\" takes no feed rate").arg(axis->name, axis->controller);
        qint64 steps = 0;
        const QString why = checkAxisTarget(*axis, it.value(), absolute, &steps);
        if (!why.isEmpty())
            return why;
        auto target = std::find_if(plan->begin(), plan->end(),
                                   [s](const StepTargets& t) { return t.session == s; });
        if (target == plan->end())
            target = plan->insert(plan->end(), StepTargets{s, {}});
        target->steps.insert(axis->axis, steps);
    }
    for (const StepTargets& t : std::as_const(*plan)) {
        // The controller's own rules (its soft limits in steps, as the session enforces them),
        // asked before anything is sent, so that no part starts when another would be refused.
        const MachineStatus& status = t.session->status();
        const QString why = absolute ? t.session->softLimits().checkTargets(status, t.steps)
                                     : t.session->softLimits().checkRelative(status, t.steps);
        if (!why.isEmpty())
            return tr("controller \"%1\": %2").arg(controllerIdOf(t.session), why);
    }
    return {};
}

QString Machine::checkAxisTarget(const MachineAxis& axis, double value, bool absolute,
                                 qint64* steps) const
{
    if (!std::isfinite(value))
        return tr("%1: the target is not a finite number").arg(axis.name);
    const ControllerSession* s = session(axis.controller);
    const AxisStatus a = s->status().axes.value(axis.axis);
    const bool referenced = a.positionKnown && !a.positionEstimated;
    // Controllers that report arrival (laser motor axes) take targets in the device's own
    // absolute coordinates: their adapter judges an absolute target, not the host's count.
    const bool deviceAbsolute = s->capabilities().reportsArrival;
    if (absolute && !referenced && !deviceAbsolute)
        return tr("%1 is not referenced: its position is unknown, so an absolute move could go "
                  "anywhere")
            .arg(axis.name);
    const double here = axis.toUnits(a.position);
    const double to = absolute ? value : here + value;
    if (axis.hasSoftLimits() && (referenced || absolute) &&
        (to < *axis.softMinimum || to > *axis.softMaximum))
        return tr("%1 %2 %3 is outside the soft limits %4..%5")
            .arg(axis.name)
            .arg(to)
            .arg(unitKey(axis.unit))
            .arg(*axis.softMinimum)
            .arg(*axis.softMaximum);
    *steps = absolute ? axis.toSteps(value) : axis.toSteps(to) - axis.toSteps(here);
    return {};
}

void Machine::onResult(ControllerSession* session, const CommandResult& result)
{
    for (qsizetype m = 0; m < m_moves.size(); ++m) {
        PendingMove& pending = m_moves[m];
        for (Part& part : pending.parts) {
            // Only this part's own requests (the poller's requests finish with id 0).
            const bool own = result.id != 0 && (result.id == part.request ||
                                                (part.accepted && result.id == part.refresh));
            if (part.session != session || !own)
                continue;
            if (!onPartResult(part, result)) {
                const PendingMove failed = m_moves.takeAt(m);
                const QString id = controllerIdOf(session);
                const QString message = tr("controller \"%1\": %2").arg(id, result.message);
                stopAllBut(nullptr); // the failed one too: its other axes may be moving
                Q_EMIT controllerFailed(id, message);
                Q_EMIT moveFinished(failed.id, false, message);
                return;
            }
            finishArrivedMoves();
            return;
        }
    }
}

// False: the part failed.
bool Machine::onPartResult(Part& part, const CommandResult& result)
{
    if (!result.ok())
        return false;
    if (result.id == part.request) {
        part.accepted = true;
        part.endSwitch = result.value.toMap().value(QStringLiteral("endSwitch")).toStringList();
        // The request itself ended with the axes' arrival, or the status cannot show the move
        // at rest before it ran: no read of its own is needed.
        const Capabilities caps = part.session->capabilities();
        if (caps.reportsArrival || caps.statusHoldsStartedMove)
            part.refreshed = true;
        else
            part.refresh = part.session->refreshStatus();
    } else {
        part.refreshed = true;
    }
    return true;
}

void Machine::onStatus(ControllerSession* session)
{
    Q_UNUSED(session);
    finishArrivedMoves();
}

void Machine::finishArrivedMoves()
{
    for (qsizetype m = m_moves.size() - 1; m >= 0; --m) {
        bool done = true;
        QStringList shortOf;
        for (const Part& part : std::as_const(m_moves.at(m).parts)) {
            done = done && part.accepted && part.refreshed &&
                   restsAt(part.session->status(), part.axes);
            shortOf << shortOfTarget(part);
        }
        if (!done || (!shortOf.isEmpty() && confirmShortStops(m_moves[m])))
            continue;
        const quint64 id = m_moves.takeAt(m).id;
        // At rest but not where it was sent (a limit switch, a stop from elsewhere): the
        // machine never claims an arrival the devices did not report.
        if (!shortOf.isEmpty())
            Q_EMIT moveFinished(
                id, false,
                tr("the move ended before its target: %1").arg(shortOf.join(QStringLiteral("; "))));
        else
            Q_EMIT moveFinished(id, true, QString());
    }
}

// True while a part that seems to rest short of its target is read once more: the move
// ends short only when a second status read, asked for after the first, says so too.
bool Machine::confirmShortStops(PendingMove& move)
{
    bool asked = false;
    for (Part& part : move.parts) {
        if (part.confirmingShort || part.session->capabilities().reportsArrival ||
            shortOfTarget(part).isEmpty())
            continue;
        part.confirmingShort = true;
        part.refreshed = false;
        part.refresh = part.session->refreshStatus();
        asked = true;
    }
    return asked;
}

QStringList Machine::shortOfTarget(const Part& part) const
{
    QStringList out;
    const MachineStatus& status = part.session->status();
    for (Axis axis : part.axes) {
        const AxisStatus a = status.axes.value(axis);
        const QString name = machineAxisName(part.session, axis);
        const MachineAxis* machineAxis = m_description.axis(name);
        if (part.endSwitch.contains(axisName(axis))) {
            out << tr("%1 stopped at its end switch").arg(name);
        } else if (a.limitSwitch) {
            out << tr("%1 is on its limit switch").arg(name);
        } else if (part.expected.contains(axis) && a.position != part.expected.value(axis) &&
                   machineAxis) {
            out << tr("%1 stands at %2 %3, not at %4")
                       .arg(name)
                       .arg(machineAxis->toUnits(a.position))
                       .arg(unitKey(machineAxis->unit))
                       .arg(machineAxis->toUnits(part.expected.value(axis)));
        }
    }
    return out;
}

QString Machine::machineAxisName(const ControllerSession* session, Axis axis) const
{
    const QString controllerId = controllerIdOf(session);
    for (const MachineAxis& a : m_description.axes) {
        if (a.controller == controllerId && a.axis == axis)
            return a.name;
    }
    return axisName(axis);
}

void Machine::failMovesOf(const ControllerSession* session, const QString& message)
{
    for (qsizetype m = m_moves.size() - 1; m >= 0; --m) {
        const auto& parts = m_moves.at(m).parts;
        const bool involved = std::any_of(parts.cbegin(), parts.cend(), [session](const Part& p) {
            return p.session == session;
        });
        if (involved) {
            const quint64 id = m_moves.takeAt(m).id;
            Q_EMIT moveFinished(id, false, message);
        }
    }
}

} // namespace stepdeck::machine
