#pragma once
// What `stepdeck-cli run` prints (CliProgramRun.cpp; docs/cli.md "run"): the program's errors
// as FILE:LINE:COL lines, the preview of --dry-run, one progress line per block on stderr or,
// with --json, one JSON event per block on stdout and a summary at the end.
#include "CliOutput.h"
#include "machine/MachineDescription.h"
#include "program/ProgramCheck.h"
#include "program/ProgramRunner.h"
#include <QElapsedTimer>
#include <QObject>

namespace stepdeck::cli {

// Every error as "FILE:LINE:COL: message" on stderr, one line each (the compilers' form, so an
// editor can jump to it); FILE as it was given on the command line.
void printProgramErrors(const QString& path, const QList<program::ProgramError>& errors);

// The check's notes (ProgramCheckResult::notes, issue 50: a feed above the machine's highest
// runs at it) as "FILE:LINE:COL: note: message" on stderr, the compilers' form of a note; with
// --json one {"event": "note", "line", "column", "message"} object each on stdout.
void printProgramNotes(const QString& path, const QList<program::ProgramError>& notes, bool json);

// --dry-run: lines, blocks, extents per axis in its unit, the estimated duration; one JSON
// object with --json.
void printProgramPreview(const QString& path, const program::ProgramPreview& preview,
                         const machine::MachineDescription& description, bool json);

// One line on stderr without the "stepdeck-cli:" of a failure (progress, M0's prompt).
void printProgress(const QString& line);

// How far a long pass over a program is ("reading prog.ngc: 42 %"), on stderr and only when it
// is a terminal (issue 29): one line rewritten in place, at most once per percent, erased by
// done(). A check's CheckProgress.
class TerminalProgress
{
public:
    explicit TerminalProgress(const QString& what);
    ~TerminalProgress();
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;

    bool update(qint64 done, qint64 total); // true: go on
    program::CheckProgress callback();
    void done();

private:
    QString m_what;
    bool m_terminal = false;
    int m_shown = -1; // percent on screen, -1: nothing
};

// Follows a running program: "line 12/40: G0 X10" on stderr when a block starts, or with
// --json {"event":"block","line":12,"state":"done",...} on stdout when it ended; summary()
// closes the run (a JSON object with --json, a line on stdout when it finished).
class ProgramReport
{
public:
    ProgramReport(program::ProgramRunner& runner, int lines, bool json);
    ProgramReport(const ProgramReport&) = delete;
    ProgramReport& operator=(const ProgramReport&) = delete;

    // The run ended with `outcome` (its exit code and, on failure, its message);
    // `positions`: where the axes ended ("X=2.500 A=25.000"), for the finished line.
    void summary(const Outcome& outcome, const QString& positions);

private:
    void blockStarted(int line, const QString& text);
    void blockFinished(int line);
    void paused(int line, const QString& prompt);

    program::ProgramRunner& m_runner;
    int m_lines = 0;
    bool m_json = false;
    int m_line = 0; // the block running: its line and text
    QString m_text;
    QElapsedTimer m_clock;
    QObject m_guard; // the connections to the runner live as long as this
};

} // namespace stepdeck::cli
