#pragma once
#include "ProgramBlock.h"
#include "machine/MachineDescription.h"
#include "model/Capabilities.h"
#include "model/ModelInfo.h"
#include "model/ParameterSchema.h"
#include <QCoreApplication>

namespace stepdeck::program {

// The rules a run refuses by that are known before it starts (issue 28). The check
// (ProgramPlan) and the run (ProgramRates, ProgramRunner) both call these, so a rule cannot
// exist in one and not the other: what the run could refuse from what is known, the check
// refuses first. Pure.
class ProgramRules
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramRules)
public:
    // The feed-rate write of a G1 on one controller (docs/programs.md "How F maps onto each
    // model"): the model's feed-rate parameter with a rate in steps/s for each axis of the
    // block on that controller. Where the model writes every axis at once
    // (Capabilities::feedRateWholeSet, E-LAB <FS>) its axes that do not move get a value too:
    // the one the device is known to hold (known), else the block's slowest rate on that
    // controller (a rate the moving axes are refused for first), so the write never depends on
    // a value nobody wrote. Empty when the controller takes no rate or the block has no F.
    // rateSpec: the feed-rate parameter's spec in the model's schema (null: not known). Each
    // axis' rate is FeedLimit::axisRate's: above the highest the controller runs it at, that
    // highest (issue 50), unless the machine file refuses such feeds.
    static ParameterSet feedRateWrite(const machine::MachineDescription& description,
                                      const QString& controller, const Capabilities& caps,
                                      const ProgramBlock& block, const ParameterSet& known,
                                      const ParameterSpec* rateSpec);

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
