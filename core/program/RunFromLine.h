#pragma once
#include "ProgramBlock.h"
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
struct RunFromState
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::RunFromState)
public:
    std::optional<BlockKind> spindle; // SpindleOn, SpindleReverse or SpindleOff (none: untouched)
    double rpm = 0;                   // the S in effect at the start block
    std::optional<BlockKind> coolant; // CoolantMist, CoolantFlood or CoolantOff
    int tool = 0;                     // the last M6's T (0: none)

    // The blocks before `first` (ProgramReader's index); reads them through `reader`.
    static RunFromState before(ProgramReader& reader, int first);
    // The switch blocks the run sends first, in LinuxCNC's order (spindle, then coolant); a
    // switch left off is not sent (the machine's may be on: the dialog says what is sent).
    QList<ProgramBlock> switches(int line) const;
    // "spindle on at S1000 (M3), coolant on (M8), tool 3" (empty: nothing to restore).
    QString text() const;
};

} // namespace stepdeck::program
