// The check's first part (ProgramCheck): each block against what the machine's controllers
// take, before any position is followed (docs/programs.md "Check").
#include "ArcPath.h"
#include "DrillCycle.h"
#include "ProgramRules.h"
#include "ProgramSimulation.h"
#include "ProgramUnits.h"
#include "motion/executors/MoveExecutor.h"
#include <cmath>

namespace stepdeck::program {

ProgramPlan::ProgramPlan(const MachineFacts& facts, PlannedProgram* out, CheckErrors* errors)
    : m_facts(facts), m_out(*out), m_errors(errors), m_contours(facts),
      m_switches(facts.description, facts.capabilities, facts.schemas),
      m_known(facts.knownParameters)
{
    // m_facts outlives the plan unchanged: pointers into its maps stay valid.
    static const Capabilities kNone;
    for (const machine::MachineAxis& axis : facts.description.axes) {
        AxisFacts a;
        const auto caps = facts.capabilities.constFind(axis.controller);
        a.caps = caps == facts.capabilities.cend() ? &kNone : &caps.value();
        a.feedParameter = QString::fromLatin1(a.caps->feedRateParameter);
        const auto schema = facts.schemas.constFind(axis.controller);
        if (a.caps->feedRateParameter && schema != facts.schemas.cend())
            a.feedSpec = schema.value().find(a.feedParameter);
        m_axisFacts.push_back(a);
    }
}

void ProgramPlan::addMove(const AxisMove& move, PlannedBlock* out)
{
    if (out->moveCount == 0)
        out->firstMove = int(m_out.moves.size());
    m_out.moves.push_back(move);
    ++out->moveCount;
}

void ProgramPlan::plan(const ProgramBlock& block, bool reporting)
{
    m_reporting = reporting;
    m_out.moves.clear();
    m_out.block = PlannedBlock{};
    PlannedBlock& out = m_out.block;
    out.block = &block;
    checkTools(block);
    checkSpindleChange(block);
    if (planSwitch(block))
        return;
    switch (block.kind) {
    case BlockKind::Rapid:
    case BlockKind::Feed:
        planMove(block, &out);
        checkSetup(block, out);
        break;
    case BlockKind::ArcClockwise:
    case BlockKind::ArcCounterClockwise:
        planArc(block, &out);
        checkSetup(block, out);
        break;
    case BlockKind::DrillCycle:
        planCycle(block, &out);
        checkSetup(block, out);
        break;
    case BlockKind::Home:
        planHome(block, &out);
        checkSetup(block, out);
        break;
    case BlockKind::WaitInput:
        checkInput(block);
        break;
    default:
        break;
    }
}

void ProgramPlan::planMove(const ProgramBlock& block, PlannedBlock* out)
{
    const machine::MachineDescription& d = m_facts.description;
    bool ratesTaken = true;
    // A block of a contour stream writes no rate of its own: the stream's tick is written.
    const ContourMoves::Stream* stream =
        block.kind == BlockKind::Feed ? m_contours.streamOf(block) : nullptr;
    out->contour = stream;
    const motion::RatedMove rated = block.kind == BlockKind::Feed && !stream
                                        ? ProgramLowering::ratedMove(block, d)
                                        : motion::RatedMove{};
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        AxisMove m;
        m.axis = d.axisIndex(it.key());
        m.column = block.columnOf(it.key());
        if (m.axis < 0) { // the parser knew other axes than these facts
            error(block, m.column,
                  [&] { return ProgramCheck::tr("the machine has no axis %1").arg(it.key()); });
            continue;
        }
        const machine::MachineAxis& axis = d.axes.at(m.axis);
        m.value = units::toAxisUnits(axis, it.value(), block.inches);
        if (stream) {
            m.speed = m_contours.feedPerSecond(*stream, block); // an estimate's
        } else if (block.kind == BlockKind::Feed) {
            // A refused rate still moves the axis in the walk, so what follows is judged
            // from where the program means it to be (its time stays unknown).
            ratesTaken = checkRate(block, rated, m.axis, &m.speed) && ratesTaken;
        } else if (axis.maxJogSpeed && *axis.maxJogSpeed > 0) {
            m.speed = *axis.maxJogSpeed;
        } else {
            m.speed = m_axisFacts[size_t(m.axis)].caps->maxJogSpeed / axis.stepsPerUnit;
        }
        addMove(m, out);
    }
    if (stream)
        checkContourTick(block, *stream);
    else if (block.kind == BlockKind::Feed && ratesTaken)
        checkFeedWrite(block);
}

