#pragma once
#include "ArcPath.h"
#include "CompensationGeometry.h"
#include "ProgramBlock.h"
#include "ProgramCoordinates.h"
#include <QCoreApplication>
#include <functional>
#include <optional>
#include <vector>

namespace stepdeck::program {

// LinuxCNC's cutter radius compensation (issue 50 item 7, docs/programs.md "Cutter
// compensation"): with G41 (G42) in effect the tool's centre runs its radius to the left (right)
// of the programmed path in the XY plane, as LinuxCNC's interpreter computes it
// (interp_convert.cc, convert_straight_comp1/2, convert_arc_comp2, interp_queue.cc):
// - the entry move (the first move in X or Y after G41/G42, a G0 or G1) ends where a line from
//   its start touches the circle of the tool's radius about the programmed end;
// - a line runs parallel to the programmed one, an arc about the same centre with its radius
//   grown or shrunk by the tool's (shrunk to nothing: refused);
// - at an outside (convex) corner a G1, G2 or G3 first goes round the corner on an arc of the
//   tool's radius (a G0 goes straight to its start);
// - at an inside (concave) corner the move ends where its path meets the next move's, which
//   starts there; where that point lies before the move's start or past the next move's end,
//   the tool cannot reach the corner without cutting into the part: refused;
// - the first move after G40 goes from where the tool stands to its programmed end.
// A move with no X or Y travel leaves the tool where it stands.
//
// A move's end depends on the next move in X or Y (LinuxCNC queues the move until it knows it);
// here the walk hands the blocks after the one being lowered (`Following`), so that the check
// and the run, which both call this, compute the same path. Its output are blocks as the
// program would have written them for the tool's centre (G1/G2/G3 with X, Y, I, J in the block's
// own units, coordinate system and distance mode), which both then run as any block.
class CutterCompensation
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::CutterCompensation)
public:
    struct Error
    {
        int column = 1;
        QString message;
    };
    // The blocks after the one being lowered, in run order, one a call (nullptr: no more). The
    // pointer is valid until the next call.
    using Following = std::function<const ProgramBlock*()>;

    // Radians: corners turning less than this need neither an arc nor an intersection (LinuxCNC's
    // TOLERANCE_CONCAVE_CORNER).
    static constexpr double kSmallCorner = 0.01;

    // tools: the machine's table, whose diameters G41/G42 D<n> take (in X's unit), whichever
    // tool-length workflow the machine uses.
    CutterCompensation(const machine::MachineDescription& d, const ToolTable& tools);

    // An arc as the entry move (LinuxCNC's convert_arc_comp1 is not run here): the parser
    // refuses it (ProgramLine), and lower() too should a block come without the parser.
    static QString arcEntryRefusal(const ProgramBlock& block);
    // Whether `block` goes through lower(): a G0..G3 while G41/G42 is in effect, or the first
    // G0/G1 after G40 while the tool still stands off the path.
    bool applies(const ProgramBlock& block) const;
    // Whether the tool stands off the programmed path (G41/G42 entered, the move after G40
    // not yet lowered).
    bool isFollowing() const { return m_activation != 0; }
    // The blocks that run in place of `block` (one, or a corner's arc and the move), appended to
    // *out. `at`: the current point (machine coordinates), where the tool stands.
    std::optional<Error> lower(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                               const AxisPositions& at, const Following& following,
                               std::vector<ProgramBlock>* out);

    using Point = compensation::Point;
    using Path = compensation::Path;

private:
    enum class Corner : quint8 { None, Outside, Inside };

    std::optional<Error> begin(const ProgramBlock& block, const AxisPositions& at);
    // The programmed move of `block` from programmed point `from` (nullopt: no X or Y travel).
    std::optional<Path> pathOf(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                               const AxisPositions& at, Point from,
                               std::optional<Error>* error) const;
    Point programmedEnd(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                        Point from) const;
    // The next move in X or Y after the block being lowered, from the programmed point `from`;
    // nullopt where the path ends first (G40, the program's end, a block that stops the look).
    std::optional<Path> nextPath(const Following& following, const ProgramCoordinates& coordinates,
                                 const AxisPositions& at, Point from) const;
    // Where the tool's move ends given the next move (a line's tool path through lineFrom and
    // nominalEnd, starting at toolStart); sets m_corner.
    std::optional<Error> endOf(const Path& move, Point lineFrom, Point toolStart, Point nominalEnd,
                               const std::optional<Path>& next, Point* end);
    Point offsetAt(const Path& path, bool atEnd) const; // the tool's centre at an end
    bool tooSmall(const Path& path) const;              // an arc the tool does not fit inside
    ProgramBlock written(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                         BlockKind kind, Point from, Point to, std::optional<Point> centre) const;
    double toProgram(double machine, bool inches) const;

    const machine::MachineDescription& m_d;
    ToolTable m_tools;
    int m_x = -1, m_y = -1; // axis indexes
    int m_activation = 0;   // the G41/G42 being followed (0: none, the tool is on the path)
    CompSide m_side = CompSide::Off;
    double m_radius = 0; // the axes' unit
    bool m_entered = false;
    Point m_programmed;             // LinuxCNC's program_x/y: the programmed point
    Point m_tool;                   // where the tool's centre stands
    Corner m_corner = Corner::None; // at m_programmed, between the last move and the next
};

} // namespace stepdeck::program
