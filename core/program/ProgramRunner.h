#pragma once
#include "ArcPath.h"
#include "ContourMoves.h"
#include "CutterCompensation.h"
#include "DrillCycle.h"
#include "ProgramBlock.h"
#include "ProgramCheck.h"
#include "machine/Machine.h" // QPointer needs the whole class
#include "model/CommandResult.h"
#include "motion/MotionCommand.h"
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QTimer>
#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace stepdeck::motion {
class MoveExecutor;
class WaitExecutor;
class StreamExecutor;
struct RatedMove;
} // namespace stepdeck::motion

namespace stepdeck::program {

class ProgramReader;

enum class RunState {
    Idle,     // nothing started
    Running,  // a block runs, or the next one starts
    Paused,   // holding between blocks (M0, Pause, Step); resume() goes on
    Stopping, // abort asked: the machine's stop is out, waiting for the axes to stand
    Finished, // M2/M30 or the last block done
    Failed,   // a refusal, NAK, timeout or link loss during a block: the machine was stopped
    Aborted,  // abort(), STOP or PANIC
};

QString runStateText(RunState state); // "running", ... (translated, for screens and the CLI)
// What can change on an open machine between a check and the start (or the resume that took
// it): the positions, what the devices hold, the offsets and tools.
bool sameStartFacts(const MachineFacts& a, const MachineFacts& b);
bool isEnded(RunState state); // Finished, Failed, Aborted

// Runs a checked program on a machine (issue 20, docs/programs.md "Running"), one block at a
// time: a block starts only when the devices confirmed the previous one (arrival and
// standstill through Machine::move / Machine::reference, an acknowledged output, spindle or
// rate write, a dwell's time, an input's level). Nothing is sent ahead, except that feed
// moves of a contour (ContourMoves: G1/G2/G3 in G64 on a controller with a step stream) run
// as one stream (motion::StreamExecutor), their moves appended while it runs, at most
// StreamExecutor::kAheadSeconds of path ahead. It reaches the controllers only through the Machine
// and its executors (core/motion/executors). No Widgets.
//
// Faults: a refused block, a failed request, a timeout or a lost link stops every controller
// and ends the program Failed at that line with the reason and its ErrorKind; a program never
// continues after a fault by itself. abort() (the GUI's STOP and PANIC call it too) stops
// every controller and ends Aborted once the axes stand; controllers without a stop command
// (EMIS, laser axes) finish the move under way, and stopping() says so.
class ProgramRunner : public QObject
{
    Q_OBJECT
public:
    explicit ProgramRunner(machine::Machine* machine, QObject* parent = nullptr);
    ~ProgramRunner() override;
    machine::Machine* machine() const { return m_machine; }

    // The machine's motion (Machine::claimMotion, issue 49 item 4): a run holds it from its
    // start to its end, so that a program and an MDI line exclude each other in core, and the
    // machine's STOP, PANIC and close abort the run that holds it. ownerName: what the holder
    // is called in a refusal ("a program runs", the default; "an MDI line runs").
    void setOwnerName(const QString& what) { m_ownerName = what; }
    // Takes it ahead of a start whose check runs first (ProgramStarter); false with *why naming
    // the holder. releaseMotion() gives it back unless a run is under way.
    bool claimMotion(QString* why);
    void releaseMotion();

