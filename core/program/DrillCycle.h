#pragma once
#include "ArcPath.h"
#include "ProgramBlock.h"
#include "machine/MachineDescription.h"
#include <QCoreApplication>
#include <variant>
#include <vector>

namespace stepdeck::program {

// A drilling cycle (G81, G82, G83, G73) in the machine's terms (docs/programs.md "Drilling
// cycles"), expanded into moves as LinuxCNC's interpreter does. From the current point, once:
// a Z below R first goes up to R. Then per repeat (L): X Y at the fast speed, Z down to R at the
// fast speed, and
// - G81: Z at F to the bottom; G82: the same, then P seconds' dwell;
// - G83: pecks of Q at F; after each, out to R at the fast speed and back down to the peck
//   clearance above the depth reached;
// - G73: pecks of Q at F; after each, back the peck clearance at the fast speed (chip break);
// and Z out at the fast speed to the clearance level: R (G99), or the higher of R and the Z
// where the cycle began (G98). In G91, X Y are increments per repeat, R is measured from the
// current Z and Z from R. Pure, shared by the check and the run, so both take the same moves.
class DrillCycle
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::DrillCycle)
public:
    struct Error
    {
        int column = 1;
        QString message;
    };
    enum class Kind : quint8 { Rapid, Feed, Dwell };
    struct Segment
    {
        Kind kind = Kind::Rapid;
        // What it moves: (index in MachineDescription::axes, machine position in the axis'
        // unit). Empty for a dwell.
        QList<std::pair<int, double>> targets;
        double seconds = 0; // a dwell's
    };
    static constexpr int kMaxSegments = 100000; // of one cycle line (pecks and repeats)

    static std::variant<DrillCycle, Error> plan(const ProgramBlock& block,
                                                const machine::MachineDescription& d,
                                                const AxisPositions& start,
                                                const QMap<QString, double>& workOffsets);
    // LinuxCNC's G83_RAPID_DELTA, 0.010 in: 0.254 mm on a millimetre axis, else one unit.
    static double peckClearance(const machine::MachineAxis& z);
    // The cycle's rates as a G0 over every axis it can move (X, Y, Z the machine has) or a G1
    // of Z (its feed moves): what the check judges (ProgramPlan).
    static ProgramBlock rateBlock(const ProgramBlock& block, Kind kind,
                                  const machine::MachineDescription& d);
    // One segment's rates (a G0 or G1 over the axes it moves): what the run writes before it.
    static ProgramBlock segmentBlock(const ProgramBlock& block, const Segment& segment,
                                     const machine::MachineDescription& d);

    const std::vector<Segment>& segments() const { return m_segments; }
    // Where the cycle leaves X, Y and Z (the current point afterwards).
    QList<std::pair<int, double>> end() const;

private:
    DrillCycle() = default;
    void moveTo(Kind kind, const QList<std::pair<int, double>>& targets);
    void drill(const CycleWords& c, double r, double bottom, double peck, double clearance);

    std::vector<Segment> m_segments;
    int m_axis[3] = {-1, -1, -1};        // X, Y, Z (-1: the machine has no such axis)
    std::optional<double> m_position[3]; // where the moves so far put them
};

} // namespace stepdeck::program
