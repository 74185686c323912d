// ProgramRunner: the run's states and its walk through the blocks (repeats, pause, step,
// abort, faults). Starting a run and run from line's prelude are in ProgramRunnerStart.cpp,
// what each block sends in ProgramRunnerBlocks.cpp.
#include "ProgramRunner.h"
#include "ProgramLine.h"
#include "ProgramLogging.h"
#include "ProgramReader.h"
#include "RunFromLine.h"
#include "machine/ControllerFacts.h"
#include "machine/Machine.h"
#include "motion/executors/MoveExecutor.h"
#include "motion/executors/StreamExecutor.h"
#include "motion/executors/WaitExecutor.h"
#include <algorithm>

namespace stepdeck::program {

namespace {
// Bound for the axes to report standstill after abort(): past it the run ends Aborted and
// says that the standstill was not confirmed.
constexpr int kAbortSettleMs = 15000;
} // namespace

QString runStateText(RunState state)
{
    switch (state) {
    case RunState::Idle:
        return ProgramRunner::tr("idle");
    case RunState::Running:
        return ProgramRunner::tr("running");
    case RunState::Paused:
        return ProgramRunner::tr("paused");
    case RunState::Stopping:
        return ProgramRunner::tr("stopping");
    case RunState::Finished:
        return ProgramRunner::tr("finished");
    case RunState::Failed:
        return ProgramRunner::tr("failed");
    case RunState::Aborted:
        return ProgramRunner::tr("aborted");
    }
    return {};
}

bool isEnded(RunState state)
{
    return state == RunState::Finished || state == RunState::Failed || state == RunState::Aborted;
}

ProgramRunner::ProgramRunner(machine::Machine* machine, QObject* parent)
    : QObject(parent), m_machine(machine), m_ownerName(tr("a program runs"))
{
    m_abortSettle.setSingleShot(true);
    connect(&m_abortSettle, &QTimer::timeout, this, [this] {
        end(RunState::Aborted, tr("aborted; the controllers did not confirm standstill"));
    });
}

// The machine's motion needs no release here: MotionOwnership forgets an owner that is deleted
// (and the machine may have gone first).
ProgramRunner::~ProgramRunner() = default;

bool ProgramRunner::claimMotion(QString* why)
{
    return m_machine && m_machine->claimMotion(this, m_ownerName, why);
}

void ProgramRunner::releaseMotion()
{
    if (m_machine && (m_state == RunState::Idle || isEnded(m_state)))
        m_machine->releaseMotion(this);
}

int ProgramRunner::currentLine() const
{
    if (m_contour && m_contour->currentLine() > 0)
        return m_contour->currentLine(); // m_block was read ahead
    return m_index >= 0 ? m_block.line : 0;
}

void ProgramRunner::connectMachine()
{
    disconnectMachine();
    m_connections << connect(m_machine, &machine::Machine::controllerFailed, this,
                             &ProgramRunner::onControllerFailed);
    m_connections << connect(m_machine, &machine::Machine::spindleAndCoolantOff, this,
                             &ProgramRunner::onSwitchedOff);
    // The machine's STOP, PANIC or close (whoever pressed it): this run holds the motion and
    // ends. Its own abort stops the machine again, which tells nobody twice.
    m_connections << connect(m_machine, &machine::Machine::abortRequested, this, [this] {
        if (!m_aborting && !m_ownStop)
            abort();
    });
    m_connections << connect(m_machine, &machine::Machine::requestFinished, this,
                             &ProgramRunner::onRequestFinished);
}

void ProgramRunner::disconnectMachine()
{
    for (const QMetaObject::Connection& c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
}

void ProgramRunner::pause()
{
    if (m_state != RunState::Running || m_pauseAsked)
        return;
    m_pauseAsked = true;
    if (m_contour)
        m_contour
            ->close(); // the blocks appended run, then it holds (StreamExecutor::kAheadSeconds)
    Q_EMIT stateChanged(m_state); // pausePending() changed: "pausing after this block"
}

void ProgramRunner::setFeedOverride(double percent)
{
    m_feedOverride = std::clamp(percent, 10.0, 200.0) / 100.0;
    if (m_contour)
        m_contour->setFeedFactor(m_feedOverride);
}

bool ProgramRunner::holdFeed()
{
    if (m_state != RunState::Running)
        return false;
    if (!m_contour) {
        pause();
        return true;
    }
    m_feedHeld = true;
    m_contour->hold(true);
    m_operatorStop = false;
    m_prompt = tr("Feed hold: the path stops where it is; Resume goes on from there");
    setState(RunState::Paused);
    Q_EMIT paused(currentLine(), m_prompt);
    return true;
}

void ProgramRunner::resume()
{
    if (m_state == RunState::Running && m_pauseAsked) {
        m_pauseAsked = false; // the pause asked for is withdrawn before it held
        Q_EMIT stateChanged(m_state);
        return;
    }
    if (m_state != RunState::Paused || refuseToGoOn())
        return;
    if (restNeedsCheck()) {
        const MachineFacts facts = restFacts();
        resumeChecked(facts, ProgramCheck::checkRest(m_program, facts, restBlock()));
        return;
    }
    if (std::exchange(m_feedHeld, false) && m_contour) {
        m_prompt.clear();
        setState(RunState::Running);
        m_contour->hold(false); // on along the path from where it stands
        return;
    }
    m_pauseAsked = false;
    m_stepOnly = false;
    m_prompt.clear();
    setState(RunState::Running);
    if (m_heldInPath)
        resumePath(); // on along the arc or cycle it held in
    else
        runNext();
}

void ProgramRunner::step()
{
    if (m_state != RunState::Paused || refuseToGoOn())
        return;
    if (restNeedsCheck()) {
        const MachineFacts facts = restFacts();
        resumeChecked(facts, ProgramCheck::checkRest(m_program, facts, restBlock()), true);
        return;
    }
    if (std::exchange(m_feedHeld, false) && m_contour) {
        // The rest of the moves already appended is the step; then it holds.
        m_pauseAsked = true;
        m_contour->close();
        m_prompt.clear();
        setState(RunState::Running);
        m_contour->hold(false);
        return;
    }
    m_pauseAsked = false;
    m_stepOnly = true;
    m_prompt.clear();
    setState(RunState::Running);
    if (m_heldInPath)
        resumePath(); // the rest of the arc or cycle is the step
    else
        runNext();
}

void ProgramRunner::abort()
{
    if (m_state != RunState::Running && m_state != RunState::Paused)
        return;
    m_aborting = true;
    m_waits->cancel();
    m_requests.clear();
    m_moves->dropPending(); // a move's rates not taken yet: the move is never sent
    m_machine->stop();
    if (m_contour)
        m_contour->cancel(); // one not given yet ends the run here
    if (isEnded(m_state))
        return;
    if (!m_moves->moveSent() && !m_contour) {
        end(RunState::Aborted, lineText(tr("aborted")));
        return;
    }
    // The axes are still braking (or, without a stop command, running out): ended once the
    // machine reports the motion's end.
    const QStringList runOut = machine::controllersWithoutStop(*m_machine);
    setState(RunState::Stopping);
    if (!runOut.isEmpty())
        Q_EMIT stopping(tr("%1 has no stop command: the move under way finishes by itself")
                            .arg(runOut.join(QStringLiteral(", "))));
    m_abortSettle.start(kAbortSettleMs);
}

void ProgramRunner::runNext()
{
    if (!m_prelude.isEmpty() && m_state == RunState::Running && !m_aborting) {
        runPrelude();
        return;
    }
    while (m_state == RunState::Running && !m_aborting) {
        if (m_contour && !m_contour->isClosed() && !m_contour->hasRoom())
            return; // StreamExecutor::roomForMoves calls again
        if (!std::exchange(m_heldBlock, false) && !advance()) {
            if (!m_compError.isEmpty())
                fail(ErrorKind::InvalidValue, m_compError);
            else if (!m_reader->error().isEmpty())
                fail(ErrorKind::InvalidValue, m_reader->error());
            else if (m_contour)
                m_contour->close(); // its end comes back here, and then the program's
            else
                finishProgram();
            return;
        }
        if (m_contour && joinsContour(m_block)) {
            if (!appendToContour(m_block))
                return;
            continue;
        }
        if (m_contour) { // a block of another kind: it waits for the contour's end
            m_heldBlock = true;
            m_contour->close();
            return;
        }
        Q_EMIT blockStarted(m_block.line, m_block.text);
        startBlock(m_block);
        return;
    }
}

// Onto the next block that does something; repeats are counted here.
bool ProgramRunner::advance()
{
    if (!m_compQueue.empty()) { // the move after a corner's arc (CutterCompensation)
        m_block = std::move(m_compQueue.front());
        m_compQueue.pop_front();
        m_uncounted = false;
        return true;
    }
    for (;;) {
        const ProgramBlock* read = m_reader->at(++m_index);
        if (!read)
            return false; // the end, or the file cannot be read as it was checked (error())
        m_block = *read;
        const ProgramBlock& b = m_block;
        if (!b.message.isEmpty())
            Q_EMIT operatorMessage(b.line, b.message);
        switch (b.kind) {
        case BlockKind::Modal:
            continue;
        case BlockKind::RepeatStart:
            if (b.count <= 0)
                m_index = b.partner; // its endrepeat; on after it
            else
                m_loops << Loop{m_index, b.count - 1};
            continue;
        case BlockKind::RepeatEnd:
            if (!m_loops.isEmpty() && m_loops.last().remaining > 0) {
                --m_loops.last().remaining;
                m_index = m_loops.last().start;
            } else if (!m_loops.isEmpty()) {
                m_loops.removeLast();
            }
            continue;
        default:
            return !m_comp->applies(b) || compensate();
        }
    }
    return false;
}

// The block as the tool's path under cutter compensation, as the check walked it: a corner's
// arc first (not counted as a block of its own), then the move. false: refused (m_compError).
bool ProgramRunner::compensate()
{
    std::vector<ProgramBlock> out;
    int next = m_index + 1;
    const auto following = [this, &next]() { return m_reader->at(next++); };
    if (const auto error = m_comp->lower(m_block, m_coordinates, m_programmed, following, &out)) {
        m_compError = error->message;
        return false;
    }
    m_block = std::move(out.front());
    for (size_t i = 1; i < out.size(); ++i)
        m_compQueue.push_back(std::move(out[i]));
    m_uncounted = !m_compQueue.empty();
    return true;
}

void ProgramRunner::blockDone()
{
    if (m_state != RunState::Running || m_aborting)
        return;
    if (std::exchange(m_approaching, false)) {
        approachDone();
        return;
    }
    if (!std::exchange(m_uncounted, false))
        ++m_blocksDone;
    const ProgramBlock& block = m_block;
    if (m_arc || m_cycle)
        endPath(&m_programmed);
    else
        m_coordinates.advance(block, m_machine->description(), &m_programmed);
    Q_EMIT blockFinished(block.line);
    if (block.kind == BlockKind::End) {
        finishProgram(true);
        return;
    }
    const bool operatorStop = waitsForOperator(block.kind, m_optionalStops);
    if (operatorStop || m_pauseAsked || m_stepOnly) {
        m_prompt = operatorStop ? promptOf(block) : QString();
        m_operatorStop = operatorStop;
        m_pauseAsked = false;
        startTouchOff(block);
        setState(RunState::Paused);
        Q_EMIT paused(block.line, m_prompt);
        return;
    }
    runNext();
}

void ProgramRunner::finishProgram(bool programEnd)
{
    // The fast speeds a G1 changed go back before the run says it finished; at M2/M30 the
    // spindle and the coolant go off then, as LinuxCNC's program end switches them off (a
    // Fusion 360 post ends "G0 Z15 / M30" with no M5). A program that runs out without M2 (an
    // MDI line) leaves them as they are.
    m_requests.clear();
    const QMap<RequestId, QString> writes = m_moves->restore();
    for (auto it = writes.cbegin(); it != writes.cend(); ++it)
        m_requests.insert(it.key());
    const auto then = [this, programEnd] {
        if (!programEnd) {
            end(RunState::Finished, tr("finished"));
            return;
        }
        m_spindleOn = false;
        m_endSwitching = true;
        m_machine->switchOffSpindleAndCoolant();
        if (!m_machine->isSwitchingOff()) // nothing to switch on this machine
            onSwitchedOff(true, {});
    };
    m_afterRequests = then;
    if (m_requests.isEmpty())
        then();
}

void ProgramRunner::onSwitchedOff(bool ok, const QString& message)
{
    if (!std::exchange(m_endSwitching, false) || m_state != RunState::Running || m_aborting)
        return;
    if (ok) {
        end(RunState::Finished, tr("finished"));
        return;
    }
    m_failureKind = ErrorKind::Timeout;
    end(RunState::Failed, lineText(message));
}

void ProgramRunner::fail(ErrorKind kind, const QString& message)
{
    if (isEnded(m_state) || m_state == RunState::Idle)
        return;
    if (m_aborting) { // a stop ends a motion with an error: that is the abort's end
        end(RunState::Aborted, lineText(tr("aborted")));
        return;
    }
    m_waits->cancel();
    // Every controller: a program never continues after a fault. The machine's abortRequested
    // that follows is this run's own stop, not an abort.
    m_ownStop = true;
    m_machine->stop();
    m_ownStop = false;
    m_failureKind = kind;
    end(RunState::Failed, lineText(message));
}

void ProgramRunner::end(RunState state, const QString& message)
{
    if (isEnded(m_state))
        return;
    m_abortSettle.stop();
    if (m_waits)
        m_waits->cancel();
    m_arc.reset();
    m_cycle.reset();
    m_heldInPath = false;
    dropContour();
    m_heldBlock = false;
    m_feedHeld = false;
    m_endSwitching = false;
    m_restChanged = false;
    m_prelude.clear();
    m_approaching = false;
    m_requests.clear();
    m_afterRequests = nullptr;
    if (m_moves) {
        if (state != RunState::Finished && m_machine)
            m_moves->restore(); // best effort after a fault or abort: not awaited
        m_moves->forget();
    }
    disconnectMachine();
    if (m_machine)
        m_machine->releaseMotion(this);
    m_endMessage = message;
    qCInfo(lcProgram) << "program" << runStateText(state) << message;
    setState(state);
    Q_EMIT finished(state, message);
}

void ProgramRunner::setState(RunState state)
{
    if (m_state == state)
        return;
    if (state != RunState::Paused)
        m_touchOff = {}; // a touch-off hold ends with the hold
    m_state = state;
    // Held between blocks, the run lends the machine to the operator's hands (jogging Z to
    // touch off at M6, issue 47 item 2); held in a path (a feed hold, an arc's chord, a
    // cycle's segment) or running, not: the rest goes on from where the path stopped.
    if (m_machine) // end() may come after the window closed the machine
        m_machine->lendMotion(this, state == RunState::Paused && !m_feedHeld && !m_heldInPath);
    Q_EMIT stateChanged(state);
}

// M0's comment; M6's "Load tool n" with the line's comment or else the table's text.
QString ProgramRunner::promptOf(const ProgramBlock& block) const
{
    if (block.kind != BlockKind::ToolChange ||
        block.prompt != ProgramLine::tr("Load tool %1").arg(block.number))
        return block.prompt;
    const Tool* tool = m_nextTools.find(block.number);
    return tool && !tool->text.isEmpty()
               ? ProgramLine::tr("Load tool %1 (%2)").arg(block.number).arg(tool->text)
               : block.prompt;
}

QString ProgramRunner::lineText(const QString& message) const
{
    const int line = currentLine();
    return line > 0 ? tr("line %1: %2").arg(line).arg(message) : message;
}

} // namespace stepdeck::program
