#pragma once
#include "program/ProgramCheck.h"
#include <optional>

namespace stepdeck::ui {

// How far a run has come in the estimate (issue 20): the preview's path has a point per block
// that ends somewhere (G0, G1, G28, G4), in run order, repeats counted out. Each finished
// block moves a cursor onto its point; the time left is the estimate's rest from there.
class ProgramProgress
{
public:
    void reset(const program::ProgramPreview& preview);
    void blockFinished(int line);
    double secondsDone() const { return m_secondsDone; }
    // The estimate's rest; a thinned path (ProgramPreview::pathDecimated, whose lines do not follow
    // every block) counts down by the share of blocks still to run. nullopt when it cannot be told
    // (no estimate).
    std::optional<double> secondsLeft() const;

private:
    // How far ahead a finished block's point is looked for: blocks without a point (M-words)
    // have none, and must not make the cursor jump to a later repeat of some line.
    static constexpr int kLookAhead = 64;

    program::ProgramPreview m_preview;
    int m_cursor = -1;
    double m_secondsDone = 0;
    qint64 m_blocksDone = 0;
};

} // namespace stepdeck::ui
