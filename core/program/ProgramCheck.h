#pragma once
#include "Program.h"
#include "ProgramBlock.h"
#include "ProgramCoordinates.h"
#include "machine/MachineDescription.h"
#include "model/Capabilities.h"
#include "model/ModelInfo.h"
#include "model/ParameterSchema.h"
#include "motion/MotionCommand.h"
#include <QCoreApplication>
#include <QMap>
#include <QSet>
#include <functional>

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::program {

// What the check needs to know of a machine (issue 20, docs/programs.md "Check"): its
// description, what each controller can do, and where the axes stand now. Gathered from a
// running Machine by factsOf(), or written by hand in tests. Pure data.
struct MachineFacts
{
    machine::MachineDescription description;
    QMap<QString, Capabilities> capabilities; // controller id -> its model's capabilities
    QMap<QString, ParameterSchema> schemas;   // controller id -> its model's schema
    // Axis name -> position in the axis' unit, for the axes whose position is known now
    // (referenced, or read back). An axis not listed has an unknown position.
    QMap<QString, double> knownPositions;
    // Controller id -> its model (ModelInfo::parameterRules, setupBeforeMotion); a controller
    // not listed has no rules beyond its schema.
    QMap<QString, const ModelInfo*> models;
    // Controller id -> the parameter values its device is known to hold
    // (MachineStatus::knownParameters), which the model's rules are judged against.
    QMap<QString, ParameterSet> knownParameters;
    // Controllers whose device reports its setup incomplete (MachineStatus::setupIncomplete):
    // they refuse every move.
    QSet<QString> setupIncomplete;
    // The coordinate systems G54..G59: per system, axis name -> the machine position of its
    // work zero, in the axis' unit (an axis not listed: work = machine), and the one active
    // (the operator's "Zero X" sets its entries; a program without G54..G59 runs in it). A
    // program's absolute targets are work coordinates, as the position display shows them: the
    // machine goes to target + offset, and the soft limits (machine coordinates) are checked
    // there (issue 28, item 3; issue 29: ProgramCoordinates).
    CoordinateSystems coordinateSystems;
    int activeSystem = 0;
    // LinuxCNC's block delete switch (issue 50 item 6; the window's "Block delete (/)", the
    // CLI's --block-delete): on (LinuxCNC's default), lines starting with "/" are skipped. A
    // check of a text reads it with this (ProgramParser::setBlockDelete), and the program it
    // gives keeps it for the run; a check of a program goes by the program's own.
    bool blockDelete = true;
    // The machine's tool table (issue 29): G43's lengths; when it holds any tool, every T an M6
    // loads and every H must be in it. With tool lengths by touch-off (issue 50 item 4,
    // MachineDescription::toolLength) only its texts count (M6's prompts).
    ToolTable tools;
    // The tools whose lengths G43 applies (ProgramCoordinates): the table, or none where the
    // work Z is touched off for each tool instead.
    ToolTable lengthTools() const
    {
        return description.toolLength == machine::ToolLength::TouchOff ? ToolTable() : tools;
    }
    const QMap<QString, double>& workOffsets() const
    {
        return coordinateSystems[size_t(activeSystem)];
    }
};

MachineFacts factsOf(const machine::Machine& machine);

// One point of the preview's path: where the axes are (program units converted to the
// axes' units) after a block, and when, from the estimate.
struct PreviewPoint
{
    int line = 0;                   // the block that ends here
    double seconds = 0;             // estimated time since the start
    QMap<QString, double> position; // every axis the program has reached a known position of
    // How the path reaches this point from the one before: G0 (true) or a feed move, an arc's
    // chord, a dwell or a reference run (false); previews draw rapids apart from the cut.
    bool rapid = false;
    // Of `seconds`, those of feed moves (G1, arcs' chords, drilling cycles' feeds): the time
    // the feed override re-times (issue 47, item 11); rapids and dwells are the rest.
    double feedSeconds = 0;
    // The blocks a run has finished once it is here, this point's own included, counted as
    // ProgramRunner::blocksDone() counts them: every block that does something, in run order,
    // repeats counted out; lines of modal words only (G90, F…) and the O repeat lines are not
    // blocks of their own there. Where a run stands by its finished blocks (ProgramProgress),
    // also on a thinned path.
    qint64 blocksDone = 0;
};

struct AxisExtent
{
    double minimum = 0;
    double maximum = 0;
    bool moved = false; // the program moves this axis at all
};

// The figures of a checked program (the preview, `run --dry-run`). Everything time-related
// is an estimate from the rates that are known (G1's F, the axes' fast speed as far as the
// model's data says it), without acceleration: shown marked "estimated".
struct ProgramPreview
{
    // The path's positions and the extents are work coordinates: machine position minus
    // these offsets (the system active at the start, MachineFacts::workOffsets(); an axis not
    // listed: none).
    QMap<QString, double> workOffsets;
    int lines = 0; // lines in the file
    // Blocks the run will execute, repeats counted out: every block in run order but the O
    // repeat lines, lines of modal words only included (PreviewPoint::blocksDone leaves those
    // out, as ProgramRunner::blocksDone() does). "n block(s) run" and the Program page's
    // "Finished: n block(s) run" both name this count.
    qint64 blocksRun = 0;
    double estimatedSeconds = 0;
    QMap<QString, AxisExtent> extents; // per axis, in its unit, where the position is known
    // The path of the whole run, bounded: past kMaxPathPoints it is thinned to every 2^k-th
    // point (pathDecimated set), its last point the run's end.
    QList<PreviewPoint> path;
    bool pathDecimated = false;
    // How a block's axes move together on this machine's controllers (docs/programs.md "How F
    // maps onto each model"), and how approximate the program's feed moves across
    // controllers are.
    QString motionNote;
    // With tool lengths by touch-off (issue 50 item 4): the M6s the run holds at until the work
    // Z is set for the new tool, and that G43 adds no length. Empty otherwise.
    QString toolNote;
    // The check found errors (issue 47 item 12). The figures are then the run as the check's
    // walk followed it: soft limits, rates, unknown positions and the like leave the whole
    // path, which is shown with the errors so that the operator sees where the program goes
    // (before a work zero is set, say). Never a plan to run: ProgramCheckResult::ok() is false
    // and its program empty.
    bool hasErrors = false;

    static constexpr int kMaxPathPoints = 20000;
};

struct ProgramCheckResult
{
    QList<ProgramError> errors; // every problem, in line order (line, column of the word)
    // What the run does other than the program says, without refusing it (issue 50), in line
    // order: a feed or S above the machine's highest runs at that highest (FeedLimit), and what
    // the parser reads and does not run (Program::notes). The window's check line and the
    // CLI show them beside a clean check; they never keep a program from running.
    QList<ProgramError> notes;
    // Without errors the run's figures. With errors (preview.hasErrors) the path and figures as
    // the check walked the program, to be shown beside the errors and never run; where nothing
    // was walked (the program does not parse, its start or its file was refused, cancelled)
    // only the line count: hasPreview() false.
    ProgramPreview preview;
    // The one pass over a source: the program read (its index, for the run), when it parsed.
    std::optional<Program> program;
    bool cancelled = false; // the progress callback ended the check: nothing is known
    bool ok() const { return errors.isEmpty() && !cancelled; }
    // A path to show: the run's, or with errors the one the check walked (not runnable).
    bool hasPreview() const { return !cancelled && !preview.path.isEmpty(); }
};

// How far a check is (bytes of the text read, of its length); false ends the check
// (cancelled). Called every few thousand blocks from the thread that checks.
using CheckProgress = std::function<bool(qint64 done, qint64 total)>;

// Checks a parsed program against a machine before anything moves (docs/programs.md):
// - absolute targets in work coordinates (MachineFacts::coordinateSystems), the soft limits in
//   machine coordinates;
// - every target within the axes' soft limits, following the positions the program itself
//   reaches (relative moves from known positions; repeats counted out);
// - absolute moves only on axes whose position is known, or after the program's own G28 of
//   the axis (a reference run ends at 0 on every model);
// - G1 only where the axes' controllers take a rate (Capabilities::feedRateParameter), the
//   rate in steps/s within that parameter's schema range for every axis of the block;
// - G28 only on controllers with reference runs; M3/M5 a controller with a spindle, M7/M8/M9
//   one with coolant; M64/M65 an output and M66 an input the machine has (numbered 1.. over
//   the controllers in the file's order, docs/programs.md "Inputs and outputs");
// - feed moves across controllers only where the machine file allows them
//   (MachineDescription::crossControllerFeed; the preview notes their path error).
// fromLine > 1: the run starts at the first block on or after that line (run from line N);
// blocks before it are not checked, positions are the machine's as they stand. What the run
// sends before that block is checked first, as it will be sent (RunFromState::prelude, issue 47
// item 5): the spindle and coolant the lines before it left on (M3 S within the spindle's
// range), then the rapids to where those lines leave the tool (soft limits, known positions).
class ProgramCheck
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramCheck)
public:
    // Blocks the repeats of a run execute beyond the program's own (each of its blocks once)
    // at most; more is an error (a runaway repeat, not a long program: no length is refused).
    static constexpr qint64 kMaxRepeatedBlocks = 5000000;
    // Moves the arcs and drilling cycles of a run take at most (ArcPath, DrillCycle), counted
    // out likewise: this many, and kChordsPerBlock more for each block of the program.
    static constexpr qint64 kMaxChordsRun = 20000000;
    static constexpr qint64 kChordsPerBlock = 100;

    // A parsed program (its blocks read again from its source). lowered: each block's motion
    // commands as the walk lowers it (ProgramLowering; issue 49, `stepdeck-cli run --dry-run
    // --canon`), repeats counted out, a run from line's moves to its start first.
    static ProgramCheckResult check(const Program& program, const MachineFacts& facts,
                                    int fromLine = 1, const CheckProgress& progress = {},
                                    const motion::CommandSink& lowered = {});
    // The rest of a run that holds (issue 47: offsets or tools changed while it held at M0 or
    // M6): from the program's block `fromBlock` (ProgramReader's index), the axes where the
    // facts put them. Refused inside a repeat (its passes are not counted from a block), and
    // for a program in LinuxCNC's language whose offsets changed (its values were worked out
    // against the old ones).
    static ProgramCheckResult checkRest(const Program& program, const MachineFacts& facts,
                                        int fromBlock, const CheckProgress& progress = {});
    // The one pass (issue 29): the text parsed and checked as it is read, in bounded memory
    // whatever its length; result.program is the program when it parsed. The parser's errors,
    // where there are any, are the result's errors (the check's are then left out).
    static ProgramCheckResult check(const ProgramSource& source, const QStringList& axisNames,
                                    const MachineFacts& facts, int fromLine = 1,
                                    const CheckProgress& progress = {});
};

} // namespace stepdeck::program
