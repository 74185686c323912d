// The check's part of ProgramRules (issue 28): what a controller would refuse of a block from
// what is known before the run starts (its parameter rules, its spindle range, an incomplete
// setup), judged by the same functions the run goes through.
#include "ProgramRules.h"
#include "ProgramSimulation.h"
#include <cmath>

namespace stepdeck::program {

namespace {
ParameterRules rulesOf(const MachineFacts& facts, const QString& controller)
{
    const ModelInfo* model = facts.models.value(controller);
    return model ? model->parameterRules : ParameterRules{};
}
} // namespace

// Why `controller` would refuse the rate write of `block` (*set: that write), or empty.
QString ProgramPlan::feedWriteRefusal(const QString& controller, const ProgramBlock& block,
                                      ParameterSet* set) const
{
    const Capabilities caps = m_facts.capabilities.value(controller);
    const ParameterSet known = m_known.value(controller);
    const auto schema = m_facts.schemas.constFind(controller);
    const ParameterSpec* spec = schema == m_facts.schemas.cend() || !caps.feedRateParameter
                                    ? nullptr
                                    : schema->find(QString::fromLatin1(caps.feedRateParameter));
    *set = motion::MoveRates::feedRateWrite(m_facts.description, controller, caps,
                                            ProgramLowering::ratedMove(block, m_facts.description),
                                            known, spec);
    if (set->isEmpty())
        return {};
    // A program's G1s mostly write the rate the one before wrote: judged once (the rules see
    // nothing but the write and what the device holds).
    JudgedWrite& last = m_judged[controller];
    if (last.valid && last.set == *set && last.known == known)
        return last.why;
    last = JudgedWrite{true, *set, known,
                       ProgramRules::parameterWrite(m_facts.schemas.value(controller), caps,
                                                    rulesOf(m_facts, controller), *set, known)};
    return last.why;
}

// G1's rate write on each controller of the block, as the run makes it (motion::MoveExecutor),
// against the model's own rules (E-LAB: feed speed below start speed, a value for every axis). A
// refusal names the highest F that would pass, where one does.
void ProgramPlan::checkFeedWrite(const ProgramBlock& block)
{
    // The G1 before wrote the same F over the same axes, every controller took it and nothing
    // the rules judge by changed since: this one is taken too (a CAM program's G1s mostly are).
    if (m_lastTakenFeed.matches(block))
        return;
    bool allTaken = true;
    bool changed = false;
    for (const machine::MachineController& c : m_facts.description.controllers) {
        ParameterSet set;
        const QString why = feedWriteRefusal(c.id, block, &set);
        if (set.isEmpty())
            continue;
        if (why.isEmpty()) {
            ParameterSet& known = m_known[c.id];
            for (auto it = set.cbegin(); it != set.cend(); ++it)
                for (auto a = it->perAxis.cbegin(); a != it->perAxis.cend(); ++a) {
                    QMap<Axis, QVariant>& held = known[it.key()].perAxis;
                    if (held.value(a.key()) != a.value()) {
                        held.insert(a.key(), a.value());
                        changed = true;
                        m_tickHeld.clear(); // a rate of its own replaced a contour's tick
                    }
                }
            continue;
        }
        allTaken = false;
        error(block, block.columnOf(QStringLiteral("F")), [&] {
            // Only for the errors kept (CheckErrors): the highest F taken, by halving the
            // interval (the rules are monotonic in the rate).
            ProgramBlock slower = block;
            double taken = 0;
            double refused = *block.feed;
            for (int i = 0; i < 40 && refused - taken > 1e-3; ++i) {
                slower.feed = (taken + refused) / 2;
                // G93: the axes' rates scale with F (InverseTime).
                for (auto r = slower.axisRates.begin(); r != slower.axisRates.end(); ++r)
                    r.value() = block.axisRates.value(r.key()) * *slower.feed / *block.feed;
                ParameterSet unused;
                (feedWriteRefusal(c.id, slower, &unused).isEmpty() ? taken : refused) =
                    *slower.feed;
            }
            const double highest = std::floor(taken * 10) / 10;
            const QString head =
                ProgramCheck::tr("F%1: controller \"%2\" would refuse its rate: %3")
                    .arg(figure(*block.feed), c.id, why);
            return highest > 0
                       ? ProgramCheck::tr("%1; F%2 or less is taken, or change the setup on the "
                                          "Setup page")
                             .arg(head, figure(highest))
                       : ProgramCheck::tr("%1; set it on the Setup page first").arg(head);
        });
    }
    m_lastTakenFeed = LastTakenFeed{};
    if (allTaken && !changed && block.axisRates.isEmpty())
        m_lastTakenFeed = LastTakenFeed{true, *block.feed, block.inches, block.axes.keys()};
}

// A move or reference run on a controller that reports its setup incomplete is refused by the
// device: named once per controller, at its first such block.
void ProgramPlan::checkSetup(const ProgramBlock& block, const PlannedBlock& planned)
{
    for (int i = planned.firstMove; i < planned.firstMove + planned.moveCount; ++i) {
        const AxisMove& m = m_out.moves.at(size_t(i));
        if (m.axis < 0)
            continue;
        const machine::MachineAxis& axis = m_facts.description.axes.at(m.axis);
        if (!m_facts.setupIncomplete.contains(axis.controller) ||
            m_setupReported.contains(axis.controller))
            continue;
        m_setupReported.insert(axis.controller);
        const ModelInfo* model = m_facts.models.value(axis.controller);
        const QString why =
            ProgramRules::setupIncomplete(m_facts.schemas.value(axis.controller),
                                          model ? model->setupBeforeMotion : QStringList{}, true);
        error(block, m.column, [&] {
            return ProgramCheck::tr("%1: controller \"%2\": %3")
                .arg(axis.name, axis.controller, why);
        });
    }
}

// An accepted M3 S, M4 S or S (motion::SwitchExecutor::accepts named what it refuses): what
// runs otherwise than written is noted.
void ProgramPlan::noteSpindle(const ProgramBlock& block, double rpm, bool reverse)
{
    const QString controller = m_switches.switchController(&Capabilities::spindle);
    if (reverse && !m_facts.capabilities.value(controller).spindleReverse) // a laser's (issue 50)
        note(block, block.columnOf({}), CheckErrors::kLaserNote, 0, [] {
            return ProgramCheck::tr("M4 runs as M3 on this laser: the beam's power is S, "
                                    "constant (GRBL's M4 lowers the power where the feed "
                                    "slows; StepDeck's controllers have no such power)");
        });
    // Above maxRpm the spindle runs at maxRpm, as GRBL clamps S at $30 (issue 50); a laser's S
    // is its power.
    const std::optional<double> maxRpm = m_facts.description.spindle.maxRpm;
    if (const double runs = motion::SwitchExecutor::spindleRpm(rpm, maxRpm); runs < rpm)
        note(block, block.columnOf(QStringLiteral("S")), CheckErrors::kSpindleNote, block.rpm, [&] {
            const QString text =
                m_facts.description.spindle.laser
                    ? ProgramCheck::tr("S%1 runs at S%2, the laser's full power (the machine "
                                       "file's spindle scale)")
                    : ProgramCheck::tr("S%1 runs at S%2, the spindle's maxRpm (the machine file's "
                                       "spindle scale)");
            return text.arg(figure(block.rpm), figure(runs));
        });
}

// M6's T and G43's H name tools of the machine's table once it holds any (issue 29); a G43
// with a length needs the tool axis.
void ProgramPlan::checkTools(const ProgramBlock& block)
{
    // Tool lengths by touch-off (issue 50 item 4): G43 takes no length from the table and M6
    // holds for the work Z instead, so a T or an H needs no entry (an empty table is no error).
    if (m_facts.description.toolLength == machine::ToolLength::TouchOff)
        return;
    const ToolTable& tools = m_facts.tools;
    if (block.kind == BlockKind::ToolChange && !tools.isEmpty() && !tools.find(block.number)) {
        error(block, block.columnOf({}), [&] {
            return ProgramCheck::tr("T%1: tool %1 is not in the machine's tool table")
                .arg(block.number);
        });
    }
    if (!block.appliesLengthOffset || block.lengthTool <= 0)
        return; // G43 H0: no offset, as in LinuxCNC
    const int column = block.columnOf(QStringLiteral("H"));
    const Tool* tool = tools.find(block.lengthTool);
    if (!tool) {
        error(block, column, [&] {
            return tools.isEmpty()
                       ? ProgramCheck::tr("G43: the machine's tool table is empty: enter tool "
                                          "%1's length first")
                             .arg(block.lengthTool)
                       : ProgramCheck::tr("G43: tool %1 is not in the machine's tool table")
                             .arg(block.lengthTool);
        });
        return;
    }
    if (tool->length != 0 && !m_facts.description.axis(ProgramCoordinates::toolAxis()))
        error(block, column, [&] {
            return ProgramCheck::tr("G43: the machine has no axis %1 for tool %2's length")
                .arg(ProgramCoordinates::toolAxis())
                .arg(block.lengthTool);
        });
}

} // namespace stepdeck::program
