#pragma once
#include "EmisCodec.h"
#include <QCoreApplication>
#include <QMap>

// The SMC-IC4 command grammar of chapter 9, read on the device side (simulator), for the
// validation of input programs (9.17) and for the traffic console. Pure: no I/O.
namespace stepdeck::emis {

// Translation context of the grammar's messages (they reach the CLI and the program editor).
struct Grammar
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::Grammar)
};

// Value ranges. Where the manual states one, it is cited; where it is silent the bound chosen
// here is written down. The board answers <BEL> to values it does not accept, so a bound that
// is too wide is caught by the board, one that is too narrow would lock technicians out:
// the chosen bounds are generous.
namespace limits {
constexpr qint64 kSpeedMin = 1;        // steps/s; 0 would never arrive (9.4, 9.5: no range given)
constexpr qint64 kSpeedMax = 65535;    // chosen: 16 bits, above every example (200..1800)
constexpr qint64 kRampMin = 1;         // ms (9.6: no range given)
constexpr qint64 kRampMax = 10000;     // chosen: 10 s
constexpr qint64 kRunCurrentMax = 100; // 9.8: "% vom Nennwert"
constexpr qint64 kIdleCurrentMax = 25; // 6: "Automatische Ruhestromreduzierung 0% bis 25%"
constexpr qint64 kOffsetMax = 65535;   // steps (9.10: no range given; chosen)
constexpr qint64 kWaitMax = 600000;    // ms (9.13: no range given; chosen: 10 min)
constexpr qint64 kVectorMax = 2147483647; // steps (9.11: none given; chosen: 32-bit signed)
constexpr int kTitleMax = 60;             // characters of a program header (9.17: none given)
bool isStepResolution(qint64 microsteps); // 9.7: 1, 2, 4, ..., 256
} // namespace limits

// One system-parameter entry (9.14) as written with "##" and as *PRSYS reports it (9.15).
struct SystemEntry
{
    enum class Key {
        StepResolution,  // "D,x32,y16,z64,u1"
        Currents,        // "c,x100,0,y100,0,..." (run, idle per axis)
        ReferenceSwitch, // "REFSW,xNO,...,uNC"
        StartSpeed,      // "S,x200,..."
        WorkSpeed,       // "E,x1800,..."
        ReferenceSpeed,  // "E9,x400,..."
        Ramp,            // "R,100"
        SmcFlex,         // "S,200,1800,100": start, work, ramp for SMCflex compatibility
    };
    Key key = Key::Ramp;
    QMap<Axis, qint64> values;                        // D, S, E, E9; Currents: run current
    QMap<Axis, qint64> idle;                          // Currents: idle current
    QMap<Axis, bool> normallyClosed;                  // ReferenceSwitch
    qint64 ramp = 0;                                  // Ramp
    qint64 flexStart = 0, flexWork = 0, flexRamp = 0; // SmcFlex

    // The motors the entry names ("##R,100" and "##S,200,1800,100" apply to all four): the
    // fewest <ACK>s after "Ready!" a board may send for it (kStoredAcks).
    int motorCount() const;
};
std::optional<SystemEntry> parseSystemEntry(const QByteArray& entry, QString* error);
QByteArray formatSystemEntry(const SystemEntry& entry); // without "##" and <CR>

// 9.15: "*PRSYS:" followed by the stored entries. The manual shows no example of the list, so
// the reading is lenient: entries in the "##" write syntax, with or without the "##",
// separated by blanks, CR, LF, ';' or the next "##". Entries that do not parse are kept in
// `unparsed` and otherwise ignored. Entries of the same kind are applied in order (store()).
struct SystemParameters
{
    QList<SystemEntry> entries; // at most one per key
    QList<QByteArray> unparsed;
    const SystemEntry* find(SystemEntry::Key key) const;
    // Applies a "##" write to this copy. A later entry overrides the values it names and keeps
    // the motors it does not name ("##c,x50,10" after "##c,x100,0,y100,0,..." changes only X):
    // the manual (9.14, 9.16 "können einfach überschrieben werden") does not say what happens
    // to the motors a write leaves out; StepDeck reads it as "they keep their stored values".
    void store(const SystemEntry& entry);
};
SystemParameters parseSystemParameters(const QByteArray& text);
QByteArray formatSystemParameters(const QList<SystemEntry>& entries); // "*PRSYS:##D,...\r\n##R,100"

