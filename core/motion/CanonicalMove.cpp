#include "CanonicalMove.h"
#include <QCoreApplication>
#include <cmath>

namespace stepdeck::motion {

namespace {

bool isPlaneSlot(const CanonicalMove& m, int slot)
{
    return m.arc && (slot == m.arc->plane[0] || slot == m.arc->plane[1]);
}

// The arc's length in its plane: the sweep at the mean radius (ArcPath::length's measure).
double planeLength(const ArcGeometry& a)
{
    return std::fabs(a.sweep) * 0.5 * (a.startRadius + a.endRadius);
}

} // namespace

CanonicalMove CanonicalMove::straight(int axisCount, const Position& start, const Position& end,
                                      double feed, int line)
{
    CanonicalMove m;
    m.kind = Kind::Line;
    m.axisCount = axisCount;
    m.start = start;
    m.end = end;
    m.feed = feed;
    m.line = line;
    return m;
}

double CanonicalMove::length() const
{
    double sum = 0;
    for (int i = 0; i < axisCount; ++i) {
        if (isPlaneSlot(*this, i))
            continue;
        const double d = end[size_t(i)] - start[size_t(i)];
        sum += d * d;
    }
    if (arc) {
        const double p = planeLength(*arc);
        sum += p * p;
    }
    return std::sqrt(sum);
}

Position CanonicalMove::at(double s) const
{
    const double total = length();
    const double u = total > 0 ? std::clamp(s / total, 0.0, 1.0) : 1.0;
    Position p = start;
    for (int i = 0; i < axisCount; ++i)
        p[size_t(i)] = start[size_t(i)] + u * (end[size_t(i)] - start[size_t(i)]);
    if (arc) {
        // The end is the programmed end exactly; on the way the point turns about the centre.
        if (u < 1.0) {
            const double angle = arc->startAngle + u * arc->sweep;
            const double radius = arc->startRadius + u * (arc->endRadius - arc->startRadius);
            p[size_t(arc->plane[0])] = arc->centre[0] + radius * std::cos(angle);
            p[size_t(arc->plane[1])] = arc->centre[1] + radius * std::sin(angle);
        }
    }
    return p;
}

double CanonicalMove::slotRatePerFeed(int slot) const
{
    const double total = length();
    if (total <= 0 || slot < 0 || slot >= axisCount)
        return 0;
    if (isPlaneSlot(*this, slot)) {
        // d(r cos a)/du = r' cos a - r a' sin a: at most |r'| + r |a'|, per unit of u.
        const double rMax = std::max(arc->startRadius, arc->endRadius);
        return (std::fabs(arc->endRadius - arc->startRadius) + rMax * std::fabs(arc->sweep)) /
               total;
    }
    return std::fabs(end[size_t(slot)] - start[size_t(slot)]) / total;
}

QString CanonicalMove::invalidReason() const
{
    if (axisCount <= 0 || axisCount > kMaxAxes)
        return QCoreApplication::translate("stepdeck::motion::CanonicalMove",
                                           "a move over %1 axes (1..%2)")
            .arg(axisCount)
            .arg(kMaxAxes);
    for (int i = 0; i < axisCount; ++i)
        if (!std::isfinite(start[size_t(i)]) || !std::isfinite(end[size_t(i)]))
            return QCoreApplication::translate("stepdeck::motion::CanonicalMove",
                                               "a move to a position that is not a number");
    if (kind != Kind::Rapid && !(std::isfinite(feed) && feed > 0))
        return QCoreApplication::translate("stepdeck::motion::CanonicalMove",
                                           "a feed move without a feed rate");
    if (kind == Kind::Arc) {
        if (!arc)
            return QCoreApplication::translate("stepdeck::motion::CanonicalMove",
                                               "an arc without its centre");
        const ArcGeometry& a = *arc;
        const bool planeSlots = a.plane[0] >= 0 && a.plane[0] < axisCount && a.plane[1] >= 0 &&
                                a.plane[1] < axisCount && a.plane[0] != a.plane[1];
        if (!planeSlots || !std::isfinite(a.sweep) || !std::isfinite(a.startAngle) ||
            !(a.startRadius >= 0) || !(a.endRadius >= 0) || !std::isfinite(a.centre[0]) ||
            !std::isfinite(a.centre[1]))
            return QCoreApplication::translate("stepdeck::motion::CanonicalMove",
                                               "an arc whose geometry is not valid");
    }
    return {};
}

} // namespace stepdeck::motion
