// The check's walk through a G2/G3 (docs/programs.md "Arcs"): the path the run takes
// (ArcPath, from the same current point), its chords' ends as the device's counts, the soft
// limits at the true curve's extremes, and the preview's points along it.
#include "ProgramSimulation.h"
#include <cmath>

namespace stepdeck::program {

AxisMove* ProgramSimulation::plannedMove(const PlannedBlock& planned, int axis)
{
    AxisMove* const first = m_moves.data() + planned.firstMove;
    for (AxisMove* m = first; m != first + planned.moveCount; ++m)
        if (m->axis == axis)
            return m;
    return nullptr;
}

// G10, G92 and its kin: the coordinates the following blocks' words are in.
void ProgramSimulation::coordinates(PlannedBlock& planned)
{
    const ProgramBlock& block = *planned.block;
    const QString why = m_coordinates.apply(block, m_facts.description, m_programmed);
    if (!why.isEmpty() && m_errors->once(block.line, 0, kBlockError)) {
        m_errors->add(block.line, block.columnOf({}), [&] { return why; });
    }
}

void ProgramSimulation::arc(PlannedBlock& planned)
{
    const ProgramBlock& block = *planned.block;
    const std::variant<ArcPath, ArcPath::Error> planning =
        ArcPath::plan(block, m_facts.description, m_programmed,
                      m_coordinates.offsets(block, m_facts.description));
    if (const ArcPath::Error* e = std::get_if<ArcPath::Error>(&planning)) {
        if (m_errors->once(planned.block->line, 0, kBlockError)) {
            m_errors->add(block.line, e->column, [&] { return e->message; });
        }
        return; // where it would end is unknown: the positions stay as they were
    }
    const ArcPath& path = std::get<ArcPath>(planning);
    if (const ContourMoves::Stream* stream = planned.contour)
        checkContourFeed(
            planned, *stream,
            m_contours.arcMove(*stream, block, path, m_contours.positionOf(*stream, m_programmed)));
    // The soft limits where the curve reaches furthest on each axis, not only at its chords.
    for (const auto& [axis, range] : path.bounds()) {
        AxisMove* m = plannedMove(planned, axis);
        if (!m)
            continue; // the plan named its axis or rate
        checkLimit(block, *m, range.first);
        checkLimit(block, *m, range.second);
        noteExtentAt(axis, range.first - m_offset[size_t(axis)]);
        noteExtentAt(axis, range.second - m_offset[size_t(axis)]);
    }
    if (m_facts.description.controllers.size() > 1) {
        AxisList moving;
        for (const auto& [axis, value] : path.end()) {
            Q_UNUSED(value);
            const AxisMove* m = plannedMove(planned, axis);
            moving.append({axis, m ? m->speed : 0.0});
        }
        noteControllers(block, moving);
    }
    arcChords(path, planned);
}

// Arcs' chords and cycles' moves, counted out like blocks: false (and an error, once) past
// ProgramCheck::kMaxChordsRun.
bool ProgramSimulation::countChords(qint64 chords, PlannedBlock& planned)
{
    m_chordsRun += chords;
    const qint64 bound =
        ProgramCheck::kMaxChordsRun + ProgramCheck::kChordsPerBlock * m_firstVisits;
    if (m_chordsRun <= bound)
        return true;
    if (m_errors->once(planned.block->line, 0, kBlockError)) {
        const ProgramBlock& block = *planned.block;
        m_errors->add(block.line, block.columnOf({}), [&] {
            return ProgramCheck::tr("the run's arcs and cycles need more than %1 moves").arg(bound);
        });
    }
    return false;
}

// Each chord as the run sends it: an absolute move of every moving axis. Its time: along the
// chord at F where the controllers coordinate (CoordinatedFeed) or the arc is a contour's
// (the E-LAB's stream), else the slowest axis' (each axis at its own rate: docs/programs.md
// "How F maps").
void ProgramSimulation::arcChords(const ArcPath& path, PlannedBlock& planned)
{
    const ProgramBlock& block = *planned.block;
    if (!countChords(path.chords(), planned))
        return;
    std::vector<double> speed(m_axes.size(), 0.0);
    // A contour's arc (the E-LAB's stream) runs along its path at F too.
    bool coordinated = !block.inverseTime;
    const bool contour = planned.contour != nullptr;
    for (const auto& [axis, value] : path.end()) {
        Q_UNUSED(value);
        if (const AxisMove* m = plannedMove(planned, axis))
            speed[size_t(axis)] = m->speed;
        coordinated = coordinated && m_coordinated.contains(m_axes.at(axis).controller);
    }
    for (qint64 k = 1; k <= path.chords(); ++k) {
        double seconds = 0;
        double squares = 0;
        for (const auto& [axis, value] : path.pointAt(k)) {
            const size_t a = size_t(axis);
            const machine::MachineAxis& machineAxis = m_axes.at(axis);
            const qint64 steps = machineAxis.toSteps(value);
            const double time = speed[a] > 0 ? std::abs(double(steps - m_steps[a])) /
                                                   machineAxis.stepsPerUnit / speed[a]
                                             : 0.0;
            seconds = std::max(seconds, time);
            squares += time * time;
            m_steps[a] = steps;
            m_known[a] = 1;
            m_moved[a] = 1;
            if (k == path.chords())
                m_programmed[a] = value; // the programmed end exactly
        }
        const double chord = coordinated || contour ? std::sqrt(squares) : seconds;
        m_seconds += chord;
        m_feedSeconds += chord;
        addPoint(block.line);
    }
}

} // namespace stepdeck::program

namespace stepdeck::program {

// G81..G83, G73: each of the cycle's moves as the run sends it (DrillCycle, from the same
// current point), the soft limits at each target, the preview's points with rapids apart.
void ProgramSimulation::cycle(PlannedBlock& planned)
{
    const ProgramBlock& block = *planned.block;
    const std::variant<DrillCycle, DrillCycle::Error> planning =
        DrillCycle::plan(block, m_facts.description, m_programmed,
                         m_coordinates.offsets(block, m_facts.description));
    if (const DrillCycle::Error* e = std::get_if<DrillCycle::Error>(&planning)) {
        if (m_errors->once(planned.block->line, 0, kBlockError)) {
            m_errors->add(block.line, e->column, [&] { return e->message; });
        }
        return;
    }
    const DrillCycle& cycle = std::get<DrillCycle>(planning);
    if (!countChords(qint64(cycle.segments().size()), planned))
        return;
    for (const DrillCycle::Segment& s : cycle.segments()) {
        double seconds = s.seconds;
        for (const auto& [axis, value] : s.targets) {
            AxisMove* m = plannedMove(planned, axis);
            if (!m)
                continue; // the plan named its axis
            const size_t a = size_t(axis);
            const machine::MachineAxis& machineAxis = m_axes.at(axis);
            checkLimit(block, *m, value);
            const qint64 steps = machineAxis.toSteps(value);
            const double speed = s.kind == DrillCycle::Kind::Feed ? planned.feedSpeed : m->speed;
            if (speed > 0)
                seconds = std::max(seconds, std::abs(double(steps - m_steps[a])) /
                                                machineAxis.stepsPerUnit / speed);
            m_steps[a] = steps;
            m_known[a] = 1;
            m_moved[a] = 1;
            noteExtent(axis);
        }
        m_seconds += seconds;
        if (s.kind == DrillCycle::Kind::Feed)
            m_feedSeconds += seconds;
        addPoint(block.line, s.kind == DrillCycle::Kind::Rapid);
    }
    for (const auto& [axis, value] : cycle.end())
        m_programmed[size_t(axis)] = value;
}

} // namespace stepdeck::program
