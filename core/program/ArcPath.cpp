// G2/G3 as LinuxCNC's rs274ngc reads them (interp_arc.cc: arc_data_ijk, arc_data_r), run as
// chords (docs/programs.md "Arcs").
#include "ArcPath.h"
#include "ProgramUnits.h"
#include <cmath>

namespace stepdeck::program {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
// LinuxCNC's tolerances for the end point of an I J K arc (interp_internal.hh): the radii at
// start and end may differ by CENTER_ARC_RADIUS_TOLERANCE (mm: 2 x 0.01 x sqrt 2; inch:
// 2 x 0.001 x sqrt 2) or by SPIRAL_RELATIVE_TOLERANCE (0.1 %) of the radius, whichever is
// larger, but never by more than 100 times the absolute one. RADIUS_TOLERANCE (0.00005 in)
// is how far an R arc's radius may fall short of half the distance to its end.
constexpr double kCentreToleranceMm = 2 * 0.01 * 1.41421356237309505;
constexpr double kCentreToleranceInch = 2 * 0.001 * 1.41421356237309505;
constexpr double kSpiralRelativeTolerance = 0.001;
constexpr double kRadiusToleranceInch = 0.00005;
constexpr double kMaxRadius = 1e9; // axis units: far beyond any machine, keeps figures finite

struct PlaneAxes
{
    QString axes[2]; // in LinuxCNC's order: the angle turns from the first towards the second
    QString helix;
    const std::optional<double> ArcWords::*centre[2];
};

PlaneAxes planeAxes(Plane plane)
{
    switch (plane) {
    case Plane::XZ:
        return {{QStringLiteral("Z"), QStringLiteral("X")},
                QStringLiteral("Y"),
                {&ArcWords::k, &ArcWords::i}};
    case Plane::YZ:
        return {{QStringLiteral("Y"), QStringLiteral("Z")},
                QStringLiteral("X"),
                {&ArcWords::j, &ArcWords::k}};
    case Plane::XY:
        break;
    }
    return {{QStringLiteral("X"), QStringLiteral("Y")},
            QStringLiteral("Z"),
            {&ArcWords::i, &ArcWords::j}};
}

int indexOf(const machine::MachineDescription& d, const QString& name)
{
    for (int i = 0; i < d.axes.size(); ++i)
        if (d.axes.at(i).name == name)
            return i;
    return -1;
}

// Where an axis word sends its axis, in machine coordinates (the axis' unit).
double targetOf(const ProgramBlock& block, const machine::MachineAxis& axis, double start,
                const QMap<QString, double>& workOffsets)
{
    const auto it = block.axes.constFind(axis.name);
    if (it == block.axes.cend())
        return start;
    return *units::wordTarget(axis, it.value(), block.inches, block.relative,
                              workOffsets.value(axis.name, 0.0), start);
}

// The angle in [0, 2 pi) from `from` to `to`, turning counter-clockwise.
double turnBetween(double from, double to)
{
    double d = std::fmod(to - from, kTwoPi);
    return d < 0 ? d + kTwoPi : d;
}

} // namespace

double ArcPath::chordTolerance(const machine::MachineAxis& axis)
{
    return axis.unit == machine::AxisUnit::Step ? 0.5 : 0.01;
}

QStringList ArcPath::movingAxes(const ProgramBlock& block)
{
    const PlaneAxes plane = planeAxes(block.plane);
    QStringList names{plane.axes[0], plane.axes[1]};
    if (block.axes.contains(plane.helix))
        names << plane.helix;
    return names;
}

double ArcPath::length() const
{
    const double planar = std::abs(m_sweep) * (m_startRadius + m_endRadius) / 2;
    return m_helix >= 0 ? std::hypot(planar, m_helixEnd - m_helixStart) : planar;
}

ProgramBlock ArcPath::rateBlock(const ProgramBlock& block)
{
    ProgramBlock rates = block;
    rates.kind = BlockKind::Feed;
    rates.axes.clear();
    for (const QString& name : movingAxes(block))
        rates.axes.insert(name, block.axes.value(name, 0.0));
    return rates;
}

