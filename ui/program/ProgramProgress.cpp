#include "ProgramProgress.h"

namespace stepdeck::ui {

void ProgramProgress::reset(const program::ProgramPreview& preview)
{
    m_preview = preview;
    m_cursor = -1;
    m_secondsDone = 0;
}

void ProgramProgress::blockFinished(int line)
{
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
    if (m_preview.estimatedSeconds <= 0 || m_preview.pathTruncated)
        return std::nullopt;
    return qMax(0.0, m_preview.estimatedSeconds - m_secondsDone);
}

} // namespace stepdeck::ui
