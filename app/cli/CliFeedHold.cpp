#include "CliFeedHold.h"
#include "../common/SignalPipe.h"
#include "CliMachineSession.h"
#include "CliOutput.h"
#include "CliProgramOutput.h"
#include "CliText.h"
#include "program/ProgramRunner.h"
#include <QJsonObject>
#include <cmath>
#include <csignal>

namespace stepdeck::cli {

using program::RunState;

namespace {
constexpr int kSignals[] = {SIGTSTP, SIGCONT, SIGUSR1, SIGUSR2};
}

CliFeedHold::CliFeedHold(program::ProgramRunner& runner, CliMachineSession& session, bool json)
    : m_runner(runner), m_session(session), m_json(json)
{
    m_session.setProgramSignals([this](int number) { return onSignal(number); });
    for (int number : kSignals)
        app::SignalPipe::catchAlso(number);
}

CliFeedHold::~CliFeedHold()
{
    for (int number : kSignals)
        app::SignalPipe::release(number);
    m_session.setProgramSignals({});
}

bool CliFeedHold::onSignal(int signalNumber)
{
    switch (signalNumber) {
    case SIGTSTP:
        hold();
        return true;
    case SIGCONT:
        resume();
        return true;
    case SIGUSR1:
        changeOverride(10);
        return true;
    case SIGUSR2:
        changeOverride(-10);
        return true;
    default:
        return false;
    }
}

void CliFeedHold::changeOverride(int percent)
{
    m_runner.setFeedOverride(m_runner.feedOverride() + percent);
    const int now = int(std::lround(m_runner.feedOverride()));
    if (m_json)
        printJson(QJsonObject{{"event", "override"}, {"percent", now}});
    printProgress(CliText::tr("feed override %1 %").arg(now));
}

void CliFeedHold::hold()
{
    if (m_holding || !m_runner.holdFeed())
        return;
    m_holding = true;
    const int line = m_runner.currentLine();
    if (m_json)
        printJson(QJsonObject{{"event", "hold"}, {"line", line}, {"contour", m_runner.feedHeld()}});
    printProgress(m_runner.feedHeld()
                      ? CliText::tr("line %1: feed hold; the path stops where it is "
                                    "(SIGCONT, e.g. fg, resumes)")
                            .arg(line)
                      : CliText::tr("line %1: feed hold after this block (SIGCONT, e.g. fg, "
                                    "resumes)")
                            .arg(line));
}

void CliFeedHold::resume()
{
    if (!m_holding)
        return;
    m_holding = false;
    const int line = m_runner.currentLine();
    if (m_runner.state() == RunState::Paused)
        m_runner.resume();
    if (m_json)
        printJson(QJsonObject{{"event", "resume"}, {"line", line}});
    printProgress(CliText::tr("line %1: resumed").arg(line));
}

} // namespace stepdeck::cli
