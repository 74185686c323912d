#include "WireBudget.h"
#include <cmath>

namespace stepdeck {

namespace {
// Rounding slack far below a nanosecond, so that a byte that has just left is not counted
// again through floating-point noise.
constexpr double kCharacterSlack = 1e-6;
constexpr double kNsSlack = 1e-3;
} // namespace

void WireBudget::setCharacterUs(double us)
{
    m_characterNs = qMax(1.0, us * 1000.0);
}

qint64 WireBudget::write(qint64 bytes, qint64 nowNs)
{
    const double start = qMax(double(nowNs), m_lineFreeNs);
    if (bytes > 0)
        m_lineFreeNs = start + double(bytes) * m_characterNs;
    // std::ceil, not qCeil: qCeil returns int, and nanoseconds pass 2^31 after 2.1 s.
    return qint64(std::ceil(start - kNsSlack));
}

qint64 WireBudget::backlog(qint64 nowNs) const
{
    const double remaining = m_lineFreeNs - double(nowNs);
    if (remaining <= 0)
        return 0;
    return qMax<qint64>(0, qint64(std::ceil(remaining / m_characterNs - kCharacterSlack)));
}

qint64 WireBudget::nsUntilBacklog(qint64 bytes, qint64 nowNs) const
{
    // At most `bytes` are left once no more than bytes * character time remains.
    const double due = m_lineFreeNs - double(qMax<qint64>(0, bytes)) * m_characterNs;
    return qMax<qint64>(0, qint64(std::ceil(due - double(nowNs) - kNsSlack)));
}

} // namespace stepdeck
