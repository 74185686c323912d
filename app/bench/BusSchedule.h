#pragma once
#include <QJsonObject>
#include <QList>
#include <QStringList>
#include <optional>

namespace stepdeck::bench {

// Issue 32, step 4: a Nanotec bus of many drives, one of them moving, on the paced wire at
// the product's poll interval (50 ms). Measured at the device: when each drive's status '$'
// arrived there. The moving drive's read interval (median, p99, longest), the idle round (per
// idle drive the longest gap between two of its reads; the median and the longest over the
// drives) and the wire's use (characters both ways per second against the 1920 of 19200 8N1).
// Figures only: docs/benchmark.md, "A bus of many drives".
struct BusScheduleFigure
{
    int drives = 0;
    int movingAddress = 0;
    int movingReads = 0;
    std::optional<double> movingMedianMs, movingP99Ms, movingMaxMs;
    int idleDrivesRead = 0; // idle drives read at least twice in the window
    std::optional<double> idleRoundMedianMs, idleRoundMaxMs;
    std::optional<double> wireUse; // 0..1
    double windowMs = 0;
    QString note; // why a figure is missing
};

// 8, 32 and 254 drives; windowMs: how long reads are recorded once the move runs.
QList<BusScheduleFigure> measureBusSchedule(int windowMs);
QJsonObject busScheduleJson(const QList<BusScheduleFigure>& figures);
QStringList busScheduleText(const QList<BusScheduleFigure>& figures);

} // namespace stepdeck::bench