    // Checks the program against the machine as it stands (ProgramCheck) and starts it at the
    // first block on or after fromLine (the modal state is the block's own, rebuilt by the
    // parser from the lines before it; the spindle and coolant those lines left on are
    // switched on first, then the axes go at rapid to where those lines leave the tool, Z up
    // first or down last: RunFromState::prelude, which the check walked first). stepOnly: run
    // one block, then pause. False with *errors when the check fails or a program runs
    // already: nothing is sent.
    bool start(const Program& program, int fromLine, QList<ProgramError>* errors,
               bool stepOnly = false);
    // start() in two halves, so that a long program's check runs off the GUI thread (issue 29:
    // 10^7 lines take seconds): startFacts() here, checkForStart() on any thread, then
    // startChecked() here with what that check used and found. startChecked() refuses (nothing
    // sent) when the machine's facts changed meanwhile (an axis moved or became known, a work
    // offset, a tool, a parameter the device holds): the check would not be of this machine.
    MachineFacts startFacts() const;
    static ProgramCheckResult checkForStart(const Program& program, const MachineFacts& facts,
                                            int fromLine, const CheckProgress& progress = {});
    bool startChecked(const Program& program, int fromLine, const MachineFacts& checkedFacts,
                      const ProgramCheckResult& checked, QList<ProgramError>* errors,
                      bool stepOnly = false);
    // The coordinate systems programs run in (MachineFacts::coordinateSystems, the active
    // one): taken at start() for the whole run, so that a zero set while the run holds does
    // not move the rest of the path. G10 changes the run's copy and says so
    // (coordinateSystemSet).
    //
    // While the run holds (Paused) they are for the rest of this run too (issue 47: a touch-off
    // at M6 or M0, by the DRO's Zero or a G10 L20): restNeedsCheck() then, and resume() and
    // step() first check the rest of the program with them from the held block, the axes where
    // they stand now, and go on only if that check passes; else the run stays held and
    // resumeRefused says why.
    void setCoordinateSystems(const CoordinateSystems& systems, int active);
    // Told how far start()'s check is (a long program takes seconds); it may cancel it.
    void setCheckProgress(CheckProgress progress) { m_checkProgress = std::move(progress); }
    // The machine's tool table (G43's lengths, M6's prompts), taken at start().
    // While the run holds, as setCoordinateSystems (a tool's length measured at M6).
    void setToolTable(const ToolTable& tools);
    // Only G54's offsets, G54 active.
    void setWorkOffsets(const QMap<QString, double>& offsets)
    {
        setCoordinateSystems(CoordinateSystems{offsets}, 0);
    }
    // The work offsets of the system active when the run started last (the preview's frame).
    QMap<QString, double> workOffsets() const
    {
        return m_coordinates.systems()[size_t(m_coordinates.activeAtStart())];
    }
    // LinuxCNC's optional-stop switch: on, M1 holds like M0; off, the run passes it. On by
    // default (as in LinuxCNC's AXIS): a forgotten stop is safer than a missed one. May change
    // while a program runs; it counts when the run reaches an M1.
    void setOptionalStops(bool on) { m_optionalStops = on; }
    bool optionalStops() const { return m_optionalStops; }

    void pause(); // finish the current block, then hold (pausePending() until then)
    // Feed hold (issue 30): a contour running as a step stream stops on its path at once
    // (StreamExecutor::hold: within ElabCtlMotionOps::kContourLeadSeconds at the board), Paused
    // with feedHeld(); resume() goes on along the path from there. Without a contour under way
    // it is pause(): a block of its own finishes first, an arc holds at the end of its running
    // chord (the EMIS and Nanotec executors: neither stops a positioning move on a ramp; the
    // Nanotec's S, 6.2, stops without one and may lose steps). False when nothing runs.
    bool holdFeed();
    bool feedHeld() const { return m_feedHeld; }
    // Feed override, 10..200 % (issue 30): a contour's ticks not yet given run at that share of
    // F (a move at most as fast as one step per tick allows), from now and for the contours
    // after; on coordinating controllers (EMIS, Nanotec) from the next move or chord, each rate
    // within its parameter's range; an E-LAB block of its own runs at its F. May change at any
    // time.
    void setFeedOverride(double percent);
    double feedOverride() const { return m_feedOverride * 100; }
    // From Paused: on with the next block; while a pause is pending: withdrawn. With
    // restNeedsCheck(), the rest is checked first, here on the caller's thread (a front end that
    // must not wait checks restFacts() from restBlock() elsewhere and calls resumeChecked()).
    void resume();
    bool restNeedsCheck() const { return m_restChanged && m_state == RunState::Paused; }
    MachineFacts restFacts() const; // the machine now, with the offsets and tools given while held
    int restBlock() const;          // the block the rest's check starts at (the next one)
    const Program& program() const { return m_program; }
    // Goes on with the rest checked (ProgramCheck::checkRest) as restFacts() from restBlock();
    // refused (false, and
    // resumeRefused with the reason) when the check failed, the machine changed meanwhile, or
    // the run holds where the rest cannot be checked from a block (inside a repeat, an arc, a
    // cycle or a feed hold, with a G92 offset in effect). stepOnly: as step().
    bool resumeChecked(const MachineFacts& checkedFacts, const ProgramCheckResult& checked,
                       bool stepOnly = false);
    void step(); // from Paused: run one block, then pause again
    // Tool lengths by touch-off (issue 50 item 4, MachineDescription::toolLength, on a machine
    // with Z): at M6 the run holds as at M0, its prompt naming the tool, and resume() and
    // step() are refused (resumeRefused says why) until the work Z of the system the run cuts
    // in was set for the new tool while it held: the DRO's Zero Z or a G10 L20 Z, given here
    // by setCoordinateSystems() with another Z. awaitsTouchOff(): held there, Z not set yet.
    bool awaitsTouchOff() const;
    // The one way on from such a hold without a new Z, on the operator's word that the tool in
    // the spindle is the one the work Z was set for. Offered only where that can be so
    // (sameToolResumable): the M6 loads the same T as the run's M6 before it (nothing to
    // change), or it is the run's first M6, where StepDeck cannot know which tool is in and a
    // shop touches off before pressing Run (a CAM file opens with "T1 M6"; zeroing Z again at
    // the same spot would change nothing). An M6 of another T always needs its touch-off: its
    // length differs, and a forgotten one cuts at the wrong depth. False (and resumeRefused)
    // where it is not offered; else on as resume() (step() with stepOnly).
    bool sameToolResumable() const { return awaitsTouchOff() && m_touchOff.sameTool; }
    bool resumeSameTool(bool stepOnly = false);
    void abort(); // stop every controller; ends Aborted once the axes stand

