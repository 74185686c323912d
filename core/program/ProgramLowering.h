#pragma once
#include "ArcPath.h"
#include "ProgramBlock.h"
#include "ProgramCoordinates.h"
#include "motion/MotionCommand.h"
#include "motion/executors/MoveRates.h"
#include <optional>
#include <vector>

namespace stepdeck::program {

// A block lowered to motion commands (issue 49 item 2, docs/architecture.md "One motion
// path"), as LinuxCNC's interpreter turns a block into canonical machining calls: units, work
// offsets, G92, the tool length, G53, arcs (ArcPath) and drilling cycles (DrillCycle) applied,
// every position in machine coordinates. Stateful only in what it told last: the frame
// commands come where they change, in LinuxCNC's order of execution within a line (the feed
// first; plane, units, tool length and coordinate system after the line's tool change,
// spindle, coolant, outputs and dwell, before its motion and stops). The walk that calls it (the
// check's, ProgramSimulation) owns the current point, the repeats and the coordinates.
class ProgramLowering
{
public:
    struct Error
    {
        int column = 1;
        QString message;
    };
    explicit ProgramLowering(const machine::MachineDescription& d);

    // The commands of `block`, from the current point `at` (machine coordinates) with
    // `coordinates` as they stand for it (a G10 or G92 block's after it applied them), appended
    // to *out. An arc or a drilling cycle that cannot be laid: its error, and its motion left
    // out (its frame commands and message are told).
    std::optional<Error> lower(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                               const AxisPositions& at, std::vector<motion::MotionCommand>* out);
    // The switch a block makes (M3/M4 S, M5, M7/M8/M9, M64/M65 P, M66's wait), the same the
    // lowering emits; nullopt for any other block. The check and the run hand it to the
    // machine's SwitchExecutor, so that they judge one command.
    static std::optional<motion::MotionCommand> switchCommand(const ProgramBlock& block);
    // An S on a line of another action ("G1 X5 S500"): the new speed of a running spindle.
    static std::optional<motion::MotionCommand> speedChange(const ProgramBlock& block);
    // A G0 or G1 of its own (or an arc's or a drilling cycle's rate block, ArcPath::rateBlock,
    // DrillCycle::rateBlock) as the move executor takes its speeds (motion::MoveRates): a G1's
    // F on each axis in the axis' unit per second, or the axis' resolved rate
    // (ProgramBlock::axisRates: G93, the shares of F on a coordinating controller). Without
    // targets: the run adds the machine targets it sends, the check needs none.
    static motion::RatedMove ratedMove(const ProgramBlock& block,
                                       const machine::MachineDescription& d);

private:
    struct Frame
    {
        int line = 0;
        bool inches = false;
        Plane plane = Plane::XY;
        motion::Offsets offsets;
    };
    void lowerFeed(const ProgramBlock& block, std::vector<motion::MotionCommand>* out);
    // offsets false: the units and plane only.
    void lowerFrame(const Frame& frame, std::vector<motion::MotionCommand>* out,
                    bool offsets = true);
    void lowerSwitch(const ProgramBlock& block, std::vector<motion::MotionCommand>* out) const;
    motion::MachinePoint moveEnd(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                                 const AxisPositions& at) const;
    std::optional<Error> lowerArc(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                                  const AxisPositions& at,
                                  std::vector<motion::MotionCommand>* out) const;
    std::optional<Error> lowerCycle(const ProgramBlock& block,
                                    const ProgramCoordinates& coordinates, const AxisPositions& at,
                                    std::vector<motion::MotionCommand>* out) const;
    motion::Offsets offsetsOf(const ProgramBlock& block,
                              const ProgramCoordinates& coordinates) const;

    const machine::MachineDescription& m_d;
    int m_toolAxis = -1;
    // What was told last (nothing yet: told at the first block).
    std::optional<bool> m_inches;
    std::optional<Plane> m_plane;
    std::optional<std::pair<double, bool>> m_feed;
    std::optional<motion::Offsets> m_offsets;
    // A frame change on a line whose blocks so far come before it in LinuxCNC's order: told
    // before the line's first block that depends on it, else when the next line begins.
    std::optional<Frame> m_pending;
};

} // namespace stepdeck::program