std::variant<ArcPath, ArcPath::Error> ArcPath::plan(const ProgramBlock& block,
                                                    const machine::MachineDescription& d,
                                                    const AxisPositions& start,
                                                    const QMap<QString, double>& workOffsets)
{
    const QString g = blockWord(block.kind);
    const int column = block.columnOf({});
    const PlaneAxes plane = planeAxes(block.plane);
    ArcPath path;
    const auto known = [&](int index, int wordColumn) -> std::optional<Error> {
        if (start.at(size_t(index)))
            return std::nullopt;
        const QString name = d.axes.at(index).name;
        return Error{wordColumn, tr("%1: the position of %2 is unknown, so the arc has no start: "
                                    "reference the axis first (G28 %2)")
                                     .arg(g, name)};
    };
    for (int p = 0; p < 2; ++p) {
        path.m_axis[p] = indexOf(d, plane.axes[p]);
        if (path.m_axis[p] < 0)
            return Error{column, tr("%1: the machine has no axis %2, which an arc in this plane "
                                    "turns")
                                     .arg(g, plane.axes[p])};
        if (const std::optional<Error> e = known(path.m_axis[p], block.columnOf(plane.axes[p])))
            return *e;
    }
    const machine::MachineAxis& first = d.axes.at(path.m_axis[0]);
    const machine::MachineAxis& second = d.axes.at(path.m_axis[1]);
    if (first.unit != second.unit)
        return Error{column, tr("%1: %2 and %3 have different units (%4, %5); an arc needs one")
                                 .arg(g, first.name, second.name, machine::unitKey(first.unit),
                                      machine::unitKey(second.unit))};
    for (int p = 0; p < 2; ++p) {
        const machine::MachineAxis& axis = d.axes.at(path.m_axis[p]);
        path.m_start[p] = *start.at(size_t(path.m_axis[p]));
        path.m_end[p] = targetOf(block, axis, path.m_start[p], workOffsets);
    }
    if (block.axes.contains(plane.helix)) {
        path.m_helix = indexOf(d, plane.helix);
        if (path.m_helix >= 0) {
            if (const std::optional<Error> e = known(path.m_helix, block.columnOf(plane.helix)))
                return *e;
            const machine::MachineAxis& axis = d.axes.at(path.m_helix);
            path.m_helixStart = *start.at(size_t(path.m_helix));
            path.m_helixEnd = targetOf(block, axis, path.m_helixStart, workOffsets);
        }
    }
    if (!block.arc.radius) {
        // arc_data_ijk: the centre's words, from the start (G91.1) or in work coordinates.
        for (int p = 0; p < 2; ++p) {
            const machine::MachineAxis& axis = d.axes.at(path.m_axis[p]);
            const double word =
                units::toAxisUnits(axis, (block.arc.*plane.centre[p]).value_or(0.0), block.inches);
            path.m_centre[p] = block.arc.centreAbsolute ? word + workOffsets.value(axis.name, 0.0)
                                                        : path.m_start[p] + word;
        }
    }
    const double tolerance = std::min(chordTolerance(first), chordTolerance(second));
    const double scale = units::toAxisUnits(first, 1.0, block.inches); // 25.4: G20 on mm
    if (const std::optional<Error> e = path.resolveCentre(block, tolerance, scale))
        return *e;
    return path;
}

// arc_data_r: the centre on the perpendicular bisector, on the side that makes the shorter
// arc for +R and the longer one for -R.
std::optional<ArcPath::Error> ArcPath::radiusCentre(const ProgramBlock& block, double inch)
{
    const QString g = blockWord(block.kind);
    const bool clockwise = block.kind == BlockKind::ArcClockwise;
    const double du = m_end[0] - m_start[0];
    const double dv = m_end[1] - m_start[1];
    const double chord = std::hypot(du, dv);
    const double r = std::abs(*block.arc.radius) * inch;
    if (chord < 1e-9)
        return Error{block.columnOf(QStringLiteral("R")),
                     tr("%1 with R: the end point is the start point; a full circle takes "
                        "I, J or K")
                         .arg(g)};
    const double half = chord / 2;
    if (half - r > kRadiusToleranceInch * units::kMillimetresPerInch)
        return Error{block.columnOf(QStringLiteral("R")),
                     tr("%1: R%2 is too short to reach the end point, %3 away")
                         .arg(g, figure(*block.arc.radius), figure(chord / inch))};
    const double along = std::min(half, r);
    const double turn = (clockwise == (*block.arc.radius > 0)) ? -kPi / 2 : kPi / 2;
    const double theta = std::atan2(dv, du) + turn;
    const double offset = r * std::cos(std::asin(along / r));
    m_centre[0] = m_start[0] + du / 2 + offset * std::cos(theta);
    m_centre[1] = m_start[1] + dv / 2 + offset * std::sin(theta);
    return std::nullopt;
}