    RunState state() const { return m_state; }
    int currentLine() const; // the block running or about to run (0: none)
    qint64 blocksDone() const { return m_blocksDone; }
    bool pausePending() const { return m_pauseAsked && m_state == RunState::Running; }
    QString prompt() const { return m_prompt; } // M0's (M1's) prompt while Paused at it
    // Paused at M0, M6 or (with optional stops) M1, not by pause() or a step.
    bool pausedAtOperatorStop() const { return m_state == RunState::Paused && m_operatorStop; }
    // Why the program ended Failed or Aborted ("line 12: ..."), and the kind of the fault:
    // the failed request's ErrorKind (Refused also for a block the machine's rules refused
    // before sending, LinkDown for a lost link, Timeout for M66's Q); None when a move ended
    // short of its target without a failed request (an end switch, a stop from elsewhere).
    QString endMessage() const { return m_endMessage; }
    ErrorKind failureKind() const { return m_failureKind; }
    const ProgramPreview& preview() const { return m_preview; } // of the check at start()
    // The notes of the check at start() (ProgramCheckResult::notes: a feed above the machine's
    // highest runs at it, issue 50), for a front end that did not check it itself.
    const QList<ProgramError>& checkNotes() const { return m_checkNotes; }

Q_SIGNALS:
    void stateChanged(stepdeck::program::RunState state);
    void blockStarted(int line, const QString& text);
    void blockFinished(int line);
    // Paused at M0 or M1 (prompt: its comment), M6, after pause() or a step (prompt empty).
    void paused(int line, const QString& prompt);
    // abort() while motion on a controller without a stop command runs out (message says so).
    void stopping(const QString& message);
    // The run reached a line with "(MSG, text)" (LinuxCNC): text for the operator.
    void operatorMessage(int line, const QString& text);
    // G10 L2/L20 set a coordinate system (0 = G54) to these offsets (machine position of its
    // work zero per axis): the window keeps them for the next runs, as LinuxCNC does.
    void coordinateSystemSet(int system, const QMap<QString, double>& offsets);
    void finished(stepdeck::program::RunState state, const QString& message);
    // resume() or step() with offsets changed while held: the rest's check failed, or cannot
    // be made where the run holds; the run stays held.
    void resumeRefused(const QString& reason);
    // The rest of the run takes the offsets and tools given while it held (its check passed).
    void restChecked(const QString& message);

private:
    struct Loop
    {
        int start = 0;        // index of the RepeatStart block
        qint64 remaining = 0; // iterations left after the current one
    };
    // The run's walk (ProgramRunner.cpp).
    void resetRun(const MachineFacts& facts);
    void connectMachine();
    void disconnectMachine();
    void runNext();
    void runPrelude();   // the next block of m_prelude
    void approachDone(); // a rapid of m_prelude arrived
    bool advance();      // onto the next block that does something; false at the end
    bool compensate();   // m_block under G41/G42 (CutterCompensation)
    void blockDone();
    void finishProgram(bool programEnd = false); // programEnd: M2/M30, spindle and coolant off
    void onSwitchedOff(bool ok, const QString& message); // M2/M30: spindle and coolant off
    QString restUncheckable() const; // why the rest cannot be checked from a block (empty: can)
    void takeRest(const MachineFacts& facts); // the new offsets and tools, the axes as they stand
    void go(bool stepOnly);                   // on from Paused (resume / step)
    void fail(ErrorKind kind, const QString& message);
    void failSoon(ErrorKind kind, const QString& message); // once the signal emission is over
    void end(RunState state, const QString& message);
    void setState(RunState state);
    QString lineText(const QString& message) const;
    QString promptOf(const ProgramBlock& block) const;
    // Touch-off holds (ProgramRunnerRest.cpp).
    bool begin(const Program& program, int fromLine, const MachineFacts& checkedFacts,
               const ProgramCheckResult& checked, QList<ProgramError>* errors, bool stepOnly);
    void startTouchOff(const ProgramBlock& block); // at a hold: an M6 that waits for Z?
    bool refuseWithoutTouchOff();                  // resume/step: refused while it waits
    bool refuseToGoOn(); // resume/step: refused while jogging, or waiting for a touch-off
    // What each block sends (ProgramRunnerBlocks.cpp).
    void startBlock(const ProgramBlock& block);  // a new S first, then startAction()
    void startAction(const ProgramBlock& block); // what the block's action sends
    void startMove(const ProgramBlock& block);
    void pushMove(const motion::RatedMove& move); // to the move executor
    void applyCoordinates(const ProgramBlock& block);
    // Blocks of many moves: an arc's chords, a cycle's moves (ProgramRunnerPaths.cpp).
    void startArc(const ProgramBlock& block);
    void sendChord();
    void startCycle(const ProgramBlock& block);
    void startSegment(); // the cycle's m_segment: its move or dwell
    // After a chord or a cycle's move arrived (or its dwell ended): true while the block goes
    // on, or holds there on pause().
    bool nextInPath();
    void resumePath();                       // on from where the block held (m_heldInPath)
    void endPath(AxisPositions* programmed); // the block done: its end as the current point
    void onWaitFinished(bool ok, ErrorKind kind, const QString& message);
    void startHome(const ProgramBlock& block);
    void startSwitch(const ProgramBlock& block, std::function<void()> then);
    void startSwitchCommand(const motion::MotionCommand& command, std::function<void()> then);
    void awaitRequests(const QMap<RequestId, QString>& requests, std::function<void()> then);
    void onRequestFinished(const QString& controllerId, const CommandResult& result);
    void onMoveFinished(bool ok, ErrorKind kind, const QString& message);
    void onControllerFailed(const QString& controllerId, const QString& message);
    // Contours (ProgramRunnerContour.cpp).
    bool joinsContour(const ProgramBlock& block) const;
    void openContour(const ContourMoves::Stream& stream);
    bool appendToContour(const ProgramBlock& block); // false: the run failed
    void onContourFinished(bool ok, ErrorKind kind, const QString& message);
    void dropContour();

