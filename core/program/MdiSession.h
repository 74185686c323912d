#pragma once
#include "Program.h"
#include "ProgramLine.h"
#include <QCoreApplication>
#include <QStringList>
#include <optional>

namespace stepdeck::program {

// Manual data input (MDI, issue 31; issue 30: programs, MDI lines and Go to reach the
// controllers the same way): one G-code line at a time, each run as a program of that one line
// through ProgramRunner, so it passes the same check before anything moves. As in LinuxCNC's
// MDI, the modal state carries from line to line: G91, G20, F, the plane, G64 stay until a line
// changes them. A line's state is taken only once it ran to its end (lineRan(true)); a refused,
// failed or aborted line leaves the state as it was. Pure: no machine, no I/O.
class MdiSession
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::MdiSession)
public:
    static constexpr int kHistoryLines = 100; // the oldest goes first

    // The line as a program of one line, parsed in the state the last finished line left;
    // nullopt with *errors (at line 1) for a line that does not parse or does nothing. The
    // line goes into the history either way (an operator corrects a typo by Up).
    std::optional<Program> prepare(const QString& line, const QStringList& axisNames,
                                   QList<ProgramError>* errors);
    // The prepared line ran: finished (to its end) takes the state it leaves. A line that
    // selected G54..G59 gives that system (0 = G54) for the window to make active, and the
    // next lines run in whichever system the window has active then, as programs do.
    std::optional<int> lineRan(bool finished);
    void reset(); // G-code's defaults (another machine), the history kept

    const ModalState& modal() const { return m_modal; }
    // The state in G-code words, as LinuxCNC's "Active G-codes": "G90 G21 G17 G64 F300".
    static QString modalText(const ModalState& modal);
    QStringList history() const { return m_history; } // oldest first, no repeat in a row

private:
    ModalState m_modal;
    std::optional<ModalState> m_pending; // after the prepared line
    QStringList m_history;
};

} // namespace stepdeck::program
