// MachineSetup.h: a controller's setup from the machine file, written on every connect.
#include "MachineSetup.h"
#include "Machine.h"
#include "controller/ControllerSession.h"
#include "model/ModelInfo.h"

namespace stepdeck::machine {

namespace {

// Read back only where every value can be read (a write-only board's values cannot).
bool verifiable(const ModelInfo& model, const ParameterSet& set)
{
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = model.schema.find(it.key());
        if (!spec || !spec->readable)
            return false;
    }
    return !set.isEmpty();
}

} // namespace

MachineSetup::MachineSetup(Machine* machine) : QObject(machine)
{
    for (const MachineController& c : machine->description().controllers) {
        ControllerSession* s = machine->session(c.id);
        if (!s || c.setup.isEmpty())
            continue;
        connect(s, &ControllerSession::linkStateChanged, this,
                [this, c, s](LinkState state, const QString&) {
                    if (state == LinkState::Connected)
                        write(c, s);
                    else
                        m_writes.remove(c.id); // its result, if any, reports the failure
                });
        connect(s, &ControllerSession::requestFinished, this,
                [this, c](const CommandResult& r) { onResult(c, r); });
    }
}

void MachineSetup::write(const MachineController& c, ControllerSession* s)
{
    m_results.remove(c.id);
    m_writes.insert(c.id, s->writeParameters(c.setup, verifiable(*s->model(), c.setup)));
}

void MachineSetup::onResult(const MachineController& c, const CommandResult& r)
{
    const auto it = m_writes.constFind(c.id);
    if (it == m_writes.cend() || it.value() != r.id)
        return;
    m_writes.erase(it);
    m_results.insert(c.id, r);
    if (r.ok())
        Q_EMIT written(c.id, true,
                       tr("controller \"%1\": wrote its setup from %2 (%n parameter(s))", nullptr,
                          int(c.setup.size()))
                           .arg(c.id, c.setupFile));
    else
        Q_EMIT written(c.id, false,
                       tr("controller \"%1\": writing its setup from %2 failed: %3")
                           .arg(c.id, c.setupFile, r.message));
}

} // namespace stepdeck::machine
