#include "ProgramProgress.h"

namespace stepdeck::ui {

void ProgramProgress::reset(const program::ProgramPreview& preview)
{
    m_preview = preview;
    m_cursor = 0;
    m_blocksDone = 0;
}

void ProgramProgress::blockFinished(int line)
{
    Q_UNUSED(line);
    ++m_blocksDone;
    const QList<program::PreviewPoint>& path = m_preview.path;
    while (m_cursor + 1 < path.size() && path.at(m_cursor + 1).blocksDone <= m_blocksDone)
        ++m_cursor;
}

ProgramProgress::Done ProgramProgress::done() const
{
    const QList<program::PreviewPoint>& path = m_preview.path;
    if (path.isEmpty())
        return {};
    const program::PreviewPoint& at = path.at(m_cursor);
    Done d{at.seconds, at.feedSeconds};
    if (!m_preview.pathDecimated || m_cursor + 1 >= path.size())
        return d;
    // A thinned path: the blocks between two kept points (their own points left out) share
    // the time between them by their count. On a whole path the blocks between two points
    // have none, and no time.
    const program::PreviewPoint& next = path.at(m_cursor + 1);
    const qint64 between = next.blocksDone - at.blocksDone;
    if (between > 1) {
        const double share = double(m_blocksDone - at.blocksDone) / double(between);
        d.seconds += (next.seconds - at.seconds) * share;
        d.feedSeconds += (next.feedSeconds - at.feedSeconds) * share;
    }
    return d;
}

std::optional<ProgramTimeLeft> ProgramProgress::timeLeft() const
{
    const double total = m_preview.estimatedSeconds;
    if (!(total > 0))
        return std::nullopt;
    // The path's last point is the run's end: its seconds are the estimate's.
    const double feed =
        m_preview.path.isEmpty() ? 0.0 : qBound(0.0, m_preview.path.last().feedSeconds, total);
    const Done d = done();
    ProgramTimeLeft left;
    left.feedSeconds = qMax(0.0, feed - d.feedSeconds);
    left.otherSeconds = qMax(0.0, (total - feed) - (d.seconds - d.feedSeconds));
    return left;
}

std::optional<double> ProgramProgress::secondsLeft() const
{
    const std::optional<ProgramTimeLeft> left = timeLeft();
    if (!left)
        return std::nullopt;
    return left->at(m_feedOverride);
}

} // namespace stepdeck::ui
