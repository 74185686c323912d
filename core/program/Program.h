#pragma once
#include "ProgramBlock.h"
#include "ProgramLine.h"
#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <memory>
#include <unordered_map>
#include <vector>

class QFile;

namespace stepdeck::program {

class NgcLineMap;
struct ProgramExpansionInfo;

// Where a program's text comes from (issue 29, "streamed, any length"): a file, read again by
// every pass (the check, the run, a run from line N), or bytes held in memory (the editor's
// text, tests). Cheap to copy: the bytes are shared.
class ProgramSource
{
public:
    ProgramSource() = default;
    static ProgramSource file(const QString& path);
    static ProgramSource bytes(const QByteArray& text);
    // A file that lives as long as a copy of the source does (a worked-out program, issue 33).
    static ProgramSource temporaryFile(std::shared_ptr<QFile> file);

    bool isFile() const { return m_isFile; }
    QString path() const { return m_path; }
    // The source's length in bytes now (a file's size on disk); -1 when it cannot be read.
    qint64 size() const;

private:
    friend class ProgramSourceReader;
    QString m_path;
    QByteArray m_bytes;
    bool m_isFile = false;
    std::shared_ptr<QFile> m_keep;
};

// Reads byte ranges of a source: a file opened once and kept open, or the bytes themselves.
class ProgramSourceReader
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramSourceReader)
public:
    explicit ProgramSourceReader(const ProgramSource& source);
    ~ProgramSourceReader();
    ProgramSourceReader(const ProgramSourceReader&) = delete;
    ProgramSourceReader& operator=(const ProgramSourceReader&) = delete;

    bool open(QString* error);
    // Up to `length` bytes from `offset`; empty at the end. Fewer bytes than asked, or an
    // empty result before the end, with *error set when the source cannot be read.
    QByteArray read(qint64 offset, qint64 length, QString* error);
    qint64 size() const { return m_size; }

private:
    ProgramSource m_source;
    std::unique_ptr<QFile> m_file;
    qint64 m_size = 0;
};

// What the parser carries from line to line, so that parsing can go on at any line of the
// index (ProgramReader) as if it had read every line before it.
struct ParserState
{
    int line = 0;   // lines read
    int blocks = 0; // blocks given out
    ModalState modal;
    int endLine = 0;            // the line of M2/M30, once read
    bool anyWords = false;      // a line with words was read
    int percentOpen = 0;        // the line of the first "%", if any
    bool percentClosed = false; // the second "%": LinuxCNC ignores what follows it
    bool named = false;         // a Fanuc program number was read (ProgramParser::programNumber)
};

// A point the program's text can be read again from: the state before line `state.line + 1`,
// which starts at byte `offset`. `hash` covers the bytes of its lines up to the next
// checkpoint, so that a file changed since the check is noticed before its blocks run.
struct ProgramCheckpoint
{
    qint64 offset = 0;
    quint64 hash = 0;
    ParserState state;
};

// The sparse index of a program, bounded whatever its length: a checkpoint every
// kCheckpointLines lines (run from line, errors, repeats, the run's reading) and the partners of
// its repeats. About 200 bytes per checkpoint: 10^7 lines take about 1 MB.
struct ProgramIndex
{
    static constexpr int kCheckpointLines = 2048;
    std::vector<ProgramCheckpoint> checkpoints; // the first at line 0, byte 0
    std::unordered_map<int, int> partners;      // RepeatStart <-> RepeatEnd block indices
    qint64 bytes = 0;                           // the source's length when it was read
    // LinuxCNC's block delete switch the program was read with (ProgramParser::setBlockDelete):
    // every reading of it again skips the same "/" lines.
    bool blockDelete = true;
    // A worked-out program (issue 33): its lines' source lines; null: the text is the source.
    std::shared_ptr<const NgcLineMap> lineMap;

    int partner(int block) const
    {
        const auto it = partners.find(block);
        return it == partners.end() ? -1 : it->second;
    }
    // The checkpoint whose lines hold block `block` (the last one that starts at or before it).
    size_t checkpointOfBlock(int block) const;
    // The checkpoint whose lines hold line `line` (1-based).
    size_t checkpointOfLine(int line) const;
};

// A checked or parsed program: where its text is and its index. The blocks themselves are read
// again from the source when they are needed (ProgramReader), so a program of any length takes
// a bounded amount of memory. Cheap to copy.
struct Program
{
    ProgramSource source;
    QStringList axisNames; // what the parser was given
    int lines = 0;         // lines in the file
    int blockCount = 0;    // blocks in the file (lines with words)
    std::shared_ptr<const ProgramIndex> index;
    // A program in LinuxCNC's language: what it was worked out from and against (its blocks'
    // lines are the source's); null: the source is the text (ProgramExpansion).
    std::shared_ptr<const ProgramExpansionInfo> expansion;
    // A Fanuc-style program number before the first block ("O1001 (BRACKET)", ":1001"), as
    // written; empty: none.
    QString name;
    // What the parser read and does not run, or reads otherwise than LinuxCNC (the lines after
    // the program's end, "/" lines skipped, GRBL's "$" lines, a zero arc offset along the
    // plane's normal): the check's notes, in line order (ProgramCheckResult::notes).
    QList<ProgramError> notes;

    // Every block, read into memory (tests and small tools: a long program takes its size;
    // ProgramReader reads one window at a time).
    QList<ProgramBlock> allBlocks() const;
};

// A hash step over one line's bytes (ProgramCheckpoint::hash).
quint64 hashLine(quint64 hash, const char* data, qsizetype size);

} // namespace stepdeck::program
