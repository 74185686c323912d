#pragma once
#include <QList>
#include <QString>
#include <functional>
#include <optional>
#include <variant>
#include <vector>

// The motion commands (issue 49 item 1, docs/architecture.md "One motion path"): the canonical
// vocabulary a program is lowered to, as LinuxCNC's interpreter calls its canonical machining
// functions (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, DWELL, ...). A program's block becomes
// some of these (program::ProgramLowering); what consumes them (the canonical text of
// `stepdeck-cli run --dry-run --canon`, and executors) needs no G-code.
//
// Positions are machine coordinates in each axis' unit (mm, degree or step), indexed like
// MachineDescription::axes; nullopt: not known (a relative move from an axis whose position is
// unknown). The frame commands (units, plane, offsets, feed) say in which program terms the
// blocks were written, so that the canonical text can give them back in those terms.
namespace stepdeck::motion {

using MachinePoint = std::vector<std::optional<double>>;

// G0, a G53 G0, a drilling cycle's rapid: every axis at its fast speed to `end`.
struct Traverse
{
    int line = 0;
    MachinePoint end;
};

// G1, a drilling cycle's feed: a straight line to `end` at the feed in effect.
struct StraightFeed
{
    int line = 0;
    MachinePoint end;
};

// G2/G3: an arc in the plane of axes[0] and axes[1] (LinuxCNC's first and second axis) about
// `centre`, `rotation` turns (+ counter-clockwise, LinuxCNC's sign), ending at `end`; the
// plane's third axis and the others go evenly to their ends (a helix).
struct ArcFeed
{
    int line = 0;
    MachinePoint end;
    int axes[2] = {-1, -1};
    double centre[2] = {0, 0};
    int rotation = 1;
};

struct Dwell
{
    int line = 0;
    double seconds = 0;
};

// G28 in StepDeck: a reference run of the axes named (all when empty); they end at 0.
struct Reference
{
    int line = 0;
    QList<int> axes; // indices; empty: every axis
};

struct SpindleOn
{
    int line = 0;
    double rpm = 0; // the S in effect, as written
    bool reverse = false;
};
struct SpindleOff
{
    int line = 0;
};
struct SpindleSpeed // an S on its own line while the spindle may turn
{
    int line = 0;
    double rpm = 0;
};

struct Coolant
{
    enum class Kind : quint8 { Mist, Flood, Off };
    int line = 0;
    Kind kind = Kind::Off;
};

// M64/M65 P: output `number` (1-based over the machine) on or off.
struct Output
{
    int line = 0;
    int number = 0;
    bool on = true;
};

// M66 P L Q: input `number` high (L3) or low (L4), at most `seconds`.
struct WaitInput
{
    int line = 0;
    int number = 0;
    bool high = true;
    double seconds = 0;
};

// M0, M1, M6: the run holds for the operator.
struct Pause
{
    enum class Kind : quint8 { Stop, OptionalStop, ToolChange };
    int line = 0;
    Kind kind = Kind::Stop;
    int tool = 0; // ToolChange: T
    QString prompt;
};

struct Message // (MSG, ...)
{
    int line = 0;
    QString text;
};

struct ProgramEnd // M2/M30, after the spindle and coolant off the lowering puts before it
{
    int line = 0;
};

// Frame commands: emitted where they change, before the command of the block that changes
// them (as LinuxCNC's interpreter emits them for the words it reads).
struct LengthUnits
{
    int line = 0;
    bool inches = false;
};
struct SelectPlane
{
    enum class Plane : quint8 { XY, XZ, YZ };
    int line = 0;
    Plane plane = Plane::XY;
};
struct FeedRate // the program's F as written (program unit per minute, or G93's 1/min)
{
    int line = 0;
    double feed = 0;
    bool inverseTime = false;
};
// The offsets in effect (each axis' unit, by axis index): G54..G59's (system 0..5), G92's,
// and the tool length on the tool axis (G43 H; `tool` 0: none).
struct Offsets
{
    int line = 0;
    int system = 0;
    std::vector<double> workOffset;
    std::vector<double> axisOffset;
    int tool = 0;
    double toolLength = 0;
    int toolAxis = -1;
};

using MotionCommand =
    std::variant<Traverse, StraightFeed, ArcFeed, Dwell, Reference, SpindleOn, SpindleOff,
                 SpindleSpeed, Coolant, Output, WaitInput, Pause, Message, ProgramEnd, LengthUnits,
                 SelectPlane, FeedRate, Offsets>;

// Where a walk's lowered commands go (ProgramCheck::check's `lowered`).
using CommandSink = std::function<void(const MotionCommand&)>;

// The program line a command comes from.
inline int lineOf(const MotionCommand& command)
{
    return std::visit([](const auto& c) { return c.line; }, command);
}

} // namespace stepdeck::motion
