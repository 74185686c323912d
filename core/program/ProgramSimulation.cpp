// The check's walk (ProgramCheck): the blocks as the run executes them, repeats counted out,
// following the positions the program reaches (docs/programs.md "Check", "Preview").
#include "ProgramSimulation.h"
#include "CoordinatedFeed.h"
#include "InverseTime.h"
#include "motion/executors/MoveExecutor.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::program {

ProgramSimulation::ProgramSimulation(const MachineFacts& facts, ProgramReader* reader,
                                     CheckErrors* errors)
    : m_facts(facts), m_axes(facts.description.axes), m_reader(*reader), m_moves(m_planned.moves),
      m_errors(errors), m_plan(facts, &m_planned, errors), m_contours(m_plan.contours()),
      m_coordinates(facts.coordinateSystems, facts.activeSystem, facts.lengthTools()),
      m_comp(facts.description, facts.tools)
{
    const size_t n = size_t(m_axes.size());
    m_steps.assign(n, 0);
    m_known.assign(n, 0);
    m_moved.assign(n, 0);
    m_extentKnown.assign(n, 0);
    m_minimum.assign(n, 0);
    m_maximum.assign(n, 0);
    m_offset.assign(n, 0);
    m_programmed.assign(n, std::nullopt);
    for (auto c = facts.capabilities.cbegin(); c != facts.capabilities.cend(); ++c)
        if (c->coordinatedFeed)
            m_coordinated.insert(c.key());
    for (size_t i = 0; i < n; ++i) {
        const machine::MachineAxis& axis = m_axes.at(qsizetype(i));
        const double offset = facts.workOffsets().value(axis.name, 0.0);
        m_offset[i] = std::isfinite(offset) ? offset : 0.0;
        const auto it = facts.knownPositions.constFind(axis.name);
        if (it != facts.knownPositions.cend() && std::isfinite(it.value())) {
            m_steps[i] = axis.toSteps(it.value());
            m_known[i] = 1;
            m_programmed[i] = it.value();
            noteExtent(int(i));
        }
    }
}

bool ProgramSimulation::run(int start, ProgramPreview* preview, const CheckProgress& progress)
{
    constexpr int kProgressBlocks = 4096;
    addPoint(0);
    runPrelude();
    m_firstUnvisited = start;
    bool cancelled = false;
    bool walking = true; // false past the bound of repeated blocks: the rest is only planned
    int i = start;
    for (int sinceProgress = 0;; ++sinceProgress) {
        if (progress && sinceProgress >= kProgressBlocks) {
            sinceProgress = 0;
            if (!progress(m_reader.bytesRead(), m_reader.totalBytes())) {
                cancelled = true;
                break;
            }
        }
        const ProgramBlock* block = m_reader.at(i);
        if (!block)
            break;
        if (!walking || m_reader.parseFailed()) {
            // What the check reports now is the parser's errors, or the plan's of each block.
            if (!m_reader.parseFailed())
                visit(i, *block);
            ++i;
            continue;
        }
        const BlockKind kind = block->kind;
        if (kind == BlockKind::RepeatStart) {
            i = repeatStart(i, *block);
            continue;
        }
        if (kind == BlockKind::RepeatEnd) {
            visit(i, *block);
            if (!repeatEnd(&i, m_reader.partner(i)))
                ++i;
            continue;
        }
        // Under cutter compensation the block runs as the tool's path (CutterCompensation),
        // which looks at the blocks after it: the walk keeps its own copy.
        const bool compensated = m_comp.applies(*block);
        if (compensated) {
            m_compBlock = *block;
            block = &m_compBlock;
        }
        const bool first = compensated ? markVisit(i, *block) : visit(i, *block);
        ++m_blocksRun;
        if (kind != BlockKind::Modal) // as ProgramRunner::advance() passes modal words by
            ++m_blocksDone;
        if (!first && ++m_repeatedBlocks > ProgramCheck::kMaxRepeatedBlocks) {
            tooManyBlocks(*block);
            walking = false;
            i = std::max(i + 1, m_firstUnvisited);
            continue;
        }
        if (compensated)
            compensate(i, *block, first);
        else
            execute(m_planned.block);
        if (kind == BlockKind::End)
            walking = false; // nothing follows M2/M30 (the parser refuses it)
        ++i;
    }
    finish(preview);
    return !cancelled;
}

