#pragma once
#include <QObject>

namespace stepdeck::program {
class ProgramRunner;
}

namespace stepdeck::cli {

class CliMachineSession;

// The CLI's feed hold and feed override while a program runs (issue 30): Ctrl-Z (SIGTSTP)
// holds the feed (ProgramRunner::holdFeed: a contour stops on its path, a block of its own
// finishes first) and SIGCONT (fg, kill -CONT) resumes it; SIGUSR1 raises the feed override by
// 10 %, SIGUSR2 lowers it (10..200 %). Each is said on stderr, and with --json as an event
// {"event":"hold"|"resume","line":n} or {"event":"override","percent":p} on stdout. The
// signals are caught only while the program runs, so the process itself is never stopped
// mid-motion; afterwards they have their defaults again.
class CliFeedHold
{
public:
    CliFeedHold(program::ProgramRunner& runner, CliMachineSession& session, bool json);
    ~CliFeedHold();
    CliFeedHold(const CliFeedHold&) = delete;
    CliFeedHold& operator=(const CliFeedHold&) = delete;

    // Held by the operator (Ctrl-Z) and not resumed yet: M0's Enter does not answer it.
    bool holding() const { return m_holding; }

private:
    bool onSignal(int signalNumber);
    void hold();
    void resume();
    void changeOverride(int percent);

    program::ProgramRunner& m_runner;
    CliMachineSession& m_session;
    bool m_json = false;
    bool m_holding = false;
};

} // namespace stepdeck::cli
