#pragma once
#include "NgcInterpreter.h"
#include "program/Program.h"
#include <QCoreApplication>
#include <QHash>
#include <memory>
#include <vector>

namespace stepdeck::program {

// The lines a worked-out program (ProgramExpansion) was given out from: its line n (1-based)
// came from the source's line sourceLine(n). Runs of consecutive lines take one entry: a loop
// of a million passes over a three-line body takes about 8 MB.
class NgcLineMap
{
public:
    void add(int expandedLine, int sourceLine);
    int sourceLine(int expandedLine) const;
    size_t runs() const { return m_runs.size(); }
    // The source columns of a source line's words, in their order (a line gives out the same
    // letters each time it runs; its values may be longer than what was written, so the
    // worked-out text's columns are not the file's).
    void setWordColumns(int sourceLine, const QList<int>& columns);
    // The source column of word `index` of a line given out from `sourceLine`; 1 where none is
    // known (a folder subroutine's line, named by its call).
    int wordColumn(int sourceLine, qsizetype index) const;

private:
    struct Run
    {
        int expanded;
        int source;
    };
    std::vector<Run> m_runs;
    int m_lastExpanded = 0;
    int m_lastSource = 0;
    QHash<int, QList<int>> m_wordColumns; // bounded by the source's size
};

// What a program in LinuxCNC's language was worked out against; a run refuses a program
// worked out against other offsets (ProgramCheck).
struct ProgramExpansionInfo
{
    std::shared_ptr<const NgcLineMap> lines;
    int sourceLines = 0;
    CoordinateSystems coordinateSystems;
    int activeSystem = 0;
    // The lines working out did not give out and the parser never sees: those block delete
    // skipped and those after the program's end (ProgramParser::blockDeleteNote, unreadNote).
    QList<ProgramError> notes;
};

// A program in LinuxCNC's language (issue 33: parameters, expressions, O words) worked out
// into the ordinary program it runs (NgcInterpreter): the lines in the order they run, their
// values in place. The check parses and checks that text, and the run runs the same text, so
// what runs is what was checked. Programs without the language are not worked out: they are
// read as they are, streamed (issue 29). A program in the language is read whole into memory
// (at most kMaxSourceBytes); what it gives out is kept in memory up to kMemoryBytes and in a
// temporary file beyond.
class ProgramExpansion
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramExpansion)
public:
    static constexpr qint64 kMaxSourceBytes = 8 * 1024 * 1024;
    static constexpr qint64 kMemoryBytes = 4 * 1024 * 1024;

    struct Result
    {
        ProgramSource source; // the worked-out text
        std::shared_ptr<const ProgramExpansionInfo> info;
    };

    // Whether the text uses the language: "#" or "[" outside comments, an O word other than
    // repeat/endrepeat, or a (DEBUG, …)/(PRINT, …) comment. nullopt with *error when the
    // source cannot be read.
    static std::optional<bool> usesLanguage(const ProgramSource& source, QString* error);
    static bool usesLanguage(QByteArrayView text);
    // nullopt with *errors (line:column, of the source) when it cannot be worked out, or
    // without errors when keepGoing (asked every few thousand lines) ended it.
    static std::optional<Result> expand(const ProgramSource& source, const NgcContext& context,
                                        QList<ProgramError>* errors, int maxErrors = 100,
                                        const std::function<bool()>& keepGoing = {});
};

} // namespace stepdeck::program
