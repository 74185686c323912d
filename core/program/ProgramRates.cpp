#include "ProgramRates.h"
#include "ProgramLowering.h"
#include "ProgramUnits.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"

namespace stepdeck::program {

namespace {
// The controllers of a block's axes, in the machine's order.
QStringList controllersOf(const machine::MachineDescription& d, const ProgramBlock& block)
{
    QStringList ids;
    for (const machine::MachineController& c : d.controllers)
        for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it)
            if (const machine::MachineAxis* a = d.axis(it.key());
                a && a->controller == c.id && !ids.contains(c.id))
                ids << c.id;
    return ids;
}
} // namespace

QMap<RequestId, QString> ProgramRates::before(const ProgramBlock& block)
{
    const machine::MachineDescription& d = m_machine->description();
    if (block.kind == BlockKind::Rapid)
        return putBack(controllersOf(d, block));
    if (block.kind != BlockKind::Feed || !block.feed)
        return {};
    QMap<RequestId, QString> requests;
    for (const QString& id : controllersOf(d, block)) {
        ControllerSession* s = m_machine->session(id);
        const Capabilities caps = s->capabilities();
        if (!caps.feedRateParameter)
            continue; // the check refused such a program; Machine::move refuses it again
        const QString name = QString::fromLatin1(caps.feedRateParameter);
        // The same write the check judged (ProgramRules), against what the device holds.
        const ParameterSet rate = motion::MoveRates::feedRateWrite(
            d, id, caps, ProgramLowering::ratedMove(block, d), s->status().knownParameters,
            s->model()->schema.find(name));
        if (rate.isEmpty())
            continue;
        Controller& c = m_controllers[id];
        if (caps.feedRateSetsRapid) {
            const ParameterSpec* spec = s->model()->schema.find(name);
            // Read once, before the first write, where the device can say it; else the value
            // the adapter knows it holds (EMIS: written in this session or stored).
            if (c.fast.perAxis.isEmpty() && c.read == 0 && spec && spec->readable) {
                c.read = s->readParameters({name});
                requests.insert(c.read, id);
            } else if (c.fast.perAxis.isEmpty() && c.read == 0) {
                c.fast = s->status().knownParameters.value(name);
            }
            c.changed = true;
        }
        ParameterSet write = rate;
        write.insert(interpolationWrite(id, caps, block, s->status().knownParameters));
        requests.insert(s->writeParameters(write, false), id);
    }
    return requests;
}

ParameterSet ProgramRates::interpolationWrite(const QString& id, const Capabilities& caps,
                                              const ProgramBlock& block, const ParameterSet& known)
{
    if (!caps.interpolationParameter)
        return {};
    const machine::MachineDescription& d = m_machine->description();
    int moving = 0;
    for (auto it = block.axisRates.cbegin(); it != block.axisRates.cend(); ++it)
        if (const machine::MachineAxis* a = d.axis(it.key()); a && a->controller == id)
            ++moving;
    const QString name = QString::fromLatin1(caps.interpolationParameter);
    const QVariant held = known.value(name).global;
    if (moving < 2 || (held.isValid() && held.toBool()))
        return {};
    Controller& c = m_controllers[id];
    if (!c.interpolationWritten) {
        c.interpolationWritten = true;
        c.interpolationBefore = held;
    }
    return {{name, ParameterValue{QVariant(true), {}}}};
}

void ProgramRates::onResult(const QString& controllerId, const CommandResult& result)
{
    auto it = m_controllers.find(controllerId);
    if (it == m_controllers.end() || result.id != it->read)
        return;
    it->read = 0;
    if (!result.ok() || !result.value.canConvert<ParameterSet>())
        return;
    const ControllerSession* s = m_machine->session(controllerId);
    const QString name = QString::fromLatin1(s->capabilities().feedRateParameter);
    it->fast = result.value.value<ParameterSet>().value(name);
}

QString ProgramRates::cannotPutBack(const ProgramBlock& rapid) const
{
    const machine::MachineDescription& d = m_machine->description();
    for (const QString& id : controllersOf(d, rapid)) {
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

QMap<RequestId, QString> ProgramRates::restore()
{
    QMap<RequestId, QString> requests = putBack(m_controllers.keys());
    for (auto it = m_controllers.begin(); it != m_controllers.end(); ++it) {
        if (!std::exchange(it->interpolationWritten, false) || !it->interpolationBefore.isValid() ||
            it->interpolationBefore.toBool())
            continue; // not turned on by this run, or not known before: left on
        ControllerSession* s = m_machine->session(it.key());
        const QString name = QString::fromLatin1(s->capabilities().interpolationParameter);
        requests.insert(
            s->writeParameters({{name, ParameterValue{it->interpolationBefore, {}}}}, false),
            it.key());
    }
    return requests;
}

QMap<RequestId, QString> ProgramRates::putBack(const QStringList& controllers)
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

} // namespace stepdeck::program
