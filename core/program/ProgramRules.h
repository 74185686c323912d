#pragma once
#include "ProgramBlock.h"
#include "machine/MachineDescription.h"
#include "model/Capabilities.h"
#include "model/ModelInfo.h"
#include "model/ParameterSchema.h"
#include <QCoreApplication>

namespace stepdeck::program {

// The rules a run refuses by that are known before it starts (issue 28). The check
// (ProgramPlan) and the run (ProgramRunner) both call these, so a rule cannot
// exist in one and not the other: what the run could refuse from what is known, the check
// refuses first. Pure.
class ProgramRules
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramRules)
public:
    // Why the controller would refuse writing `set`: the schema's ranges, then the model's own
    // rules (ModelInfo::parameterRules) against what the device is known to hold. Empty: it
    // takes it.
    static QString parameterWrite(const ParameterSchema& schema, const Capabilities& caps,
                                  const ParameterRules& modelRules, const ParameterSet& set,
                                  const ParameterSet& known);

    // A move on a controller that reports its setup incomplete (MachineStatus::setupIncomplete,
    // E-LAB tmInvSetup) is refused by the device: the parameters to write first
    // (ModelInfo::setupBeforeMotion, by their labels). Empty when the setup is complete.
    static QString setupIncomplete(const ParameterSchema& schema,
                                   const QStringList& setupBeforeMotion, bool incomplete);
};

} // namespace stepdeck::program
