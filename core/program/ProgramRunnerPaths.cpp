// ProgramRunner: blocks of many moves. An arc runs as chords (ArcPath), a drilling cycle as its
// moves and dwell (DrillCycle), each planned from the current point as the check planned it;
// each move starts when the one before arrived, and a pause holds between two of them.
#include "CoordinatedFeed.h"
#include "InverseTime.h"
#include "ProgramRates.h"
#include "ProgramRunner.h"
#include "machine/Machine.h"

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
    if (m_chordsCoordinated) {
        sendChord();
        return;
    }
    // G93: the path speed that covers the curve in 1/F minutes (InverseTime), as the check.
    const QMap<RequestId, QString> rates = m_rates->before(
        ArcPath::rateBlock(block.inverseTime ? InverseTime::resolveArc(block, *m_arc) : block));
    awaitRequests(rates, [this] { sendChord(); });
}

void ProgramRunner::sendChord()
{
    if (!m_arc)
        return;
    ++m_chord;
    if (m_chordsCoordinated) {
        const QMap<RequestId, QString> rates = m_rates->before(CoordinatedFeed::resolveChord(
            m_block, *m_arc, m_chord, m_machine->description(), m_coordinated, m_feedOverride));
        awaitRequests(rates, [this] { moveChord(); });
        return;
    }
    moveChord();
}

void ProgramRunner::moveChord()
{
    if (!m_arc)
        return;
    QMap<QString, double> targets;
    const machine::MachineDescription& d = m_machine->description();
    for (const auto& [axis, value] : m_arc->pointAt(m_chord))
        targets.insert(d.axes.at(axis).name, value);
    QString refusal;
    m_motion = m_machine->move(targets, true, &refusal, machine::Machine::MoveKind::Feed, this);
    if (m_motion == 0)
        fail(ErrorKind::Refused, refusal);
}

// G81..G83, G73: each move with the rates of a G0 or G1 over the axes it moves (ProgramRates
// writes G1's rate, or puts the fast speed back before a rapid), the dwell by the timer.
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
        m_dwell.start(int(std::min(s.seconds * 1000.0, 2.0e9)));
        return;
    }
    const ProgramBlock segment = DrillCycle::segmentBlock(m_block, s, m_machine->description());
    if (const QString why = m_rates->cannotPutBack(segment);
        s.kind == DrillCycle::Kind::Rapid && !why.isEmpty()) {
        fail(ErrorKind::Refused, why);
        return;
    }
    const QMap<RequestId, QString> rates = m_rates->before(segment);
    awaitRequests(rates, [this] { sendSegment(); });
}

void ProgramRunner::sendSegment()
{
    if (!m_cycle)
        return;
    const DrillCycle::Segment& s = m_cycle->segments().at(m_segment);
    QMap<QString, double> targets;
    const machine::MachineDescription& d = m_machine->description();
    for (const auto& [axis, value] : s.targets)
        targets.insert(d.axes.at(axis).name, value);
    QString refusal;
    m_motion =
        m_machine->move(targets, true, &refusal,
                        s.kind == DrillCycle::Kind::Feed ? machine::Machine::MoveKind::Feed
                                                         : machine::Machine::MoveKind::Positioning,
                        this);
    if (m_motion == 0)
        fail(ErrorKind::Refused, refusal);
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

void ProgramRunner::onDwellDone()
{
    if (m_state != RunState::Running || m_aborting)
        return;
    if (m_cycle && nextInPath())
        return;
    blockDone();
}

} // namespace stepdeck::program
