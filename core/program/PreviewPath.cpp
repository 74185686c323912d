#include "PreviewPath.h"

namespace stepdeck::program {

void PreviewPath::add(const PreviewPoint& at, const std::vector<qint64>& steps,
                      const std::vector<char>& known)
{
    PreviewPoint merged = at; // its times and count are the run's up to here: kept as they are
    merged.rapid = at.rapid && m_mergedRapid;
    if (++m_sinceKept < m_stride) {
        // Not kept (yet): only what it takes to draw it should it be the run's end; the point
        // itself (a map of positions) is made at finish().
        m_mergedRapid = merged.rapid;
        m_pending.valid = true;
        m_pending.at = merged;
        m_pending.steps = steps;
        m_pending.known = known;
        return;
    }
    m_sinceKept = 0;
    m_mergedRapid = true;
    m_pending.valid = false;
    m_path << pointAt(merged, steps, known);
    if (m_path.size() >= ProgramPreview::kMaxPathPoints)
        thin();
}

PreviewPoint PreviewPath::pointAt(const PreviewPoint& at, const std::vector<qint64>& steps,
                                  const std::vector<char>& known) const
{
    PreviewPoint point = at;
    point.position.clear();
    for (qsizetype i = 0; i < m_axes.size(); ++i)
        if (known[size_t(i)])
            point.position.insert(m_axes.at(i).name,
                                  m_axes.at(i).toUnits(steps[size_t(i)]) - m_offsets[size_t(i)]);
    return point;
}

void PreviewPath::thin()
{
    QList<PreviewPoint> kept;
    kept.reserve(m_path.size() / 2 + 1);
    for (qsizetype i = 0; i < m_path.size(); i += 2) {
        PreviewPoint p = m_path.at(i);
        if (i > 0)
            p.rapid = p.rapid && m_path.at(i - 1).rapid;
        kept << p;
    }
    m_path = std::move(kept);
    m_stride *= 2;
    m_decimated = true;
}

void PreviewPath::finish(ProgramPreview* preview) const
{
    preview->path = m_path;
    if (m_pending.valid) // the run's end, between two kept points
        preview->path << pointAt(m_pending.at, m_pending.steps, m_pending.known);
    preview->pathDecimated = m_decimated;
}

} // namespace stepdeck::program
