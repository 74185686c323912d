#include "ProgramReader.h"
#include "ProgramLogging.h"
#include <algorithm>

namespace stepdeck::program {

namespace {
// The window of a one pass holds this many blocks behind the newest: more than the blocks of
// one checkpoint's lines, so that a block that left it can be read again from a checkpoint
// whose lines are all read.
constexpr size_t kWindowBlocks = 2 * ProgramIndex::kCheckpointLines + 16;
} // namespace

ProgramReader::ProgramReader(const Program& program)
    : m_program(program), m_source(program.source), m_axisNames(program.axisNames),
      m_reader(std::make_unique<ProgramSourceReader>(program.source))
{
    QString why;
    if (!program.index) {
        fail(tr("the program was not read"));
    } else if (!m_reader->open(&why)) {
        fail(why);
    } else if (m_reader->size() != program.index->bytes) {
        fail(tr("the program's file changed since it was checked (%1 bytes, were %2): check it "
                "again")
                 .arg(m_reader->size())
                 .arg(program.index->bytes));
    }
    m_size = m_reader->size();
}

ProgramReader::ProgramReader(const ProgramSource& source, const QStringList& axisNames,
                             std::shared_ptr<const NgcLineMap> lineMap, bool blockDelete)
    : m_source(source), m_axisNames(axisNames),
      m_reader(std::make_unique<ProgramSourceReader>(source)),
      m_live(std::make_unique<ProgramParser>(axisNames)), m_window(kWindowBlocks)
{
    QString why;
    if (!m_reader->open(&why))
        fail(why);
    m_size = m_reader->size();
    m_live->setBlockDelete(blockDelete);
    if (lineMap)
        m_live->setLineMap(std::move(lineMap));
    m_live->setSink([this](ProgramBlock&& block) {
        if (!m_window.push(std::move(block)))
            ++m_windowFirst;
    });
}

ProgramReader::~ProgramReader() = default;

const ProgramIndex& ProgramReader::currentIndex() const
{
    return m_live ? m_live->index() : *m_program.index;
}

void ProgramReader::fail(const QString& message)
{
    if (m_error.isEmpty()) {
        m_error = message;
        qCWarning(lcProgram) << "program reader:" << message;
    }
}

bool ProgramReader::pull()
{
    if (!m_live || m_liveEnd || !m_error.isEmpty())
        return false;
    QString why;
    const QByteArray bytes = m_reader->read(m_liveOffset, kReadBytes, &why);
    if (!why.isEmpty()) {
        fail(why);
        return false;
    }
    if (bytes.isEmpty()) {
        m_liveEnd = true;
        m_live->flush(); // the last line needs no newline
        return true;
    }
    m_liveOffset += bytes.size();
    m_live->feed(bytes);
    return true;
}

const ProgramBlock* ProgramReader::fromWindow(int index)
{
    while (index >= m_windowFirst + int(m_window.size()))
        if (!pull())
            return nullptr; // past the end (or the source failed: error())
    // A pull gives out whole lines: a block may have left the window already.
    return index >= m_windowFirst ? &m_window[size_t(index - m_windowFirst)] : nullptr;
}

const ProgramBlock* ProgramReader::at(int index)
{
    if (index < 0 || !m_error.isEmpty())
        return nullptr;
    if (m_live && index >= m_windowFirst) {
        if (const ProgramBlock* b = fromWindow(index); b || index >= m_windowFirst)
            return b;
    }
    if (m_chunkCheckpoint == size_t(-1) || index < m_chunkFirst ||
        index >= m_chunkFirst + int(m_chunk.size())) {
        const ProgramIndex& in = currentIndex();
        if (!m_live && index >= m_program.blockCount)
            return nullptr;
        if (!loadChunk(in.checkpointOfBlock(index)))
            return nullptr;
        if (index >= m_chunkFirst + int(m_chunk.size())) {
            fail(tr("the program's file changed since it was checked: check it again"));
            return nullptr;
        }
    }
    ProgramBlock& block = m_chunk[size_t(index - m_chunkFirst)];
    return &block;
}

bool ProgramReader::loadChunk(size_t checkpoint)
{
    const ProgramIndex& in = currentIndex();
    const ProgramCheckpoint& from = in.checkpoints.at(checkpoint);
    const bool last = checkpoint + 1 >= in.checkpoints.size();
    if (last && m_live) {
        fail(tr("internal: the pass reads back lines it has not finished"));
        return false;
    }
    const qint64 end = last ? m_program.index->bytes : in.checkpoints.at(checkpoint + 1).offset;
    QString why;
    const QByteArray bytes = m_reader->read(from.offset, end - from.offset, &why);
    if (!why.isEmpty()) {
        fail(why);
        return false;
    }
    m_chunk.clear();
    m_chunkCheckpoint = size_t(-1);
    ProgramParser parser(m_axisNames, in, from);
    parser.setSink([this](ProgramBlock&& block) { m_chunk.push_back(std::move(block)); });
    parser.feed(bytes);
    if (last)
        parser.flush();
    const ParserState expected = last ? ParserState{m_program.lines, m_program.blockCount, {}}
                                      : in.checkpoints.at(checkpoint + 1).state;
    if (qint64(bytes.size()) != end - from.offset || parser.errorCount() > 0 ||
        parser.state().line != expected.line || parser.state().blocks != expected.blocks ||
        parser.hash() != from.hash) {
        fail(tr("the program's file changed since it was checked (lines %1..%2 differ): check it "
                "again")
                 .arg(from.state.line + 1)
                 .arg(expected.line));
        return false;
    }
    m_chunkFirst = from.state.blocks;
    m_chunkCheckpoint = checkpoint;
    if (!m_live) // how far a pass over a Program got (a repeat's next pass reads back)
        m_liveOffset = std::max(m_liveOffset, end);
    return true;
}

int ProgramReader::partner(int index)
{
    const ProgramBlock* block = at(index);
    if (!block || (block->kind != BlockKind::RepeatStart && block->kind != BlockKind::RepeatEnd))
        return -1;
    for (;;) {
        const int p = currentIndex().partner(index);
        if (p >= 0 || !m_live)
            return p;
        if (!pull())
            return -1;
    }
}

int ProgramReader::firstBlockAtLine(int line)
{
    if (m_live) {
        for (int i = 0;; ++i) {
            const ProgramBlock* b = at(i);
            if (!b)
                return -1;
            if (b->line >= line)
                return i;
        }
    }
    const ProgramIndex& in = currentIndex();
    for (size_t c = in.checkpointOfLine(line); c < in.checkpoints.size(); ++c) {
        const int first = in.checkpoints.at(c).state.blocks;
        const int next = c + 1 < in.checkpoints.size() ? in.checkpoints.at(c + 1).state.blocks
                                                       : m_program.blockCount;
        for (int i = first; i < next; ++i) {
            const ProgramBlock* b = at(i);
            if (!b)
                return -1;
            if (b->line >= line)
                return i;
        }
    }
    return -1;
}

int ProgramReader::lastBlockLine()
{
    if (m_live) {
        while (pull()) {
        }
        return m_window.empty() ? 0 : m_window.back().line;
    }
    const ProgramBlock* b = at(m_program.blockCount - 1);
    return b ? b->line : 0;
}

int ProgramReader::enclosingRepeat(int block)
{
    int outer = -1;
    for (const auto& [a, b] : currentIndex().partners)
        if (a < block && b >= block && (outer < 0 || a < outer))
            outer = a;
    if (m_live)
        for (const int open : m_live->openRepeatBlocks())
            if (open < block && (outer < 0 || open < outer))
                outer = open;
    return outer;
}

std::optional<Program> ProgramReader::finish(QList<ProgramError>* errors)
{
    if (!m_live)
        return m_program;
    while (pull()) {
        m_window.clear(); // nobody reads them any more
        m_windowFirst = m_live->state().blocks;
    }
    if (!m_error.isEmpty()) {
        if (errors)
            *errors = {ProgramError{0, 0, m_error}};
        return std::nullopt;
    }
    std::optional<Program> program = m_live->finish(errors);
    if (program)
        program->source = m_source;
    return program;
}

QList<ProgramBlock> Program::allBlocks() const
{
    return ProgramReader::readAll(*this);
}

QList<ProgramBlock> ProgramReader::readAll(const Program& program)
{
    QList<ProgramBlock> out;
    ProgramReader reader(program);
    for (int i = 0; const ProgramBlock* b = reader.at(i); ++i)
        out << *b;
    return out;
}

} // namespace stepdeck::program
