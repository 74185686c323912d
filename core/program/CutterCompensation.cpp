// G41/G42 as LinuxCNC's interpreter computes the tool's path (interp_convert.cc:
// convert_straight_comp1, convert_straight_comp2, convert_arc_comp2; interp_queue.cc:
// move_endpoint_and_flush for inside corners). Everything here is in machine coordinates of X
// and Y (millimetres); blocks go out in the block's own units and coordinates.
#include "CutterCompensation.h"
#include "CompensationGeometry.h"
#include "ProgramUnits.h"
#include <cmath>

namespace stepdeck::program {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
constexpr double kLengthEpsilon = 1e-9; // mm: no travel

} // namespace

using namespace compensation;

CutterCompensation::CutterCompensation(const machine::MachineDescription& d, const ToolTable& tools)
    : m_d(d), m_tools(tools)
{
    for (int i = 0; i < d.axes.size(); ++i) {
        if (d.axes.at(i).name == QLatin1String("X"))
            m_x = i;
        if (d.axes.at(i).name == QLatin1String("Y"))
            m_y = i;
    }
}

QString CutterCompensation::arcEntryRefusal(const ProgramBlock& block)
{
    return tr("%1 enters cutter compensation: the first move after G41/G42 must be a straight "
              "line (G0 or G1)")
        .arg(blockWord(block));
}

bool CutterCompensation::applies(const ProgramBlock& block) const
{
    const bool move = block.kind == BlockKind::Rapid || block.kind == BlockKind::Feed;
    if (block.comp.on())
        return move || isArc(block.kind);
    return move && m_activation != 0;
}

double CutterCompensation::toProgram(double machine, bool inches) const
{
    return machine / units::toAxisUnits(m_d.axes.at(m_x), 1.0, inches);
}

std::optional<CutterCompensation::Error> CutterCompensation::begin(const ProgramBlock& block,
                                                                   const AxisPositions& at)
{
    m_activation = 0;
    const int column = block.actionColumn > 0 ? block.actionColumn : 1;
    if (m_x < 0 || m_y < 0 || m_d.axes.at(m_x).unit != machine::AxisUnit::Millimetre ||
        m_d.axes.at(m_y).unit != machine::AxisUnit::Millimetre)
        return Error{column, tr("cutter compensation needs the axes X and Y in millimetres")};
    if (!at[size_t(m_x)] || !at[size_t(m_y)])
        return Error{column, tr("cutter compensation begins where X or Y is unknown: reference "
                                "them first (G28)")};
    double diameter = 0;
    if (block.comp.diameter) {
        diameter = units::toAxisUnits(m_d.axes.at(m_x), *block.comp.diameter, block.inches);
    } else if (block.comp.tool > 0) {
        const Tool* tool = m_tools.find(block.comp.tool);
        if (!tool)
            return Error{column, tr("cutter compensation: tool %1 is not in the tool table; give "
                                    "its diameter with G41.1/G42.1 D<diameter>")
                                     .arg(block.comp.tool)};
        diameter = tool->diameter;
    }
    m_activation = block.comp.activation;
    m_side = block.comp.side;
    m_radius = diameter / 2;
    m_entered = false;
    m_corner = Corner::None;
    m_tool = m_programmed = Point{*at[size_t(m_x)], *at[size_t(m_y)]};
    return std::nullopt;
}

CutterCompensation::Point CutterCompensation::programmedEnd(const ProgramBlock& block,
                                                            const ProgramCoordinates& coordinates,
                                                            Point from) const
{
    Point end = from;
    for (const auto& [index, value] : {std::pair{m_x, &end.x}, std::pair{m_y, &end.y}}) {
        const machine::MachineAxis& axis = m_d.axes.at(index);
        const auto word = block.axes.constFind(axis.name);
        if (word != block.axes.cend())
            *value = *coordinates.target(block, axis, word.value(), *value);
    }
    return end;
}

