#pragma once
#include "NgcLineExpander.h"
#include "NgcParameters.h"
#include "NgcStatement.h"
#include <QCoreApplication>
#include <functional>
#include <memory>

namespace stepdeck::program {

// The bounds of working a program out (NgcInterpreter): a loop's passes each time it is
// entered, the lines run and the lines given out. Lower ones serve tests and the fuzz target.
struct NgcLimits
{
    qint64 passes = 1000000;
    qint64 steps = 20000000; // a long line counts once per 64 characters
    qint64 lines = 5000000;
};

// What a program in LinuxCNC's language is worked out against (ProgramExpansion).
struct NgcContext
{
    NgcLimits limits;
    CoordinateSystems coordinateSystems; // #5221.. (MachineFacts)
    int activeSystem = 0;                // #5220 - 1
    // LinuxCNC's SUBROUTINE_PATH: "O<name> call" of a subroutine the file does not hold reads
    // <folder>/<name>.ngc (MachineDescription::subroutineFolder). Empty: none.
    QString subroutineFolder;
    // LinuxCNC's block delete switch (ProgramParser::setBlockDelete): on, a line whose first
    // character is "/" is skipped whole, O words and assignments too; off, it runs without it.
    bool blockDelete = true;
};

// Runs the control flow of a program in LinuxCNC's language (issue 33): O-word subroutines,
// branches and loops, parameters and expressions, and gives out its ordinary lines in the order
// they run, their values worked out (NgcLineExpander). The check and the run both take what it
// gives out (ProgramExpansion), so what runs is what was checked. Bounded: a loop runs at most
// kMaxPasses times each time it is entered, calls nest kMaxCallDepth deep (LinuxCNC's
// INTERP_SUB_ROUTINE_LEVELS), at most kMaxSteps lines run (a long line counting once per 64
// characters) and kMaxLines are given out (NgcContext::limits); past a
// bound the program is refused with an error naming the line. The first error ends the work.
class NgcInterpreter
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::NgcInterpreter)
public:
    static constexpr int kMaxCallDepth = 10;
    static constexpr qint64 kMaxPasses = NgcLimits{}.passes;
    static constexpr qint64 kMaxSteps = NgcLimits{}.steps;
    static constexpr qint64 kMaxLines = NgcLimits{}.lines;
    static constexpr qint64 kMaxSubroutineBytes = 1024 * 1024;

    // text, sourceLine (1-based, of the main file; a folder subroutine's lines: its call's) and
    // the source columns of the text's words in their order (none for a folder subroutine's
    // line: its words stand in another file). false: stop (the receiver failed).
    using Output =
        std::function<bool(const QString& text, int sourceLine, const QList<int>& columns)>;

    NgcInterpreter(const QStringList& lines, const NgcContext& context, Output output);
    ~NgcInterpreter();
    // Asked every few thousand lines run; false ends the work (cancelled(), no error).
    void setKeepGoing(std::function<bool()> keepGoing) { m_keepGoing = std::move(keepGoing); }
    // Every structure error of the main file, or the first error of the run.
    bool run(QList<ProgramError>* errors, int maxErrors);
    bool cancelled() const { return m_cancelled; }
    // After run(), for the check's notes: the main file's lines block delete skipped and the
    // first of them (1-based); the line the program ended at outside any call (M2, M30 or the
    // closing "%"; 0: it ran to the file's end or ended in a subroutine), and the lines with
    // text after it that LinuxCNC does not read (subroutine definitions there are read, and a
    // "%" closing a program opened with one is its end).
    int deletedLines() const { return m_deleted; }
    int firstDeletedLine() const { return m_firstDeleted; }
    int endLine() const { return m_endLine; }
    int unreadLines() const;

private:
    struct File;
    struct Frame;
    bool step();
    bool ordinary(const QString& text);
    void noteInput(const NgcExpandedLine& line);
    bool statement(const NgcStatement& s);
    bool branch(int line);
    bool loopStatement(const NgcStatement& s);
    bool pass(const NgcStatement& s, int loop); // one more pass of `loop`, within the bound
    bool repeat(const NgcStatement& s);
    bool jumpOut(const NgcStatement& s);
    bool call(const NgcStatement& s);
    bool leave(const NgcStatement& s);
    std::optional<double> condition(const NgcStatement& s, bool required);
    const File* findSubroutine(const QString& label, int* line);
    bool fail(int column, const QString& message);
    bool failAt(const std::optional<ProgramError>& error);
    int sourceLine() const;

    NgcContext m_context;
    Output m_output;
    std::function<bool()> m_keepGoing;
    bool m_cancelled = false;
    NgcParameters m_parameters;
    std::vector<std::unique_ptr<File>> m_files; // [0]: the main file
    QList<Frame> m_frames;
    int m_pc = 0;
    const File* m_file = nullptr;
    qint64 m_steps = 0;
    int m_sinceAsked = 0; // lines run since keepGoing was asked
    qint64 m_lines = 0;
    bool m_ended = false;
    bool m_percentOpen = false;
    int m_endLine = 0;
    bool m_endedAtPercent = false;
    int m_deleted = 0;
    int m_firstDeleted = 0;
    std::optional<ProgramError> m_error;
};

} // namespace stepdeck::program