namespace {
// An error of a block the run sends before its start block, named so: its own words are not on
// the line the error stands at.
QString preludeError(const ProgramBlock& block, const QString& why)
{
    if (block.kind == BlockKind::Rapid)
        return ProgramCheck::tr("run from line %1: the move to its start point first (%2): %3")
            .arg(block.line)
            .arg(block.text, why);
    return ProgramCheck::tr("run from line %1: %2 first, as the lines before it left it: %3")
        .arg(block.line)
        .arg(block.text, why);
}
} // namespace

// The prelude's blocks planned and executed as any block, the current point following them, so
// that the start block is judged from where the run will have put the axes. Their errors are
// gathered apart: CheckErrors::once keys of their own (a start block's word at the same column
// is not taken for told already), and each named as the prelude's.
void ProgramSimulation::runPrelude()
{
    if (m_prelude.isEmpty())
        return;
    CheckErrors walk;
    std::swap(*m_errors, walk); // the plan (m_plan) adds to *m_errors as well
    QList<ProgramError> found;
    for (const ProgramBlock& block : std::as_const(m_prelude)) {
        m_plan.plan(block);
        execute(m_planned.block);
        const QList<ProgramError> errors = m_errors->take();
        for (const ProgramError& e : errors)
            found << ProgramError{block.line, 1, preludeError(block, e.message)};
    }
    std::swap(*m_errors, walk);
    for (const ProgramError& e : std::as_const(found))
        *m_errors << e;
}

// At an O repeat: its first pass begins (the index of the block after it), or a repeat of no
// passes is skipped (the index after its endrepeat).
int ProgramSimulation::repeatStart(int i, const ProgramBlock& block)
{
    const qint64 count = block.count;
    const int line = block.line;
    const int column = block.columnOf({});
    visit(i, block);
    const int end = m_reader.partner(i); // reads on: `block` may be gone
    if (count <= 0 || end < 0) {
        skipBody(i + 1, end);
        return end < 0 ? i + 1 : end + 1;
    }
    m_loops.push_back(Loop{i, line, column, count - 1, m_blocksRun});
    return i + 1;
}

// Plans the block: the first time with its errors (true), again in a repeat's next pass
// without them.
bool ProgramSimulation::visit(int i, const ProgramBlock& block)
{
    const bool first = markVisit(i, block);
    plan(block, first);
    return first;
}

bool ProgramSimulation::markVisit(int i, const ProgramBlock& block)
{
    const bool first = i >= m_firstUnvisited;
    if (first) {
        m_firstUnvisited = i + 1;
        ++m_firstVisits;
        if (m_firstVisit)
            m_firstVisit(block);
    }
    return first;
}

// The blocks CutterCompensation runs in place of block i, each planned and executed as the run
// sends them. Where it refuses, the block is walked as written so that the walk goes on.
void ProgramSimulation::compensate(int i, const ProgramBlock& block, bool first)
{
    m_compOut.clear();
    int next = i + 1;
    const auto following = [this, &next]() { return m_reader.at(next++); };
    if (const auto error =
            m_comp.lower(block, m_coordinates, m_programmed, following, &m_compOut)) {
        if (first)
            m_errors->add(block.line, error->column, [&] { return error->message; });
        m_compOut.assign(1, block);
    }
    for (const ProgramBlock& b : m_compOut) {
        plan(b, first);
        execute(m_planned.block);
    }
}

void ProgramSimulation::plan(const ProgramBlock& block, bool first)
{
    if (CoordinatedFeed::applies(block, m_facts.description, m_coordinated)) {
        // Each axis' share of F follows from where the block starts, as the run resolves it.
        const machine::MachineDescription& d = m_facts.description;
        m_resolved = CoordinatedFeed::resolve(block, d, m_coordinated, m_programmed,
                                              m_coordinates.offsets(block, d));
        m_plan.plan(m_resolved, first);
    } else if (block.inverseTime) {
        // Its rates follow from where it starts (InverseTime), as the run resolves them.
        const machine::MachineDescription& d = m_facts.description;
        const QMap<QString, double> offsets = m_coordinates.offsets(block, d);
        if (isArc(block.kind)) {
            const auto path = ArcPath::plan(block, d, m_programmed, offsets);
            const ArcPath* arc = std::get_if<ArcPath>(&path);
            m_resolved = arc ? InverseTime::resolveArc(block, *arc) : block; // else: arc() says
        } else {
            m_resolved = InverseTime::resolve(block, d, m_programmed, offsets);
        }
        m_plan.plan(m_resolved, first);
    } else {
        m_plan.plan(block, first);
    }
}

