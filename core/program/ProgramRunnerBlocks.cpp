// ProgramRunner: what each block sends and what it waits for before the next one starts.
#include "CoordinatedFeed.h"
#include "InverseTime.h"
#include "ProgramLowering.h"
#include "ProgramRules.h"
#include "ProgramRunner.h"
#include "ProgramUnits.h"
#include "machine/ControllerFacts.h"
#include "machine/Machine.h"
#include "model/ModelOperations.h"
#include "motion/executors/SwitchExecutor.h"
#include "motion/executors/WaitExecutor.h"

namespace stepdeck::program {

void ProgramRunner::startBlock(const ProgramBlock& block)
{
    m_blockError = ErrorKind::None;
    // A line's actions are blocks of their own in LinuxCNC's order of execution (ProgramLine),
    // S with the first of them. S on a block of another action ("G1 X5 S500"): while the program
    // has the spindle on, its new speed goes out first. With the spindle off, S is only the
    // speed the next M3 starts at.
    if (m_spindleOn)
        if (const std::optional<motion::MotionCommand> speed =
                ProgramLowering::speedChange(block)) {
            startSwitchCommand(*speed, [this] { startAction(m_block); });
            return;
        }
    startAction(m_block);
}

void ProgramRunner::startAction(const ProgramBlock& block)
{
    if (const ContourMoves::Stream* stream = m_contourMoves->streamOf(block)) {
        // A G1/G2/G3 of a contour: the first block of a stream, after what its line switched.
        openContour(*stream);
        if (appendToContour(block))
            runNext();
        return;
    }
    switch (block.kind) {
    case BlockKind::Rapid:
    case BlockKind::Feed:
        startMove(block);
        return;
    case BlockKind::ArcClockwise:
    case BlockKind::ArcCounterClockwise:
        startArc(block);
        return;
    case BlockKind::DrillCycle:
        startCycle(block);
        return;
    case BlockKind::Home:
        startHome(block);
        return;
    case BlockKind::SetCoordinates:
    case BlockKind::AxisOffset:
    case BlockKind::AxisOffsetReset:
    case BlockKind::AxisOffsetSuspend:
    case BlockKind::AxisOffsetRestore:
        applyCoordinates(block);
        return;
    case BlockKind::Dwell:
        // At least P between the previous block's confirmation and the next block's first
        // byte: the wait starts only now.
        m_waits->push(motion::Dwell{block.line, block.seconds});
        return;
    case BlockKind::WaitInput:
        // M66: its level from a status read asked for now (WaitExecutor).
        m_waits->push(motion::WaitInput{block.line, block.number, block.inputHigh, block.seconds});
        return;
    case BlockKind::Pause:
    case BlockKind::OptionalPause:
    case BlockKind::ToolChange:
    case BlockKind::End:
    case BlockKind::SpindleSpeed: // a running spindle got the speed in startBlock()
        blockDone(); // pauses at M0, M6 (and M1 with optional stops), finishes at M2/M30
        return;
    default:
        startSwitch(block, [this] { blockDone(); });
        return;
    }
}

// A G0 or G1 of its own: the move executor writes G1's rates (or puts G0's fast speed back)
// first, and sends the move once they were taken.
void ProgramRunner::startMove(const ProgramBlock& block)
{
    // G93, or a G1 on coordinating controllers: each axis' rate from where the block starts,
    // as the check resolved it.
    const machine::MachineDescription& d = m_machine->description();
    ProgramBlock resolved = block;
    if (block.inverseTime)
        resolved = InverseTime::resolve(block, d, m_programmed, m_coordinates.offsets(block, d));
    else if (CoordinatedFeed::applies(block, d, m_coordinated, m_feedOverride != 1.0))
        resolved = CoordinatedFeed::resolve(block, d, m_coordinated, m_programmed,
                                            m_coordinates.offsets(block, d), m_feedOverride);
    motion::RatedMove move = ProgramLowering::ratedMove(resolved, d);
    move.absolute = !block.relative;
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it)
        if (const int a = d.axisIndex(it.key()); a >= 0)
            // Relative: the distance (a target from 0), as Machine::move takes it.
            move.targets.emplace_back(
                a,
                *m_coordinates.target(block, d.axes.at(a), it.value(),
                                      block.relative ? std::optional<double>(0.0) : std::nullopt));
    pushMove(move);
}

// Refused when a G0 cannot run at the fast speed (the check refused it first).
void ProgramRunner::pushMove(const motion::RatedMove& move)
{
    if (const QString why = m_moves->cannotPutBack(move); !move.feed && !why.isEmpty()) {
        fail(ErrorKind::Refused, why);
        return;
    }
    m_moves->push(move);
}

