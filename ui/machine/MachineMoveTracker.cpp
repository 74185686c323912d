#include "MachineMoveTracker.h"

namespace stepdeck::ui {

std::optional<MachineMoveTracker::Shown> MachineMoveTracker::update(const QString& axis,
                                                                    qint64 steps, bool moving,
                                                                    const MoveProfile& profile)
{
    Move& move = m_moves[axis];
    if (!moving) {
        move.active = false;
        m_standing.insert(axis, steps);
        return std::nullopt;
    }
    if (!move.active) {
        move.active = true;
        move.from = m_standing.value(axis, steps);
        move.clock.start();
    }
    Shown shown;
    shown.target = steps;
    if (profile.isValid()) {
        const qint64 distance = qAbs(steps - move.from);
        const double done =
            MoveEstimate::travelled(double(distance), profile, move.clock.elapsed() / 1000.0);
        shown.estimate = move.from + (steps >= move.from ? 1 : -1) * qint64(done);
    }
    return shown;
}

void MachineMoveTracker::forget(const QString& axis)
{
    m_moves.remove(axis);
    m_standing.remove(axis);
}

void MachineMoveTracker::clear()
{
    m_moves.clear();
    m_standing.clear();
}

bool MachineMoveTracker::anyMoving() const
{
    for (const Move& m : m_moves)
        if (m.active)
            return true;
    return false;
}

} // namespace stepdeck::ui
