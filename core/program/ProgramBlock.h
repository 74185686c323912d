#pragma once
#include <QMap>
#include <QString>
#include <QStringList>
#include <optional>

namespace stepdeck::program {

// What one line of a motion program does (issue 20, docs/programs.md). The words are a
// G-code subset with LinuxCNC's meanings; a line holds at most one action besides the modal
// words G90/G91, G20/G21 and F.
enum class BlockKind : quint8 {
    Modal,          // only modal words (G90, G21, F...) or an N number: nothing runs
    Rapid,          // G0: positioning at the axes' fast speed
    Feed,           // G1: positioning at the feed rate F (unit/min)
    Home,           // G28: reference run of the named axes (none named: all, machine order)
    Dwell,          // G4 P<seconds>
    Pause,          // M0: until the operator resumes; prompt = the line's comment
    OptionalPause,  // M1: as M0 while the optional-stop switch is on (LinuxCNC)
    ToolChange,     // M6: pause until the operator loaded tool `number` ("Load tool n (comment)")
    End,            // M2, M30
    SpindleOn,      // M3 S<rpm>
    SpindleReverse, // M4 S<rpm>: counter-clockwise, only where the controller can reverse
    SpindleOff,     // M5
    CoolantMist,    // M7
    CoolantFlood,   // M8
    CoolantOff,     // M9
    OutputOn,       // M64 P<n>
    OutputOff,      // M65 P<n>
    WaitInput,      // M66 P<n> L3|L4 Q<seconds>
    RepeatStart,    // O<n> repeat [count]
    RepeatEnd,      // O<n> endrepeat
};

// LinuxCNC's plane selection (modal group 2): the plane arcs lie in.
enum class Plane : quint8 { XY, XZ, YZ };
// LinuxCNC's path control mode (modal group 13).
enum class PathMode : quint8 { ExactPath, ExactStop, Blend };

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

struct ProgramBlock
{
    int line = 0; // 1-based line of the file
    QString text; // the line as written, without surrounding white space
    BlockKind kind = BlockKind::Modal;
    // Axis words in the program's units as written (G20: inch for mm axes), by machine axis.
    QMap<QString, double> axes;
    // The modal state in effect for this block (after the line's own modal words).
    bool relative = false;               // G91
    bool inches = false;                 // G20
    std::optional<double> feed;          // F, unit/min
    Plane plane = Plane::XY;             // G17 / G18 / G19
    PathMode pathMode = PathMode::Blend; // G61 / G61.1 / G64
    std::optional<double> pathTolerance; // G64 P
    double seconds = 0;                  // G4 P, M66 Q
    int number = 0;                      // M64/M65/M66 P: output or input number; M6: the tool (T)
    bool inputHigh = true;               // M66 L3 (high) or L4 (low)
    double rpm = 0;                      // M3 / M4 S
    QString prompt;                      // M0, M1: the comment on its line
    QString message;  // "(MSG, text)": shown to the operator when the run reaches the line
    int oNumber = 0;  // O<n>
    qint64 count = 0; // O repeat: how many times
    int partner = -1; // RepeatStart <-> RepeatEnd: the index of the other block
    // Where the line's words stand (1-based columns), so that the check (ProgramCheck) names
    // the word it refuses: axis words by axis name ("X"), parameters by letter ("F", "P", "S",
    // "L", "Q"). actionColumn: the G or M word (the O word of a repeat); 0 for a line without
    // one (axis words moving with the last G0/G1, or only modal words).
    QMap<QString, int> columns;
    int actionColumn = 0;

    // The column of a word on this line, or of the action (or else 1) when it is not here
    // (F from an earlier line). An empty word: the action's column (or 1).
    int columnOf(const QString& word) const;

    bool operator==(const ProgramBlock& o) const;
};

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

struct Program
{
    QList<ProgramBlock> blocks; // every line that holds a word, in file order
    int lines = 0;              // lines in the file
};

} // namespace stepdeck::program
