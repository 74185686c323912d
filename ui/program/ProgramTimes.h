#pragma once
#include <QCoreApplication>
#include <QString>

namespace stepdeck::ui {

// The estimate's rest of a run (ProgramProgress), split by what the feed override re-times
// (issue 47, item 11): the feed moves' seconds at their F (100 %), and the rest (rapids,
// dwells), which no override changes. M0, M66 and G28 have no time in the estimate.
struct ProgramTimeLeft
{
    double feedSeconds = 0;
    double otherSeconds = 0;
    // At a feed override of `percent` (10..200, as ProgramRunner::setFeedOverride clamps
    // it): the feed moves take 100/percent of their time.
    double at(double percent) const
    {
        return otherSeconds + feedSeconds * 100.0 / qBound(10.0, percent, 200.0);
    }
};

// How the Program page writes its estimated times (issue 20): always marked as estimates,
// since the preview knows no accelerations and only the rates the models' data gives.
class ProgramTimes
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::ProgramTimes)
public:
    static QString duration(double seconds);          // "1 min 20 s"
    static QString estimatedDuration(double seconds); // "≈ 1 min 20 s (estimated)"
    static QString estimatedLeft(double seconds);     // "≈ 1 min 20 s left (estimated)"
};

} // namespace stepdeck::ui