// G10, G92 and its kin change the coordinates of the blocks after them; nothing is sent. A G10
// is reported, so the window keeps the table for the next runs.
void ProgramRunner::applyCoordinates(const ProgramBlock& block)
{
    const QString why = m_coordinates.apply(block, m_machine->description(), m_programmed);
    if (!why.isEmpty()) {
        fail(ErrorKind::Refused, why); // the check refused it first
        return;
    }
    if (block.kind == BlockKind::SetCoordinates) {
        const int system = block.number == 0 ? m_coordinates.systemOf(block) : block.number - 1;
        Q_EMIT coordinateSystemSet(system, m_coordinates.systems()[size_t(system)]);
    }
    blockDone();
}

void ProgramRunner::startHome(const ProgramBlock& block)
{
    motion::Reference reference{block.line, {}}; // none named: every axis
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it)
        reference.axes << m_machine->description().axisIndex(it.key());
    m_moves->push(reference);
}

// Spindle, coolant and outputs: the command the lowering makes of the block.
void ProgramRunner::startSwitch(const ProgramBlock& block, std::function<void()> then)
{
    const std::optional<motion::MotionCommand> command = ProgramLowering::switchCommand(block);
    if (!command) {
        fail(ErrorKind::Unsupported,
             tr("%1: the machine has nothing to switch").arg(blockWord(block.kind)));
        return;
    }
    startSwitchCommand(*command, std::move(then));
}

// Refused by the machine's SwitchExecutor as the check was told (asked again of the machine as
// it is now: nothing is sent), else one request, done when the controller acknowledged it.
void ProgramRunner::startSwitchCommand(const motion::MotionCommand& command,
                                       std::function<void()> then)
{
    const MachineFacts facts = factsOf(*m_machine);
    const motion::SwitchExecutor switches(facts.description, facts.capabilities, facts.schemas);
    if (const std::optional<motion::SwitchExecutor::Refusal> refusal = switches.accepts(command)) {
        fail(refusal->kind, refusal->text);
        return;
    }
    QString controller;
    const RequestId id = switches.push(command, *m_machine, &controller);
    if (id == 0) {
        fail(ErrorKind::Unsupported, tr("%1: the machine has nothing to switch")
                                         .arg(motion::SwitchExecutor::wordOf(command)));
        return;
    }
    if (std::holds_alternative<motion::SpindleOn>(command))
        m_spindleOn = true;
    else if (std::holds_alternative<motion::SpindleOff>(command))
        m_spindleOn = false;
    awaitRequests({{id, controller}}, std::move(then));
}

void ProgramRunner::awaitRequests(const QMap<RequestId, QString>& requests,
                                  std::function<void()> then)
{
    m_requests.clear();
    for (auto it = requests.cbegin(); it != requests.cend(); ++it)
        m_requests.insert(it.key());
    if (m_requests.isEmpty()) {
        then();
        return;
    }
    m_afterRequests = std::move(then);
}

void ProgramRunner::onRequestFinished(const QString& controllerId, const CommandResult& result)
{
    if (!result.ok() && result.id != 0)
        m_blockError = result.error;
    if (result.id == 0 || !m_requests.remove(result.id))
        return;
    if (!result.ok()) {
        fail(result.error, tr("controller \"%1\": %2").arg(controllerId, result.message));
        return;
    }
    if (m_requests.isEmpty() && m_afterRequests) {
        const std::function<void()> then = std::exchange(m_afterRequests, nullptr);
        then();
    }
}

// A move or a reference run of the move executor ended: the block goes on (an arc's next
// chord, a cycle's next move) or is done.
void ProgramRunner::onMoveFinished(bool ok, ErrorKind kind, const QString& message)
{
    if (m_aborting) {
        end(RunState::Aborted,
            lineText(ok ? tr("aborted after the move under way ended") : tr("aborted")));
        return;
    }
    if (!ok && kind != ErrorKind::None) {
        fail(kind, message); // a write or the move refused
        return;
    }
    if (!ok) {
        failSoon(ErrorKind::None, message);
        return;
    }
    if (nextInPath())
        return;
    blockDone();
}

// The machine reports a failed move from the same requestFinished emission that brings this
// runner the request's failure, and it is connected first: the fault is judged once that
// emission is over, so a NAK is a NAK and not "ended short". None stays None only when no
// request failed: a move that ended short of its target (an end switch, a stop from elsewhere).
void ProgramRunner::failSoon(ErrorKind kind, const QString& message)
{
    const quint64 run = m_run;
    QMetaObject::invokeMethod(
        this,
        [this, run, kind, message] {
            if (run == m_run)
                fail(kind != ErrorKind::None ? kind : m_blockError, message);
        },
        Qt::QueuedConnection);
}

void ProgramRunner::onControllerFailed(const QString& controllerId, const QString& message)
{
    const bool linkLost = machine::linkDown(*m_machine, controllerId);
    if (m_aborting && !linkLost)
        return; // the stop's own effect on the motion under way; its end comes as usual
    if (linkLost) {
        // At once: the machine has just posted the stop to the other controllers, and their
        // requests cancelled by it may come back before a queued failSoon would run (seen
        // once under load: the run failed "Cancelled" instead of LinkDown).
        fail(ErrorKind::LinkDown, message);
        return;
    }
    failSoon(ErrorKind::None, message);
}

} // namespace stepdeck::program
