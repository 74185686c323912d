#pragma once
#include "WordMap.h"
#include <QMap>
#include <QString>
#include <QStringList>
#include <optional>

namespace stepdeck::program {

// What one block of a motion program does (issue 20, docs/programs.md). The words are a
// G-code subset with LinuxCNC's meanings; a line of several actions ("M5 M9") gives a block
// for each, in LinuxCNC's order of execution (ProgramLine).
enum class BlockKind : quint8 {
    Modal,               // only modal words (G90, G21, F...) or an N number: nothing runs
    Rapid,               // G0: positioning at the axes' fast speed
    Feed,                // G1: positioning at the feed rate F (unit/min)
    ArcClockwise,        // G2: an arc (or helix) in the plane, run as chords at F (ArcPath)
    ArcCounterClockwise, // G3
    Home,                // G28: reference run of the named axes (none named: all, machine order)
    Dwell,               // G4 P<seconds>
    Pause,               // M0: until the operator resumes; prompt = the line's comment
    OptionalPause,       // M1: as M0 while the optional-stop switch is on (LinuxCNC)
    ToolChange,      // M6: pause until the operator loaded tool `number` ("Load tool n (comment)")
    End,             // M2, M30
    SpindleOn,       // M3 S<rpm>
    SpindleReverse,  // M4 S<rpm>: counter-clockwise, only where the controller can reverse
    SpindleOff,      // M5
    SpindleSpeed,    // S alone on a line: the speed of the spindle from now on (LinuxCNC)
    CoolantMist,     // M7
    CoolantFlood,    // M8
    CoolantOff,      // M9
    OutputOn,        // M64 P<n>
    OutputOff,       // M65 P<n>
    WaitInput,       // M66 P<n> L3|L4 Q<seconds>
    SetCoordinates,  // G10 L2 / L20 P<n>: a coordinate system's offsets (ProgramCoordinates)
    AxisOffset,      // G92: the current point gets the axis words' values
    AxisOffsetReset, // G92.1: G92's offset zero
    AxisOffsetSuspend, // G92.2: G92's offset kept but not applied
    AxisOffsetRestore, // G92.3: applied again
    DrillCycle,        // G81 G82 G83 G73: holes at X Y from R down to Z (DrillCycle)
    RepeatStart,       // O<n> repeat [count]
    RepeatEnd,         // O<n> endrepeat
};

// LinuxCNC's plane selection (modal group 2): the plane arcs lie in.
enum class Plane : quint8 { XY, XZ, YZ };
// LinuxCNC's path control mode (modal group 13).
enum class PathMode : quint8 { ExactPath, ExactStop, Blend };

// G2 and G3.
inline bool isArc(BlockKind kind)
{
    return kind == BlockKind::ArcClockwise || kind == BlockKind::ArcCounterClockwise;
}

// M3, M4, M5.
inline bool isSpindleSwitch(BlockKind kind)
{
    return kind == BlockKind::SpindleOn || kind == BlockKind::SpindleReverse ||
           kind == BlockKind::SpindleOff;
}

// The centre and turns of a G2/G3 as written (LinuxCNC): I J K (the centre; incremental from
// the start unless G90.1) or R (the radius: + the shorter arc, - the longer one), P turns.
struct ArcWords
{
    std::optional<double> i, j, k; // program units, as written
    std::optional<double> radius;  // R
    int turns = 1;                 // P: 1 = the arc as given, each more adds a full circle
    bool centreAbsolute = false;   // G90.1 in effect (G91.1, incremental, is the default)

    bool operator==(const ArcWords& o) const
    {
        return i == o.i && j == o.j && k == o.k && radius == o.radius && turns == o.turns &&
               centreAbsolute == o.centreAbsolute;
    }
};

// A drilling cycle as written (LinuxCNC's G81, G82, G83, G73; docs/programs.md "Drilling
// cycles"): the hole's bottom Z and the retract plane R (program units; G91: R from the current
// Z, Z from R), Q the peck depth (G83, G73), P the dwell at the bottom (G82), L repeats and the
// retract mode (G98 to the initial level, G99 to R). R, Z, Q and P are sticky while the same
// cycle stays the motion mode, as in LinuxCNC.
struct CycleWords
{
    int code = 81;
    double r = 0;
    double bottom = 0;       // Z
    double peck = 0;         // Q
    double dwell = 0;        // P, seconds
    int repeats = 1;         // L
    bool retractToR = false; // G99 (G98, the initial level, is the default)

    bool operator==(const CycleWords& o) const
    {
        return code == o.code && r == o.r && bottom == o.bottom && peck == o.peck &&
               dwell == o.dwell && repeats == o.repeats && retractToR == o.retractToR;
    }
};

// LinuxCNC's cutter radius compensation (modal group 7; docs/programs.md "Cutter
// compensation"): the side of the programmed path the tool runs on and where its diameter comes
// from. CutterCompensation moves the path by the tool's radius.
enum class CompSide : quint8 { Off, Left, Right }; // G40, G41, G42
struct CutterComp
{
    CompSide side = CompSide::Off;
    int tool = -1;                  // G41/G42: the tool table's tool (D, or the one M6 loaded)
    std::optional<double> diameter; // G41.1/G42.1 D: the diameter, program units
    int activation = 0;             // counts the program's G41/G42: each begins a new entry