// A contour's stream runs at the tick rate ContourMoves chose from what the device holds,
// written as the feed-rate parameter on every axis of its controller: from then on the device
// holds that (the next G1 of its own is judged against it).
void ProgramPlan::checkContourTick(const ProgramBlock& block, const ContourMoves::Stream& stream)
{
    if (stream.tickRate <= 0) {
        error(block, block.columnOf(QStringLiteral("F")), [&] {
            return ProgramCheck::tr("the move runs in the contour stream of controller \"%1\", "
                                    "but %2")
                .arg(stream.controller, stream.tickRefusal);
        });
        return;
    }
    if (m_tickHeld == stream.controller)
        return; // the contour before wrote it (a CAM program's feed moves mostly are one)
    const auto c = m_facts.capabilities.constFind(stream.controller);
    if (c == m_facts.capabilities.cend() || !c->feedRateParameter)
        return;
    ParameterValue& held = m_known[stream.controller][QString::fromLatin1(c->feedRateParameter)];
    for (Axis a : c->axes)
        held.perAxis.insert(a, qint64(stream.tickRate));
    m_tickHeld = stream.controller;
    m_lastTakenFeed = LastTakenFeed{};
}

// G2/G3: the rates of a G1 over the axes the arc moves (ArcPath::rateBlock), kept with the
// arc's own block, so that errors name its words; the path itself is the walk's
// (ProgramSimulation::arc), which knows where the arc starts. An axis the machine lacks is
// named there.
void ProgramPlan::planArc(const ProgramBlock& block, PlannedBlock* out)
{
    ProgramBlock rates = ArcPath::rateBlock(block);
    for (const QString& name : rates.axes.keys())
        if (m_facts.description.axisIndex(name) < 0)
            rates.axes.remove(name);
    planMove(rates, out);
}

// G81..G83, G73: the fast speeds of X, Y, Z (the axis moves) and Z's rate at F as a G1's, kept
// with the cycle's own block so that errors name its words; the moves themselves are the walk's
// (ProgramSimulation::cycle), which knows where the cycle starts.
void ProgramPlan::planCycle(const ProgramBlock& block, PlannedBlock* out)
{
    const machine::MachineDescription& d = m_facts.description;
    planMove(DrillCycle::rateBlock(block, DrillCycle::Kind::Rapid, d), out);
    const ProgramBlock feed = DrillCycle::rateBlock(block, DrillCycle::Kind::Feed, d);
    const int z = d.axisIndex(QStringLiteral("Z"));
    if (z >= 0 && checkRate(feed, ProgramLowering::ratedMove(feed, d), z, &out->feedSpeed))
        checkFeedWrite(feed);
}

