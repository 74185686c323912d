#pragma once
// Paths in three axes as the program tests compare them at the device (tst_camprograms,
// tst_ngcrun): any point type with x, y and z.
#include <QList>
#include <QString>
#include <cmath>

namespace stepdeck::test {

template <typename P> QString pointText(const P& p)
{
    return QStringLiteral("(%1, %2, %3)").arg(p.x).arg(p.y).arg(p.z);
}

// Within `d` on every axis.
template <typename P> bool near(const P& a, const P& b, double d)
{
    return std::abs(a.x - b.x) <= d && std::abs(a.y - b.y) <= d && std::abs(a.z - b.z) <= d;
}

// The index of the first of `points` that `path` does not pass within `tolerance`, in order;
// -1: it passes them all.
template <typename P>
qsizetype firstNotPassed(const QList<P>& path, const QList<P>& points, double tolerance)
{
    qsizetype at = 0;
    for (qsizetype i = 0; i < points.size(); ++i) {
        while (at < path.size() && !near(path.at(at), points.at(i), tolerance))
            ++at;
        if (at == path.size())
            return i;
    }
    return -1;
}

} // namespace stepdeck::test