    bool on() const { return side != CompSide::Off; }
    bool operator==(const CutterComp& o) const
    {
        return side == o.side && tool == o.tool && diameter == o.diameter &&
               activation == o.activation;
    }
};

// M0 and M6: the program holds until the operator resumes (the block's prompt says why).
inline bool waitsForOperator(BlockKind kind)
{
    return kind == BlockKind::Pause || kind == BlockKind::ToolChange;
}

// Whether a run holds at a block of `kind`: M0 and M6 always, M1 while the optional-stop
// switch is on (ProgramRunner::setOptionalStops).
inline bool waitsForOperator(BlockKind kind, bool optionalStops)
{
    return waitsForOperator(kind) || (optionalStops && kind == BlockKind::OptionalPause);
}

// The word that makes a block, for messages and previews ("G0", "M64", "O repeat").
QString blockWord(BlockKind kind);
struct ProgramBlock;
QString blockWord(const ProgramBlock& block); // as blockWord(kind); a cycle by its code ("G83")

struct ProgramBlock
{
    int line = 0; // 1-based line of the file
    QString text; // the line as written, without surrounding white space
    BlockKind kind = BlockKind::Modal;
    // Axis words in the program's units as written (G20: inch for mm axes), by machine axis.
    WordMap<QString, double> axes;
    // The modal state in effect for this block (after the line's own modal words).
    bool relative = false;      // G91
    bool inches = false;        // G20
    std::optional<double> feed; // F, unit/min (inverseTime: 1/minutes)
    bool inverseTime = false;   // G93: this G1 takes 1/F minutes (InverseTime)
    // G93 resolved where the block starts (InverseTime::resolve), or a G94 G1 on controllers
    // that coordinate (CoordinatedFeed::resolve): each moving axis' rate in its unit per
    // minute, in place of F. An axis without one: F (G94), or none (G93: it does not move).
    WordMap<QString, double> axisRates;
    Plane plane = Plane::XY;             // G17 / G18 / G19
    PathMode pathMode = PathMode::Blend; // G61 / G61.1 / G64
    std::optional<double> pathTolerance; // G64 P
    double seconds = 0;                  // G4 P, M66 Q
    int number = 0;                      // M64/M65/M66 P: output or input number; M6: the tool (T)
    bool inputHigh = true;               // M66 L3 (high) or L4 (low)
    double rpm = 0;                      // S in effect (modal; 0 until a line sets it)
    // S is on this line, for this block (a running spindle changes speed): the first of the
    // line's blocks, or its M3/M4/M5 (ProgramLine).
    bool spindleChange = false;
    QString prompt;   // M0, M1: the comment on its line
    ArcWords arc;     // G2/G3
    CycleWords cycle; // G81..G83, G73 (Z is here, not in axes)
    // G54..G59 in effect (0 = G54); -1: none selected yet, the system active when the run
    // started (LinuxCNC keeps the active system across programs).
    int coordinateSystem = -1;
    bool machineCoordinates = false; // G53: this G0/G1's words are machine coordinates
    bool fromPosition = false;       // G10 L20 (the current point gets the words' values)
    // G43: the tool whose length offsets the tool axis (Z), -1 none (G49); 0 (H0) none either.
    int lengthTool = -1;
    bool appliesLengthOffset = false; // G43 is on this line (the check names its tool here)
    CutterComp comp;                  // G40 / G41 / G42 in effect
    QString message;  // "(MSG, text)": shown to the operator when the run reaches the line
    int oNumber = 0;  // O<n>
    qint64 count = 0; // O repeat: how many times
    int partner = -1; // RepeatStart <-> RepeatEnd: the index of the other block
    // Where the line's words stand (1-based columns), so that the check (ProgramCheck) names
    // the word it refuses: axis words by axis name ("X"), parameters by letter ("F", "P", "S",
    // "L", "Q"). actionColumn: the G or M word (the O word of a repeat); 0 for a line without
    // one (axis words moving with the last G0/G1, or only modal words).
    WordMap<QString, int> columns;
    int actionColumn = 0;

    // The column of a word on this line, or of the action (or else 1) when it is not here
    // (F from an earlier line). An empty word: the action's column (or 1).
    int columnOf(const QString& word) const;

    bool operator==(const ProgramBlock& o) const;
};

// "12.5", "-3", "1234567": a figure for messages and previews (at most 3 decimals).
QString figure(double value);

// "12:5: message": where a program is wrong (1-based line and column) and why.
struct ProgramError
{
    int line = 0;
    int column = 0;
    QString message;

    QString text() const;
    bool operator==(const ProgramError& o) const
    {
        return line == o.line && column == o.column && message == o.message;
    }
};

} // namespace stepdeck::program
