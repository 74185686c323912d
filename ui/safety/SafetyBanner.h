#pragma once
#include "controller/Controller.h"
#include "machine/Machine.h"
#include "program/ProgramRunner.h"
#include <QCoreApplication>

namespace stepdeck::ui {

// What the safety bar's banner says, as a pure function of what is known, so every case can
// be tested without a device. The order is the order of urgency: a machine that may still be
// moving comes before anything about positions or referencing.
// Truth rules (issue 7 rule 2, issue 11): "stopped" is never claimed unless the device
// confirmed standstill; "Release the emergency stop" only when the device reports its
// emergency-stop input and the host did not send the panic itself; "Ready" only while
// connected with every axis referenced.
struct SafetyBannerInput
{
    LinkState link = LinkState::Disconnected;
    MachineStatus status;
    // How the axes' positions are known, the worst over every axis (MachineContext::
    // positionKnowledge: the source Go to, the check and the referencing lamps judge by).
    machine::PositionKnowledge positions = machine::PositionKnowledge::Unknown;
    bool positionsLost = false;       // panic or reconnect since the last full referencing
    bool movingWhenLinkEnded = false; // the last status before the link ended showed motion
    bool hostPanicSent = false;       // PANIC pressed here, no motion started since
    // A program's run (issue 47 item 15): while it runs or holds the banner says so, not
    // "Ready". jobLine: the line running or held at.
    program::RunState job = program::RunState::Idle;
    int jobLine = 0;
};

struct SafetyBannerText
{
    QString text;
    QString severity; // "fault", "warning", "ok", "idle", "job"
    bool offerReference = false;
};

class SafetyBanner
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::SafetyBanner)
public:
    static SafetyBannerText compute(const SafetyBannerInput& in);
    // The warning STOP and PANIC carry permanently for a model without a stop command.
    static QString mayStillMoveText();
    // Every text compute() can return (in the current language): the banner reserves the
    // room of the longest, so a new state never re-flows the window (issue 16).
    static QStringList possibleTexts();
    // The setup page's title, as the banner names it.
    static QString setupPageTitle();

private:
    static SafetyBannerText disconnected(const SafetyBannerInput& in);
    static std::optional<SafetyBannerText> job(const SafetyBannerInput& in);
};

} // namespace stepdeck::ui
Q_DECLARE_METATYPE(stepdeck::ui::SafetyBannerInput)
