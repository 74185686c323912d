// ProgramRunner: feed moves of a contour (ContourMoves) as one step stream
// (motion::StreamExecutor). The
// blocks are appended as the stream makes room; a block of another kind (or a pause, a step,
// a switch on the line) waits until the stream ended.
#include "FeedLimit.h"
#include "ProgramRunner.h"
#include "machine/Machine.h"
#include "motion/executors/StreamExecutor.h"

namespace stepdeck::program {

// Whether `block` continues the open contour: a feed move of the same stream with no spindle
// speed to change first, while no pause or step asks to hold after the block under way.
bool ProgramRunner::joinsContour(const ProgramBlock& block) const
{
    if (!m_contour || m_contour->isClosed() || m_pauseAsked || m_stepOnly)
        return false;
    const ContourMoves::Stream* stream = m_contourMoves->streamOf(block);
    return stream && stream->controller == m_contour->stream().controller &&
           !(block.spindleChange && m_spindleOn);
}

void ProgramRunner::openContour(const ContourMoves::Stream& stream)
{
    dropContour();
    m_contour = std::make_unique<motion::StreamExecutor>(m_machine, stream);
    motion::StreamExecutor* c = m_contour.get();
    connect(c, &motion::StreamExecutor::blockStarted, this, &ProgramRunner::blockStarted);
    connect(c, &motion::StreamExecutor::blockFinished, this, [this](int line) {
        ++m_blocksDone;
        Q_EMIT blockFinished(line);
    });
    connect(c, &motion::StreamExecutor::roomForMoves, this, &ProgramRunner::runNext);
    connect(c, &motion::StreamExecutor::finished, this, &ProgramRunner::onContourFinished);
    c->start(m_programmed, m_feedOverride);
}

// The block's move from where the contour ends, and the program's current point after it (as
// blockDone() moves it for a block of its own).
bool ProgramRunner::appendToContour(const ProgramBlock& block)
{
    const machine::MachineDescription& d = m_machine->description();
    const ContourMoves::Stream& stream = m_contour->stream();
    motion::CanonicalMove move;
    if (block.kind == BlockKind::Feed) {
        move = m_contourMoves->lineMove(stream, block, m_contour->end(), [&](const QString& axis) {
            return m_coordinates.offset(block, axis);
        });
        m_coordinates.advance(block, d, &m_programmed);
    } else {
        const std::variant<ArcPath, ArcPath::Error> planning =
            ArcPath::plan(block, d, m_programmed, m_coordinates.offsets(block, d));
        if (const ArcPath::Error* e = std::get_if<ArcPath::Error>(&planning)) {
            fail(ErrorKind::Refused, e->message); // the check refused it first
            return false;
        }
        const ArcPath& path = std::get<ArcPath>(planning);
        move = m_contourMoves->arcMove(stream, block, path, m_contour->end());
        for (const auto& [axis, value] : path.end())
            m_programmed[size_t(axis)] = value;
    }
    // Above the highest feed its tick allows, the move runs at that highest, as the check said
    // in its note and estimated (issue 50: the one function both take it from).
    move.feed = FeedLimit::contourFeed(stream, move, d.limits);
    if (const QString why = m_contour->append(move, block.text); !why.isEmpty()) {
        fail(ErrorKind::Refused, why); // the check refused it first (its feed, its start)
        return false;
    }
    return true;
}

void ProgramRunner::onContourFinished(bool ok, ErrorKind kind, const QString& message)
{
    const int line = m_contour->lastFinishedLine();
    dropContour();
    if (m_aborting) {
        end(RunState::Aborted,
            lineText(ok ? tr("aborted after the move under way ended") : tr("aborted")));
        return;
    }
    if (!ok) {
        fail(kind, message);
        return;
    }
    if (m_pauseAsked || m_stepOnly) {
        m_pauseAsked = false;
        m_prompt.clear();
        m_operatorStop = false;
        setState(RunState::Paused);
        Q_EMIT paused(line, QString());
        return;
    }
    runNext();
}

// Deleted once the signal it may be emitting is over; the controller keeps the stream's
// ContourFeed for as long as it runs.
void ProgramRunner::dropContour()
{
    if (!m_contour)
        return;
    disconnect(m_contour.get(), nullptr, this, nullptr);
    m_contour->cancel();
    m_contour.release()->deleteLater();
}

} // namespace stepdeck::program
