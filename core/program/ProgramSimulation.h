#pragma once
// Internal to ProgramCheck: a program's blocks planned in the machine's terms (ProgramPlan.cpp)
// and walked with their repeats counted out (ProgramSimulation.cpp, arcs in
// ProgramSimulationArc.cpp, moves across controllers in ProgramSimulationControllers.cpp).
#include "ArcPath.h"
#include "ContourMoves.h"
#include "CutterCompensation.h"
#include "DrillCycle.h"
#include "FeedLimit.h"
#include "PreviewPath.h"
#include "ProgramCheck.h"
#include "ProgramLowering.h"
#include "ProgramReader.h"
#include "motion/executors/SwitchExecutor.h"
#include <QVarLengthArray>
#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

namespace stepdeck::program {

// One axis of a block in the axis' own terms, worked out once before the walk.
struct AxisMove
{
    int axis = 0;     // index in MachineDescription::axes
    double value = 0; // G0/G1: the target (absolute) or distance (relative) in the axis' unit
    int column = 1;   // the axis word, or the action for the axes of a bare G28
    double speed = 0; // unit/s this block moves the axis at; 0: not known
};

struct PlannedBlock
{
    const ProgramBlock* block = nullptr;
    // G0/G1: its axis words, G28: the axes it references, as PlannedProgram::moves[first,
    // first + count).
    int firstMove = 0;
    int moveCount = 0;
    double feedSpeed = 0; // a drilling cycle's Z at F, unit/s (0: not known)
    // G1/G2/G3 of a contour: the stream it runs in (ContourMoves::streamOf), else null.
    const ContourMoves::Stream* contour = nullptr;
};

// The block the walk is at, planned (the program's blocks are streamed: one at a time).
struct PlannedProgram
{
    PlannedBlock block;
    std::vector<AxisMove> moves;
};

// The check's errors, bounded however many a program has: the first ProgramParser::kMaxErrors
// in line order (and column) are kept exactly, and a last line says that more follow.
class CheckErrors
{
public:
    CheckErrors& operator<<(const ProgramError& error);
    // Adds an error; message() is called (the text formatted) only while the error can still
    // be listed, so that a million errors cost no million messages.
    template <typename Message> void add(int line, int column, const Message& message)
    {
        if (m_cutoffLine > 0 && line > m_cutoffLine) {
            m_lastLine = std::max(m_lastLine, line);
            m_dropped = true;
            return;
        }
        *this << ProgramError{line, column, message()};
    }
    QList<ProgramError> take(); // in line order, at most kMaxErrors + the "more follow" line
    // A word a repeat runs many times is reported once: true the first time for this line,
    // column and kind of error. Bounded: only errors that can still be listed are remembered.
    bool once(int line, int column, int kind);
    bool any() const { return !m_errors.isEmpty() || m_dropped; }

