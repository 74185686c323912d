#pragma once
#include "ProgramTimes.h"
#include "program/ProgramCheck.h"
#include <optional>

namespace stepdeck::ui {

// How far a run has come in the estimate (issue 20), by time (issue 47, item 11): the
// preview's path has a point per block that ends somewhere (G0, G1, the chords of G2/G3, a
// cycle's moves, G28, G4), in run order, repeats counted out, each with the estimate's seconds
// up to it (of them the feed moves') and the blocks finished there (PreviewPoint::blocksDone,
// counted as ProgramRunner::blocksDone() counts them). Each finished block counts one; the run
// stands at the last point its count has reached, so a long block is its seconds of the
// estimate, not one step of many. On a thinned path (ProgramPreview::pathDecimated) the
// blocks between two kept points share the time between them by their count. The time left is
// the estimate's rest from there, the feed moves' part at the feed override.
class ProgramProgress
{
public:
    void reset(const program::ProgramPreview& preview); // the override stays
    // The runner finished a block (ProgramRunner::blockFinished). The count places it, not the
    // line (repeats, blocks without a point); line is only the runner's report.
    void blockFinished(int line);
    // The run's feed override in percent (ProgramRunner::feedOverride(); 100 until set).
    void setFeedOverride(double percent) { m_feedOverride = percent; }
    double feedOverride() const { return m_feedOverride; }
    qint64 blocksDone() const { return m_blocksDone; }
    // Where the run stands on the estimate's clock (at F: the preview's time axis).
    double secondsDone() const { return done().seconds; }
    // The estimate's rest, split as the override re-times it (ProgramTimeLeft::at); nullopt
    // when it cannot be told (no estimate).
    std::optional<ProgramTimeLeft> timeLeft() const;
    // The rest at the feed override set.
    std::optional<double> secondsLeft() const;

private:
    struct Done
    {
        double seconds = 0;
        double feedSeconds = 0;
    };
    Done done() const;

    program::ProgramPreview m_preview;
    qsizetype m_cursor = 0; // the last point the finished blocks reached
    qint64 m_blocksDone = 0;
    double m_feedOverride = 100;
};

} // namespace stepdeck::ui
