// The check of a program before anything moves (issue 20, docs/programs.md "Check"): the
// blocks against the controllers (ProgramPlan.cpp), then the run walked with its positions
// (ProgramSimulation.cpp); factsOf() in ProgramFacts.cpp.
#include "ProgramCheck.h"
#include "ArcPath.h"
#include "DrillCycle.h"
#include "ProgramParser.h"
#include "ProgramReader.h"
#include "ProgramSimulation.h"
#include "RunFromLine.h"
#include "language/ProgramExpansion.h"
#include <QSet>
#include <algorithm>
#include <limits>

namespace stepdeck::program {

namespace {

// The index of the block a run from `fromLine` starts at, or -1 with the reason in *errors.
int startIndex(ProgramReader& reader, int fromLine, CheckErrors* errors)
{
    if (fromLine <= 1)
        return 0;
    const int start = reader.firstBlockAtLine(fromLine);
    if (start < 0) {
        if (!reader.error().isEmpty())
            return -1;
        const int last = reader.lastBlockLine();
        *errors << ProgramError{
            fromLine, 1,
            last == 0
                ? ProgramCheck::tr("run from line %1: the program has no blocks").arg(fromLine)
                : ProgramCheck::tr("run from line %1: the program's last block is on line %2")
                      .arg(fromLine)
                      .arg(last)};
        return -1;
    }
    // The outermost repeat around the start: its passes would be lost (docs/programs.md).
    const int outer = reader.enclosingRepeat(start);
    if (outer >= 0) {
        const ProgramBlock* b = reader.at(outer);
        *errors << ProgramError{fromLine, 1,
                                ProgramCheck::tr("run from line %1 is inside the repeat of "
                                                 "line %2: start at line %2 or after its "
                                                 "endrepeat")
                                    .arg(fromLine)
                                    .arg(b ? b->line : 0)};
        return -1;
    }
    // Cutter compensation enters the path at its first move (CutterCompensation): a run
    // cannot join it halfway.
    if (const ProgramBlock* b = reader.at(start); b && b->comp.on()) {
        *errors << ProgramError{fromLine, 1,
                                ProgramCheck::tr("run from line %1: cutter compensation (G41/G42) "
                                                 "is on there; start on a line before it is "
                                                 "turned on, or after its G40")
                                    .arg(fromLine)};
        return -1;
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

// A G1 on a controller whose rate is also its fast speed is followed by the fast speed put back
// before a G0 (motion::MoveExecutor): only where it can be read back or is known. Where not, a G0
// (or a drilling cycle's rapid) on such a controller in a program that also has a G1 there would
// run at the last F: refused at every such block. The walk streams the blocks, so a G0 is judged
// once the whole program is read: what it needs of each block is kept, bounded (the first
// kMaxErrors + 1 blocks per controller: more can never be listed).
class FastSpeedPutBack
{
public:
    explicit FastSpeedPutBack(const MachineFacts& facts) : m_facts(facts)
    {
        for (const machine::MachineController& c : facts.description.controllers)
            if (!unreadableFastSpeed(facts, c.id).isEmpty())
                m_unreadable.insert(c.id);
    }

    void visit(const ProgramBlock& block)
    {
        if (m_unreadable.isEmpty())
            return;
        noteG1(block);
        if (block.kind == BlockKind::Rapid || block.kind == BlockKind::DrillCycle)
            noteRapid(block);
    }

    void report(CheckErrors* errors) const
    {
        for (const Rapid& r : m_rapids)
            for (const Candidate& c : r.candidates)
                if (m_withG1.contains(c.controller)) {
                    errors->add(r.line, c.column, [&] { return c.message; });
                    break;
                }
    }

private:
    struct Candidate
    {
        QString controller;
        int column = 0;
        QString message;
    };
    struct Rapid
    {
        int line = 0;
        QList<Candidate> candidates; // in the block's axis order
    };

    // The controllers a G1 rate is written to: a G1's axes', an arc's (the rates of a G1 over
    // the axes it moves, ArcPath::rateBlock), a drilling cycle's Z (DrillCycle::rateBlock).
    void noteG1(const ProgramBlock& b)
    {
        if (b.kind != BlockKind::Feed && !isArc(b.kind) && b.kind != BlockKind::DrillCycle)
            return;
        const QStringList axes = isArc(b.kind) ? ArcPath::movingAxes(b)
                                 : b.kind == BlockKind::DrillCycle
                                     ? QStringList{QStringLiteral("Z")}
                                     : b.axes.keys();
        for (const QString& name : axes)
            if (const machine::MachineAxis* a = m_facts.description.axis(name))
                m_withG1.insert(a->controller);
    }

    void noteRapid(const ProgramBlock& block)
    {
        const machine::MachineDescription& d = m_facts.description;
        // A drilling cycle moves X, Y and Z at the fast speed too.
        const ProgramBlock b = block.kind == BlockKind::DrillCycle
                                   ? DrillCycle::rateBlock(block, DrillCycle::Kind::Rapid, d)
                                   : block;
        Rapid rapid{b.line, {}};
        bool wanted = false;
        for (auto it = b.axes.cbegin(); it != b.axes.cend(); ++it) {
            const machine::MachineAxis* a = d.axis(it.key());
            if (!a || !m_unreadable.contains(a->controller))
                continue;
            int& kept = m_kept[a->controller];
            wanted = wanted || kept <= ProgramParser::kMaxErrors;
            ++kept;
            rapid.candidates << Candidate{a->controller, b.columnOf(a->name), message(block, *a)};
        }
        if (wanted)
            m_rapids << rapid;
    }

    QString message(const ProgramBlock& block, const machine::MachineAxis& a) const
    {
        const QString label = unreadableFastSpeed(m_facts, a.controller);
        if (block.kind == BlockKind::DrillCycle)
            return ProgramCheck::tr("%1: %4 moves it at the fast speed in a program with G1 on "
                                    "controller \"%2\", whose fast speed (%3) cannot be read "
                                    "back to be put back after G1; drill with G1 and F only")
                .arg(a.name, a.controller, label, blockWord(block));
        return ProgramCheck::tr("%1: G0 in a program with G1 on controller \"%2\": its fast "
                                "speed (%3) cannot be read back to be put back after G1; move %1 "
                                "with G1 and F only, or with G0 only")
            .arg(a.name, a.controller, label);
    }

    const MachineFacts& m_facts;
    QSet<QString> m_unreadable; // controllers whose fast speed cannot be put back
    QSet<QString> m_withG1;
    QMap<QString, int> m_kept; // per controller: rapids kept
    QList<Rapid> m_rapids;
};

// Tool lengths by touch-off (issue 50 item 4, MachineDescription::toolLength): what the run does
// instead of taking a table's lengths, said with the preview (ProgramPreview::toolNote): it holds
// at each M6 until the work Z is set for the new tool (ProgramRunner), and G43 adds nothing. The
// first M6 lines are named; a machine without Z has nothing to touch off.
class TouchOffNote
{
public:
    explicit TouchOffNote(const MachineFacts& facts)
        : m_on(facts.description.toolLength == machine::ToolLength::TouchOff &&
               facts.description.axis(ProgramCoordinates::toolAxis()))
    {}

    void visit(const ProgramBlock& block)
    {
        if (!m_on)
            return;
        if (block.kind == BlockKind::ToolChange && ++m_changes <= kNamed)
            m_lines << QString::number(block.line);
        m_lengthOffset = m_lengthOffset || (block.appliesLengthOffset && block.lengthTool > 0);
    }

    QString text() const
    {
        if (m_changes == 0 && !m_lengthOffset)
            return {};
        if (m_changes == 0)
            return ProgramCheck::tr("tool lengths by touch-off (the machine file's toolLength): "
                                    "G43 adds no length; set the work Z for the tool in the "
                                    "spindle before the run");
        QString lines = m_lines.join(QStringLiteral(", "));
        if (m_changes > kNamed)
            lines += QStringLiteral(", \u2026");
        const int changes = int(std::min<qint64>(m_changes, std::numeric_limits<int>::max()));
        return ProgramCheck::tr("tool lengths by touch-off (the machine file's toolLength): the "
                                "run holds at %n tool change(s) (M6, line(s) %1) until the work "
                                "Z is set for the new tool; G43 adds no length",
                                nullptr, changes)
            .arg(lines);
    }

private:
    static constexpr qint64 kNamed = 5;
    bool m_on = false;
    qint64 m_changes = 0;
    QStringList m_lines;
    bool m_lengthOffset = false; // a G43 with a tool, which a table would have given a length
};

// The preview as the walk left it (issue 47 item 12): with errors it stays, flagged, where the
// walk went through the program (soft limits, rates, unknown positions leave its path); where it
// did not (walked false: no start, the file could not be read, the program does not parse) or
// was cancelled, only the line count is kept.
void settlePreview(ProgramCheckResult* result, bool walked)
{
    ProgramPreview& preview = result->preview;
    if (!walked || result->cancelled) {
        ProgramPreview none;
        none.lines = preview.lines;
        preview = none;
    }
    preview.hasErrors = !result->errors.isEmpty();
}

// The walk of a check over a reader (the program's blocks, or the one pass over its text) from
// its block `start` (-1: none, *errors says why), after the blocks a run from line sends first.
void walkFrom(ProgramReader& reader, const MachineFacts& facts, int start,
              const CheckProgress& progress, CheckErrors* errors, ProgramCheckResult* result,
              const QList<ProgramBlock>& prelude = {}, const motion::CommandSink& lowered = {})
{
    if (start >= 0) {
        FastSpeedPutBack putBack(facts);
        TouchOffNote touchOff(facts);
        ProgramSimulation simulation(facts, &reader, errors);
        simulation.setFirstVisit([&putBack, &touchOff](const ProgramBlock& b) {
            putBack.visit(b);
            touchOff.visit(b);
        });
        simulation.setPrelude(prelude);
        simulation.setLowered(lowered);
        result->cancelled = !simulation.run(start, &result->preview, progress);
        putBack.report(errors);
        result->preview.toolNote = touchOff.text();
    }
    if (!reader.error().isEmpty())
        *errors << ProgramError{0, 0, reader.error()};
    result->errors = errors->take();
    result->notes << errors->takeNotes(); // the walk's (issue 50: feeds and S limited)
    settlePreview(result, start >= 0 && reader.error().isEmpty());
}

// Run from line (issue 47 item 5): what the run sends before its start block (the switches the
// lines before it left on, the rapids to its start point), from the one function the runner
// takes it from (ProgramRunner::startChecked), with the same facts: the check judges what the
// run will do first. None from the first block.
QList<ProgramBlock> runFromPrelude(ProgramReader& reader, const MachineFacts& facts, int start)
{
    if (start <= 0)
        return {};
    const RunFromState state = RunFromState::before(reader, start, facts);
    const ProgramBlock* first = reader.at(start);
    return first ? state.prelude(facts, first->line) : QList<ProgramBlock>{};
}

void walk(ProgramReader& reader, const MachineFacts& facts, int fromLine,
          const CheckProgress& progress, ProgramCheckResult* result,
          const motion::CommandSink& lowered = {})
{
    CheckErrors errors;
    const int start = startIndex(reader, fromLine, &errors);
    walkFrom(reader, facts, start, progress, &errors, result, runFromPrelude(reader, facts, start),
             lowered);
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
        for (auto it = m_once.begin(); it != m_once.end();)
            it = int(*it >> 20) > m_cutoffLine ? m_once.erase(it) : std::next(it);
    }
}

bool CheckErrors::once(int line, int column, int kind)
{
    if (m_cutoffLine > 0 && line > m_cutoffLine)
        return true; // add() drops it, without a message
    const quint64 key =
        quint64(quint32(line)) << 20 | quint64(column & 0xFFFF) << 4 | quint64(kind & 0xF);
    if (m_once.contains(key))
        return false;
    m_once.insert(key);
    return true;
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

QList<ProgramError> CheckErrors::takeNotes()
{
    for (const NoteAt& at : std::as_const(m_noteAt))
        if (at.moreLines > 0) {
            ProgramError& n = m_notes[at.index];
            const int more = int(std::min<qint64>(at.moreLines, std::numeric_limits<int>::max()));
            n.message =
                ProgramCheck::tr("%1 (also on %n more line(s))", nullptr, more).arg(n.message);
        }
    std::stable_sort(m_notes.begin(), m_notes.end(),
                     [](const ProgramError& a, const ProgramError& b) {
                         return a.line != b.line ? a.line < b.line : a.column < b.column;
                     });
    m_noteAt.clear();
    return std::exchange(m_notes, {});
}

namespace {

// A program in LinuxCNC's language runs its lines in the order its control flow gives (issue 33):
// a run starts at its start, and its values were worked out against the offsets it reads.
bool refuseForExpansion(const ProgramExpansionInfo* info, const MachineFacts& facts, int fromLine,
                        QList<ProgramError>* errors)
{
    if (fromLine > 1) {
        *errors << ProgramError{
            fromLine, 1,
            ProgramCheck::tr("run from line %1: a program with parameters or O words runs its "
                             "lines in the order its control flow gives; run it from its start")
                .arg(fromLine)};
        return true;
    }
    if (info && (info->coordinateSystems != facts.coordinateSystems ||
                 info->activeSystem != facts.activeSystem)) {
        *errors << ProgramError{0, 0,
                                ProgramCheck::tr("the offsets changed since the program's "
                                                 "parameters were worked out: check it again")};
        return true;
    }
    return false;
}

NgcContext contextOf(const MachineFacts& facts)
{
    NgcContext context;
    context.coordinateSystems = facts.coordinateSystems;
    context.activeSystem = facts.activeSystem;
    context.subroutineFolder = facts.description.subroutineFolderPath;
    context.blockDelete = facts.blockDelete;
    return context;
}

// What the parser and the working out read and do not run (Program::notes,
// ProgramExpansionInfo::notes) among the walk's notes, in line order.
void addProgramNotes(const Program& program, ProgramCheckResult* result)
{
    result->notes << program.notes;
    if (program.expansion)
        result->notes << program.expansion->notes;
    std::stable_sort(result->notes.begin(), result->notes.end(),
                     [](const ProgramError& a, const ProgramError& b) {
                         return a.line != b.line ? a.line < b.line : a.column < b.column;
                     });
}

} // namespace

ProgramCheckResult ProgramCheck::check(const Program& program, const MachineFacts& facts,
                                       int fromLine, const CheckProgress& progress,
                                       const motion::CommandSink& lowered)
{
    ProgramCheckResult result;
    result.preview.lines = program.expansion ? program.expansion->sourceLines : program.lines;
    if (program.expansion &&
        refuseForExpansion(program.expansion.get(), facts, fromLine, &result.errors)) {
        settlePreview(&result, false);
        return result;
    }
    ProgramReader reader(program);
    walk(reader, facts, fromLine, progress, &result, lowered);
    addProgramNotes(program, &result);
    if (result.ok())
        result.program = program;
    return result;
}

ProgramCheckResult ProgramCheck::checkRest(const Program& program, const MachineFacts& facts,
                                           int fromBlock, const CheckProgress& progress)
{
    ProgramCheckResult result;
    result.preview.lines = program.expansion ? program.expansion->sourceLines : program.lines;
    if (program.expansion &&
        refuseForExpansion(program.expansion.get(), facts, 1, &result.errors)) {
        settlePreview(&result, false);
        return result;
    }
    ProgramReader reader(program);
    const ProgramBlock* first = reader.at(fromBlock);
    if (first && reader.enclosingRepeat(fromBlock) >= 0) {
        result.errors << ProgramError{first->line, 1,
                                      tr("the run holds inside a repeat, whose passes a check "
                                         "from here cannot count: the new offsets cannot be "
                                         "checked for the rest")};
        settlePreview(&result, false);
        return result;
    }
    CheckErrors errors; // no block left (first null): nothing left to refuse
    walkFrom(reader, facts, first ? fromBlock : -1, progress, &errors, &result);
    if (result.ok())
        result.program = program;
    return result;
}

ProgramCheckResult ProgramCheck::check(const ProgramSource& source, const QStringList& axisNames,
                                       const MachineFacts& facts, int fromLine,
                                       const CheckProgress& progress)
{
    ProgramCheckResult result;
    QString why;
    const std::optional<bool> language = ProgramExpansion::usesLanguage(source, &why);
    if (!language) {
        result.errors = {ProgramError{0, 0, why}};
        settlePreview(&result, false);
        return result;
    }
    std::optional<ProgramExpansion::Result> expanded;
    if (*language) {
        if (refuseForExpansion(nullptr, facts, fromLine, &result.errors)) {
            settlePreview(&result, false);
            return result;
        }
        // Working out has no bytes to count: the progress stays at 0 but can cancel it.
        const qint64 total = source.size();
        expanded = ProgramExpansion::expand(source, contextOf(facts), &result.errors, 100,
                                            [&] { return !progress || progress(0, total); });
        if (!expanded) {
            result.cancelled = result.errors.isEmpty();
            settlePreview(&result, false);
            return result;
        }
    }
    ProgramReader reader(expanded ? expanded->source : source, axisNames,
                         expanded ? expanded->info->lines : nullptr, facts.blockDelete);
    walk(reader, facts, fromLine, progress, &result);
    if (result.cancelled)
        return result;
    // The parser's errors come first: a program that does not parse is not checked further.
    QList<ProgramError> parseErrors;
    result.program = reader.finish(&parseErrors);
    if (!result.program) {
        result.errors = parseErrors;
        settlePreview(&result, false); // the walk stopped at the first parse error: no path
    }
    result.preview.lines = result.program ? result.program->lines : 0;
    if (result.program && expanded) {
        result.program->expansion = expanded->info;
        result.preview.lines = expanded->info->sourceLines;
    }
    if (result.program)
        addProgramNotes(*result.program, &result);
    if (!result.ok())
        result.program.reset();
    return result;
}

} // namespace stepdeck::program
