#pragma once
#include "program/MdiSession.h"
#include "program/ProgramRunner.h"
#include <QObject>
#include <QPointer>
#include <functional>

namespace stepdeck::ui {

class MachineContext;
class ProgramStarter;

// One G-code line at a time on the open machine (issue 31's MDI line; issue 30: "programs, MDI
// lines and Go to reach controllers through the motion layer"): each line runs as a program of
// that one line through its own ProgramRunner, after the same check a program has (off the GUI
// thread, ProgramStarter), so that a line is refused with its reason before anything moves,
// and its moves take the same path to the controllers (contours, coordinated feeds, arcs).
// MDI lines keep their modal state from line to line (MdiSession); Go to's lines are lines of
// their own, in G-code's defaults, outside the MDI's state and history.
//
// One line at a time, and none while something else holds the machine's motion (a program:
// Machine::claimMotion). The machine's STOP, PANIC and close abort a line (its runner holds the
// motion); abort() does it from here. M0 or M6 on a line hold it like a program: resume().
class MachineMdi : public QObject
{
    Q_OBJECT
public:
    explicit MachineMdi(MachineContext* context, QObject* parent = nullptr);
    ~MachineMdi() override;

    // An MDI line, in the state the last finished one left; it goes into the history. The
    // id that ended() reports, or 0 and *refusal when refused at once (nothing sent).
    quint64 runLine(const QString& line, QString* refusal);
    // A line of its own (Go to), in G-code's defaults; the MDI's state and history unchanged.
    quint64 runOwnLine(const QString& line, QString* refusal);
    // The window's feed override (10..200 %, the Program page's), for the lines' feed moves as
    // for a program's.
    void setFeedOverride(int percent);
    void resume(); // a line held at M0 or M6 goes on
    void abort();  // the line being checked or run ends (the machine's stop does it too)

    bool isBusy() const; // a line is checked or runs
    bool isPausedAtOperatorStop() const;
    QString prompt() const;
    const program::MdiSession& session() const { return m_session; }
    program::ProgramRunner* runner() const { return m_runner; }

Q_SIGNALS:
    void busyChanged(bool busy);
    void started(quint64 id);
    // The line's end: finished (ok), or why not ("X is not referenced", "Aborted", ...).
    void ended(quint64 id, bool ok, const QString& message);
    void paused(quint64 id, const QString& prompt); // at M0 or M6
    void operatorMessage(int line, const QString& text);

private:
    quint64 start(const QString& line, bool mdi, QString* refusal);
    void onMachineChanged();
    void onStartRefused(const QList<program::ProgramError>& errors);
    void onFinished(program::RunState state, const QString& message);
    void end(bool ok, const QString& message);

    MachineContext* m_context;
    ProgramStarter* m_starter;
    program::ProgramRunner* m_runner = nullptr;
    QPointer<QObject> m_runnerMachine;
    program::MdiSession m_session;
    int m_feedOverride = 100;
    quint64 m_lastId = 0;
    quint64 m_current = 0;       // the line being checked or run (0: none)
    bool m_currentIsMdi = false; // its state is taken when it finishes
};

} // namespace stepdeck::ui
