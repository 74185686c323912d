// What the check knows of a machine (ProgramCheck.h), gathered from a running Machine. (Its
// own file: only what reads a live Machine links the Machine.)
#include "ProgramCheck.h"
#include "machine/Machine.h"

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
            if (session->status().setupIncomplete)
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
