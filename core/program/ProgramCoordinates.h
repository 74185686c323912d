#pragma once
#include "ArcPath.h"
#include "ProgramBlock.h"
#include "ToolTable.h"
#include "machine/MachineDescription.h"
#include <QCoreApplication>
#include <QMap>
#include <array>

namespace stepdeck::program {

// LinuxCNC's coordinate systems G54..G59 (issue 29, docs/programs.md "Coordinates"): per
// system, each axis' machine position of its work zero, in the axis' unit (an axis not
// listed: 0). Index 0 is G54. The operator's "Zero X" sets the active system's entry.
constexpr int kCoordinateSystems = 6;
using CoordinateSystems = std::array<QMap<QString, double>, kCoordinateSystems>;

QString coordinateSystemWord(int index); // "G54" .. "G59"

// The coordinates a program's absolute words are in, as the program changes them: the table
// (G10 L2 / L20 write it), the system each block selects (ProgramBlock::coordinateSystem; -1:
// the one active when the run started), the G92 offset (G92, G92.1, G92.2, G92.3) and the
// tool length offset on the tool axis Z (G43: the block's lengthTool's length in the table).
// machine position = word + offset(block, axis); G53 blocks: offset 0. The check and the run
// each carry one from the same start, so both send a word to one machine position. Pure.
class ProgramCoordinates
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramCoordinates)
public:
    ProgramCoordinates() = default;
    ProgramCoordinates(const CoordinateSystems& systems, int active, const ToolTable& tools = {});
    static QString toolAxis() { return QStringLiteral("Z"); } // LinuxCNC's default

    // The offset of an absolute word of `block` on `axis`.
    double offset(const ProgramBlock& block, const QString& axis) const;
    // Every axis' offset for `block` (for ArcPath, advanceAxisPositions).
    QMap<QString, double> offsets(const ProgramBlock& block,
                                  const machine::MachineDescription& d) const;
    // The system a block runs in (its own, or the one active at the start).
    int systemOf(const ProgramBlock& block) const;

    // G10 L2/L20 and the G92 family change the state; other blocks leave it. An error (empty:
    // none) where a word needs a position that is unknown (G10 L20, G92).
    QString apply(const ProgramBlock& block, const machine::MachineDescription& d,
                  const AxisPositions& current);

    // The machine position an axis word of `block` names (the axis' unit): an absolute word
    // at word + offset, a relative one from `at`; nullopt where `at` is unknown. The one place
    // a word becomes a target (issue 49): advance() and ProgramLowering take it from here.
    std::optional<double> target(const ProgramBlock& block, const machine::MachineAxis& axis,
                                 double word, std::optional<double> at) const;
    // The length G43 H adds on the tool axis for `block` (0: none, or no such tool).
    double toolLength(const ProgramBlock& block) const;
    bool axisOffsetApplied() const { return m_axisOffsetApplied; } // G92.2 suspends it

    // The current point after a G0/G1 (its axis words: absolute ones at word + offset,
    // relative ones from where the axis stands; unknown stays unknown) or a G28 (0 on the axes
    // it references). The check's walk and the run both follow the program with this.
    void advance(const ProgramBlock& block, const machine::MachineDescription& d,
                 AxisPositions* positions) const;

    const CoordinateSystems& systems() const { return m_systems; }
    int activeAtStart() const { return m_active; }
    QMap<QString, double> axisOffset() const { return m_axisOffset; } // G92's, per axis

private:
    QString setSystem(const ProgramBlock& block, const machine::MachineDescription& d,
                      const AxisPositions& current);
    QString setAxisOffset(const ProgramBlock& block, const machine::MachineDescription& d,
                          const AxisPositions& current);

    CoordinateSystems m_systems;
    int m_active = 0;
    QMap<QString, double> m_axisOffset; // G92, in each axis' unit
    bool m_axisOffsetApplied = true;    // G92.2 suspends it, G92.3 applies it again
    ToolTable m_tools;
};

} // namespace stepdeck::program
