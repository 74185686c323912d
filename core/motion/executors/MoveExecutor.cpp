#include "MoveExecutor.h"
#include "Logging.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"

namespace stepdeck::motion {

MoveExecutor::MoveExecutor(machine::Machine* machine, const QObject* owner, QObject* parent)
    : QObject(parent), m_machine(machine), m_owner(owner)
{
    connect(machine, &machine::Machine::requestFinished, this, &MoveExecutor::onRequestFinished);
    connect(machine, &machine::Machine::moveFinished, this, &MoveExecutor::onMoveFinished);
    connect(machine, &machine::Machine::referenceFinished, this, &MoveExecutor::onMoveFinished);
}

void MoveExecutor::push(const Reference& reference)
{
    m_move = RatedMove{};
    m_move.line = reference.line;
    QStringList axes; // none: every axis
    for (int a : reference.axes)
        if (a >= 0 && a < m_machine->description().axes.size())
            axes << m_machine->description().axes.at(a).name;
    QString refusal;
    started(m_machine->reference(axes, &refusal, m_owner), refusal);
}

QString MoveExecutor::referenceRefusal(const Capabilities& caps, const QString& axis,
                                       const QString& controller)
{
    if (caps.has(MotionMode::Reference))
        return {};
    return tr("%1: controller \"%2\" has no reference run (G28)").arg(axis, controller);
}

QString MoveExecutor::relativeRefusal(const Capabilities& caps, const QString& axis,
                                      const QString& controller)
{
    if (!caps.relativeNeedsPosition)
        return {};
    return tr("%1: controller \"%2\" moves to targets only, so a relative move (G91) needs the "
              "axis' position: home it (G28 %1) or move it to an absolute target first")
        .arg(axis, controller);
}

void MoveExecutor::started(quint64 id, const QString& refusal)
{
    m_motion = id;
    if (m_motion == 0)
        Q_EMIT finished(false, ErrorKind::Refused, refusal);
}

// The controllers of a move's axes, in the machine's order.
QStringList MoveExecutor::controllersOf(const RatedMove& move) const
{
    QStringList ids;
    const machine::MachineDescription& d = m_machine->description();
    for (const machine::MachineController& c : d.controllers)
        for (const auto& [axis, value] : move.targets)
            if (axis >= 0 && axis < d.axes.size() && d.axes.at(axis).controller == c.id &&
                !ids.contains(c.id))
                ids << c.id;
    return ids;
}

void MoveExecutor::push(const RatedMove& move)
{
    m_move = move;
    const QMap<RequestId, QString> requests =
        move.feed ? rateWrites(move) : putBack(controllersOf(move));
    m_requests.clear();
    for (auto it = requests.cbegin(); it != requests.cend(); ++it)
        m_requests.insert(it.key());
    m_pending = !m_requests.isEmpty();
    if (!m_pending)
        sendMove();
}

QMap<RequestId, QString> MoveExecutor::rateWrites(const RatedMove& move)
{
    const machine::MachineDescription& d = m_machine->description();
    QMap<RequestId, QString> requests;
    for (const QString& id : controllersOf(move)) {
        ControllerSession* s = m_machine->session(id);
        const Capabilities caps = s->capabilities();
        if (!caps.feedRateParameter)
            continue; // the check refused such a program; Machine::move refuses it again
        const QString name = QString::fromLatin1(caps.feedRateParameter);
        const ParameterSpec* spec = s->model()->schema.find(name);
        // The same write the check judged, against what the device holds.
        const ParameterSet known = s->status().knownParameters;
        const ParameterSet rate = MoveRates::feedRateWrite(d, id, caps, move, known, spec);
        if (rate.isEmpty())
            continue;
        Controller& c = m_controllers[id];
        if (caps.feedRateSetsRapid) {
            // Read once, before the first write, where the device can say it; else the value
            // the adapter knows it holds (EMIS: written in this session or stored).
            if (c.fast.perAxis.isEmpty() && c.read == 0 && spec && spec->readable) {
                c.read = s->readParameters({name});
                requests.insert(c.read, id);
            } else if (c.fast.perAxis.isEmpty() && c.read == 0) {
                c.fast = known.value(name);
            }
            c.changed = true;
        }
        ParameterSet write = rate;
        write.insert(interpolationWrite(id, caps, move, known));
        requests.insert(s->writeParameters(write, false), id);
    }
    return requests;
}

ParameterSet MoveExecutor::interpolationWrite(const QString& id, const Capabilities& caps,
                                              const RatedMove& move, const ParameterSet& known)
{
    if (!caps.interpolationParameter)
        return {};
    const machine::MachineDescription& d = m_machine->description();
    int together = 0;
    for (const AxisSpeed& s : move.speeds)
        if (s.together && s.axis >= 0 && s.axis < d.axes.size() &&
            d.axes.at(s.axis).controller == id)
            ++together;
    const QString name = QString::fromLatin1(caps.interpolationParameter);
    const QVariant held = known.value(name).global;
    if (together < 2 || (held.isValid() && held.toBool()))
        return {};
    Controller& c = m_controllers[id];
    if (!c.interpolationWritten) {
        c.interpolationWritten = true;
        c.interpolationBefore = held;
    }
    return {{name, ParameterValue{QVariant(true), {}}}};
}

QString MoveExecutor::cannotPutBack(const RatedMove& move) const
{
    const machine::MachineDescription& d = m_machine->description();
    for (const QString& id : controllersOf(move)) {
        const auto it = m_controllers.constFind(id);
        if (it == m_controllers.cend() || !it->changed || it->read != 0)
            continue;
        bool known = !it->fast.perAxis.isEmpty();
        for (const machine::MachineAxis& a : d.axes)
            known = known && (a.controller != id || it->fast.perAxis.contains(a.axis));
        if (!known)
            return tr("controller \"%1\": its fast speed is no longer known, so G0 would run "
                      "at the last F; the program stops here")
                .arg(id);
    }
    return {};
}

QMap<RequestId, QString> MoveExecutor::restore()
{
    if (!m_machine)
        return {};
    QMap<RequestId, QString> requests = putBack(m_controllers.keys());
    for (auto it = m_controllers.begin(); it != m_controllers.end(); ++it) {
        if (!std::exchange(it->interpolationWritten, false) || !it->interpolationBefore.isValid() ||
            it->interpolationBefore.toBool())
            continue; // not turned on here, or not known before: left on
        ControllerSession* s = m_machine->session(it.key());
        const QString name = QString::fromLatin1(s->capabilities().interpolationParameter);
        requests.insert(
            s->writeParameters({{name, ParameterValue{it->interpolationBefore, {}}}}, false),
            it.key());
    }
    return requests;
}

QMap<RequestId, QString> MoveExecutor::putBack(const QStringList& controllers)
{
    QMap<RequestId, QString> requests;
    for (const QString& id : controllers) {
        auto it = m_controllers.find(id);
        if (it == m_controllers.end() || !it->changed || it->fast.perAxis.isEmpty())
            continue; // unchanged, or not readable: the check refuses G0 after G1 there
        ControllerSession* s = m_machine->session(id);
        const QString name = QString::fromLatin1(s->capabilities().feedRateParameter);
        requests.insert(s->writeParameters({{name, it->fast}}, false), id);
        it->changed = false;
    }
    return requests;
}

void MoveExecutor::sendMove()
{
    m_pending = false;
    const machine::MachineDescription& d = m_machine->description();
    QMap<QString, double> targets;
    for (const auto& [axis, value] : m_move.targets)
        if (axis >= 0 && axis < d.axes.size())
            targets.insert(d.axes.at(axis).name, value);
    QString refusal;
    started(m_machine->move(targets, m_move.absolute, &refusal,
                            m_move.feed ? machine::Machine::MoveKind::Feed
                                        : machine::Machine::MoveKind::Positioning,
                            m_owner),
            refusal);
}

void MoveExecutor::dropPending()
{
    m_pending = false;
    m_requests.clear();
}

void MoveExecutor::forget()
{
    dropPending();
    m_motion = 0;
}

void MoveExecutor::onRequestFinished(const QString& controllerId, const CommandResult& result)
{
    if (result.id == 0)
        return;
    // A read before the first feed write keeps the fast speed to put back (also when the move
    // it came with was dropped: the device changed as written).
    if (auto it = m_controllers.find(controllerId);
        it != m_controllers.end() && result.id == it->read) {
        it->read = 0;
        if (result.ok() && result.value.canConvert<ParameterSet>()) {
            const QString name = QString::fromLatin1(
                m_machine->session(controllerId)->capabilities().feedRateParameter);
            it->fast = result.value.value<ParameterSet>().value(name);
        }
    }
    if (!m_pending || !m_requests.remove(result.id))
        return;
    if (!result.ok()) {
        dropPending();
        Q_EMIT finished(false, result.error,
                        tr("controller \"%1\": %2").arg(controllerId, result.message));
        return;
    }
    if (m_requests.isEmpty())
        sendMove();
}

void MoveExecutor::onMoveFinished(quint64 id, bool ok, const QString& message)
{
    if (id == 0 || id != m_motion)
        return;
    m_motion = 0;
    qCDebug(lcMotion) << "move of line" << m_move.line << (ok ? "arrived" : "ended:") << message;
    Q_EMIT finished(ok, ErrorKind::None, message);
}

} // namespace stepdeck::motion