std::optional<CutterCompensation::Path>
CutterCompensation::pathOf(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                           const AxisPositions& at, Point from, std::optional<Error>* error) const
{
    Path p;
    p.line = block.line;
    p.start = from;
    if (!isArc(block.kind)) {
        p.end = programmedEnd(block, coordinates, from);
        if (length(p.end - p.start) < kLengthEpsilon)
            return std::nullopt;
        return p;
    }
    AxisPositions start = at;
    for (std::optional<double>& a : start)
        a = a.value_or(0.0); // only X and Y are read here: a helix' start matters not
    start[size_t(m_x)] = from.x;
    start[size_t(m_y)] = from.y;
    const auto planned = ArcPath::plan(block, m_d, start, coordinates.offsets(block, m_d));
    if (const ArcPath::Error* e = std::get_if<ArcPath::Error>(&planned)) {
        *error = Error{e->column, e->message};
        return std::nullopt;
    }
    const ArcPath::Shape s = std::get<ArcPath>(planned).shape();
    p.arc = true;
    p.centre = {s.centre[0], s.centre[1]};
    p.end = {s.end[0], s.end[1]};
    p.sweep = s.sweep;
    return p;
}

std::optional<CutterCompensation::Path>
CutterCompensation::nextPath(const Following& following, const ProgramCoordinates& coordinates,
                             const AxisPositions& at, Point from) const
{
    while (const ProgramBlock* b = following()) {
        if (b->comp.activation != m_activation || !b->comp.on())
            return std::nullopt; // G40, or a new G41/G42: the path ends here
        const bool move = b->kind == BlockKind::Rapid || b->kind == BlockKind::Feed;
        if (move || isArc(b->kind)) {
            std::optional<Error> error;
            if (std::optional<Path> p = pathOf(*b, coordinates, at, from, &error))
                return p;
            if (error)
                return std::nullopt; // the arc is refused when it is lowered
            continue;                // no X or Y travel: the corner is with the move after it
        }
        switch (b->kind) {
        case BlockKind::End:
        case BlockKind::RepeatStart:
        case BlockKind::RepeatEnd:
        case BlockKind::Home:
        case BlockKind::DrillCycle:
            return std::nullopt;
        default:
            continue; // switches, dwells, pauses, messages, modal words
        }
    }
    return std::nullopt;
}

bool CutterCompensation::tooSmall(const Path& path) const
{
    // The tool runs inside an arc where it is on the side the arc turns to.
    const bool inside = (m_side == CompSide::Left) == (path.sweep > 0);
    return path.arc && inside && length(path.start - path.centre) <= m_radius;
}

CutterCompensation::Point CutterCompensation::offsetAt(const Path& path, bool atEnd) const
{
    const Point n = left(tangentAt(path, atEnd));
    const double r = m_side == CompSide::Left ? m_radius : -m_radius;
    return (atEnd ? path.end : path.start) + r * n;
}

