#include "NearestName.h"
#include <algorithm>
#include <vector>

namespace stepdeck::names {

int editDistance(QStringView a, QStringView b)
{
    const QString x = a.toString().toLower();
    const QString y = b.toString().toLower();
    const qsizetype n = x.size();
    const qsizetype m = y.size();
    // d[i][j]: distance between the first i characters of x and the first j of y.
    std::vector<std::vector<int>> d(size_t(n + 1), std::vector<int>(size_t(m + 1), 0));
    for (qsizetype i = 0; i <= n; ++i)
        d[size_t(i)][0] = int(i);
    for (qsizetype j = 0; j <= m; ++j)
        d[0][size_t(j)] = int(j);
    for (qsizetype i = 1; i <= n; ++i) {
        for (qsizetype j = 1; j <= m; ++j) {
            const size_t si = size_t(i);
            const size_t sj = size_t(j);
            const int cost = x.at(i - 1) == y.at(j - 1) ? 0 : 1;
            d[si][sj] = std::min({d[si - 1][sj] + 1, d[si][sj - 1] + 1, d[si - 1][sj - 1] + cost});
            if (i > 1 && j > 1 && x.at(i - 1) == y.at(j - 2) && x.at(i - 2) == y.at(j - 1))
                d[si][sj] = std::min(d[si][sj], d[si - 2][sj - 2] + 1);
        }
    }
    return d[size_t(n)][size_t(m)];
}

QString nearest(const QString& typed, const QStringList& candidates)
{
    // Two letters are too little to guess from ("st": set? stop? status?).
    if (typed.size() < 3 || candidates.contains(typed, Qt::CaseInsensitive))
        return {};
    const int allowed = typed.size() == 3 ? 1 : 2;
    QString best;
    int bestDistance = allowed + 1;
    for (const QString& candidate : candidates) {
        const int distance = editDistance(typed, candidate);
        if (distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    if (!best.isEmpty())
        return best;
    QStringList starting;
    for (const QString& candidate : candidates) {
        if (candidate.startsWith(typed, Qt::CaseInsensitive))
            starting << candidate;
    }
    return starting.size() == 1 ? starting.constFirst() : QString();
}

} // namespace stepdeck::names
