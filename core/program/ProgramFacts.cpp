// What the check knows of a machine (ProgramCheck.h), gathered from a running Machine. (Its
// own file: only what reads a live Machine links the Machine.)
#include "ProgramCheck.h"
#include "machine/ControllerFacts.h"
#include "machine/Machine.h"

namespace stepdeck::program {

MachineFacts factsOf(const machine::Machine& machine)
{
    MachineFacts facts;
    facts.description = machine.description();
    for (const machine::MachineController& c : facts.description.controllers) {
        if (std::optional<machine::ControllerFacts> f = machine::controllerFacts(machine, c.id)) {
            facts.capabilities.insert(c.id, std::move(f->capabilities));
            facts.schemas.insert(c.id, std::move(f->schema));
            facts.models.insert(c.id, f->model);
            facts.knownParameters.insert(c.id, std::move(f->knownParameters));
            if (f->setupIncomplete)
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
