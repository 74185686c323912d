#pragma once
#include "ProgramBlock.h"
#include "machine/MachineDescription.h"
#include <QCoreApplication>
#include <optional>
#include <variant>
#include <vector>

namespace stepdeck::program {

// Where the program has put each axis (by MachineDescription::axes index), in machine
// coordinates and the axis' unit, unrounded: LinuxCNC's "current point", which an arc's
// centre and radius are measured from. nullopt: the position is unknown.
using AxisPositions = std::vector<std::optional<double>>;

// A G2/G3 in the machine's terms (docs/programs.md "Arcs"), as LinuxCNC's interpreter reads it:
// the plane's two axes turn about the centre (I J K from the start, G90.1 absolute, or R: +
// the shorter arc, - the longer), P turns, the plane's third axis moving with the angle (a
// helix). An end point off the circle within LinuxCNC's tolerance makes a spiral that ends
// exactly there; beyond it the arc is an error naming the radius difference. The path runs as
// chords whose middle is at most `tolerance` (the machine's chord tolerance) off the true
// curve. Pure, shared by the check and the run, so both take the same path.
class ArcPath
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ArcPath)
public:
    struct Error
    {
        int column = 1;
        QString message;
    };
    // The chord tolerance of an axis in its unit: 0.01 mm (UGS and bCNC draw arcs so), 0.01
    // degree, half a step on axes counted in steps.
    static double chordTolerance(const machine::MachineAxis& axis);
    static constexpr qint64 kMaxChords = 1000000; // of one arc

    static std::variant<ArcPath, Error> plan(const ProgramBlock& block,
                                             const machine::MachineDescription& d,
                                             const AxisPositions& start,
                                             const QMap<QString, double>& workOffsets);

    // The names of the axes an arc block moves: the plane's two and the helix axis when the
    // block names it, the machine's axis names as the block writes them.
    static QStringList movingAxes(const ProgramBlock& block);
    // The arc's rates as a G1 over its moving axes (motion::MoveRates::feedRateWrite, the check's
    // rate rules): what is written before its first chord.
    static ProgramBlock rateBlock(const ProgramBlock& block);

    qint64 chords() const { return m_chords; }
    // The end of chord k (1..chords()): each moving axis' machine position. k = chords() is
    // the programmed end exactly.
    QList<std::pair<int, double>> pointAt(qint64 k) const;
    // The end point (machine coordinates) by axis index, as the current point afterwards.
    QList<std::pair<int, double>> end() const { return pointAt(m_chords); }
    // The extreme positions the true curve reaches on each moving axis (not only the chords'
    // ends): where the soft limits are checked.
    QList<std::pair<int, std::pair<double, double>>> bounds() const;
    double radius() const { return m_startRadius; }
    // The length of the true curve in the axes' unit: the sweep at the mean radius (a spiral's
    // radius changes evenly), with the helix axis' travel (G93, InverseTime).
    double length() const;
    double sweep() const { return m_sweep; } // radians; + counter-clockwise
    // The curve itself, by machine axis index (ContourMoves lays it on a step stream whole).
    struct Shape
    {
        int axis[2]; // the plane's axes; the angle runs from axis[0] towards axis[1]
        int helix;   // -1: none moves
        double centre[2];
        double startRadius, endRadius, startAngle, sweep;
        double end[2];
        double helixEnd;
    };
    Shape shape() const
    {
        return Shape{
            {m_axis[0], m_axis[1]}, m_helix, {m_centre[0], m_centre[1]}, m_startRadius, m_endRadius,
            m_startAngle,           m_sweep, {m_end[0], m_end[1]},       m_helixEnd};
    }

private:
    ArcPath() = default;
    // inch: the axes' unit per program unit (25.4 for G20 on millimetre axes, else 1).
    std::optional<Error> resolveCentre(const ProgramBlock& block, double tolerance, double inch);
    std::optional<Error> radiusCentre(const ProgramBlock& block, double inch);
    double planeAt(double angle, double radius, int i) const;

    int m_axis[2] = {-1, -1}; // the plane's axes, in LinuxCNC's order
    int m_helix = -1;         // the third axis, when it moves
    double m_start[2] = {0, 0};
    double m_end[2] = {0, 0};
    double m_centre[2] = {0, 0};
    double m_helixStart = 0, m_helixEnd = 0;
    double m_startAngle = 0;
    double m_sweep = 0;
    double m_startRadius = 0, m_endRadius = 0;
    qint64 m_chords = 1;
};

} // namespace stepdeck::program