// O repeat [0]: its blocks do not run, but they are checked as blocks (the plan's errors).
void ProgramSimulation::skipBody(int from, int end)
{
    if (end < 0)
        return;
    for (int i = std::max(from, m_firstUnvisited); i < end; ++i) {
        const ProgramBlock* block = m_reader.at(i);
        if (!block)
            return;
        visit(i, *block);
    }
}

// At an endrepeat: true with *i at the first block of the next pass.
bool ProgramSimulation::repeatEnd(int* i, int partner)
{
    if (m_loops.empty() || m_loops.back().start != partner)
        return false;
    Loop& loop = m_loops.back();
    // A pass that ran no block (only empty repeats inside) is every pass: the rest are
    // skipped, so that nested empty repeats cannot spin for 10^12 passes.
    if (loop.remaining > 0 && m_blocksRun > loop.blocksBefore) {
        --loop.remaining;
        loop.blocksBefore = m_blocksRun;
        *i = partner + 1;
        return true;
    }
    m_loops.pop_back();
    return false;
}

void ProgramSimulation::setLowered(motion::CommandSink lowered)
{
    m_lowered = std::move(lowered);
    m_lowering = m_lowered ? std::make_unique<ProgramLowering>(m_facts.description) : nullptr;
}

// The block's motion commands to the sink. An arc or cycle the lowering cannot lay is the
// check's error already (arc(), cycle()): its commands are left out.
void ProgramSimulation::lower(const ProgramBlock& block)
{
    m_lowerOut.clear();
    m_lowering->lower(block, m_coordinates, m_programmed, &m_lowerOut);
    for (const motion::MotionCommand& c : m_lowerOut)
        m_lowered(c);
}

void ProgramSimulation::execute(PlannedBlock& planned)
{
    const ProgramBlock& block = *planned.block;
    const bool framing =
        block.kind == BlockKind::SetCoordinates || block.kind == BlockKind::AxisOffset ||
        block.kind == BlockKind::AxisOffsetReset || block.kind == BlockKind::AxisOffsetSuspend ||
        block.kind == BlockKind::AxisOffsetRestore;
    if (m_lowering && !framing)
        lower(block);
    switch (block.kind) {
    case BlockKind::Rapid:
    case BlockKind::Feed:
        move(planned);
        break;
    case BlockKind::ArcClockwise:
    case BlockKind::ArcCounterClockwise:
        arc(planned);
        break;
    case BlockKind::DrillCycle:
        cycle(planned);
        break;
    case BlockKind::Home:
        home(planned);
        break;
    case BlockKind::SetCoordinates:
    case BlockKind::AxisOffset:
    case BlockKind::AxisOffsetReset:
    case BlockKind::AxisOffsetSuspend:
    case BlockKind::AxisOffsetRestore:
        coordinates(planned);
        if (m_lowering)
            lower(block);
        break;
    case BlockKind::Dwell:
        m_seconds += block.seconds;
        addPoint(block.line);
        break;
    default: // M66's wait, M0's pause: no time known; the rest moves nothing
        break;
    }
}

void ProgramSimulation::move(PlannedBlock& planned)
{
    const ProgramBlock& block = *planned.block;
    if (block.axes.isEmpty())
        return; // "G0" alone only sets the motion mode
    // The axes of a block start together, each at its own rate: the block lasts as long as
    // its slowest axis (no acceleration: an estimate). A contour's block runs along its path
    // at F (the stream's steps are the line's, every axis at its share): the root of the
    // axes' times squared, as a coordinated chord (arcChords).
    double seconds = 0;
    double squares = 0;
    if (const ContourMoves::Stream* stream = planned.contour) {
        const motion::CanonicalMove line = m_contours.lineMove(
            *stream, block, m_contours.positionOf(*stream, m_programmed),
            [&](const QString& axis) { return m_coordinates.offset(block, axis); });
        checkContourFeed(planned, *stream, line);
    }
    AxisMove* const first = m_moves.data() + planned.firstMove;
    // Across controllers only on a machine of several (the check's rate: no list otherwise).
    const bool feed = block.kind == BlockKind::Feed && planned.moveCount > 1 &&
                      m_facts.description.controllers.size() > 1;
    AxisList moving;
    for (AxisMove* m = first; m != first + planned.moveCount; ++m) {
        const qint64 before = m_steps[size_t(m->axis)];
        const double axisSeconds = moveAxis(block, *m);
        seconds = std::max(seconds, axisSeconds);
        squares += axisSeconds * axisSeconds;
        if (feed && m_steps[size_t(m->axis)] != before)
            moving.append({m->axis, m->speed});
    }
    if (moving.size() > 1)
        noteControllers(block, moving);
    m_coordinates.advance(block, m_facts.description, &m_programmed);
    if (planned.contour)
        seconds = std::sqrt(squares);
    m_seconds += seconds;
    if (block.kind == BlockKind::Feed)
        m_feedSeconds += seconds;
    addPoint(block.line, block.kind == BlockKind::Rapid);
}

