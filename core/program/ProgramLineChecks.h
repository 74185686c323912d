#pragma once
// Internal to ProgramLine: a line's words sorted by role, and the checks of each action's
// words (ProgramLineChecks.cpp).
#include "ProgramBlock.h"
#include "ProgramLexer.h"
#include <QMap>
#include <QVarLengthArray>
#include <cmath>
#include <vector>

namespace stepdeck::program {

constexpr int kMaxTool = 99999;         // the highest T a program may select
constexpr int kMaxArcTurns = 1000;      // G2/G3 P: the most turns of one helix
constexpr int kMaxCycleRepeats = 10000; // G81..G83, G73 L: the most holes of one line

inline bool isWhole(double v)
{
    return std::floor(v) == v && std::fabs(v) < 1e9;
}

// An action word of a line that runs beside its main action (issue 50, LinuxCNC's order of
// execution): M3..M9, M6, M0/M1/M2/M30, G92.1..G92.3, and G4 or M64..M66 beside a move.
struct LineAction
{
    BlockKind kind = BlockKind::Modal;
    const ProgramWord* word = nullptr;
};

// A line's words sorted by role: its main action (the one its axis words or parameters belong
// to), the actions beside it, the modal words, the parameters and the axes, each at most once.
struct Words
{
    std::optional<BlockKind> action;
    const ProgramWord* actionWord = nullptr;
    QVarLengthArray<LineAction, 4> others;  // as written; ProgramLine orders them
    int mWords = 0;                         // M words on the line (LinuxCNC: at most 4)
    std::optional<bool> relative;           // G90 / G91
    std::optional<bool> inches;             // G21 / G20
    const ProgramWord* unitsWord = nullptr; // its word
    // LinuxCNC's other modal groups, each at most once a line (issue 29): the word of each
    // group given (group number as LinuxCNC numbers them), and what it sets.
    QMap<int, const ProgramWord*> groups;
    std::optional<Plane> plane;                      // G17 / G18 / G19
    std::optional<PathMode> pathMode;                // G61 / G61.1 / G64
    const ProgramWord* tool = nullptr;               // T: selects the tool M6 changes to
    bool cancelsMotion = false;                      // G80: no modal motion afterwards
    std::optional<bool> centreAbsolute;              // G90.1 / G91.1
    std::optional<int> coordinateSystem;             // G54..G59 (0 = G54)
    const ProgramWord* machineCoordinates = nullptr; // G53
    std::optional<bool> lengthOffset;                // G43 (true) / G49 (false)
    std::optional<int> cutterComp;                   // G40, G41, G41.1, G42, G42.1 (tenths)
    std::optional<bool> retractToR;                  // G99 (true) / G98 (false)
    std::optional<bool> inverseTime;                 // G93 (true) / G94 (false)
    int cycleCode = 0;                               // G81, G82, G83, G73: its number
    WordMap<QChar, const ProgramWord*> parameters;
    WordMap<QString, const ProgramWord*> axes;
    // LinuxCNC's polar coordinates: "@" the distance from the origin, "^" the angle in degrees
    // from +X; applyPolar turns them into X and Y (polarXY, which axes then point to).
    const ProgramWord* polarRadius = nullptr;
    const ProgramWord* polarAngle = nullptr;
    ProgramWord polarXY[2];
};

struct ModalState;

// An action's place in LinuxCNC's tables (issue 50, docs/programs.md "Several words on one
// line"): its modal group (G: 0 non-modal, 1 motion; M: 4 stopping, 5 inputs and outputs,
// 6 tool change, 7 spindle, 8 coolant, offset by 100 so that they meet no G group; -1: none)
// and its step in LinuxCNC's order of execution.
struct ActionRole
{
    int group = -1;
    int step = 24;
};
ActionRole actionRole(BlockKind kind);

// Why a G or M word (its code in tenths) is not run: what it is and what to write instead,
// where StepDeck knows the word (ProgramLineUnsupported.cpp); "G38.2 is not supported" else.
QString unsupportedWord(const ProgramWord& word, int tenths);

// A line's words after its N number, [first, last), sorted into *out (ProgramLineWords.cpp);
// false with *error at the first that does not fit.
bool sortLineWords(int line, const QStringList& axisNames, const ProgramWord* first,
                   const ProgramWord* last, Words* out, std::optional<ProgramError>* error);

// The line's modal words into *modal (ProgramLineModes.cpp): (column, message) of the first
// that does not fit; column 0: none.
std::pair<int, QString> applyModalWords(Words* words, ModalState* modal);
// "@" and "^" (LinuxCNC's polar coordinates) as the X and Y words they stand for, with the
// modal state after the line's words (ProgramLine.cpp): (column, message) of a refusal;
// column 0: none.
std::pair<int, QString> applyPolar(Words* words, const ModalState& modal,
                                   const QStringList& axisNames);
// G40, G41/G42 [D<tool>], G41.1/G42.1 D<diameter> into *modal (ProgramLineModes.cpp).
std::pair<int, QString> applyCutterComp(Words* words, ModalState* modal);
// What LinuxCNC refuses while cutter compensation is on, and an arc as its entry or exit move,
// for the line's blocks (ProgramLineModes.cpp): (column, message); column 0: none. *after's
// compMove is updated.
std::pair<int, QString> checkCutterComp(const Words& words, const ModalState& before,
                                        ModalState* after, const std::vector<ProgramBlock>& blocks);
// G81, G82, G83, G73: the cycle's numbers (this line's, or sticky) into block->cycle and
// *modal (ProgramLineModes.cpp).
std::pair<int, QString> drillCycle(const Words& sorted, ModalState* modal, ProgramBlock* block);

// The first word of a sorted line that none of its actions takes (its main block's kind, the
// others beside it): (column, message); column 0: none.
std::pair<int, QString> checkUnusedWords(const Words& words, BlockKind mainKind);
// The first missing or out-of-range word of block->kind, whose word is `action` (null: a line
// of axis words moving with the modal motion): (column, message); column 0: none. Fills the
// action's values into *block.
std::pair<int, QString> checkActionWords(const Words& words, const ProgramWord* action,
                                         ProgramBlock* block);

// "O<n> repeat [count]" / "O<n> endrepeat": the block, or nullopt with *error.
std::optional<ProgramBlock> repeatBlock(const LexedLine& line, const ProgramWord& o, int lineNumber,
                                        std::optional<ProgramError>* error);

} // namespace stepdeck::program