    // Watched: a window may close the machine under a run still stopping (its end then must not
    // reach the machine that went).
    QPointer<machine::Machine> m_machine;
    std::unique_ptr<ProgramReader> m_reader; // the running program's blocks, read as it goes
    Program m_program;                       // the running program (the rest's check reads it)
    bool m_restChanged = false;  // offsets or tools given while held, not yet checked for the rest
    bool m_endSwitching = false; // M2/M30 or the end: waiting for spindle and coolant off
    // Run from line (issue 47 item 5): the spindle and coolant the lines before it switched on,
    // switched before its first block, then the rapids to its start point (RunFromState::
    // prelude, as the check walked them).
    QList<ProgramBlock> m_prelude;
    bool m_approaching = false;      // m_block is one of m_prelude's rapids
    ProgramBlock m_block;            // the block at m_index
    CoordinateSystems m_nextSystems; // setCoordinateSystems()
    int m_nextActive = 0;
    ToolTable m_nextTools;
    CheckProgress m_checkProgress;
    ProgramCoordinates m_coordinates; // the running program's
    ProgramPreview m_preview;
    QList<ProgramError> m_checkNotes;
    RunState m_state = RunState::Idle;
    int m_index = -1; // the block running (or the one before the next)
    QList<Loop> m_loops;
    qint64 m_blocksDone = 0;
    bool m_pauseAsked = false;
    bool m_stepOnly = false;
    bool m_optionalStops = true;
    bool m_spindleOn = false; // an M3/M4 of this run is in effect (no M5 since)
    bool m_aborting = false;
    QString m_ownerName;
    bool m_ownStop = false; // fail() stops the machine: not an abort from outside
    QString m_prompt;
    bool m_operatorStop = false; // the last pause was at M0, M6 or M1
    // The touch-off hold the run is in (awaitsTouchOff), if any.
    struct TouchOff
    {
        bool pending = false;          // held at an M6 that waits for its work Z
        int tool = 0;                  // the M6's T
        std::optional<int> toolBefore; // the T of the run's M6 before it (none: its first)
        bool sameTool = false;         // resumeSameTool() is offered
        int system = 0;                // the coordinate system the run cuts in there (0 = G54)
        double z = 0;                  // that system's Z offset when the hold began
        bool zSet = false;             // setCoordinateSystems() gave it another Z since
    };
    TouchOff m_touchOff;
    std::optional<int> m_lastTool; // the T of the run's last M6 (none before its first)
    QString m_endMessage;
    ErrorKind m_failureKind = ErrorKind::None;
    quint64 m_run = 0; // counts start(): a queued fault of an earlier run is dropped
    // What the current block waits for.
    QSet<RequestId> m_requests; // session requests of the block (output, spindle; the end's)
    std::function<void()> m_afterRequests;
    // The last request of a controller that failed while the block ran (the ErrorKind of a
    // failed move: Machine::moveFinished says only why).
    ErrorKind m_blockError = ErrorKind::None;
    QTimer m_abortSettle;
    std::unique_ptr<motion::MoveExecutor> m_moves; // moves of their own, with their rates
    std::unique_ptr<motion::WaitExecutor> m_waits; // dwells, input waits
    // The current point (ArcPath): where the blocks done put the axes, unrounded.
    AxisPositions m_programmed;
    std::optional<ArcPath> m_arc;      // the arc running, its chords sent one at a time
    qint64 m_chord = 0;                // the chord under way (1..chords)
    bool m_chordsCoordinated = false;  // each chord writes its own shares of F (CoordinatedFeed)
    std::optional<DrillCycle> m_cycle; // the drilling cycle running, one move at a time
    size_t m_segment = 0;              // its move under way
    bool m_heldInPath = false;         // paused between two moves of m_arc or m_cycle
    QList<QMetaObject::Connection> m_connections;
    // The machine's facts at start() and the contour streams they give (ContourMoves keeps a
    // reference to them).
    MachineFacts m_runFacts;
    QSet<QString> m_coordinated; // controllers of m_runFacts that coordinate (CoordinatedFeed)
    std::unique_ptr<ContourMoves> m_contourMoves;
    std::unique_ptr<motion::StreamExecutor> m_contour; // the contour running, if any
    // m_block was read but waits for the contour to end (runNext takes it, not the next one).
    bool m_heldBlock = false;
    // G41/G42 (CutterCompensation, from m_runFacts): the blocks a compensated block runs as after
    // m_block, whether m_block is a corner's arc (not counted), and a refusal that ends the run.
    std::unique_ptr<CutterCompensation> m_comp;
    std::deque<ProgramBlock> m_compQueue;
    bool m_uncounted = false;
    QString m_compError;
    bool m_feedHeld = false; // holdFeed() held a contour on its path
    double m_feedOverride = 1.0;
};

} // namespace stepdeck::program
