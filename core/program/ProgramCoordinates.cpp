// G54..G59, G10 L2/L20, G53 and the G92 family as LinuxCNC's interpreter applies them
// (docs/programs.md "Coordinates").
#include "ProgramCoordinates.h"
#include "ProgramUnits.h"

namespace stepdeck::program {

QString coordinateSystemWord(int index)
{
    return QStringLiteral("G%1").arg(54 + index);
}

ProgramCoordinates::ProgramCoordinates(const CoordinateSystems& systems, int active,
                                       const ToolTable& tools)
    : m_systems(systems), m_active(active >= 0 && active < kCoordinateSystems ? active : 0),
      m_tools(tools)
{}

int ProgramCoordinates::systemOf(const ProgramBlock& block) const
{
    return block.coordinateSystem >= 0 && block.coordinateSystem < kCoordinateSystems
               ? block.coordinateSystem
               : m_active;
}

double ProgramCoordinates::offset(const ProgramBlock& block, const QString& axis) const
{
    if (block.machineCoordinates)
        return 0.0;
    double offset = m_systems[size_t(systemOf(block))].value(axis, 0.0);
    if (m_axisOffsetApplied)
        offset += m_axisOffset.value(axis, 0.0);
    if (axis == toolAxis())
        offset += toolLength(block); // a longer tool stands higher: Z goes up by its length
    return offset;
}

double ProgramCoordinates::toolLength(const ProgramBlock& block) const
{
    if (block.lengthTool > 0)
        if (const Tool* tool = m_tools.find(block.lengthTool))
            return tool->length;
    return 0.0;
}

std::optional<double> ProgramCoordinates::target(const ProgramBlock& block,
                                                 const machine::MachineAxis& axis, double word,
                                                 std::optional<double> at) const
{
    return units::wordTarget(axis, word, block.inches, block.relative,
                             block.relative ? 0.0 : offset(block, axis.name), at);
}

QMap<QString, double> ProgramCoordinates::offsets(const ProgramBlock& block,
                                                  const machine::MachineDescription& d) const
{
    QMap<QString, double> out;
    for (const machine::MachineAxis& axis : d.axes)
        if (const double o = offset(block, axis.name); o != 0.0)
            out.insert(axis.name, o);
    return out;
}

void ProgramCoordinates::advance(const ProgramBlock& block, const machine::MachineDescription& d,
                                 AxisPositions* positions) const
{
    if (block.kind == BlockKind::Home) {
        for (int i = 0; i < d.axes.size(); ++i)
            if (block.axes.isEmpty() || block.axes.contains(d.axes.at(i).name))
                (*positions)[size_t(i)] = 0.0; // a reference run ends at 0 on every model
        return;
    }
    if (block.kind != BlockKind::Rapid && block.kind != BlockKind::Feed)
        return;
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        const machine::MachineAxis* axis = d.axis(it.key());
        if (!axis)
            continue;
        std::optional<double>& at = (*positions)[size_t(axis - d.axes.constData())];
        at = target(block, *axis, it.value(), at);
    }
}

QString ProgramCoordinates::apply(const ProgramBlock& block, const machine::MachineDescription& d,
                                  const AxisPositions& current)
{
    switch (block.kind) {
    case BlockKind::SetCoordinates:
        return setSystem(block, d, current);
    case BlockKind::AxisOffset:
        return setAxisOffset(block, d, current);
    case BlockKind::AxisOffsetReset: // G92.1: zero, and applied (LinuxCNC)
        m_axisOffset.clear();
        m_axisOffsetApplied = true;
        return {};
    case BlockKind::AxisOffsetSuspend:
        m_axisOffsetApplied = false;
        return {};
    case BlockKind::AxisOffsetRestore:
        m_axisOffsetApplied = true;
        return {};
    default:
        return {};
    }
}

namespace {
// The current machine position of a named axis, or the reason it is not known.
std::optional<double> currentOf(const machine::MachineDescription& d, const AxisPositions& current,
                                const QString& name, int* index)
{
    for (int i = 0; i < d.axes.size(); ++i)
        if (d.axes.at(i).name == name) {
            *index = i;
            return current.at(size_t(i));
        }
    *index = -1;
    return std::nullopt;
}
} // namespace

// G10 L2 P<n>: the system's offsets are the words (in the program's units, unaffected by G91,
// as in LinuxCNC). G10 L20 P<n>: the offsets that make the current point read the words.
QString ProgramCoordinates::setSystem(const ProgramBlock& block,
                                      const machine::MachineDescription& d,
                                      const AxisPositions& current)
{
    const int system = block.number == 0 ? systemOf(block) : block.number - 1;
    QMap<QString, double>& table = m_systems[size_t(system)];
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        int index = -1;
        const std::optional<double> here = currentOf(d, current, it.key(), &index);
        if (index < 0)
            continue;
        const double value = units::toAxisUnits(d.axes.at(index), it.value(), block.inches);
        if (!block.fromPosition) {
            table.insert(it.key(), value);
            continue;
        }
        if (!here)
            return tr("G10 L20: the position of %1 is unknown: reference it first (G28 %1)")
                .arg(it.key());
        const double axisOffset = m_axisOffsetApplied ? m_axisOffset.value(it.key(), 0.0) : 0.0;
        table.insert(it.key(), *here - value - axisOffset);
    }
    return {};
}

// G92: the offset that makes the current point read the words in the system in effect.
QString ProgramCoordinates::setAxisOffset(const ProgramBlock& block,
                                          const machine::MachineDescription& d,
                                          const AxisPositions& current)
{
    const int system = systemOf(block);
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        int index = -1;
        const std::optional<double> here = currentOf(d, current, it.key(), &index);
        if (index < 0)
            continue;
        if (!here)
            return tr("G92: the position of %1 is unknown: reference it first (G28 %1)")
                .arg(it.key());
        const double value = units::toAxisUnits(d.axes.at(index), it.value(), block.inches);
        m_axisOffset.insert(it.key(),
                            *here - m_systems[size_t(system)].value(it.key(), 0.0) - value);
    }
    m_axisOffsetApplied = true;
    return {};
}

} // namespace stepdeck::program