double ProgramSimulation::moveAxis(const ProgramBlock& block, AxisMove& m)
{
    const machine::MachineAxis& axis = m_axes.at(m.axis);
    const size_t a = size_t(m.axis);
    m_moved[a] = 1;
    const bool wasKnown = m_known[a];
    const double here = wasKnown ? axis.toUnits(m_steps[a]) : 0.0;
    double distance = std::abs(m.value);
    if (!block.relative) {
        if (!wasKnown && m_errors->once(block.line, m.column, kUnknownPosition)) {
            m_errors->add(block.line, m.column, [&] {
                return ProgramCheck::tr("%1: the position is unknown, so an absolute move could go "
                                        "anywhere: reference the axis first (G28 %1) or move it "
                                        "relatively (G91)")
                    .arg(axis.name);
            });
        }
        // The target is in work coordinates: the machine goes to target + offset.
        const double target = m.value + m_coordinates.offset(block, axis.name);
        distance = wasKnown ? std::abs(target - here) : 0.0;
        m_steps[a] = axis.toSteps(target);
        m_known[a] = 1; // on from the target, so that one error does not bring others
    } else if (wasKnown) {
        // As Machine::move counts a relative move: the difference of the whole steps.
        m_steps[a] += axis.toSteps(here + m.value) - axis.toSteps(here);
    } else if (const QString why = motion::MoveExecutor::relativeRefusal(
                   m_facts.capabilities.value(axis.controller), axis.name, axis.controller);
               !why.isEmpty() && m_errors->once(block.line, m.column, kUnknownPosition)) {
        m_errors->add(block.line, m.column, [&] { return why; });
    }
    const double seconds = m.speed > 0 ? distance / m.speed : 0.0;
    if (!m_known[a])
        return seconds; // a relative move from an unknown position: its target is unknown too
    // The soft limits are machine coordinates.
    checkLimit(block, m,
               block.relative ? here + m.value : m.value + m_coordinates.offset(block, axis.name));
    noteExtent(m.axis);
    return seconds;
}

void ProgramSimulation::checkLimit(const ProgramBlock& block, AxisMove& m, double to)
{
    const machine::MachineAxis& axis = m_axes.at(m.axis);
    if (axis.hasSoftLimits() && (to < *axis.softMinimum || to > *axis.softMaximum) &&
        m_errors->once(block.line, m.column, kSoftLimit)) {
        m_errors->add(block.line, m.column, [&] {
            const double offset = m_coordinates.offset(block, axis.name);
            if (offset != 0.0)
                return ProgramCheck::tr("%1 reaches %2 %3 in work coordinates, %4 %3 in machine "
                                        "coordinates: outside the soft limits %5..%6 %3 (machine)")
                    .arg(axis.name, figure(to - offset), machine::unitKey(axis.unit), figure(to),
                         figure(*axis.softMinimum), figure(*axis.softMaximum));
            return ProgramCheck::tr("%1 reaches %2 %3, outside the soft limits %4..%5 %3")
                .arg(axis.name, figure(to), machine::unitKey(axis.unit), figure(*axis.softMinimum),
                     figure(*axis.softMaximum));
        });
    }
}

