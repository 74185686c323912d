#include "ContourMoves.h"
#include "ProgramUnits.h"
#include <cmath>

namespace stepdeck::program {

ContourMoves::ContourMoves(const MachineFacts& facts)
    : m_facts(facts),
      m_streams(motion::StreamExecutor::streamsOf(facts.description, facts.capabilities,
                                                  facts.schemas, facts.knownParameters)),
      m_streamOfAxis(size_t(facts.description.axes.size()), -1),
      m_slotOfAxis(size_t(facts.description.axes.size()), -1)
{
    for (size_t s = 0; s < m_streams.size(); ++s)
        for (int slot = 0; slot < m_streams[s].scale.axisCount; ++slot)
            if (const int axis = m_streams[s].axisOfSlot[size_t(slot)]; axis >= 0) {
                m_streamOfAxis[size_t(axis)] = int(s);
                m_slotOfAxis[size_t(axis)] = slot;
            }
}

int ContourMoves::slotOf(const QString& axisName) const
{
    const int i = m_facts.description.axisIndex(axisName);
    return i < 0 ? -1 : m_slotOfAxis[size_t(i)];
}

const ContourMoves::Stream* ContourMoves::streamOf(const ProgramBlock& block) const
{
    const bool arc =
        block.kind == BlockKind::ArcClockwise || block.kind == BlockKind::ArcCounterClockwise;
    if ((block.kind != BlockKind::Feed && !arc) || !block.feed || block.inverseTime ||
        block.pathMode != PathMode::Blend || m_streams.empty())
        return nullptr;
    int stream = -1;
    const machine::MachineAxis* first = nullptr;
    // False: the block runs on its own (an axis without a stream, axes of two controllers
    // whose parts run apart, millimetres and degrees without one path speed).
    const auto joins = [&](const QString& name) {
        const int i = m_facts.description.axisIndex(name);
        if (i < 0 || m_streamOfAxis[size_t(i)] < 0 ||
            (stream >= 0 && m_streamOfAxis[size_t(i)] != stream))
            return false;
        stream = m_streamOfAxis[size_t(i)];
        const machine::MachineAxis& axis = m_facts.description.axes.at(i);
        if (first && axis.unit != first->unit)
            return false;
        first = &axis;
        return true;
    };
    if (arc) {
        for (const QString& name : ArcPath::movingAxes(block))
            if (!joins(name))
                return nullptr;
    } else {
        for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it)
            if (!joins(it.key()))
                return nullptr;
    }
    return stream < 0 ? nullptr : &m_streams[size_t(stream)];
}

double ContourMoves::feedPerSecond(const Stream& stream, const ProgramBlock& block) const
{
    for (int i = 0; i < stream.scale.axisCount; ++i)
        if (const int a = stream.axisOfSlot[size_t(i)]; a >= 0 && block.feed)
            return units::toAxisUnits(m_facts.description.axes.at(a), *block.feed, block.inches) /
                   60.0;
    return 0;
}

motion::Position ContourMoves::positionOf(const Stream& stream, const AxisPositions& current) const
{
    motion::Position p{};
    for (int i = 0; i < stream.scale.axisCount; ++i)
        if (const int a = stream.axisOfSlot[size_t(i)]; a >= 0 && size_t(a) < current.size())
            p[size_t(i)] = current[size_t(a)].value_or(0.0);
    return p;
}

motion::CanonicalMove ContourMoves::startMove(const Stream& stream, const ProgramBlock& block,
                                              const motion::Position& from) const
{
    motion::CanonicalMove move;
    move.kind = motion::CanonicalMove::Kind::Line;
    move.line = block.line;
    move.axisCount = stream.scale.axisCount;
    move.start = from;
    move.end = from;
    move.feed = feedPerSecond(stream, block);
    move.pathMode = motion::PathMode::Blend;
    return move;
}

motion::CanonicalMove ContourMoves::arcMove(const Stream& stream, const ProgramBlock& block,
                                            const ArcPath& path, const motion::Position& from) const
{
    motion::CanonicalMove move = startMove(stream, block, from);
    const ArcPath::Shape shape = path.shape();
    motion::ArcGeometry g;
    for (int p = 0; p < 2; ++p) {
        g.plane[p] = m_slotOfAxis[size_t(shape.axis[p])];
        g.centre[p] = shape.centre[p];
        move.end[size_t(g.plane[p])] = shape.end[p];
    }
    g.startRadius = shape.startRadius;
    g.endRadius = shape.endRadius;
    g.startAngle = shape.startAngle;
    g.sweep = shape.sweep;
    if (shape.helix >= 0)
        move.end[size_t(m_slotOfAxis[size_t(shape.helix)])] = shape.helixEnd;
    move.kind = motion::CanonicalMove::Kind::Arc;
    move.arc = g;
    return move;
}

QString ContourMoves::feedRefusal(const Stream& stream, const motion::CanonicalMove& move,
                                  const ProgramBlock& block) const
{
    if (stream.tickRate <= 0 || move.length() <= 0 || !block.feed || *block.feed <= 0)
        return {};
    const double needed = motion::ContourSteps::neededTickRate(move, stream.scale);
    if (needed <= stream.tickRate)
        return {};
    // The highest feed in the program's own terms (per minute, G20 in inches).
    const double perProgramUnit = move.feed / *block.feed;
    const double highest =
        motion::ContourSteps::highestFeed(move, stream.scale, stream.tickRate) / perProgramUnit;
    return tr("F%1 is too fast for the contour stream of controller \"%2\": at its %3 ticks/s "
              "(one step per tick at most) this move's highest feed is F%4")
        .arg(figure(*block.feed), stream.controller)
        .arg(stream.tickRate)
        .arg(figure(std::floor(highest * 10) / 10)); // rounded down: that F runs
}

} // namespace stepdeck::program
