#include "SafetyBanner.h"

namespace stepdeck::ui {

QString SafetyBanner::setupPageTitle()
{
    // The title of the setup page's dock as the window shows it (German: "Einrichtung").
    return QCoreApplication::translate("stepdeck::ui::MainWindow", "Setup");
}

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

// A program that runs or holds: what the operator watches then, in place of "Ready" (issue 47
// item 15). Faults, a panic and an incomplete setup still come first.
std::optional<SafetyBannerText> SafetyBanner::job(const SafetyBannerInput& in)
{
    using program::RunState;
    switch (in.job) {
    case RunState::Running:
        return SafetyBannerText{tr("Program running, line %1: STOP (Esc) ends it, Hold (F2) stops "
                                   "it on its path.")
                                    .arg(in.jobLine),
                                QStringLiteral("job")};
    case RunState::Paused:
        return SafetyBannerText{
            tr("Program held at line %1: Resume goes on, STOP (Esc) ends it.").arg(in.jobLine),
            QStringLiteral("job")};
    case RunState::Stopping:
        return SafetyBannerText{
            tr("Program stopping at line %1: waiting for the axes to stand.").arg(in.jobLine),
            QStringLiteral("warning")};
    default:
        return std::nullopt;
    }
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
                   "on the %1 page first. The controller refuses every move until then.")
                    .arg(setupPageTitle()),
                QStringLiteral("warning")};
    if (const std::optional<SafetyBannerText> running = job(in))
        return *running;
    if (in.positions == machine::PositionKnowledge::Referenced)
        return {tr("Ready: all axes referenced."), QStringLiteral("ok")};
    if (in.positions == machine::PositionKnowledge::Estimated)
        return {tr("Positions estimated, not confirmed by the controller: reference the axes "
                   "before any absolute move."),
                QStringLiteral("warning"), true};
    if (in.positionsLost)
        return {tr("Positions are lost (panic stop or reconnect). Reference the machine before "
                   "any absolute move."),
                QStringLiteral("fault"), true};
    return {tr("Not referenced: positions are unknown until the axes are referenced."),
            QStringLiteral("warning"), true};
}

QStringList SafetyBanner::possibleTexts()
{
    QStringList out;
    for (LinkState link :
         {LinkState::Disconnected, LinkState::Connecting, LinkState::Connected, LinkState::Lost}) {
        for (int flags = 0; flags < (1 << 8); ++flags) {
            SafetyBannerInput in;
            in.link = link;
            in.status.motionUnconfirmed = flags & 1;
            in.movingWhenLinkEnded = flags & 2;
            in.status.panic = flags & 4;
            in.hostPanicSent = flags & 8;
            in.jobLine = 8888888; // the widest line number a program has
            in.status.setupIncomplete = flags & 16;
            in.positionsLost = flags & 32;
            in.positions = (flags & 64)    ? machine::PositionKnowledge::Referenced
                           : (flags & 128) ? machine::PositionKnowledge::Estimated
                                           : machine::PositionKnowledge::Unknown;
            for (program::RunState job : {program::RunState::Idle, program::RunState::Running,
                                          program::RunState::Paused, program::RunState::Stopping}) {
                in.job = job;
                const QString text = compute(in).text;
                if (!out.contains(text))
                    out << text;
            }
        }
    }
    return out;
}

} // namespace stepdeck::ui