void ProgramSimulation::home(const PlannedBlock& planned)
{
    // A reference run ends at 0 on every model (docs/programs.md "Check"); how long it takes
    // depends on where the switch is: no time is added.
    const AxisMove* const first = m_moves.data() + planned.firstMove;
    for (const AxisMove* m = first; m != first + planned.moveCount; ++m) {
        const size_t a = size_t(m->axis);
        m_moved[a] = 1;
        m_steps[a] = 0;
        m_known[a] = 1;
        m_programmed[a] = 0.0;
        noteExtent(m->axis);
    }
    addPoint(planned.block->line);
}

void ProgramSimulation::noteExtent(int axis)
{
    noteExtentAt(axis, workOf(size_t(axis)));
}

void ProgramSimulation::noteExtentAt(int axis, double at)
{
    const size_t a = size_t(axis);
    if (!m_extentKnown[a]) {
        m_extentKnown[a] = 1;
        m_minimum[a] = m_maximum[a] = at;
        return;
    }
    m_minimum[a] = std::min(m_minimum[a], at);
    m_maximum[a] = std::max(m_maximum[a], at);
}

double ProgramSimulation::workOf(size_t a) const
{
    return m_axes.at(qsizetype(a)).toUnits(m_steps[a]) - m_offset[a];
}

void ProgramSimulation::addPoint(int line, bool rapid)
{
    PreviewPoint at;
    at.line = line;
    at.seconds = m_seconds;
    at.rapid = rapid;
    at.feedSeconds = m_feedSeconds;
    at.blocksDone = m_blocksDone;
    m_path.add(at, m_steps, m_known);
}

void ProgramSimulation::tooManyBlocks(const ProgramBlock& block)
{
    // Named at the outermost repeat that makes the run so long, else at the block itself.
    const int line = m_loops.empty() ? block.line : m_loops.front().line;
    const int column = m_loops.empty() ? block.columnOf({}) : m_loops.front().column;
    *m_errors << ProgramError{line, column,
                              ProgramCheck::tr("the repeats run more than %1 blocks beyond the "
                                               "program's own")
                                  .arg(ProgramCheck::kMaxRepeatedBlocks)};
}

void ProgramSimulation::finish(ProgramPreview* preview) const
{
    preview->blocksRun = m_blocksRun;
    preview->estimatedSeconds = m_seconds;
    preview->motionNote = controllersNote();
    m_path.finish(preview);
    for (qsizetype i = 0; i < m_axes.size(); ++i)
        if (m_offset[size_t(i)] != 0.0)
            preview->workOffsets.insert(m_axes.at(i).name, m_offset[size_t(i)]);
    for (qsizetype i = 0; i < m_axes.size(); ++i) {
        const size_t a = size_t(i);
        if (m_extentKnown[a])
            preview->extents.insert(m_axes.at(i).name,
                                    AxisExtent{m_minimum[a], m_maximum[a], bool(m_moved[a])});
    }
}

// The stream runs every tick at one rate, at most one step per tick on each axis: a feed whose
// path needs more on some axis runs at the highest the tick allows, as LinuxCNC limits a move
// to its axes' velocities (FeedLimit::contourFeed, the same function the run streams by), with
// a note; where the machine file refuses such feeds it is refused (ContourMoves::feedRefusal),
// once per line.
void ProgramSimulation::checkContourFeed(PlannedBlock& planned, const ContourMoves::Stream& stream,
                                         const motion::CanonicalMove& move)
{
    const ProgramBlock& block = *planned.block;
    const int column = block.columnOf(QStringLiteral("F"));
    const double feed = FeedLimit::contourFeed(stream, move, m_facts.description.limits);
    if (feed < move.feed && block.feed) {
        const double share = feed / move.feed;
        m_errors->note(block.line, column, CheckErrors::kContourNote, *block.feed, [&] {
            return ProgramCheck::tr("F%1 runs at F%2, the highest this move can run at in the "
                                    "contour stream of controller \"%3\" (%4 ticks/s, one step "
                                    "per tick at most)")
                .arg(figure(*block.feed), figure(*block.feed * share), stream.controller)
                .arg(stream.tickRate);
        });
        AxisMove* const first = m_moves.data() + planned.firstMove;
        for (AxisMove* m = first; m != first + planned.moveCount; ++m)
            m->speed *= share; // the estimate at the feed that runs
        return;
    }
    const QString why = m_contours.feedRefusal(stream, move, block);
    if (!why.isEmpty() && m_errors->once(block.line, column, kContourFeed))
        m_errors->add(block.line, column, [&] { return why; });
}

} // namespace stepdeck::program
