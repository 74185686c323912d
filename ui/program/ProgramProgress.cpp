#include "ProgramProgress.h"

namespace stepdeck::ui {

void ProgramProgress::reset(const program::ProgramPreview& preview)
{
    m_preview = preview;
    m_cursor = -1;
    m_secondsDone = 0;
    m_blocksDone = 0;
}

void ProgramProgress::blockFinished(int line)
{
    ++m_blocksDone;
    const QList<program::PreviewPoint>& path = m_preview.path;
    const qsizetype end = qMin<qsizetype>(path.size(), m_cursor + 1 + kLookAhead);
    for (qsizetype i = m_cursor + 1; i < end; ++i) {
        if (path.at(i).line == line) {
            m_cursor = int(i);
            m_secondsDone = path.at(i).seconds;
            return;
        }
    }
}

std::optional<double> ProgramProgress::secondsLeft() const
{
    if (m_preview.estimatedSeconds <= 0)
        return std::nullopt;
    if (!m_preview.pathDecimated)
        return qMax(0.0, m_preview.estimatedSeconds - m_secondsDone);
    // Beyond its path the estimate cannot follow the run: the estimate's share of the blocks
    // still to run (issue 28: a long program's time left counts down all the same).
    if (m_preview.blocksRun <= 0)
        return std::nullopt;
    const double left = double(qMax<qint64>(0, m_preview.blocksRun - m_blocksDone));
    return m_preview.estimatedSeconds * left / double(m_preview.blocksRun);
}

} // namespace stepdeck::ui