std::optional<CutterCompensation::Error>
CutterCompensation::endOf(const Path& move, Point lineFrom, Point toolStart, Point nominalEnd,
                          const std::optional<Path>& next, Point* end)
{
    *end = nominalEnd;
    m_corner = Corner::None;
    if (!next)
        return std::nullopt;
    // The tool's direction at the end: square to the radius from the programmed point to it
    // (LinuxCNC's theta), which holds for the entry move's tangent line too.
    const double sign = m_side == CompSide::Left ? 1.0 : -1.0;
    const Point normal = (sign / m_radius) * (nominalEnd - move.end);
    const Point t1 = Point{normal.y, -normal.x};
    const Point t2 = tangentAt(*next, false);
    const double turn = std::atan2(cross(t1, t2), dot(t1, t2)); // + left
    if (std::fabs(turn) < kSmallCorner)
        return std::nullopt;
    const bool towardTool = m_side == CompSide::Left ? turn > 0 : turn < 0;
    if (!towardTool || std::fabs(turn) > kPi - kSmallCorner) {
        m_corner = Corner::Outside;
        return std::nullopt;
    }
    // Inside: where this move's tool path meets the next one's.
    Geometry g1, g2;
    g1.circle = move.arc;
    g1.a = lineFrom;
    g1.b = nominalEnd;
    g1.centre = move.centre;
    g1.radius = length(nominalEnd - move.centre);
    const Point nextStart = offsetAt(*next, false);
    const Point nextEnd = offsetAt(*next, true);
    g2.circle = next->arc;
    g2.a = nextStart;
    g2.b = nextEnd;
    g2.centre = next->centre;
    g2.radius = length(nextStart - next->centre);
    if (tooSmall(*next))
        return std::nullopt; // refused when it comes
    const std::vector<Point> candidates = intersections(g1, g2);
    const Point* best = nullptr;
    for (const Point& c : candidates)
        if (!best || length(c - nominalEnd) < length(*best - nominalEnd))
            best = &c;
    const double diameter = 2 * m_radius;
    const auto gouges = [&] {
        return Error{1, tr("cutter compensation: the tool (diameter %1) cannot reach the inside "
                           "corner of lines %2 and %3 without cutting into the part")
                            .arg(figure(diameter))
                            .arg(move.line)
                            .arg(next->line)};
    };
    if (!best)
        return gouges();
    const double onMove = along(g1, move, toolStart, *best);
    const double onNext = along(g2, *next, nextStart, *best);
    const bool beforeStart =
        move.arc ? onMove <= 0 || onMove > std::fabs(move.sweep) + 1e-9 : onMove <= 0;
    const bool pastEnd =
        next->arc ? onNext >= std::fabs(next->sweep) && onNext < kTwoPi - 1e-9 : onNext >= 1;
    if (beforeStart || pastEnd)
        return gouges();
    *end = *best;
    m_corner = Corner::Inside;
    return std::nullopt;
}

ProgramBlock CutterCompensation::written(const ProgramBlock& block,
                                         const ProgramCoordinates& coordinates, BlockKind kind,
                                         Point from, Point to, std::optional<Point> centre) const
{
    ProgramBlock out = block;
    out.kind = kind;
    const machine::MachineAxis& x = m_d.axes.at(m_x);
    const machine::MachineAxis& y = m_d.axes.at(m_y);
    const auto word = [&](const machine::MachineAxis& axis, double target, double start) {
        return toProgram(block.relative ? target - start
                                        : target - coordinates.offset(block, axis.name),
                         block.inches);
    };
    out.axes.insert(x.name, word(x, to.x, from.x));
    out.axes.insert(y.name, word(y, to.y, from.y));
    if (centre) {
        ArcWords arc;
        arc.centreAbsolute = block.arc.centreAbsolute;
        arc.turns = isArc(block.kind) ? block.arc.turns : 1;
        arc.i = toProgram(arc.centreAbsolute ? centre->x - coordinates.offset(block, x.name)
                                             : centre->x - from.x,
                          block.inches);
        arc.j = toProgram(arc.centreAbsolute ? centre->y - coordinates.offset(block, y.name)
                                             : centre->y - from.y,
                          block.inches);
        out.arc = arc;
    }
    return out;
}

