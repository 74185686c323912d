#pragma once
#include "machine/MoveEstimate.h"
#include <QElapsedTimer>
#include <QMap>
#include <QString>
#include <optional>

namespace stepdeck::ui {

// What the read-out shows of an axis whose controller reports no position during a move
// (Capabilities::positionReadback false, the E-LAB): its core already counts the target the
// moment the move is sent, so the count is where the axis is heading, not where it is. Per
// machine axis this remembers where the axis stood when the move began and, from the ramp
// parameters known in this session (MoveEstimate), where it probably is now. Pure
// bookkeeping: nothing is sent or read.
class MachineMoveTracker
{
public:
    struct Shown
    {
        qint64 target = 0;
        std::optional<qint64> estimate; // none: the ramp is not known (show the target)
    };

    // A status of the axis: steps as the core counts them, moving or not. While it moves the
    // answer is what to show; standing, it remembers the position (nullopt).
    std::optional<Shown> update(const QString& axis, qint64 steps, bool moving,
                                const MoveProfile& profile);
    void forget(const QString& axis); // link down, an unknown position: no move to follow
    void clear();
    bool anyMoving() const;

private:
    struct Move
    {
        bool active = false;
        qint64 from = 0;
        QElapsedTimer clock;
    };
    QMap<QString, Move> m_moves;
    QMap<QString, qint64> m_standing; // where each axis was last seen standing
};

} // namespace stepdeck::ui
