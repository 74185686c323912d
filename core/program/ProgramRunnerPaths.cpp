// ProgramRunner: blocks of many moves. An arc runs as chords (ArcPath), a drilling cycle as its
// moves and dwell (DrillCycle), each planned from the current point as the check planned it;
// each move starts when the one before arrived, and a pause holds between two of them.
#include "CoordinatedFeed.h"
#include "InverseTime.h"
#include "ProgramLowering.h"
#include "ProgramRunner.h"
#include "machine/Machine.h"
#include "motion/executors/WaitExecutor.h"

namespace stepdeck::program {

// G2/G3: the arc's rates written once as for a G1 over its axes (on coordinating controllers:
// each chord's shares of F before it), then one chord after the other, each an absolute move.
void ProgramRunner::startArc(const ProgramBlock& block)
{
    std::variant<ArcPath, ArcPath::Error> planning =
        ArcPath::plan(block, m_machine->description(), m_programmed,
                      m_coordinates.offsets(block, m_machine->description()));
    if (const ArcPath::Error* e = std::get_if<ArcPath::Error>(&planning)) {
        fail(ErrorKind::Refused, e->message); // the check refused it first
        return;
    }
    m_arc = std::get<ArcPath>(std::move(planning));
    m_chord = 0;
    // On coordinating controllers each chord gets the shares of F along it (sendChord).
    m_chordsCoordinated =
        !CoordinatedFeed::resolveChord(block, *m_arc, 1, m_machine->description(), m_coordinated)
             .axisRates.isEmpty();
    sendChord();
}

// A chord as a feed move: the first with the arc's rates (G93: the path speed that covers the
// curve in 1/F minutes, InverseTime, as the check), the others at them; on coordinating
// controllers each with its own shares of F.
void ProgramRunner::sendChord()
{
    if (!m_arc)
        return;
    ++m_chord;
    const machine::MachineDescription& d = m_machine->description();
    motion::RatedMove chord;
    if (m_chordsCoordinated)
        chord =
            ProgramLowering::ratedMove(CoordinatedFeed::resolveChord(m_block, *m_arc, m_chord, d,
                                                                     m_coordinated, m_feedOverride),
                                       d);
    else if (m_chord == 1)
        chord = ProgramLowering::ratedMove(
            ArcPath::rateBlock(m_block.inverseTime ? InverseTime::resolveArc(m_block, *m_arc)
                                                   : m_block),
            d);
    chord.line = m_block.line;
    chord.feed = true;
    for (const auto& [axis, value] : m_arc->pointAt(m_chord))
        chord.targets.emplace_back(axis, value);
    pushMove(chord);
}

// G81..G83, G73: each move with the rates of a G0 or G1 over the axes it moves (the move
// executor writes G1's rate, or puts the fast speed back before a rapid), the dwell by the timer.
void ProgramRunner::startCycle(const ProgramBlock& block)
{
    std::variant<DrillCycle, DrillCycle::Error> planning =
        DrillCycle::plan(block, m_machine->description(), m_programmed,
                         m_coordinates.offsets(block, m_machine->description()));
    if (const DrillCycle::Error* e = std::get_if<DrillCycle::Error>(&planning)) {
        fail(ErrorKind::Refused, e->message); // the check refused it first
        return;
    }
    m_cycle = std::get<DrillCycle>(std::move(planning));
    m_segment = 0;
    if (m_cycle->segments().empty()) {
        blockDone(); // already where the cycle would leave it
        return;
    }
    startSegment();
}

void ProgramRunner::startSegment()
{
    const DrillCycle::Segment& s = m_cycle->segments().at(m_segment);
    if (s.kind == DrillCycle::Kind::Dwell) {
        m_waits->push(motion::Dwell{m_block.line, s.seconds});
        return;
    }
    const machine::MachineDescription& d = m_machine->description();
    motion::RatedMove move = ProgramLowering::ratedMove(DrillCycle::segmentBlock(m_block, s, d), d);
    for (const auto& [axis, value] : s.targets)
        move.targets.emplace_back(axis, value);
    pushMove(move);
}

bool ProgramRunner::nextInPath()
{
    const bool more =
        m_arc ? m_chord < m_arc->chords() : m_cycle && m_segment + 1 < m_cycle->segments().size();
    if (!more)
        return false;
    if (m_cycle)
        ++m_segment;
    if (m_pauseAsked) {
        m_pauseAsked = false;
        m_heldInPath = true;
        setState(RunState::Paused);
        Q_EMIT paused(currentLine(), QString());
        return true;
    }
    resumePath();
    return true;
}

void ProgramRunner::resumePath()
{
    m_heldInPath = false;
    if (m_arc)
        sendChord();
    else if (m_cycle)
        startSegment();
}

void ProgramRunner::endPath(AxisPositions* programmed)
{
    const QList<std::pair<int, double>> end = m_arc ? m_arc->end() : m_cycle->end();
    for (const auto& [axis, value] : end)
        (*programmed)[size_t(axis)] = value;
    m_arc.reset();
    m_cycle.reset();
}

// A dwell or an input wait (WaitExecutor) ended: the cycle's next move, or the block done.
void ProgramRunner::onWaitFinished(bool ok, ErrorKind kind, const QString& message)
{
    if (!ok) {
        fail(kind, message);
        return;
    }
    if (m_state != RunState::Running || m_aborting)
        return;
    if (m_cycle && nextInPath())
        return;
    blockDone();
}

} // namespace stepdeck::program