    // The check's notes (issue 50: a feed or S above the machine's highest runs at it). One
    // per kind and programmed value (a CAM program's F6000 on a thousand lines is one note): at
    // the first line it holds for, counting the further lines (a repeat's next passes are not
    // counted again); message() is called once per note. At most kMaxNotes.
    enum NoteKind {
        kContourNote = 1,
        kRateNote = 2,
        kInverseTimeNote = 3,
        kSpindleNote = 4,
        kLaserNote = 5
    };
    static constexpr int kMaxNotes = 100;
    template <typename Message>
    void note(int line, int column, NoteKind kind, double value, const Message& message)
    {
        const auto it = m_noteAt.find({int(kind), value});
        if (it != m_noteAt.end()) {
            if (line > it->lastLine) {
                it->lastLine = line;
                ++it->moreLines;
            }
            return;
        }
        if (m_notes.size() >= kMaxNotes)
            return;
        m_noteAt.insert({int(kind), value}, NoteAt{int(m_notes.size()), line, 0});
        m_notes << ProgramError{line, column, message()};
    }
    QList<ProgramError> takeNotes(); // in line order, each with the lines more it holds for

private:
    void prune();
    QSet<quint64> m_once;
    QList<ProgramError> m_errors;
    bool m_dropped = false;
    int m_lastLine = 0;
    int m_cutoffLine = 0; // once pruned: errors after this line can never be listed
    struct NoteAt
    {
        int index = 0;    // in m_notes
        int lastLine = 0; // the last line counted
        qint64 moreLines = 0;
    };
    QMap<std::pair<int, double>, NoteAt> m_noteAt;
    QList<ProgramError> m_notes;
};

// Plans one block against the machine (the part of the check that needs no positions): what
// the axes' controllers take (G1's rate, G28, spindle, coolant, outputs, inputs). Errors go to
// *errors.
class ProgramPlan
{
public:
    ProgramPlan(const MachineFacts& facts, PlannedProgram* out, CheckErrors* errors);
    // Into *out (its block and moves); reporting false: the block was planned before (a
    // repeat's next pass), its errors are not told again.
    void plan(const ProgramBlock& block, bool reporting = true);
    const ContourMoves& contours() const { return m_contours; }

private:
    void planMove(const ProgramBlock& block, PlannedBlock* out);
    void planArc(const ProgramBlock& block, PlannedBlock* out);
    void planCycle(const ProgramBlock& block, PlannedBlock* out);
    void planHome(const ProgramBlock& block, PlannedBlock* out);
    void addMove(const AxisMove& move, PlannedBlock* out);
    bool checkRate(const ProgramBlock& block, const motion::RatedMove& rated, int axisIndex,
                   double* speed);
    // A rate FeedLimit lowered (issue 50): the note naming the F the axis or move runs at.
    void noteRate(const ProgramBlock& block, const machine::MachineAxis& axis,
                  const motion::MoveRates::AxisRate& rate);
    void checkContourTick(const ProgramBlock& block, const ContourMoves::Stream& stream);
    void checkFeedWrite(const ProgramBlock& block);
    QString feedWriteRefusal(const QString& controller, const ProgramBlock& block,
                             ParameterSet* set) const;
    void checkSetup(const ProgramBlock& block, const PlannedBlock& planned);
    void checkSpindleChange(const ProgramBlock& block);
    bool planSwitch(const ProgramBlock& block);
    // false (and the executor's refusal at its word) when the machine would refuse `command`.
    bool acceptSwitch(const ProgramBlock& block, const motion::MotionCommand& command);
    void noteSpindle(const ProgramBlock& block, double rpm, bool reverse);
    void checkInput(const ProgramBlock& block);
    void checkTools(const ProgramBlock& block);
    template <typename Message>
    void error(const ProgramBlock& block, int column, const Message& message)
    {
        if (m_reporting)
            m_errors->add(block.line, column, message);
    }
    template <typename Message>
    void note(const ProgramBlock& block, int column, CheckErrors::NoteKind kind, double value,
              const Message& message)
    {
        if (m_reporting)
            m_errors->note(block.line, column, kind, value, message);
    }

