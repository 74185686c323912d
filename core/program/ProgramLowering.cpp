// A block lowered to motion commands (issue 49 item 2; LinuxCNC's interpreter -> canonical
// calls). docs/architecture.md "One motion path".
#include "ProgramLowering.h"
#include "DrillCycle.h"
#include "ProgramUnits.h"

namespace stepdeck::program {

using namespace stepdeck::motion;

namespace {
// Whether a block's action comes after plane, units, tool length and coordinate system in
// LinuxCNC's order of execution (docs/programs.md, steps 15-22: before G10, G92, G28, motion
// and the stops, steps 23-25), or before them (outputs, M6, spindle, coolant, dwell: 7-14).
bool dependsOnFrame(BlockKind kind)
{
    switch (kind) {
    case BlockKind::ToolChange:
    case BlockKind::SpindleOn:
    case BlockKind::SpindleReverse:
    case BlockKind::SpindleOff:
    case BlockKind::SpindleSpeed:
    case BlockKind::CoolantMist:
    case BlockKind::CoolantFlood:
    case BlockKind::CoolantOff:
    case BlockKind::OutputOn:
    case BlockKind::OutputOff:
    case BlockKind::WaitInput:
    case BlockKind::Dwell:
        return false;
    default:
        return true;
    }
}
} // namespace

ProgramLowering::ProgramLowering(const machine::MachineDescription& d) : m_d(d)
{
    m_toolAxis = d.axisIndex(ProgramCoordinates::toolAxis());
}

std::optional<ProgramLowering::Error> ProgramLowering::lower(const ProgramBlock& block,
                                                             const ProgramCoordinates& coordinates,
                                                             const AxisPositions& at,
                                                             std::vector<MotionCommand>* out)
{
    if (block.kind == BlockKind::RepeatStart || block.kind == BlockKind::RepeatEnd)
        return std::nullopt; // the walk counts repeats out; they command nothing
    const Frame frame{block.line, block.inches, block.plane, offsetsOf(block, coordinates)};
    if (!m_inches) {
        // The program's first block: the units and plane it starts in, first (as rs274 tells
        // them before anything); its offsets in the line's order below.
        lowerFrame(frame, out, false);
    } else if (m_pending && m_pending->line != block.line) {
        lowerFrame(*m_pending, out); // the line before ended: its frame holds from here
        m_pending.reset();
    }
    // LinuxCNC's order of execution (docs/programs.md): the message (2), feed (3, 4), S (5),
    // then the action.
    if (!block.message.isEmpty())
        out->push_back(Message{block.line, block.message});
    lowerFeed(block, out);
    if (block.spindleChange)
        out->push_back(SpindleSpeed{block.line, block.rpm});
    if (dependsOnFrame(block.kind)) {
        lowerFrame(frame, out);
        m_pending.reset();
    } else {
        m_pending = frame;
    }
    switch (block.kind) {
    case BlockKind::Rapid:
    case BlockKind::Feed:
        if (block.axes.isEmpty())
            return std::nullopt; // "G0" alone only sets the motion mode
        if (block.kind == BlockKind::Rapid)
            out->push_back(Traverse{block.line, moveEnd(block, coordinates, at)});
        else
            out->push_back(StraightFeed{block.line, moveEnd(block, coordinates, at)});
        return std::nullopt;
    case BlockKind::ArcClockwise:
    case BlockKind::ArcCounterClockwise:
        return lowerArc(block, coordinates, at, out);
    case BlockKind::DrillCycle:
        return lowerCycle(block, coordinates, at, out);
    case BlockKind::Home: {
        Reference reference{block.line, {}};
        for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it)
            if (const int i = m_d.axisIndex(it.key()); i >= 0)
                reference.axes << i;
        out->push_back(reference);
        return std::nullopt;
    }
    case BlockKind::Dwell:
        out->push_back(Dwell{block.line, block.seconds});
        return std::nullopt;
    case BlockKind::Pause:
        out->push_back(Pause{block.line, Pause::Kind::Stop, 0, block.prompt});
        return std::nullopt;
    case BlockKind::OptionalPause:
        out->push_back(Pause{block.line, Pause::Kind::OptionalStop, 0, block.prompt});
        return std::nullopt;
    case BlockKind::ToolChange:
        out->push_back(Pause{block.line, Pause::Kind::ToolChange, block.number, block.prompt});
        return std::nullopt;
    case BlockKind::End:
        // The program's end switches the spindle and the coolant off, as LinuxCNC's M2/M30 do
        // and as the run does (issue 47 item 1).
        out->push_back(SpindleOff{block.line});
        out->push_back(Coolant{block.line, Coolant::Kind::Off});
        out->push_back(ProgramEnd{block.line});
        return std::nullopt;
    default:
        lowerSwitch(block, out);
        return std::nullopt;
    }
}