struct Command
{
    enum class Kind {
        Invalid,
        Version,         // @V
        Input,           // @I<n>
        AllInputs,       // @IG
        Output,          // A<n>,<0|1>
        StartSpeed,      // #S<v>, #S,<a><v>
        WorkSpeed,       // #E1,<v>, #E1,<a><v>
        ReferenceSpeed,  // #E9,<v>
        Ramp,            // #R<v>
        StepResolution,  // D,<a><v>
        Current,         // c,<a><run>,<idle>
        Home,            // $H<axes>[,a], $H,<axes> (9.17 example)
        ReferenceOffset, // #O<a>,<v>
        Vector,          // L1,<a><v>[,...]
        Interpolation,   // IP0 / IP1
        Wait,            // W<ms>
        SystemWrite,     // ##<entry>
        ReadSystem,      // *PRSYS
        ClearSystem,     // *PESYS
        ProgramOpen,     // *PWIN<n>
        ProgramHeader,   // IJ<n>,1 <title><STX>
        ProgramEnd,      // <ETX>
        ProgramErase,    // *PEIN<n>
    };
    Kind kind = Kind::Invalid;
    QByteArray text;           // as received, without its terminator
    int number = 0;            // input, output or program input
    bool on = false;           // output, interpolation
    std::optional<Axis> axis;  // per-axis forms; nullopt: all axes
    qint64 value = 0;          // speed, ramp, microsteps, run current, offset, wait
    qint64 idle = 0;           // Current: idle current
    QList<Axis> axes;          // Home, in the order given
    bool simultaneous = false; // Home ",a"
    QList<VectorTarget> targets;
    SystemEntry system;
    QByteArray title; // ProgramHeader
    QString error;    // Invalid: why
    bool isMotion() const { return kind == Kind::Home || kind == Kind::Vector; }
};

// Parses one command. `terminator`: <CR> for commands, <STX> for a program header (9.17).
// Syntax only; see rangeError() for the values.
Command parseCommand(const QByteArray& text, char terminator = kCr);
// Why a syntactically valid command's values are outside the manual's ranges; empty if fine.
QString rangeError(const Command& command);
// Why a command cannot be stored in an input program; empty when it can. Programs hold what
// the board executes by itself: motion, speeds, currents, outputs, waits (9.17 examples:
// "$H,x", "L1,x191", "W1500"); not queries, system parameters or program management.
QString programRefusal(const Command& command);
// parseCommand + rangeError + programRefusal: empty when `line` may go into a program.
QString validateProgramLine(const QByteArray& line);

// Device side framing: commands end with <CR>, a program header with <STX>, and <ETX> alone
// ends programming (9.17). LF and blanks between commands are ignored. Bounded.
class CommandDecoder
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::CommandDecoder)

public:
    static constexpr int kMaxFrame = 256;
    struct Frame
    {
        QByteArray text;
        char terminator = kCr;
        bool overlong = false;
    };
    QList<Frame> feed(const QByteArray& bytes);
    void reset();
    int buffered() const { return int(m_buffer.size()); }
    // Bytes consumed without appearing in a frame's text or terminator: LF and blanks between
    // commands, empty <CR> lines and the tail of an overlong frame (checked by the fuzz target).
    qint64 skippedBytes() const { return m_skipped; }

private:
    QByteArray m_buffer;
    bool m_discarding = false;
    qint64 m_skipped = 0;
};

} // namespace stepdeck::emis
