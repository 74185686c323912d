// ProgramRunner: starting a run (the check it starts on, the facts it was checked with, the
// coordinates and current point it takes from them) and run from line's prelude before the
// first block. The walk is in ProgramRunner.cpp, what each block sends in ProgramRunnerBlocks.cpp.
#include "ProgramLogging.h"
#include "ProgramReader.h"
#include "ProgramRunner.h"
#include "RunFromLine.h"
#include "machine/Machine.h"
#include "motion/executors/MoveExecutor.h"
#include "motion/executors/StreamExecutor.h"
#include "motion/executors/WaitExecutor.h"
#include <algorithm>

namespace stepdeck::program {

bool ProgramRunner::start(const Program& program, int fromLine, QList<ProgramError>* errors,
                          bool stepOnly)
{
    const MachineFacts facts = startFacts();
    return startChecked(program, fromLine, facts,
                        checkForStart(program, facts, fromLine, m_checkProgress), errors, stepOnly);
}

MachineFacts ProgramRunner::startFacts() const
{
    MachineFacts facts = factsOf(*m_machine);
    facts.coordinateSystems = m_nextSystems;
    facts.activeSystem = m_nextActive;
    facts.tools = m_nextTools;
    return facts;
}

ProgramCheckResult ProgramRunner::checkForStart(const Program& program, const MachineFacts& facts,
                                                int fromLine, const CheckProgress& progress)
{
    return ProgramCheck::check(program, facts, fromLine, progress);
}

// Where the axes stand and which are known, what the devices hold, the offsets and tools the
// run takes. The description, models and capabilities are the machine's own for as long as it
// is open.
bool sameStartFacts(const MachineFacts& a, const MachineFacts& b)
{
    return a.knownPositions == b.knownPositions && a.knownParameters == b.knownParameters &&
           a.setupIncomplete == b.setupIncomplete && a.coordinateSystems == b.coordinateSystems &&
           a.activeSystem == b.activeSystem && a.tools == b.tools &&
           a.description.axes.size() == b.description.axes.size();
}

bool ProgramRunner::startChecked(const Program& program, int fromLine,
                                 const MachineFacts& checkedFacts,
                                 const ProgramCheckResult& checked, QList<ProgramError>* errors,
                                 bool stepOnly)
{
    if (m_state == RunState::Running || m_state == RunState::Paused ||
        m_state == RunState::Stopping) {
        if (errors)
            *errors = {ProgramError{0, 0, tr("a program runs already")}};
        return false;
    }
    QString holder;
    if (!claimMotion(&holder)) { // another runner (a program, an MDI line) holds the machine
        if (errors)
            *errors = {ProgramError{0, 0, holder}};
        return false;
    }
    if (!begin(program, fromLine, checkedFacts, checked, errors, stepOnly)) {
        releaseMotion();
        return false;
    }
    return true;
}

// startChecked() with the machine's motion held.
bool ProgramRunner::begin(const Program& program, int fromLine, const MachineFacts& checkedFacts,
                          const ProgramCheckResult& checked, QList<ProgramError>* errors,
                          bool stepOnly)
{
    const MachineFacts facts = startFacts();
    if (!sameStartFacts(checkedFacts, facts)) {
        if (errors)
            *errors = {ProgramError{0, 0,
                                    tr("the machine changed while the program was checked (a "
                                       "position, an offset, a tool or a parameter): run it "
                                       "again to check it anew")}};
        return false;
    }
    if (!checked.ok()) {
        if (errors)
            *errors = checked.cancelled
                          ? QList<ProgramError>{ProgramError{0, 0, tr("the check was cancelled")}}
                          : checked.errors;
        return false;
    }
    auto reader = std::make_unique<ProgramReader>(program);
    const int first = fromLine <= 1 ? 0 : reader->firstBlockAtLine(fromLine);
    if (first < 0 || !reader->error().isEmpty()) { // the check found it: the file changed since
        if (errors)
            *errors = {ProgramError{fromLine, 1,
                                    reader->error().isEmpty()
                                        ? tr("the program's file changed: check it again")
                                        : reader->error()}};
        return false;
    }
    // Run from line (issue 47 item 5): the blocks the check walked before its start block, from
    // the same function and the facts it judged (sameStartFacts: the machine's now).
    m_prelude.clear();
    m_approaching = false;
    if (first > 0) {
        const RunFromState from = RunFromState::before(*reader, first, checkedFacts);
        m_prelude = from.prelude(checkedFacts, reader->at(first)->line);
    }
    m_reader = std::move(reader);
    m_program = program;
    m_restChanged = false;
    m_endSwitching = false;
    m_block = ProgramBlock{};
    m_preview = checked.preview;
    m_checkNotes = checked.notes;
    resetRun(facts);
    m_arc.reset();
    m_cycle.reset();
    m_heldInPath = false;
    m_spindleOn = false;
    // advance() steps onto the first block on or after fromLine.
    m_index = first - 1;
    m_loops.clear();
    m_blocksDone = 0;
    m_pauseAsked = false;
    m_stepOnly = stepOnly;
    m_aborting = false;
    m_prompt.clear();
    m_touchOff = {};
    m_lastTool.reset(); // which tool is in at the start is not known
    m_endMessage.clear();
    m_failureKind = ErrorKind::None;
    ++m_run;
    m_moves = std::make_unique<motion::MoveExecutor>(m_machine, this);
    connect(m_moves.get(), &motion::MoveExecutor::finished, this, &ProgramRunner::onMoveFinished);
    m_waits = std::make_unique<motion::WaitExecutor>(m_machine);
    connect(m_waits.get(), &motion::WaitExecutor::finished, this, &ProgramRunner::onWaitFinished);
    connectMachine();
    setState(RunState::Running);
    // Queued: the caller sees start() return before the first block's signals.
    QMetaObject::invokeMethod(this, &ProgramRunner::runNext, Qt::QueuedConnection);
    return true;
}

// The run's coordinates, current point and contour streams from the facts it was checked with.
void ProgramRunner::resetRun(const MachineFacts& facts)
{
    m_coordinates = ProgramCoordinates(m_nextSystems, m_nextActive, facts.lengthTools());
    // The current point starts where the check started it: the machine's known positions.
    m_programmed.assign(size_t(facts.description.axes.size()), std::nullopt);
    for (qsizetype i = 0; i < facts.description.axes.size(); ++i)
        if (const auto it = facts.knownPositions.constFind(facts.description.axes.at(i).name);
            it != facts.knownPositions.cend())
            m_programmed[size_t(i)] = it.value();
    dropContour();
    m_heldBlock = false;
    m_feedHeld = false;
    m_contourMoves.reset(); // it refers to m_runFacts
    m_runFacts = facts;
    m_contourMoves = std::make_unique<ContourMoves>(m_runFacts);
    m_comp = std::make_unique<CutterCompensation>(m_runFacts.description, m_runFacts.tools);
    m_compQueue.clear();
    m_uncounted = false;
    m_compError.clear();
    m_coordinated.clear();
    for (auto c = facts.capabilities.cbegin(); c != facts.capabilities.cend(); ++c)
        if (c->coordinatedFeed)
            m_coordinated.insert(c.key());
}

// Run from line: what the lines before it switched on, then the rapids to where they leave the
// tool (RunFromState::prelude), before its first block. They are no blocks of the program: not
// counted, not reported finished; a step runs them with the first block.
void ProgramRunner::runPrelude()
{
    m_block = m_prelude.takeFirst();
    Q_EMIT blockStarted(m_block.line, m_block.text);
    if (m_block.kind == BlockKind::Rapid) {
        m_approaching = true; // blockDone() hands its end to approachDone()
        startBlock(m_block);
        return;
    }
    startSwitch(m_block, [this] { runNext(); });
}

// A rapid of the approach arrived: the current point is the machine position it went to (G53),
// so that the first block's arcs and relative moves start from the start point, as checked.
void ProgramRunner::approachDone()
{
    m_coordinates.advance(m_block, m_machine->description(), &m_programmed);
    if (m_pauseAsked) { // Pause while on the way: held there, Resume goes on to the start point
        m_pauseAsked = false;
        m_operatorStop = false;
        m_prompt.clear();
        setState(RunState::Paused);
        Q_EMIT paused(m_block.line, m_prompt);
        return;
    }
    runNext();
}

} // namespace stepdeck::program