// Spindle, coolant, outputs and inputs: one command each. G10 and the G92 family command
// nothing of their own: their offsets are the frame (lowerFrame).
void ProgramLowering::lowerSwitch(const ProgramBlock& block, std::vector<MotionCommand>* out) const
{
    // Modal, SpindleSpeed (told above), G10, G92...: nothing beyond the frame.
    if (std::optional<MotionCommand> command = switchCommand(block))
        out->push_back(std::move(*command));
}

std::optional<MotionCommand> ProgramLowering::switchCommand(const ProgramBlock& block)
{
    switch (block.kind) {
    case BlockKind::SpindleOn:
    case BlockKind::SpindleReverse:
        return SpindleOn{block.line, block.rpm, block.kind == BlockKind::SpindleReverse};
    case BlockKind::SpindleOff:
        return SpindleOff{block.line};
    case BlockKind::CoolantMist:
        return Coolant{block.line, Coolant::Kind::Mist};
    case BlockKind::CoolantFlood:
        return Coolant{block.line, Coolant::Kind::Flood};
    case BlockKind::CoolantOff:
        return Coolant{block.line, Coolant::Kind::Off};
    case BlockKind::OutputOn:
    case BlockKind::OutputOff:
        return Output{block.line, block.number, block.kind == BlockKind::OutputOn};
    case BlockKind::WaitInput:
        return WaitInput{block.line, block.number, block.inputHigh, block.seconds};
    default:
        return std::nullopt;
    }
}

std::optional<MotionCommand> ProgramLowering::speedChange(const ProgramBlock& block)
{
    if (!block.spindleChange || isSpindleSwitch(block.kind))
        return std::nullopt;
    return SpindleSpeed{block.line, block.rpm};
}

motion::RatedMove ProgramLowering::ratedMove(const ProgramBlock& block,
                                             const machine::MachineDescription& d)
{
    motion::RatedMove move;
    move.line = block.line;
    move.feed = block.kind == BlockKind::Feed;
    move.inverseTime = block.inverseTime;
    if (!move.feed || !block.feed)
        return move;
    // The same figures units::feedStepsPerSecond takes: F per minute in the program's unit.
    for (auto it = block.axisRates.cbegin(); it != block.axisRates.cend(); ++it)
        if (const int a = d.axisIndex(it.key()); a >= 0)
            move.speeds.push_back(
                {a, units::toAxisUnits(d.axes.at(a), it.value(), false) / 60.0, true});
    if (block.inverseTime)
        return move; // G93: an axis without a resolved rate does not move
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it)
        if (const int a = d.axisIndex(it.key()); a >= 0 && !block.axisRates.contains(it.key()))
            move.speeds.push_back(
                {a, units::toAxisUnits(d.axes.at(a), *block.feed, block.inches) / 60.0, false});
    return move;
}

// The feed mode and rate: LinuxCNC sets them first on a line (its order of execution, 2 and 3).
void ProgramLowering::lowerFeed(const ProgramBlock& block, std::vector<MotionCommand>* out)
{
    if (!block.feed)
        return;
    const std::pair<double, bool> feed{*block.feed, block.inverseTime};
    if (m_feed != feed) {
        m_feed = feed;
        out->push_back(FeedRate{block.line, feed.first, feed.second});
    }
}

// The frame commands that changed.
void ProgramLowering::lowerFrame(const Frame& frame, std::vector<MotionCommand>* out, bool offsets)
{
    if (m_inches != frame.inches) {
        m_inches = frame.inches;
        out->push_back(LengthUnits{frame.line, frame.inches});
    }
    if (m_plane != frame.plane) {
        m_plane = frame.plane;
        out->push_back(SelectPlane{frame.line, SelectPlane::Plane(frame.plane)});
    }
    const Offsets& o = frame.offsets;
    if (offsets &&
        (!m_offsets || m_offsets->system != o.system || m_offsets->workOffset != o.workOffset ||
         m_offsets->axisOffset != o.axisOffset || m_offsets->tool != o.tool ||
         m_offsets->toolLength != o.toolLength)) {
        m_offsets = o;
        out->push_back(o);
    }
}

