#include "ProgramParser.h"
#include "ProgramLine.h"
#include <algorithm>

namespace stepdeck::program {

ProgramParser::ProgramParser(const QStringList& axisNames) : m_axisNames(axisNames) {}

std::optional<Program> ProgramParser::parse(const QByteArray& text, const QStringList& axisNames,
                                            QList<ProgramError>* errors)
{
    ProgramParser parser(axisNames);
    parser.feed(text);
    return parser.finish(errors);
}

void ProgramParser::feed(const QByteArray& bytes)
{
    // A line longer than kMaxLineLength characters is an error; its bytes are not kept (at
    // most four UTF-8 bytes per character are buffered), so the buffer stays bounded.
    constexpr qsizetype kMaxPendingBytes = kMaxLineLength * 4;
    qsizetype start = 0;
    for (;;) {
        const qsizetype newline = bytes.indexOf('\n', start);
        const qsizetype end = newline < 0 ? bytes.size() : newline;
        if (!m_pendingTooLong) {
            m_pending.append(bytes.constData() + start, end - start);
            if (m_pending.size() > kMaxPendingBytes) {
                m_pendingTooLong = true;
                m_pending.clear();
            }
        }
        if (newline < 0)
            return;
        endLine();
        start = newline + 1;
    }
}

void ProgramParser::endLine()
{
    ++m_line;
    const bool tooLong = m_pendingTooLong;
    QByteArray raw = std::move(m_pending);
    m_pending.clear();
    m_pendingTooLong = false;
    if (m_line > kMaxLines) {
        if (m_line == kMaxLines + 1)
            error(m_line, 1, tr("the program is longer than %1 lines").arg(kMaxLines));
        return;
    }
    if (m_percentClosed)
        return; // after the closing "%" (LinuxCNC ignores the rest of the file)
    if (raw.endsWith('\r'))
        raw.chop(1);
    if (m_line == 1 && raw.startsWith("\xEF\xBB\xBF"))
        raw.remove(0, 3); // a UTF-8 byte-order mark, as some editors on Windows write it
    const QString text = QString::fromUtf8(raw);
    if (tooLong || text.size() > kMaxLineLength) {
        error(m_line, kMaxLineLength + 1,
              tr("the line is longer than %1 characters").arg(kMaxLineLength));
        return;
    }
    if (!percentLine(text))
        parseLine(text);
}

bool ProgramParser::percentLine(const QString& text)
{
    if (text.trimmed() != QLatin1String("%"))
        return false;
    // LinuxCNC: a "%" on the first line with words (blank lines before it allowed) opens the
    // program, and a second "%" ends it; anywhere else it is an error.
    if (!m_anyWords && m_percentOpen == 0) {
        m_percentOpen = m_line;
        return true;
    }
    if (m_percentOpen > 0) {
        m_percentClosed = true;
        return true;
    }
    error(m_line, int(text.indexOf(QLatin1Char('%'))) + 1,
          tr("\"%\" stands only on the program's first line and, closing it, its last"));
    return true;
}

void ProgramParser::parseLine(const QString& text)
{
    const LexedLine lexed = ProgramLexer::lex(text, m_line);
    if (lexed.error) {
        error(lexed.error->line, lexed.error->column, lexed.error->message);
        return;
    }
    m_anyWords = m_anyWords || !lexed.words.isEmpty();
    if (!lexed.words.isEmpty() && m_endLine > 0) {
        error(m_line, lexed.words.first().column,
              tr("nothing may follow the program's end (line %1)").arg(m_endLine));
        return;
    }
    std::optional<ProgramError> failure;
    ModalState modal = m_modal;
    std::optional<ProgramBlock> block =
        ProgramLine::parse(lexed, m_line, m_axisNames, &modal, &failure);
    if (failure) {
        error(failure->line, failure->column, failure->message);
        noteBrokenRepeat(lexed);
        return;
    }
    if (!block)
        return; // blank or only a comment
    m_modal = modal;
    block->line = m_line;
    block->text = text.trimmed();
    if (block->kind == BlockKind::End)
        m_endLine = m_line;
    addBlock(*block);
}

// An "O<n> repeat" line with an error still opens its repeat, so that its endrepeat is not
// reported as well.
void ProgramParser::noteBrokenRepeat(const LexedLine& lexed)
{
    const QList<ProgramWord>& w = lexed.words;
    const qsizetype o = !w.isEmpty() && w.first().letter == QLatin1Char('N') ? 1 : 0;
    if (o < w.size() && w.at(o).letter == QLatin1Char('O') &&
        lexed.keyword == QLatin1String("repeat") && m_openRepeats.size() < kMaxNesting &&
        w.at(o).value >= 0 && w.at(o).value < 1e9) // an int, or no repeat
        m_openRepeats << OpenRepeat{-1, int(w.at(o).value), m_line};
}

void ProgramParser::addBlock(ProgramBlock block)
{
    const int index = int(m_program.blocks.size());
    if (block.kind == BlockKind::RepeatStart) {
        if (m_openRepeats.size() >= kMaxNesting) {
            error(block.line, 1, tr("repeats nest deeper than %1").arg(kMaxNesting));
            return;
        }
        m_openRepeats << OpenRepeat{index, block.oNumber, block.line};
    } else if (block.kind == BlockKind::RepeatEnd) {
        if (m_openRepeats.isEmpty()) {
            error(block.line, 1, tr("O%1 endrepeat without its O%1 repeat").arg(block.oNumber));
            return;
        }
        const OpenRepeat open = m_openRepeats.last();
        if (open.oNumber != block.oNumber) {
            error(block.line, 1,
                  tr("O%1 endrepeat does not close O%2 repeat (line %3)")
                      .arg(block.oNumber)
                      .arg(open.oNumber)
                      .arg(open.line));
            return;
        }
        m_openRepeats.removeLast();
        if (open.index >= 0) {
            m_program.blocks[open.index].partner = index;
            block.partner = open.index;
        }
    }
    m_program.blocks << block;
}

void ProgramParser::error(int line, int column, const QString& message)
{
    if (m_errors.size() >= kMaxErrors) {
        m_tooManyErrors = true;
        return;
    }
    m_errors << ProgramError{line, column, message};
}

std::optional<Program> ProgramParser::finish(QList<ProgramError>* errors)
{
    if (!m_pending.isEmpty() || m_pendingTooLong)
        endLine(); // the last line needs no newline
    for (const OpenRepeat& open : std::as_const(m_openRepeats)) {
        if (open.index >= 0) // a broken one was reported already
            error(open.line, 1, tr("O%1 repeat is not closed by O%1 endrepeat").arg(open.oNumber));
    }
    m_openRepeats.clear();
    if (m_percentOpen > 0 && !m_percentClosed && m_endLine == 0)
        error(m_line, 1,
              tr("the program opened with \"%\" (line %1) ends with neither \"%\" nor M2/M30")
                  .arg(m_percentOpen));
    std::stable_sort(m_errors.begin(), m_errors.end(),
                     [](const ProgramError& a, const ProgramError& b) { return a.line < b.line; });
    if (m_tooManyErrors)
        m_errors << ProgramError{
            m_line, 1, tr("more errors follow; only the first %1 are listed").arg(kMaxErrors)};
    m_program.lines = m_line;
    if (errors)
        *errors = m_errors;
    if (!m_errors.isEmpty())
        return std::nullopt;
    return m_program;
}

} // namespace stepdeck::program