// G1: the rate as the axis' controller takes it (Capabilities::feedRateParameter, steps/s
// within the parameter's schema range). *speed: the rate the device runs, in unit/s (left 0
// when refused).
bool ProgramPlan::checkRate(const ProgramBlock& block, const motion::RatedMove& rated,
                            int axisIndex, double* speed)
{
    const machine::MachineAxis& axis = m_facts.description.axes.at(axisIndex);
    const AxisFacts& facts = m_axisFacts[size_t(axisIndex)];
    const int column = block.columnOf(axis.name);
    if (!facts.caps->feedRateParameter) {
        error(block, column, [&] {
            return ProgramCheck::tr(
                       "%1: controller \"%2\" takes no feed rate, so G1 cannot move it; "
                       "use G0")
                .arg(axis.name, axis.controller);
        });
        return false;
    }
    const ParameterSpec* spec = facts.feedSpec;
    if (!spec) {
        error(block, column, [&] {
            return ProgramCheck::tr("%1: controller \"%2\" has no parameter %3 for the feed rate")
                .arg(axis.name, axis.controller, facts.feedParameter);
        });
        return false;
    }
    if (!block.feed) // the parser refuses G1 without F
        return true;
    // As the run writes it (motion::MoveRates::feedRateWrite): above the controller's highest
    // at that highest, with a note, unless the machine file refuses (issue 50).
    const motion::MoveRates::AxisRate limited = motion::MoveRates::axisRate(
        m_facts.description, axisIndex, *facts.caps, spec, m_known.value(axis.controller), rated);
    const qint64 rate = limited.runs;
    if (rate == 0)
        return true; // G93 on an axis that does not move (or from an unknown position)
    if (block.inverseTime && (rate < spec->minimum || rate > spec->maximum)) {
        error(block, block.columnOf(QStringLiteral("F")), [&] {
            return ProgramCheck::tr("G93 F%1 (the move in %2 s) moves %3 at %4 steps/s; "
                                    "controller \"%5\" takes %6..%7 steps/s (%8)")
                .arg(figure(*block.feed), figure(60.0 / *block.feed), axis.name)
                .arg(rate)
                .arg(axis.controller)
                .arg(spec->minimum)
                .arg(spec->maximum)
                .arg(ParameterSchema::displayLabel(*spec));
        });
        return false;
    }
    if (rate < spec->minimum || rate > spec->maximum) {
        error(block, block.columnOf(QStringLiteral("F")), [&] {
            return ProgramCheck::tr(
                       "F%1 is %2 steps/s on %3; controller \"%4\" takes %5..%6 steps/s "
                       "(%7)")
                .arg(figure(*block.feed))
                .arg(rate)
                .arg(axis.name, axis.controller)
                .arg(spec->minimum)
                .arg(spec->maximum)
                .arg(ParameterSchema::displayLabel(*spec));
        });
        return false;
    }
    if (limited.limited)
        noteRate(block, axis, limited);
    *speed = double(rate) / axis.stepsPerUnit;
    return true;
}

namespace {
// The F (program unit per minute) an axis moves at `stepsPerSecond`.
double feedOf(const machine::MachineAxis& axis, qint64 stepsPerSecond, bool inches)
{
    const double perMinute = double(stepsPerSecond) / axis.stepsPerUnit * 60.0;
    return inches && axis.unit == machine::AxisUnit::Millimetre
               ? perMinute / units::kMillimetresPerInch
               : perMinute;
}
} // namespace

// Named once per programmed F (CheckErrors::note), at the F word: what the axis would need, the
// highest its controller takes and why, and the F (or G93's time) the move runs at.
void ProgramPlan::noteRate(const ProgramBlock& block, const machine::MachineAxis& axis,
                           const motion::MoveRates::AxisRate& rate)
{
    const auto message = [&] {
        const Capabilities caps = m_facts.capabilities.value(axis.controller);
        const QString why =
            rate.ceiling.belowParameter
                ? ProgramCheck::tr("below its %1: feed mode has no ramp")
                      .arg(m_facts.schemas.value(axis.controller)
                               .displayLabel(QString::fromLatin1(caps.contourTickBelow)))
                : ProgramCheck::tr("%1 at most")
                      .arg(m_facts.schemas.value(axis.controller)
                               .displayLabel(QString::fromLatin1(caps.feedRateParameter)));
        const QString above = ProgramCheck::tr("above the %1 steps/s controller \"%2\" takes (%3)")
                                  .arg(rate.ceiling.rate)
                                  .arg(axis.controller, why);
        if (block.inverseTime)
            return ProgramCheck::tr("G93 F%1 (the move in %2 s) moves %3 at %4 steps/s, %5: the "
                                    "move takes %6 s")
                .arg(figure(*block.feed), figure(60.0 / *block.feed), axis.name)
                .arg(rate.programmed)
                .arg(above, figure(60.0 / *block.feed / rate.feedFactor));
        if (!block.axisRates.isEmpty())
            return ProgramCheck::tr("F%1 moves %2 at %3 steps/s, %4: the move runs at F%5")
                .arg(figure(*block.feed), axis.name)
                .arg(rate.programmed)
                .arg(above, figure(*block.feed * rate.feedFactor));
        return ProgramCheck::tr("F%1 is %2 steps/s on %3, %4: %3 runs at F%5")
            .arg(figure(*block.feed))
            .arg(rate.programmed)
            .arg(axis.name, above, figure(feedOf(axis, rate.runs, block.inches)));
    };
    note(block, block.columnOf(QStringLiteral("F")),
         block.inverseTime ? CheckErrors::kInverseTimeNote : CheckErrors::kRateNote, *block.feed,
         message);
}

