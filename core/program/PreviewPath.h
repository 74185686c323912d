#pragma once
// Internal to ProgramCheck: the preview's path as the check's walk (ProgramSimulation) adds its
// points, bounded however long the run.
#include "ProgramCheck.h"
#include <vector>

namespace stepdeck::program {

// The path stays within ProgramPreview::kMaxPathPoints however long the run: when it is full,
// every other point goes and from then on only every stride-th new point is kept, so the
// preview shows the whole run at a coarser step, its last point the run's end (the extents are
// exact anyway). A kept point is a rapid only when every point it stands for was one. A point
// not kept costs no map of positions: only its steps are held until the next one.
class PreviewPath
{
public:
    // axes: the machine's; offsets: each axis' work offset in its unit (work = machine - offset).
    PreviewPath(const QList<machine::MachineAxis>& axes, const std::vector<double>& offsets)
        : m_axes(axes), m_offsets(offsets)
    {}

    // The position after the block of at.line (steps per axis, known per axis), with at's
    // times, count and kind (its position is filled in here).
    void add(const PreviewPoint& at, const std::vector<qint64>& steps,
             const std::vector<char>& known);
    void finish(ProgramPreview* preview) const; // path and pathDecimated

private:
    PreviewPoint pointAt(const PreviewPoint& at, const std::vector<qint64>& steps,
                         const std::vector<char>& known) const;
    void thin();

    const QList<machine::MachineAxis>& m_axes;
    const std::vector<double>& m_offsets;
    QList<PreviewPoint> m_path;
    bool m_decimated = false;
    qint64 m_stride = 1; // keep every m_stride-th point
    qint64 m_sinceKept = 0;
    bool m_mergedRapid = true; // the points since the last kept one were all rapids
    struct Pending             // the last point, not kept (yet)
    {
        bool valid = false;
        PreviewPoint at; // without its position
        std::vector<qint64> steps;
        std::vector<char> known;
    } m_pending;
};

} // namespace stepdeck::program
