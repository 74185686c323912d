// What the check knows of a machine (ProgramCheck.h), gathered from a running Machine. (Its
// own file: only what reads a live Machine links the Machine.)
#include "ProgramCheck.h"
#include "machine/Machine.h"
#include <algorithm>

namespace stepdeck::program {

MachineFacts factsOf(const machine::Machine& machine)
{
    MachineFacts facts;
    facts.description = machine.description();
    for (const machine::MachineController& c : facts.description.controllers) {
        if (const ControllerSession* session = machine.session(c.id)) {
            facts.capabilities.insert(c.id, session->capabilities());
            facts.schemas.insert(c.id, session->schema());
            facts.models.insert(c.id, session->model());
            facts.knownParameters.insert(c.id, session->status().knownParameters);
            // The status word lags a write by up to a poll: what this session wrote of the
            // setup the device wants (ModelInfo::setupBeforeMotion, acknowledged, and forgotten
            // when the device lost it) completes it even before the next read says so.
            const ParameterSet& known = session->status().knownParameters;
            const QStringList& wanted = session->model()->setupBeforeMotion;
            const bool written = !wanted.isEmpty() &&
                                 std::all_of(wanted.cbegin(), wanted.cend(),
                                             [&](const QString& n) { return known.contains(n); });
            if (session->status().setupIncomplete && !written)
                facts.setupIncomplete.insert(c.id);
        }
    }
    // Only positions the devices confirmed (read back, or referenced): Machine::move refuses
    // an absolute move from an estimated position, so the check does not count on one.
    for (const machine::MachineAxis& axis : facts.description.axes) {
        const machine::MachineAxisStatus status = machine.axisStatus(axis);
        if (status.known == machine::PositionKnowledge::Referenced)
            facts.knownPositions.insert(axis.name, status.position);
    }
    return facts;
}

} // namespace stepdeck::program
