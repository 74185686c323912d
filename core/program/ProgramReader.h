#pragma once
#include "Program.h"
#include "ProgramParser.h"
#include <memory>
#include <vector>

namespace stepdeck::program {

// The blocks of a program by index, read from its source as they are needed (issue 29,
// "streamed, any length"): what stays in memory is a window of blocks, not the program.
//
// - Over a Program (its index complete, after a parse or a check): a block is read again from
//   the checkpoint before it (at most ProgramIndex::kCheckpointLines lines), and the bytes read
//   must hash as they did when the program was checked: a file changed since then is an error
//   (error()), never a different program run.
// - Over a source (the check's one pass): the reader parses the text as the walk asks for
//   blocks, building the index as it goes; earlier blocks (a repeat's next pass) are read again
//   from the index built so far. finish() gives the Program (or the parser's errors).
//
// Not thread-safe; one reader per pass.
class ProgramReader
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramReader)
public:
    // Bytes a one pass reads at a time: a few hundred lines, far fewer than its window keeps.
    static constexpr qint64 kReadBytes = 16 * 1024;

    explicit ProgramReader(const Program& program);
    // lineMap: the source is a worked-out program (ProgramExpansion) whose blocks name these
    // lines. blockDelete: LinuxCNC's switch (ProgramParser::setBlockDelete).
    ProgramReader(const ProgramSource& source, const QStringList& axisNames,
                  std::shared_ptr<const NgcLineMap> lineMap = {}, bool blockDelete = true);
    ~ProgramReader();

    // The block at `index` (0-based, file order); nullptr past the last block, or when the text
    // cannot be read as it was (error()). Valid until the next call of any method.
    const ProgramBlock* at(int index);
    // The other end of a repeat's block (reading on to it if needed), -1: none.
    int partner(int index);
    // The first block on or after `line`, -1: none.
    int firstBlockAtLine(int line);
    // The outermost repeat whose passes hold block `index` (its RepeatStart), -1: none.
    int enclosingRepeat(int index);
    // The line of the program's last block (0: none).
    int lastBlockLine();
    QString error() const { return m_error; }

    // How far the text is read (over a Program: the end of the farthest checkpoint's lines read
    // back), and its length (progress).
    qint64 bytesRead() const { return m_liveOffset; }
    qint64 totalBytes() const { return m_size; }
    bool parseFailed() const { return m_live && m_live->errorCount() > 0; }
    // One pass: reads the rest; the Program, or nullopt with the parser's errors (or the
    // source's, as a line-0 error).
    std::optional<Program> finish(QList<ProgramError>* errors);

    // Every block of a program (tests and small tools; a long program takes its size in memory).
    static QList<ProgramBlock> readAll(const Program& program);

private:
    bool pull(); // one pass: parse the next bytes; false at the end
    const ProgramBlock* fromWindow(int index);
    bool loadChunk(size_t checkpoint); // the blocks of one checkpoint's lines into m_chunk
    const ProgramIndex& currentIndex() const;
    void fail(const QString& message);

    Program m_program; // over a Program
    ProgramSource m_source;
    QStringList m_axisNames;
    std::unique_ptr<ProgramSourceReader> m_reader;
    qint64 m_size = 0;
    QString m_error;
    // One pass.
    std::unique_ptr<ProgramParser> m_live;
    qint64 m_liveOffset = 0;
    bool m_liveEnd = false;
    // The last blocks parsed, oldest first, in a ring of reused slots (a block is too large
    // for std::deque to keep more than one per allocation).
    class Window
    {
    public:
        explicit Window(size_t capacity) : m_slots(capacity) {}
        size_t size() const { return m_count; }
        bool empty() const { return m_count == 0; }
        ProgramBlock& operator[](size_t i) { return m_slots[(m_head + i) % m_slots.size()]; }
        ProgramBlock& back() { return (*this)[m_count - 1]; }
        void clear() { m_head = m_count = 0; }
        // false: full, the oldest gave way.
        bool push(ProgramBlock&& block)
        {
            if (m_count < m_slots.size()) {
                (*this)[m_count++] = std::move(block);
                return true;
            }
            m_slots[m_head] = std::move(block);
            m_head = (m_head + 1) % m_slots.size();
            return false;
        }

    private:
        std::vector<ProgramBlock> m_slots;
        size_t m_head = 0;
        size_t m_count = 0;
    };
    Window m_window{0};
    int m_windowFirst = 0;
    // A checkpoint's blocks read again.
    std::vector<ProgramBlock> m_chunk;
    int m_chunkFirst = 0;
    size_t m_chunkCheckpoint = size_t(-1);
};

} // namespace stepdeck::program