    const MachineFacts& m_facts;
    PlannedProgram& m_out;
    CheckErrors* m_errors;
    ContourMoves m_contours;
    motion::SwitchExecutor m_switches; // spindle, coolant, outputs: the run's executor too
    // Per machine axis (m_facts.description.axes): its controller's capabilities and feed
    // rate parameter, looked up once, not per block (issue 29: the check reads 10^6 lines/s).
    struct AxisFacts
    {
        const Capabilities* caps = nullptr; // null: the facts name no such controller
        QString feedParameter;              // Capabilities::feedRateParameter
        const ParameterSpec* feedSpec = nullptr;
    };
    std::vector<AxisFacts> m_axisFacts;
    // What each device holds as the blocks before this one leave it (G1's rate writes), as
    // the run's controllers will know it: the model's rules are judged against this.
    QMap<QString, ParameterSet> m_known;
    QSet<QString> m_setupReported; // controllers whose incomplete setup was named already
    // Per controller the last rate write judged (feedWriteRefusal), with what it judged by.
    struct JudgedWrite
    {
        bool valid = false;
        ParameterSet set;
        ParameterSet known;
        QString why;
    };
    mutable QHash<QString, JudgedWrite> m_judged;
    // The last G1 whose rate every controller took without a change to what they hold.
    struct LastTakenFeed
    {
        bool valid = false;
        double feed = 0;
        bool inches = false;
        QStringList axes;
        bool matches(const ProgramBlock& b) const
        {
            if (!valid || !b.feed || b.inverseTime || !b.axisRates.isEmpty() || *b.feed != feed ||
                b.inches != inches || b.axes.size() != axes.size())
                return false;
            qsizetype i = 0;
            for (auto it = b.axes.cbegin(); it != b.axes.cend(); ++it, ++i)
                if (it.key() != axes.at(i))
                    return false;
            return true;
        }
    } m_lastTakenFeed;
    bool m_reporting = true;
    // The controller whose tick the device is known to hold as its feed rate (checkContourTick
    // wrote it into m_known, no rate write since): a contour's next block needs no lookup.
    QString m_tickHeld;
};

// Walks the program's blocks from `start` as the run will (repeats counted out, at most
// ProgramCheck::kMaxRepeatedBlocks blocks beyond the program's own), planning each as it comes
// (ProgramPlan) and following the positions the program reaches: absolute moves on unknown axes
// and targets outside the soft limits are errors; the preview's figures (extents, path,
// estimated time) come from the same walk. The blocks come from a ProgramReader, so the walk
// keeps only the block it is at.
class ProgramSimulation
{
public:
    // What CheckErrors::once() tells apart on one line and column.
    enum OnceKind {
        kUnknownPosition = 1,
        kSoftLimit = 2,
        kBlockError = 3,
        kContourFeed = 4,
        kCrossController = 5
    };
    ProgramSimulation(const MachineFacts& facts, ProgramReader* reader, CheckErrors* errors);
    // Each block the first time the walk reaches it (or skips it in a repeat of no passes).
    void setFirstVisit(std::function<void(const ProgramBlock&)> visit)
    {
        m_firstVisit = std::move(visit);
    }
    // Run from line (issue 47 item 5): the blocks the run sends before its start block
    // (RunFromState::prelude: the switches the lines before it left on, the rapids to its start
    // point), walked first from where the axes stand, as the run will send them. Their errors
    // name them at the start block's line; they are no blocks of the program (not counted, as
    // ProgramRunner does not count them), but the preview's path and time include their moves.
    void setPrelude(QList<ProgramBlock> prelude) { m_prelude = std::move(prelude); }
    // Each executed block lowered to motion commands (ProgramLowering; issue 49), from the
    // current point the walk follows, before the walk executes it (a G10 or G92 block: after,
    // its offsets in the frame). None: nothing lowered.
    void setLowered(motion::CommandSink lowered);
    // false: cancelled (by progress, asked every few thousand blocks).
    bool run(int start, ProgramPreview* preview, const CheckProgress& progress = {});

private:
    struct Loop
    {
        int start = 0;        // index of the RepeatStart
        int line = 0;         // its line
        int column = 0;       // its O word
        qint64 remaining = 0; // passes left after the current one
        qint64 blocksBefore;  // m_blocksRun when the current pass began
    };
    // The block at i planned (reporting on its first visit); false at the end.
    bool visit(int i, const ProgramBlock& block);
    bool markVisit(int i, const ProgramBlock& block); // true on the first visit
    void plan(const ProgramBlock& block, bool first); // into m_planned
    void compensate(int i, const ProgramBlock& block, bool first);
    void runPrelude();
    void skipBody(int from, int end); // a repeat of no passes: its blocks planned, not walked
    int repeatStart(int i, const ProgramBlock& block);
    bool repeatEnd(int* i, int partner);
    void execute(PlannedBlock& planned);
    void lower(const ProgramBlock& block);
    void move(PlannedBlock& planned);
    void home(const PlannedBlock& planned);
    double moveAxis(const ProgramBlock& block, AxisMove& m); // its seconds at its speed
    void arc(PlannedBlock& planned);
    void coordinates(PlannedBlock& planned);
    void arcChords(const ArcPath& path, PlannedBlock& planned);
    // A block of a contour stream (ContourMoves): its feed against the stream's tick. Where
    // FeedLimit::contourFeed limits it (issue 50), the block's planned speeds are scaled to the
    // feed it runs at, for the estimate.
    void checkContourFeed(PlannedBlock& planned, const ContourMoves::Stream& stream,
                          const motion::CanonicalMove& move);
    // A feed move of `axes` (the axes that move, each with its speed in its unit/s): across
    // controllers it is refused where the machine file forbids it, else noted for the preview
    // with its estimated path error (ProgramSimulationControllers.cpp).
    using AxisList = QVarLengthArray<std::pair<int, double>, 16>;
    void noteControllers(const ProgramBlock& block, const AxisList& axes);
    QString controllersNote() const; // the preview's motion note
    void cycle(PlannedBlock& planned);
    bool countChords(qint64 chords, PlannedBlock& planned); // false: the run's bound is passed
    // Whether machine position `to` of the axis lies outside its soft limits (reported once
    // per axis word).
    void checkLimit(const ProgramBlock& block, AxisMove& m, double to);
    AxisMove* plannedMove(const PlannedBlock& planned, int axis);
    void noteExtent(int axis);
    void noteExtentAt(int axis, double work);
    // Machine position (steps) -> work position (unit) of axis a.
    double workOf(size_t a) const;
    void addPoint(int line, bool rapid = false);
    void tooManyBlocks(const ProgramBlock& block);
    void finish(ProgramPreview* preview) const;

