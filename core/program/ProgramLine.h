#pragma once
#include "ProgramBlock.h"
#include "ProgramLexer.h"
#include <QCoreApplication>
#include <vector>

namespace stepdeck::program {

// The modal state a program carries from line to line (LinuxCNC's modal groups, reduced to
// those StepDeck programs have).
struct ModalState
{
    bool relative = false;           // G91 (G90 default)
    bool inches = false;             // G20 (G21 default)
    std::optional<double> feed;      // F
    double spindleSpeed = 0;         // S (LinuxCNC starts at 0)
    std::optional<BlockKind> motion; // G0..G3, once given: a line of axis words moves so
    Plane plane = Plane::XY;         // G17 (default), G18, G19
    // G61 exact path, G61.1 exact stop, G64 blending (LinuxCNC's default) with its P
    // tolerance; kept for the continuous path of the contouring issue.
    PathMode pathMode = PathMode::Blend;
    std::optional<double> pathTolerance; // G64 P
    std::optional<int> tool;             // T: the tool selected for the next M6
    bool centreAbsolute = false;         // G90.1 (G91.1, incremental arc centres, default)
    int coordinateSystem = -1;           // G54..G59 (-1: none yet, the run's active one)
    std::optional<int> loadedTool;       // the tool the last M6 loaded
    int lengthTool = -1;                 // G43's tool (-1: G49, none)
    CutterComp comp;                     // G40 / G41 / G42
    int compActivations = 0;             // the G41/G42 so far (CutterComp::activation)
    // After G41/G42 the first move in X or Y enters the path; after G40 the first move leaves it
    // (LinuxCNC): neither may be an arc.
    enum class CompMove : quint8 { None, Entry, Exit } compMove = CompMove::None;
    bool retractToR = false;  // G99 (G98 default): where a drilling cycle retracts
    bool inverseTime = false; // G93 (G94, units per minute, default)
    // The drilling cycle in effect (motion DrillCycle): its code and its sticky numbers.
    int cycleCode = 0;
    std::optional<double> cycleR, cycleBottom, cyclePeck, cycleDwell;
};

// One lexed line to its blocks (ProgramParser's line step): which words it has, whether they
// fit together, and the values each action needs. A line of several actions ("M5 M9",
// "G0 Z2 S10000 M3", "T1 M6 G43 H1") gives a block per action in LinuxCNC's order of execution
// (issue 50, docs/programs.md "Several words on one line"), each naming the line. On success
// *modal holds the state after the line; on failure nothing changes and the error names the
// word's column.
class ProgramLine
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramLine)
public:
    // false with *error; true with the line's blocks in *blocks (cleared first; none for a
    // blank line or one of only a comment). The caller keeps *blocks to reuse its room.
    static bool parse(const LexedLine& line, int lineNumber, const QStringList& axisNames,
                      ModalState* modal, std::vector<ProgramBlock>* blocks,
                      std::optional<ProgramError>* error);
};

} // namespace stepdeck::program
