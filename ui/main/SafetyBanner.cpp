#include "SafetyBanner.h"

namespace stepdeck::ui {

QString SafetyBanner::mayStillMoveText()
{
    return tr("the controller may still be moving: use the machine's emergency stop");
}

SafetyBannerText SafetyBanner::disconnected(const SafetyBannerInput& in)
{
    const bool mayMove = in.status.motionUnconfirmed || in.movingWhenLinkEnded;
    if (in.link == LinkState::Lost) {
        if (mayMove)
            return {tr("Link lost while the machine was moving: %1. Positions are unknown: "
                       "reconnect, then reference all axes.")
                        .arg(mayStillMoveText()),
                    QStringLiteral("fault")};
        return {tr("Link lost: positions are unknown. Reconnect, then reference all axes."),
                QStringLiteral("fault")};
    }
    if (mayMove)
        return {tr("Disconnected while the machine was moving: no standstill was confirmed; "
                   "%1.")
                    .arg(mayStillMoveText()),
                QStringLiteral("fault")};
    if (in.link == LinkState::Connecting)
        return {tr("Connecting\u2026"), QStringLiteral("idle")};
    return {tr("Not connected."), QStringLiteral("idle")};
}

SafetyBannerText SafetyBanner::compute(const SafetyBannerInput& in)
{
    if (in.link != LinkState::Connected)
        return disconnected(in);
    const MachineStatus& s = in.status;
    if (s.motionUnconfirmed)
        return {tr("No standstill confirmed by the controller: %1.").arg(mayStillMoveText()),
                QStringLiteral("fault")};
    if (s.panic && in.hostPanicSent)
        return {tr("PANIC STOP sent: positions are lost; reference all axes before any "
                   "absolute move."),
                QStringLiteral("fault"), true};
    if (s.panic)
        return {tr("EMERGENCY STOP active on the machine: positions are lost. Release the "
                   "emergency stop, then reference all axes."),
                QStringLiteral("fault")};
    if (s.setupIncomplete)
        return {tr("Setup incomplete: write the setup (start speed, max speed, acceleration) "
                   "on the Setup page first. The controller refuses every move until then."),
                QStringLiteral("warning")};
    bool allReferenced = !s.axes.isEmpty();
    for (const AxisStatus& axis : s.axes)
        allReferenced = allReferenced && axis.referenced;
    if (allReferenced)
        return {tr("Ready: all axes referenced."), QStringLiteral("ok")};
    if (in.positionsLost)
        return {tr("Positions are lost (panic stop or reconnect). Reference the machine before "
                   "any absolute move."),
                QStringLiteral("fault"), true};
    return {tr("Not referenced: positions are unknown until the axes are referenced."),
            QStringLiteral("warning"), true};
}

} // namespace stepdeck::ui
