// The check of a program before anything moves (issue 20, docs/programs.md "Check"): the
// blocks against the controllers (ProgramPlan.cpp), then the run walked with its positions
// (ProgramSimulation.cpp); factsOf() in ProgramFacts.cpp.
#include "ProgramCheck.h"
#include "ProgramParser.h"
#include "ProgramSimulation.h"
#include <algorithm>

namespace stepdeck::program {

namespace {

// The index of the block a run from `fromLine` starts at, or -1 with the reason in *errors.
int startIndex(const Program& program, int fromLine, QList<ProgramError>* errors)
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

// Line order; at most ProgramParser::kMaxErrors, as the parser lists them.
void sortAndLimit(QList<ProgramError>* errors)
{
    std::stable_sort(errors->begin(), errors->end(),
                     [](const ProgramError& a, const ProgramError& b) {
                         return a.line != b.line ? a.line < b.line : a.column < b.column;
                     });
    if (errors->size() <= ProgramParser::kMaxErrors)
        return;
    const int lastLine = errors->last().line;
    errors->resize(ProgramParser::kMaxErrors);
    *errors << ProgramError{lastLine, 1,
                            ProgramCheck::tr("more errors follow; only the first %1 are listed")
                                .arg(ProgramParser::kMaxErrors)};
}

} // namespace

ProgramCheckResult ProgramCheck::check(const Program& program, const MachineFacts& facts,
                                       int fromLine)
{
    ProgramCheckResult result;
    ProgramPreview& preview = result.preview;
    preview.lines = program.lines;
    preview.motionNote = tr("the axes of a block start together, each at its own rate; the "
                            "block ends when every axis has arrived");
    const int start = startIndex(program, fromLine, &result.errors);
    if (start < 0)
        return result;
    std::vector<PlannedBlock> planned(size_t(program.blocks.size()));
    ProgramPlan plan(facts, &result.errors);
    for (qsizetype i = start; i < program.blocks.size(); ++i)
        planned[size_t(i)] = plan.plan(program.blocks.at(i));
    ProgramSimulation(facts, &planned, &result.errors).run(start, &preview);
    sortAndLimit(&result.errors);
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

} // namespace stepdeck::program