// The centre, radii, sweep and chord count (LinuxCNC's arc_data_ijk and arc_data_r).
std::optional<ArcPath::Error> ArcPath::resolveCentre(const ProgramBlock& block, double tolerance,
                                                     double inch)
{
    const QString g = blockWord(block.kind);
    const int column = block.columnOf({});
    const bool clockwise = block.kind == BlockKind::ArcClockwise;
    const bool samePoint = std::hypot(m_end[0] - m_start[0], m_end[1] - m_start[1]) < 1e-9;
    if (block.arc.radius)
        if (const std::optional<Error> e = radiusCentre(block, inch))
            return e;
    m_startRadius = std::hypot(m_start[0] - m_centre[0], m_start[1] - m_centre[1]);
    m_endRadius = std::hypot(m_end[0] - m_centre[0], m_end[1] - m_centre[1]);
    if (!std::isfinite(m_startRadius) || !std::isfinite(m_endRadius) ||
        m_startRadius > kMaxRadius || m_endRadius > kMaxRadius)
        return Error{column,
                     tr("%1: the arc's radius is larger than %2").arg(g, figure(kMaxRadius))};
    const double minimum = kRadiusToleranceInch * units::kMillimetresPerInch;
    if (m_startRadius < minimum || m_endRadius < minimum)
        return Error{column, tr("%1: the centre lies on the start or the end point").arg(g)};
    const double absTolerance = std::max(
        block.inches ? kCentreToleranceInch * units::kMillimetresPerInch : kCentreToleranceMm,
        tolerance); // half a step on axes counted in steps
    const double absError = std::abs(m_startRadius - m_endRadius);
    const double relError = absError / std::max(m_startRadius, m_endRadius);
    if (absError > absTolerance * 100 ||
        (relError > kSpiralRelativeTolerance && absError > absTolerance))
        return Error{column,
                     tr("%1: the end point is not on the arc: radius %2 at the start, %3 at the "
                        "end, %4 apart (at most %5 allowed): check the centre and the end point")
                         .arg(g, figure(m_startRadius / inch), figure(m_endRadius / inch),
                              figure(absError / inch), figure(absTolerance / inch))};
    m_startAngle = std::atan2(m_start[1] - m_centre[1], m_start[0] - m_centre[0]);
    const double endAngle = std::atan2(m_end[1] - m_centre[1], m_end[0] - m_centre[0]);
    // The turn in the arc's direction; the end at the start's angle (the same point, or a
    // spiral's end) is a full turn, as in LinuxCNC.
    const double counterClockwise = samePoint ? 0.0 : turnBetween(m_startAngle, endAngle);
    double sweep =
        clockwise ? counterClockwise - kTwoPi : (counterClockwise == 0 ? kTwoPi : counterClockwise);
    sweep += (clockwise ? -kTwoPi : kTwoPi) * (block.arc.turns - 1);
    m_sweep = sweep;
    // A chord of angle a on radius r leaves r (1 - cos(a / 2)) to the curve.
    const double r = std::max(m_startRadius, m_endRadius);
    const double step =
        tolerance >= r ? kPi / 2 : std::min(kPi / 2, 2 * std::acos(1 - tolerance / r));
    const double chords = std::ceil(std::abs(m_sweep) / step);
    if (!std::isfinite(chords) || chords > kMaxChords)
        return Error{column, tr("%1: the arc needs more than %2 chords").arg(g).arg(kMaxChords)};
    m_chords = std::max<qint64>(1, qint64(chords));
    return std::nullopt;
}

double ArcPath::planeAt(double angle, double radius, int i) const
{
    return m_centre[i] + radius * (i == 0 ? std::cos(angle) : std::sin(angle));
}

QList<std::pair<int, double>> ArcPath::pointAt(qint64 k) const
{
    QList<std::pair<int, double>> point;
    if (k >= m_chords) {
        point << std::pair{m_axis[0], m_end[0]} << std::pair{m_axis[1], m_end[1]};
        if (m_helix >= 0)
            point << std::pair{m_helix, m_helixEnd};
        return point;
    }
    const double t = double(k) / double(m_chords);
    const double angle = m_startAngle + m_sweep * t;
    const double radius = m_startRadius + (m_endRadius - m_startRadius) * t;
    point << std::pair{m_axis[0], planeAt(angle, radius, 0)}
          << std::pair{m_axis[1], planeAt(angle, radius, 1)};
    if (m_helix >= 0)
        point << std::pair{m_helix, m_helixStart + (m_helixEnd - m_helixStart) * t};
    return point;
}

QList<std::pair<int, std::pair<double, double>>> ArcPath::bounds() const
{
    double low[2], high[2];
    for (int p = 0; p < 2; ++p) {
        low[p] = std::min(m_start[p], m_end[p]);
        high[p] = std::max(m_start[p], m_end[p]);
    }
    // Each plane axis is at its extremes where the angle is 0, pi/2, pi or 3 pi/2: those the
    // arc passes count, at the (spiral's) radius there.
    const double span = std::abs(m_sweep);
    for (int quarter = 0; quarter < 4; ++quarter) {
        const double angle = quarter * kPi / 2;
        const double travelled =
            m_sweep > 0 ? turnBetween(m_startAngle, angle) : turnBetween(angle, m_startAngle);
        if (travelled > span)
            continue;
        const double radius =
            m_startRadius + (m_endRadius - m_startRadius) * (span > 0 ? travelled / span : 0);
        const int p = quarter % 2 == 0 ? 0 : 1;
        const double at = planeAt(angle, radius, p);
        low[p] = std::min(low[p], at);
        high[p] = std::max(high[p], at);
    }
    QList<std::pair<int, std::pair<double, double>>> out;
    out << std::pair{m_axis[0], std::pair{low[0], high[0]}}
        << std::pair{m_axis[1], std::pair{low[1], high[1]}};
    if (m_helix >= 0)
        out << std::pair{m_helix, std::pair{std::min(m_helixStart, m_helixEnd),
                                            std::max(m_helixStart, m_helixEnd)}};
    return out;
}

} // namespace stepdeck::program
