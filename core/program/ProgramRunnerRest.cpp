// ProgramRunner: offsets and tools changed while the run holds (issue 47, docs/programs.md
// "Touch-off while the run holds"). LinuxCNC's AXIS refuses a touch-off while a program is
// paused; Candle and UGS take a new zero for the rest of the job. StepDeck takes it, but only
// after the rest of the program passed its check with it, from where the axes stand now.
// Issue 50 item 4: with tool lengths by touch-off an M6 holds until the work Z was set for the
// new tool (docs/programs.md "Tools").
#include "ProgramLogging.h"
#include "ProgramReader.h"
#include "ProgramRunner.h"
#include "machine/Machine.h"
#include <cmath>
#include <utility>

namespace stepdeck::program {

void ProgramRunner::setCoordinateSystems(const CoordinateSystems& systems, int active)
{
    m_nextSystems = systems;
    m_nextActive = active;
    if (m_state != RunState::Paused)
        return;
    m_restChanged = m_nextSystems != m_coordinates.systems() || !(m_nextTools == m_runFacts.tools);
    // A Zero Z or G10 L20 Z is told here as the window's systems: set for the new tool once
    // the Z of the system the run cuts in differs from the one the hold began with.
    if (m_touchOff.pending)
        m_touchOff.zSet = m_nextSystems[size_t(m_touchOff.system)].value(
                              ProgramCoordinates::toolAxis(), 0.0) != m_touchOff.z;
}

void ProgramRunner::setToolTable(const ToolTable& tools)
{
    m_nextTools = tools;
    if (m_state == RunState::Paused)
        m_restChanged =
            m_nextSystems != m_coordinates.systems() || !(m_nextTools == m_runFacts.tools);
}

MachineFacts ProgramRunner::restFacts() const
{
    MachineFacts facts = startFacts();
    // The system the run's blocks without a G54..G59 of their own run in is the one active at
    // its start, whatever the window selected since.
    facts.activeSystem = m_coordinates.activeAtStart();
    return facts;
}

int ProgramRunner::restBlock() const
{
    return m_heldBlock ? m_index : m_index + 1; // a block read ahead of a contour has not run
}

QString ProgramRunner::restUncheckable() const
{
    if (m_feedHeld || m_contour)
        return tr("the run holds in the middle of a contour (feed hold), where new offsets "
                  "cannot start: put them back to resume, or stop");
    if (m_heldInPath)
        return tr("the run holds in the middle of an arc or a drilling cycle, where new offsets "
                  "cannot start: put them back to resume, or stop");
    // The tool's path was laid from the old offsets and the next moves (CutterCompensation).
    if ((m_comp && m_comp->isFollowing()) || m_block.comp.on())
        return tr("the run holds under cutter compensation (G41/G42), whose path new offsets "
                  "or tools would move: put them back to resume, or stop");
    // Its start point was worked out in the old offsets (RunFromState), in machine positions.
    if (!m_prelude.isEmpty())
        return tr("the run holds on its way to the start point of the line it runs from, which "
                  "new offsets would move: put them back to resume, or stop");
    const QMap<QString, double> g92 = m_coordinates.axisOffset();
    for (auto it = g92.cbegin(); it != g92.cend(); ++it)
        if (it.value() != 0.0)
            return tr("a G92 offset is in effect, which a check of the rest cannot follow: put "
                      "the offsets back to resume, or stop");
    return {};
}

bool ProgramRunner::resumeChecked(const MachineFacts& checkedFacts,
                                  const ProgramCheckResult& checked, bool stepOnly)
{
    if (m_state != RunState::Paused || refuseToGoOn())
        return false;
    QString why = restUncheckable();
    const MachineFacts now = restFacts();
    if (why.isEmpty() && !sameStartFacts(checkedFacts, now))
        why = tr("the machine changed while the rest was checked: resume again to check it anew");
    if (why.isEmpty() && !checked.ok())
        why = checked.cancelled || checked.errors.isEmpty()
                  ? tr("the check was cancelled")
                  : tr("the rest of the program fails its check with them, line %1: %2")
                        .arg(checked.errors.constFirst().line)
                        .arg(checked.errors.constFirst().message);
    if (!why.isEmpty()) {
        const QString message =
            tr("Not resumed: the offsets or tools changed while the run held; %1").arg(why);
        qCInfo(lcProgram) << message;
        Q_EMIT resumeRefused(message);
        return false;
    }
    takeRest(now);
    const ProgramBlock* next = m_reader->at(restBlock());
    const QString message =
        next ? tr("The rest of the program runs with the new offsets and tools (checked from "
                  "line %1).")
                   .arg(next->line)
             : tr("The new offsets and tools are taken; no move is left to run.");
    qCInfo(lcProgram) << message;
    Q_EMIT restChecked(message);
    go(stepOnly);
    return true;
}

void ProgramRunner::takeRest(const MachineFacts& facts)
{
    m_coordinates =
        ProgramCoordinates(facts.coordinateSystems, facts.activeSystem, facts.lengthTools());
    m_runFacts.coordinateSystems = facts.coordinateSystems;
    m_runFacts.tools = facts.tools;
    // The current point: where the axes stand now, where the operator moved them during the
    // hold (a jog to touch off); within a step it stays the program's unrounded point.
    const machine::MachineDescription& d = facts.description;
    for (qsizetype i = 0; i < d.axes.size() && size_t(i) < m_programmed.size(); ++i) {
        const machine::MachineAxis& a = d.axes.at(i);
        const auto it = facts.knownPositions.constFind(a.name);
        if (it == facts.knownPositions.cend())
            continue;
        const double step = std::abs(a.toUnits(1) - a.toUnits(0));
        std::optional<double>& point = m_programmed[size_t(i)];
        if (!point || std::abs(*point - it.value()) > step)
            point = it.value();
    }
    m_restChanged = false;
}

// At a hold (blockDone): an M6 with tool lengths by touch-off, on a machine with Z, waits for
// the work Z of the system it cuts in to be set for its tool (awaitsTouchOff).
void ProgramRunner::startTouchOff(const ProgramBlock& block)
{
    m_touchOff = {};
    if (block.kind != BlockKind::ToolChange)
        return;
    const std::optional<int> before = std::exchange(m_lastTool, block.number);
    const machine::MachineDescription& d = m_machine->description();
    if (d.toolLength != machine::ToolLength::TouchOff || !d.axis(ProgramCoordinates::toolAxis()))
        return;
    m_touchOff.pending = true;
    m_touchOff.tool = block.number;
    m_touchOff.toolBefore = before;
    m_touchOff.sameTool = !before || *before == block.number;
    m_touchOff.system = m_coordinates.systemOf(block);
    // The run's own copy: it holds the program's G10s, which the window keeps too.
    m_touchOff.z = m_coordinates.systems()[size_t(m_touchOff.system)].value(
        ProgramCoordinates::toolAxis(), 0.0);
    m_prompt = tr("%1, then set the work Z for it (Zero Z)").arg(m_prompt);
}

bool ProgramRunner::awaitsTouchOff() const
{
    return m_state == RunState::Paused && m_touchOff.pending && !m_touchOff.zSet;
}

// resume(), step(), resumeChecked(): refused (resumeRefused) while the hold waits for its Z.
// A run held between blocks lent the machine to the operator's hands (issue 49 item 4): it
// does not go on while the operator jogs, nor before the axes moved by hand stand (a
// controller refuses a move while an axis still runs out of its jog), since its next move
// would run beside them.
bool ProgramRunner::refuseToGoOn()
{
    QString why;
    if (m_machine && m_machine->isJogging())
        why = tr("Not resumed: the axes are being jogged; let go of the jog first");
    else if (m_machine && !m_feedHeld && !m_heldInPath &&
             m_machine->state() == machine::MachineState::Moving)
        why = tr("Not resumed: the axes are still moving; resume once they stand");
    if (why.isEmpty())
        return refuseWithoutTouchOff();
    qCInfo(lcProgram) << why;
    Q_EMIT resumeRefused(why);
    return true;
}

bool ProgramRunner::refuseWithoutTouchOff()
{
    if (!awaitsTouchOff())
        return false;
    QString message = tr("Not resumed: tool %1 takes its length from a touch-off, and the work "
                         "Z of %2 was not set since the run held: set it for tool %1 (Zero Z on "
                         "the position display)")
                          .arg(m_touchOff.tool)
                          .arg(coordinateSystemWord(m_touchOff.system));
    if (m_touchOff.sameTool)
        message += tr("; or, with the tool Z was set for still in, resume keeping Z");
    qCInfo(lcProgram) << message;
    Q_EMIT resumeRefused(message);
    return true;
}

bool ProgramRunner::resumeSameTool(bool stepOnly)
{
    if (!awaitsTouchOff())
        return false;
    if (!m_touchOff.sameTool) {
        const QString message =
            tr("Not resumed keeping Z: tool %1 follows tool %2, whose length it does not have: "
               "set the work Z for tool %1 first")
                .arg(m_touchOff.tool)
                .arg(m_touchOff.toolBefore.value_or(0));
        qCInfo(lcProgram) << message;
        Q_EMIT resumeRefused(message);
        return false;
    }
    qCInfo(lcProgram) << "tool" << m_touchOff.tool << "goes on with the work Z as it is";
    m_touchOff.pending = false; // the operator's word: the tool Z was set for is in
    go(stepOnly);
    return true;
}

void ProgramRunner::go(bool stepOnly)
{
    if (stepOnly)
        step();
    else
        resume();
}

} // namespace stepdeck::program