// The frame of the block's words: its system's offsets, G92's where applied and the tool
// length, whether or not the block itself is in machine coordinates (G53 names its target
// without them, the frame stays).
Offsets ProgramLowering::offsetsOf(const ProgramBlock& block,
                                   const ProgramCoordinates& coordinates) const
{
    Offsets o;
    o.line = block.line;
    o.system = coordinates.systemOf(block);
    o.workOffset.assign(size_t(m_d.axes.size()), 0.0);
    o.axisOffset.assign(size_t(m_d.axes.size()), 0.0);
    const QMap<QString, double>& system = coordinates.systems()[size_t(o.system)];
    const QMap<QString, double> axisOffset = coordinates.axisOffset();
    for (int i = 0; i < m_d.axes.size(); ++i) {
        const QString& name = m_d.axes.at(i).name;
        o.workOffset[size_t(i)] = system.value(name, 0.0);
        if (coordinates.axisOffsetApplied())
            o.axisOffset[size_t(i)] = axisOffset.value(name, 0.0);
    }
    if (m_toolAxis >= 0 && block.lengthTool > 0) {
        o.tool = block.lengthTool;
        o.toolLength = coordinates.toolLength(block);
        o.toolAxis = m_toolAxis;
    }
    return o;
}

// G0/G1: the axes it names at their targets (ProgramCoordinates::target), the others where
// they stand.
MachinePoint ProgramLowering::moveEnd(const ProgramBlock& block,
                                      const ProgramCoordinates& coordinates,
                                      const AxisPositions& at) const
{
    MachinePoint end = at;
    end.resize(size_t(m_d.axes.size()));
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        const int i = m_d.axisIndex(it.key());
        if (i >= 0)
            end[size_t(i)] = coordinates.target(block, m_d.axes.at(i), it.value(), end[size_t(i)]);
    }
    return end;
}

std::optional<ProgramLowering::Error>
ProgramLowering::lowerArc(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                          const AxisPositions& at, std::vector<MotionCommand>* out) const
{
    const auto planned = ArcPath::plan(block, m_d, at, coordinates.offsets(block, m_d));
    if (const auto* error = std::get_if<ArcPath::Error>(&planned))
        return Error{error->column, error->message};
    const ArcPath::Shape shape = std::get<ArcPath>(planned).shape();
    ArcFeed arc;
    arc.line = block.line;
    arc.end = at;
    arc.end.resize(size_t(m_d.axes.size()));
    for (int k = 0; k < 2; ++k) {
        arc.axes[k] = shape.axis[k];
        arc.centre[k] = shape.centre[k];
        arc.end[size_t(shape.axis[k])] = shape.end[k];
    }
    if (shape.helix >= 0)
        arc.end[size_t(shape.helix)] = shape.helixEnd;
    const int turns = std::max(1, block.arc.turns);
    arc.rotation = block.kind == BlockKind::ArcCounterClockwise ? turns : -turns;
    out->push_back(std::move(arc));
    return std::nullopt;
}

// A drilling cycle: its rapids, feeds and dwells (DrillCycle), as LinuxCNC's interpreter
// expands G81..G83 and G73 into STRAIGHT_TRAVERSE, STRAIGHT_FEED and DWELL.
std::optional<ProgramLowering::Error>
ProgramLowering::lowerCycle(const ProgramBlock& block, const ProgramCoordinates& coordinates,
                            const AxisPositions& at, std::vector<MotionCommand>* out) const
{
    const auto planned = DrillCycle::plan(block, m_d, at, coordinates.offsets(block, m_d));
    if (const auto* error = std::get_if<DrillCycle::Error>(&planned))
        return Error{error->column, error->message};
    MachinePoint here = at;
    here.resize(size_t(m_d.axes.size()));
    for (const DrillCycle::Segment& s : std::get<DrillCycle>(planned).segments()) {
        if (s.kind == DrillCycle::Kind::Dwell) {
            out->push_back(Dwell{block.line, s.seconds});
            continue;
        }
        for (const auto& [axis, position] : s.targets)
            here[size_t(axis)] = position;
        if (s.kind == DrillCycle::Kind::Rapid)
            out->push_back(Traverse{block.line, here});
        else
            out->push_back(StraightFeed{block.line, here});
    }
    return std::nullopt;
}

} // namespace stepdeck::program