std::optional<CutterCompensation::Error>
CutterCompensation::lower(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                          const AxisPositions& at, const Following& following,
                          std::vector<ProgramBlock>* out)
{
    const int column = block.actionColumn > 0 ? block.actionColumn : 1;
    if (!block.comp.on()) { // the first move after G40: from the tool to the programmed end
        const Point end = programmedEnd(block, coordinates, m_programmed);
        out->push_back(written(block, coordinates, block.kind, m_tool, end, std::nullopt));
        m_activation = 0;
        return std::nullopt;
    }
    if (block.comp.activation != m_activation) {
        // G40 then G41/G42 with no move between: the tool still stands off the path, but the
        // program goes on from its programmed point (LinuxCNC's current point after G40).
        const bool offPath = m_activation != 0;
        const Point programmed = m_programmed;
        if (std::optional<Error> e = begin(block, at))
            return e;
        if (offPath)
            m_programmed = programmed;
    }
    std::optional<Error> error;
    const std::optional<Path> path = pathOf(block, coordinates, at, m_programmed, &error);
    if (error)
        return error;
    if (!path || m_radius <= 0) { // no X or Y travel, or nothing to compensate by
        if (path) {
            out->push_back(block);
            m_tool = m_programmed = path->end;
        } else if (block.axes.contains(m_d.axes.at(m_x).name) ||
                   block.axes.contains(m_d.axes.at(m_y).name)) {
            out->push_back(written(block, coordinates, block.kind, m_tool, m_tool, std::nullopt));
        } else {
            out->push_back(block);
        }
        return std::nullopt;
    }
    Point toolStart = m_tool;
    Point lineFrom = m_tool; // a line's tool path runs through it and nominalEnd
    Point nominalEnd;
    bool rounded = false; // a corner's arc goes first
    if (!m_entered) {
        // The entry (convert_straight_comp1): to where a line from the tool touches the circle
        // of the tool's radius about the programmed end.
        if (path->arc)
            return Error{column, arcEntryRefusal(block)};
        // From the programmed point (the tool's, but after a G40 with no move since).
        const double distance = length(path->end - m_programmed);
        if (distance <= m_radius)
            return Error{column, tr("cutter compensation: the entry move (%1) is not longer "
                                    "than the tool's radius (%2), as LinuxCNC requires")
                                     .arg(figure(distance))
                                     .arg(figure(m_radius))};
        const double theta = std::acos(m_radius / distance);
        const Point back = m_programmed - path->end;
        const double alpha =
            std::atan2(back.y, back.x) + (m_side == CompSide::Left ? -theta : theta);
        nominalEnd = path->end + m_radius * Point{std::cos(alpha), std::sin(alpha)};
        m_entered = true;
    } else {
        const Point nominalStart = offsetAt(*path, false);
        nominalEnd = offsetAt(*path, true);
        if (block.kind != BlockKind::Rapid || m_corner != Corner::Outside)
            lineFrom = nominalStart; // parallel to the programmed line (a G0 cuts a corner)
        if (tooSmall(*path))
            return Error{column, tr("cutter compensation: the tool's radius (%1) is not less "
                                    "than the arc's (%2): the tool does not fit inside it, as "
                                    "LinuxCNC refuses")
                                     .arg(figure(m_radius))
                                     .arg(figure(length(path->start - path->centre)))};
        if (m_corner == Corner::Outside && block.kind != BlockKind::Rapid) {
            // Round the corner on an arc of the tool's radius about the programmed point; the
            // move's Z travels on the move itself (LinuxCNC).
            ProgramBlock xyOnly = block;
            xyOnly.axes.clear();
            xyOnly.axisRates.clear();
            out->push_back(written(xyOnly, coordinates,
                                   m_side == CompSide::Left ? BlockKind::ArcClockwise
                                                            : BlockKind::ArcCounterClockwise,
                                   m_tool, nominalStart, path->start));
            toolStart = nominalStart;
            rounded = true;
        }
    }
    const std::optional<Path> next = nextPath(following, coordinates, at, path->end);
    Point end;
    if (std::optional<Error> e = endOf(*path, lineFrom, toolStart, nominalEnd, next, &end))
        return e;
    ProgramBlock move = written(block, coordinates, block.kind, toolStart, end,
                                path->arc ? std::optional<Point>(path->centre) : std::nullopt);
    if (rounded) { // after the corner's arc: the line's switches and message went with it
        move.spindleChange = false;
        move.message.clear();
    }
    out->push_back(std::move(move));
    m_tool = end;
    m_programmed = path->end;
    return std::nullopt;
}

} // namespace stepdeck::program
