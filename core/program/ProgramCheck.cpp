// The check of a program before anything moves (issue 20, docs/programs.md "Check"): the
// blocks against the controllers (ProgramPlan.cpp), then the run walked with its positions
// (ProgramSimulation.cpp); factsOf() in ProgramFacts.cpp.
#include "ProgramCheck.h"
#include "ArcPath.h"
#include "DrillCycle.h"
#include "ProgramParser.h"
#include "ProgramSimulation.h"
#include <QSet>
#include <algorithm>

namespace stepdeck::program {

namespace {

// The index of the block a run from `fromLine` starts at, or -1 with the reason in *errors.
int startIndex(const Program& program, int fromLine, CheckErrors* errors)
{
    const QList<ProgramBlock>& blocks = program.blocks;
    if (fromLine <= 1)
        return 0;
    const auto first = std::find_if(blocks.cbegin(), blocks.cend(),
                                    [&](const ProgramBlock& b) { return b.line >= fromLine; });
    if (first == blocks.cend()) {
        *errors << ProgramError{
            fromLine, 1,
            blocks.isEmpty()
                ? ProgramCheck::tr("run from line %1: the program has no blocks").arg(fromLine)
                : ProgramCheck::tr("run from line %1: the program's last block is on line %2")
                      .arg(fromLine)
                      .arg(blocks.last().line)};
        return -1;
    }
    const int start = int(first - blocks.cbegin());
    // The outermost repeat around the start: its passes would be lost (docs/programs.md).
    for (int i = 0; i < start; ++i) {
        const ProgramBlock& b = blocks.at(i);
        if (b.kind == BlockKind::RepeatStart && b.partner >= start) {
            *errors << ProgramError{fromLine, 1,
                                    ProgramCheck::tr("run from line %1 is inside the repeat of "
                                                     "line %2: start at line %2 or after its "
                                                     "endrepeat")
                                        .arg(fromLine)
                                        .arg(b.line)};
            return -1;
        }
    }
    return start;
}

// The label of the feed-rate parameter of a controller whose G1 rate is also its fast speed
// (Capabilities::feedRateSetsRapid) and that can neither read it back nor know it for every
// axis of the controller (EMIS: no work speed written in this session nor stored): nothing to
// put back after a G1. Empty: it can be put back.
QString unreadableFastSpeed(const MachineFacts& facts, const QString& controller)
{
    const Capabilities caps = facts.capabilities.value(controller);
    if (!caps.feedRateSetsRapid || !caps.feedRateParameter)
        return {};
    const QString name = QString::fromLatin1(caps.feedRateParameter);
    const ParameterSpec* spec = facts.schemas.value(controller).find(name);
    const ParameterValue held = facts.knownParameters.value(controller).value(name);
    bool known = !held.perAxis.isEmpty();
    for (const machine::MachineAxis& a : facts.description.axes)
        known = known && (a.controller != controller || held.perAxis.contains(a.axis));
    return spec && !spec->readable && !known ? spec->label : QString();
}

// The controllers a G1 rate is written to from `start` on: a G1's axes', an arc's (the rates of
// a G1 over the axes it moves, ArcPath::rateBlock), a drilling cycle's Z (DrillCycle::rateBlock).
QSet<QString> controllersWithG1(const Program& program, int start,
                                const machine::MachineDescription& d)
{
    QSet<QString> withG1;
    for (qsizetype i = start; i < program.blocks.size(); ++i) {
        const ProgramBlock& b = program.blocks.at(i);
        if (b.kind != BlockKind::Feed && !isArc(b.kind) && b.kind != BlockKind::DrillCycle)
            continue;
        const QStringList axes = isArc(b.kind) ? ArcPath::movingAxes(b)
                                 : b.kind == BlockKind::DrillCycle
                                     ? QStringList{QStringLiteral("Z")}
                                     : b.axes.keys();
        for (const QString& name : axes)
            if (const machine::MachineAxis* a = d.axis(name))
                withG1.insert(a->controller);
    }
    return withG1;
}

// A G1 on a controller whose rate is also its fast speed is followed by the fast speed put back
// before a G0 (ProgramRates): only where it can be read back or is known. Where not, a G0 (or a
// drilling cycle's rapid) on such a controller in a program that also has a G1 there would run
// at the last F: refused at every such block.
void checkFastSpeedPutBack(const Program& program, int start, const MachineFacts& facts,
                           CheckErrors* errors)
{
    const machine::MachineDescription& d = facts.description;
    const QSet<QString> withG1 = controllersWithG1(program, start, d);
    if (withG1.isEmpty())
        return;
    for (qsizetype i = start; i < program.blocks.size(); ++i) {
        const ProgramBlock& block = program.blocks.at(i);
        if (block.kind != BlockKind::Rapid && block.kind != BlockKind::DrillCycle)
            continue;
        // A drilling cycle moves X, Y and Z at the fast speed too.
        const ProgramBlock b = block.kind == BlockKind::DrillCycle
                                   ? DrillCycle::rateBlock(block, DrillCycle::Kind::Rapid, d)
                                   : block;
        for (auto it = b.axes.cbegin(); it != b.axes.cend(); ++it) {
            const machine::MachineAxis* a = d.axis(it.key());
            if (!a || !withG1.contains(a->controller))
                continue;
            if (const QString label = unreadableFastSpeed(facts, a->controller); !label.isEmpty()) {
                errors->add(b.line, b.columnOf(a->name), [&] {
                    if (block.kind == BlockKind::DrillCycle)
                        return ProgramCheck::tr(
                                   "%1: %4 moves it at the fast speed in a program with G1 on "
                                   "controller \"%2\", whose fast speed (%3) cannot be read back "
                                   "to be put back after G1; drill with G1 and F only")
                            .arg(a->name, a->controller, label, blockWord(block));
                    return ProgramCheck::tr(
                               "%1: G0 in a program with G1 on controller \"%2\": its fast "
                               "speed (%3) cannot be read back to be put back after G1; move %1 "
                               "with G1 and F only, or with G0 only")
                        .arg(a->name, a->controller, label);
                });
                break;
            }
        }
    }
}

} // namespace

CheckErrors& CheckErrors::operator<<(const ProgramError& error)
{
    m_lastLine = std::max(m_lastLine, error.line);
    m_errors << error;
    if (m_errors.size() >= 4 * ProgramParser::kMaxErrors)
        prune();
    return *this;
}

// Keeps the first kMaxErrors in line order; the rest can never be listed.
void CheckErrors::prune()
{
    std::stable_sort(m_errors.begin(), m_errors.end(),
                     [](const ProgramError& a, const ProgramError& b) {
                         return a.line != b.line ? a.line < b.line : a.column < b.column;
                     });
    if (m_errors.size() > ProgramParser::kMaxErrors) {
        m_errors.resize(ProgramParser::kMaxErrors);
        m_dropped = true;
        m_cutoffLine = m_errors.last().line;
    }
}

QList<ProgramError> CheckErrors::take()
{
    prune();
    QList<ProgramError> out = std::move(m_errors);
    m_errors.clear();
    if (m_dropped)
        out << ProgramError{m_lastLine, 1,
                            ProgramCheck::tr("more errors follow; only the first %1 are listed")
                                .arg(ProgramParser::kMaxErrors)};
    return out;
}

ProgramCheckResult ProgramCheck::check(const Program& program, const MachineFacts& facts,
                                       int fromLine)
{
    ProgramCheckResult result;
    ProgramPreview& preview = result.preview;
    preview.lines = program.lines;
    preview.motionNote = tr("the axes of a block start together, each at its own rate; the "
                            "block ends when every axis has arrived");
    CheckErrors errors;
    const int start = startIndex(program, fromLine, &errors);
    if (start < 0) {
        result.errors = errors.take();
        return result;
    }
    PlannedProgram planned;
    planned.blocks.resize(size_t(program.blocks.size()));
    ProgramPlan plan(facts, &planned, &errors);
    for (qsizetype i = start; i < program.blocks.size(); ++i)
        plan.plan(int(i), program.blocks.at(i));
    checkFastSpeedPutBack(program, start, facts, &errors);
    ProgramSimulation(facts, &planned, &errors).run(start, &preview);
    result.errors = errors.take();
    return result;
}

namespace {
// The machine's inputs or outputs counted from 1 over the controllers in the file's order.
std::optional<MachineIo> nthIo(const MachineFacts& facts, int n, int Capabilities::*count)
{
    if (n < 1)
        return std::nullopt;
    for (const machine::MachineController& c : facts.description.controllers) {
        const int here = facts.capabilities.value(c.id).*count;
        if (n <= here)
            return MachineIo{c.id, n};
        n -= here;
    }
    return std::nullopt;
}
} // namespace

std::optional<MachineIo> machineOutput(const MachineFacts& facts, int n)
{
    return nthIo(facts, n, &Capabilities::digitalOutputs);
}

std::optional<MachineIo> machineInput(const MachineFacts& facts, int n)
{
    return nthIo(facts, n, &Capabilities::digitalInputs);
}

QString machineSwitchController(const MachineFacts& facts, bool Capabilities::*has)
{
    for (const machine::MachineController& c : facts.description.controllers)
        if (facts.capabilities.value(c.id).*has)
            return c.id;
    return {};
}

} // namespace stepdeck::program
