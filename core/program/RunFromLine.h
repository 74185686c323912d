#pragma once
#include "ProgramBlock.h"
#include "ProgramCheck.h"
#include <QCoreApplication>
#include <optional>

namespace stepdeck::program {

class ProgramReader;

// What the lines before a "Run from line N" left switched on (issue 47 item 5): the spindle
// (M3/M4 with the S in effect, or M5), the coolant (M7/M8 or M9) and the tool last loaded (M6).
// The motion modes (G90/G91, G20/G21, the plane, the coordinate system, G43, F) are each
// block's own already (the parser carries them); these are not, because they are switched by
// blocks that do not run. The run switches them before its first block, as gSender and UGS
// restore the state on a start from a line; the dialog names them before anything moves.
//
// And where those lines leave the tool, the start point: without it the run would go from
// wherever the machine stands straight into line N's first block (a "G1 X10 Y5 Z-1" plunging
// diagonally into the work, a "G1 X20" cutting in air at whatever height the tool stands).
// The run moves there first at rapid, in the safe order of gSender and UGS (approach()).
//
// prelude() is what a run from line N sends before its first block: the check walks exactly
// these blocks first (ProgramSimulation::setPrelude: soft limits, the restored S against the
// spindle's range, the rapids as any G0) and the runner sends them, both from this one
// function of the same facts, so that what the run does first is what was checked.
struct RunFromState
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::RunFromState)
public:
    std::optional<BlockKind> spindle; // SpindleOn, SpindleReverse or SpindleOff (none: untouched)
    double rpm = 0;                   // the S in effect at the start block
    std::optional<BlockKind> coolant; // CoolantMist, CoolantFlood or CoolantOff
    int tool = 0;                     // the last M6's T (0: none)
    // Where the blocks before the start leave each axis (by MachineDescription::axes index), in
    // machine coordinates and the axis' unit, followed as the run follows its current point
    // (ProgramCoordinates::advance with the facts' systems and tools; an arc's or a cycle's end).
    // nullopt: no earlier block put the axis anywhere the program determines (never positioned,
    // or only relatively from the program's unknown start): it stays where it stands.
    AxisPositions startPoint;

    // The blocks before `first` (ProgramReader's index); reads them through `reader`. facts:
    // the machine's, with the coordinate systems and tools the run takes (its startFacts()).
    static RunFromState before(ProgramReader& reader, int first, const MachineFacts& facts);
    // The switch blocks the run sends first, in LinuxCNC's order (spindle, then coolant); a
    // switch left off is not sent (the machine's may be on: the dialog says what is sent).
    QList<ProgramBlock> switches(int line) const;
    // The rapids (G53 G0, machine coordinates) from where the axes stand (facts.knownPositions)
    // to the start point: with the start above the tool axis' position (ProgramCoordinates::
    // toolAxis(), Z), Z goes up first and then the other axes; else the other axes move at the
    // current height and Z goes down last. An axis already there (to the step) does not move; a
    // machine without Z gets one rapid. An axis whose position is unknown moves too: the check
    // refuses that absolute move as any other, so the run needs the positions known.
    QList<ProgramBlock> approach(const MachineFacts& facts, int line) const;
    // switches(), then approach(): what the run sends before the block at `line`.
    QList<ProgramBlock> prelude(const MachineFacts& facts, int line) const;
    // "spindle on at S1000 (M3), coolant on (M8), tool 3" (empty: nothing to restore).
    QString text() const;
    // "Z up to 5.000 mm, then X 10.000 mm Y 5.000 mm at rapid", machine positions as the
    // position text of the Run-from-line dialog gives them (empty: nothing moves first).
    QString approachText(const MachineFacts& facts) const;
};

} // namespace stepdeck::program