void ProgramPlan::planHome(const ProgramBlock& block, PlannedBlock* out)
{
    const machine::MachineDescription& d = m_facts.description;
    QStringList refused; // controllers named once per block
    const auto add = [&](int index, int column) {
        const machine::MachineAxis& axis = d.axes.at(index);
        if (const QString why = motion::MoveExecutor::referenceRefusal(
                m_facts.capabilities.value(axis.controller), axis.name, axis.controller);
            !why.isEmpty()) {
            if (!refused.contains(axis.controller))
                error(block, column, [&] { return why; });
            refused << axis.controller;
            return;
        }
        AxisMove m;
        m.axis = index;
        m.column = column;
        addMove(m, out);
    };
    if (block.axes.isEmpty()) {
        for (int i = 0; i < d.axes.size(); ++i)
            add(i, block.columnOf({}));
        return;
    }
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        const int index = d.axisIndex(it.key());
        if (index < 0)
            error(block, block.columnOf(it.key()),
                  [&] { return ProgramCheck::tr("the machine has no axis %1").arg(it.key()); });
        else
            add(index, block.columnOf(it.key()));
    }
}

// M3, M4, M5, M7, M8, M9, M64 and M65 (a block of their own, or beside a motion): the command
// the lowering makes of the block, as the machine's SwitchExecutor accepts it -- the run asks
// the same executor the same question. false: `block` is none of them.
bool ProgramPlan::planSwitch(const ProgramBlock& block)
{
    const std::optional<motion::MotionCommand> command = ProgramLowering::switchCommand(block);
    if (!command || std::holds_alternative<motion::WaitInput>(*command))
        return false;
    if (acceptSwitch(block, *command))
        if (const auto* on = std::get_if<motion::SpindleOn>(&*command))
            noteSpindle(block, on->rpm, on->reverse);
    return true;
}

// S on a line (LinuxCNC: any line; LightBurn's "G1 X5 S500", pcb2gcode's "G00 S10000"): the
// speed a running spindle changes to (ProgramLowering::speedChange), within the same rules as
// M3's S. M3 and M4 check their own S; M5 sends none.
void ProgramPlan::checkSpindleChange(const ProgramBlock& block)
{
    if (const std::optional<motion::MotionCommand> speed = ProgramLowering::speedChange(block))
        if (acceptSwitch(block, *speed))
            noteSpindle(block, block.rpm, false);
}

bool ProgramPlan::acceptSwitch(const ProgramBlock& block, const motion::MotionCommand& command)
{
    const std::optional<motion::SwitchExecutor::Refusal> refusal = m_switches.accepts(command);
    if (!refusal)
        return true;
    error(block, block.columnOf(refusal->word), [&] { return refusal->text; });
    return false;
}

// M66 P: an input the machine has.
void ProgramPlan::checkInput(const ProgramBlock& block)
{
    if (m_switches.input(block.number))
        return;
    int count = 0;
    for (const machine::MachineController& c : m_facts.description.controllers)
        count += m_facts.capabilities.value(c.id).digitalInputs;
    error(block, block.columnOf(QStringLiteral("P")), [&] {
        const QString word = QStringLiteral("%1 P%2").arg(blockWord(block.kind)).arg(block.number);
        return count == 0
                   ? ProgramCheck::tr("%1: the machine has no digital inputs").arg(word)
                   : ProgramCheck::tr("%1: the machine's inputs are 1..%2").arg(word).arg(count);
    });
}

} // namespace stepdeck::program
