#pragma once
#include "model/Capabilities.h"
#include "model/ModelInfo.h"
#include "model/ParameterSchema.h"
#include <QStringList>
#include <optional>

namespace stepdeck::machine {

class Machine;

// What a machine knows of one of its controllers now: for the program layer (the check's
// MachineFacts, the run), which reaches the controllers through the machine and its executors
// only (issue 49: no ControllerSession in core/program).
struct ControllerFacts
{
    Capabilities capabilities;
    ParameterSchema schema;
    const ModelInfo* model = nullptr;
    ParameterSet knownParameters; // the values the device is known to hold
    // The device refuses every move until its setup is written (MachineStatus::
    // setupIncomplete, E-LAB tmInvSetup). The status word lags a write by up to a poll: what
    // this session wrote of the setup the device wants (ModelInfo::setupBeforeMotion,
    // acknowledged, and forgotten when the device lost it) completes it even before the next
    // read says so.
    bool setupIncomplete = false;
};
// nullopt: the machine has no such controller (or was not created).
std::optional<ControllerFacts> controllerFacts(const Machine& machine, const QString& id);

// The machine's controllers without a stop command (Capabilities::stopCommand: EMIS, laser
// axes), in the file's order: a move under way there runs out after a stop.
QStringList controllersWithoutStop(const Machine& machine);

// The machine has that controller and its link is not up (lost, closed, connecting).
bool linkDown(const Machine& machine, const QString& id);

} // namespace stepdeck::machine
