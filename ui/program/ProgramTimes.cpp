#include "ProgramTimes.h"

namespace stepdeck::ui {

QString ProgramTimes::duration(double seconds)
{
    const qint64 s = qIsFinite(seconds) ? qMax<qint64>(0, qRound64(qMin(seconds, 1e12))) : 0;
    if (s < 60)
        return tr("%1 s").arg(s);
    if (s < 3600)
        return tr("%1 min %2 s").arg(s / 60).arg(s % 60);
    return tr("%1 h %2 min").arg(s / 3600).arg((s % 3600) / 60);
}

QString ProgramTimes::estimatedDuration(double seconds)
{
    return tr("\u2248 %1 (estimated)").arg(duration(seconds));
}

QString ProgramTimes::estimatedLeft(double seconds)
{
    return tr("\u2248 %1 left (estimated)").arg(duration(seconds));
}

} // namespace stepdeck::ui
