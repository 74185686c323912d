#pragma once
#include "Program.h"
#include "ProgramBlock.h"
#include "ProgramLexer.h"
#include "ProgramLine.h"
#include <QByteArray>
#include <QCoreApplication>
#include <functional>

namespace stepdeck::program {

// Reads a motion program (issue 20, docs/programs.md): UTF-8, one block per line, LinuxCNC's
// words (docs/programs.md "Words"), N numbers, O<n> repeat/endrepeat and comments, and what
// posts and senders write around them (issue 50, "Around the program": a program number, "%",
// the text after the end, block delete's "/", GRBL's "$" lines; notes in Program::notes).
// Streaming (issue 29): bytes may arrive in any chunks, each block goes to the sink as soon as
// its line is read, and what the parser keeps is bounded whatever the program's length: the
// line being read (kMaxLineLength), the open repeats (kMaxNesting), the errors (kMaxErrors) and
// the sparse index (ProgramIndex). Every line that is not valid gets one error naming its line and
// column; a program with any error gives no Program. Pure: no I/O, no machine, only the names of
// the machine's axes.
//
// Replay: constructed at a checkpoint of a finished index, the parser reads on from there as if
// it had read every line before (ProgramReader), taking the repeats' partners from the index.
class ProgramParser
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramParser)
public:
    static constexpr int kMaxLineLength = 1024; // characters, as LinuxCNC's 256 but roomier
    // Lines are counted in an int: a program of more lines (some 40 GB) is refused.
    static constexpr int kMaxLines = 2147483646;
    static constexpr int kMaxErrors = 100;
    static constexpr qint64 kMaxRepeat = 1000000;
    static constexpr int kMaxNesting = 32;

    using Sink = std::function<void(ProgramBlock&& block)>;

    // axisNames: the machine's axes ("X", "A", ...); any other axis word is an error. The
    // first line starts in `start` (G-code's defaults; an MDI line: the state the last one
    // left, MdiSession).
    explicit ProgramParser(const QStringList& axisNames, const ModalState& start = {});
    // Replay from `from`, a checkpoint of `index` (which outlives the parser).
    ProgramParser(const QStringList& axisNames, const ProgramIndex& index,
                  const ProgramCheckpoint& from);

    // A worked-out program (issue 33): blocks and errors name the source's lines, and the index
    // keeps the map for the replays.
    void setLineMap(std::shared_ptr<const NgcLineMap> map);
    // LinuxCNC's block delete switch (on by default, as LinuxCNC's canon starts): on, a line
    // whose first character is "/" is skipped whole; off, it runs without the "/". Set before
    // the first byte; the index keeps it for every reading again.
    void setBlockDelete(bool on);
    // Where each block goes (by default nowhere: only the index and the errors are kept).
    void setSink(Sink sink) { m_sink = std::move(sink); }
    void feed(const QByteArray& bytes);
    // The program's index, or nullopt with *errors (every one, in line order, at most
    // kMaxErrors). Its source is left empty: the caller knows where the bytes came from.
    std::optional<Program> finish(QList<ProgramError>* errors);
    // Replay: the last line of the input without a newline is read as well.
    void flush();

    // Parses text held in memory: the Program's source is those bytes.
    static std::optional<Program> parse(const QByteArray& text, const QStringList& axisNames,
                                        QList<ProgramError>* errors, const ModalState& start = {},
                                        bool blockDelete = true);

    // A Fanuc-style program number alone on a line ("O1234", ":1234", a comment after it
    // allowed): the line trimmed, else nullopt. Before the program's first block it is the
    // program's name (Program::name), not one of LinuxCNC's O words.
    static std::optional<QString> programNumber(QStringView line);
    // The notes of lines not run, one form for the parser and the worked-out programs
    // (ProgramExpansion): `lines` after the program's end at `endLine`, and `lines` skipped by
    // block delete from `firstLine` on.
    static ProgramError unreadNote(int lines, int endLine);
    static ProgramError blockDeleteNote(int lines, int firstLine);

    const ParserState& state() const { return m_state; }
    qsizetype errorCount() const { return m_errors.size(); }
    quint64 hash() const
    {
        return m_hash;
    } // of the lines since the last checkpoint (replay: since the start)
    const ProgramIndex& index() const { return *m_index; } // built so far (not in replay)
    // The blocks of the repeats open now (their endrepeat not read yet), outermost first.
    QList<int> openRepeatBlocks() const;

private:
    void endLine();
    void noteCheckpoint();
    void readLine(QString text);
    void parseLine(const QString& text);
    // A line of only "%": the program's first or last line (LinuxCNC); true when handled.
    bool percentLine(const QString& text);
    // A line after the program's end: not read (LinuxCNC), counted for a note.
    void noteUnread(QByteArrayView raw);
    // GRBL's "$" lines ($H, $X, $32=1, ...); true when handled. `first`: the line's first
    // character that is not white space.
    bool dollarLine(const QString& text, qsizetype first);
    void homeLine(const QString& text, int column);
    bool programNumberLine(const QString& text);
    void noteZeroNormal(const LexedLine& lexed, Plane plane);
    void note(int line, int column, const QString& message);
    QList<ProgramError> takeNotes();
    void addBlock(ProgramBlock&& block);
    bool linkRepeat(ProgramBlock& block, int index);
    void noteBrokenRepeat(const LexedLine& lexed);
    void error(int line, int column, const QString& message);
    int sourceLine(int line) const;

    QStringList m_axisNames;
    std::shared_ptr<const NgcLineMap> m_lineMap;
    Sink m_sink;
    QByteArray m_pending;
    bool m_pendingTooLong = false;
    qint64 m_lineBytes = 0;  // bytes of the line being read (kept or not)
    qint64 m_lineOffset = 0; // where it starts
    ParserState m_state;
    std::vector<ProgramBlock> m_lineBlocks; // the blocks of the line read (its room reused)
    quint64 m_hash = 0;
    struct OpenRepeat
    {
        int index = -1; // of its block; -1: its line had an error (its endrepeat still fits)
        int oNumber = 0;
        int line = 0;
    };
    QList<OpenRepeat> m_openRepeats;
    std::shared_ptr<ProgramIndex> m_index; // built (not in replay)
    const ProgramIndex* m_replayIndex = nullptr;
    QList<ProgramError> m_errors;
    bool m_tooManyErrors = false;
    bool m_blockDelete = true;
    // For the notes (not replayed: a reading again gives out blocks only).
    QString m_name;
    QList<ProgramError> m_notes;
    bool m_tooManyNotes = false;
    int m_endedAt = 0; // the line of M2/M30 or of the closing "%"
    int m_unread = 0;  // lines with text after it
    // Lines counted for one note each: the first one's line and column, and its word.
    struct Counted
    {
        int count = 0;
        int line = 0;
        int column = 0;
        QString word;
    };
    Counted m_deleted;    // "/" lines skipped
    Counted m_zeroNormal; // arcs with a zero offset along the plane's normal
};

} // namespace stepdeck::program
