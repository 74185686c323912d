#include "DrillCycle.h"
#include "ProgramUnits.h"
#include <cmath>

namespace stepdeck::program {

namespace {

const char* const kAxisNames[3] = {"X", "Y", "Z"};

int axisIndexOf(const machine::MachineDescription& d, const QString& name)
{
    for (int i = 0; i < d.axes.size(); ++i)
        if (d.axes.at(i).name == name)
            return i;
    return -1;
}

} // namespace

double DrillCycle::peckClearance(const machine::MachineAxis& z)
{
    return z.unit == machine::AxisUnit::Millimetre ? 0.010 * units::kMillimetresPerInch : 1.0;
}

ProgramBlock DrillCycle::rateBlock(const ProgramBlock& block, Kind kind,
                                   const machine::MachineDescription& d)
{
    ProgramBlock rates = block;
    rates.kind = kind == Kind::Feed ? BlockKind::Feed : BlockKind::Rapid;
    rates.axes.clear();
    for (int a = kind == Kind::Feed ? 2 : 0; a < 3; ++a)
        if (axisIndexOf(d, QLatin1String(kAxisNames[a])) >= 0)
            rates.axes.insert(QLatin1String(kAxisNames[a]), 0.0);
    return rates;
}

ProgramBlock DrillCycle::segmentBlock(const ProgramBlock& block, const Segment& segment,
                                      const machine::MachineDescription& d)
{
    ProgramBlock rates = block;
    rates.kind = segment.kind == Kind::Feed ? BlockKind::Feed : BlockKind::Rapid;
    rates.axes.clear();
    for (const auto& [axis, value] : segment.targets)
        rates.axes.insert(d.axes.at(axis).name, value);
    return rates;
}

std::variant<DrillCycle, DrillCycle::Error>
DrillCycle::plan(const ProgramBlock& block, const machine::MachineDescription& d,
                 const AxisPositions& start, const QMap<QString, double>& workOffsets)
{
    const QString g = blockWord(block);
    const int column = block.columnOf({});
    const CycleWords& c = block.cycle;
    DrillCycle cycle;
    for (int a = 0; a < 3; ++a) {
        const QString name = QLatin1String(kAxisNames[a]);
        cycle.m_axis[a] = axisIndexOf(d, name);
        if (cycle.m_axis[a] < 0)
            continue;
        cycle.m_position[a] = start.at(size_t(cycle.m_axis[a]));
        if (!cycle.m_position[a])
            return Error{block.columnOf(name),
                         tr("%1: the position of %2 is unknown, so the cycle has no start: "
                            "reference the axis first (G28 %2)")
                             .arg(g, name)};
    }
    if (cycle.m_axis[2] < 0)
        return Error{column, tr("%1: the machine has no axis Z, which a drilling cycle drills "
                                "along")
                                 .arg(g)};
    const machine::MachineAxis& zAxis = d.axes.at(cycle.m_axis[2]);
    const auto z = [&](double v) { return units::toAxisUnits(zAxis, v, block.inches); };
    const double z0 = *cycle.m_position[2];
    const double r = block.relative ? z0 + z(c.r) : z(c.r) + workOffsets.value(QStringLiteral("Z"));
    const double bottom =
        block.relative ? r + z(c.bottom) : z(c.bottom) + workOffsets.value(QStringLiteral("Z"));
    const double peck = z(c.peck);
    // Segments per hole: a peck takes up to three; bounded before any is made.
    const double pecks = peck > 0 ? std::ceil((r - bottom) / peck) : 1.0;
    if (double(c.repeats) * (3.0 * pecks + 4.0) > kMaxSegments)
        return Error{
            block.columnOf(peck > 0 ? QStringLiteral("Q") : QStringLiteral("L")),
            tr("%1 takes more than %2 moves: make Q larger or L smaller").arg(g).arg(kMaxSegments)};
    const double clearance = c.retractToR ? r : std::max(r, z0);
    if (z0 < r)
        cycle.moveTo(Kind::Rapid, {{cycle.m_axis[2], r}}); // LinuxCNC's preliminary motion
    for (int repeat = 0; repeat < c.repeats; ++repeat) {
        QList<std::pair<int, double>> xy;
        for (int a = 0; a < 2; ++a) {
            const QString name = QLatin1String(kAxisNames[a]);
            if (cycle.m_axis[a] < 0 || !block.axes.contains(name))
                continue;
            const machine::MachineAxis& axis = d.axes.at(cycle.m_axis[a]);
            xy << std::pair{cycle.m_axis[a],
                            *units::wordTarget(axis, block.axes.value(name), block.inches,
                                               block.relative, workOffsets.value(name),
                                               cycle.m_position[a])};
        }
        cycle.moveTo(Kind::Rapid, xy);
        cycle.moveTo(Kind::Rapid, {{cycle.m_axis[2], r}});
        cycle.drill(c, r, bottom, peck, peckClearance(zAxis));
        cycle.moveTo(Kind::Rapid, {{cycle.m_axis[2], clearance}});
    }
    return cycle;
}

// A move to targets, left out when it moves nothing.
void DrillCycle::moveTo(Kind kind, const QList<std::pair<int, double>>& targets)
{
    Segment s;
    s.kind = kind;
    for (const auto& [axis, value] : targets) {
        for (int a = 0; a < 3; ++a) {
            if (m_axis[a] != axis || m_position[a] == value)
                continue;
            m_position[a] = value;
            s.targets << std::pair{axis, value};
        }
    }
    if (!s.targets.isEmpty())
        m_segments.push_back(s);
}

// One hole's way down from R (where Z stands) to the bottom and its dwell.
void DrillCycle::drill(const CycleWords& c, double r, double bottom, double peck, double clearance)
{
    const int z = m_axis[2];
    if (c.code == 81 || c.code == 82) {
        moveTo(Kind::Feed, {{z, bottom}});
        if (c.code == 82 && c.dwell > 0)
            m_segments.push_back(Segment{Kind::Dwell, {}, c.dwell});
        return;
    }
    double depth = r;
    while (depth > bottom) {
        double next = std::max(bottom, depth - peck);
        if (next >= depth) // Q below the resolution of a double at this depth (R far beyond any
            next = bottom; // soft limit): one feed to the bottom instead of a peck that never ends

        if (c.code == 83 && depth < r && depth + clearance < r)
            moveTo(Kind::Rapid, {{z, depth + clearance}}); // back down, short of the chips
        moveTo(Kind::Feed, {{z, next}});
        depth = next;
        if (depth <= bottom)
            break;
        moveTo(Kind::Rapid, {{z, c.code == 83 ? r : std::min(r, depth + clearance)}});
    }
}

QList<std::pair<int, double>> DrillCycle::end() const
{
    QList<std::pair<int, double>> out;
    for (int a = 0; a < 3; ++a)
        if (m_axis[a] >= 0)
            out << std::pair{m_axis[a], *m_position[a]};
    return out;
}

} // namespace stepdeck::program