    const MachineFacts& m_facts;
    const QList<machine::MachineAxis>& m_axes;
    ProgramReader& m_reader;
    PlannedProgram m_planned;
    // A G93 block, or a G94 G1 on coordinating controllers, at the current point (InverseTime,
    // CoordinatedFeed), while planned.
    ProgramBlock m_resolved;
    QSet<QString> m_coordinated; // controllers whose caps say coordinatedFeed
    std::vector<AxisMove>& m_moves;
    CheckErrors* m_errors;
    ProgramPlan m_plan;
    const ContourMoves& m_contours; // m_plan's
    std::function<void(const ProgramBlock&)> m_firstVisit;
    QList<ProgramBlock> m_prelude; // setPrelude()
    motion::CommandSink m_lowered; // setLowered()
    std::unique_ptr<ProgramLowering> m_lowering;
    std::vector<motion::MotionCommand> m_lowerOut;
    // The feed moves across controllers (noteControllers): the first line, and the largest
    // distance one axis covers while its controllers' starts may differ.
    qint64 m_crossMoves = 0;
    int m_crossLine = 0;
    double m_crossError = 0;
    QString m_crossUnit;
    int m_firstUnvisited = 0; // blocks before it were planned once
    qint64 m_firstVisits = 0; // blocks the walk planned for the first time
    // Per axis (the description's order).
    std::vector<qint64> m_steps; // the device's count the axis would hold
    std::vector<char> m_known;
    std::vector<char> m_moved;
    std::vector<char> m_extentKnown;
    std::vector<double> m_minimum, m_maximum; // work coordinates
    std::vector<double> m_offset;             // the axis' work offset, in its unit
    AxisPositions m_programmed;       // the current point (unrounded), as the run follows it
    ProgramCoordinates m_coordinates; // G54..G59, G92 as the program changes them
    std::vector<Loop> m_loops;
    CutterCompensation m_comp;
    ProgramBlock m_compBlock;            // the block compensated (the look ahead reads on)
    std::vector<ProgramBlock> m_compOut; // the blocks it runs as
    qint64 m_blocksRun = 0;
    qint64 m_blocksDone = 0;     // of them, those that do something (PreviewPoint::blocksDone)
    qint64 m_repeatedBlocks = 0; // run again by a repeat's next passes
    qint64 m_chordsRun = 0;      // arcs' chords, counted out like blocks
    double m_seconds = 0;
    double m_feedSeconds = 0; // of m_seconds, the feed moves' (PreviewPoint::feedSeconds)
    PreviewPath m_path{m_axes, m_offset}; // after m_offset: it reads the offsets
};

} // namespace stepdeck::program
