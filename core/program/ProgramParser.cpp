#include "ProgramParser.h"
#include "ProgramLine.h"
#include "language/ProgramExpansion.h"
#include <algorithm>

namespace stepdeck::program {

ProgramParser::ProgramParser(const QStringList& axisNames, const ModalState& start)
    : m_axisNames(axisNames), m_index(std::make_shared<ProgramIndex>())
{
    m_state.modal = start;
    // Replays from the first checkpoint start in the same state (ProgramReader).
    m_index->checkpoints.push_back(ProgramCheckpoint{0, 0, m_state});
}

ProgramParser::ProgramParser(const QStringList& axisNames, const ProgramIndex& index,
                             const ProgramCheckpoint& from)
    : m_axisNames(axisNames), m_lineMap(index.lineMap), m_lineOffset(from.offset),
      m_state(from.state), m_replayIndex(&index)
{
    m_blockDelete = index.blockDelete; // skips the lines the first reading skipped
}

void ProgramParser::setBlockDelete(bool on)
{
    m_blockDelete = on;
    if (m_index)
        m_index->blockDelete = on;
}

void ProgramParser::setLineMap(std::shared_ptr<const NgcLineMap> map)
{
    m_lineMap = std::move(map);
    if (m_index)
        m_index->lineMap = m_lineMap;
}

int ProgramParser::sourceLine(int line) const
{
    return m_lineMap ? m_lineMap->sourceLine(line) : line;
}

std::optional<Program> ProgramParser::parse(const QByteArray& text, const QStringList& axisNames,
                                            QList<ProgramError>* errors, const ModalState& start,
                                            bool blockDelete)
{
    ProgramParser parser(axisNames, start);
    parser.setBlockDelete(blockDelete);
    parser.feed(text);
    std::optional<Program> program = parser.finish(errors);
    if (program)
        program->source = ProgramSource::bytes(text);
    return program;
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
        m_lineBytes += end - start;
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
        m_lineOffset += 1; // the newline
        start = newline + 1;
    }
}

void ProgramParser::flush()
{
    if (!m_pending.isEmpty() || m_pendingTooLong || m_lineBytes > 0)
        endLine(); // the last line needs no newline
}

void ProgramParser::endLine()
{
    const bool tooLong = m_pendingTooLong;
    QByteArrayView raw = m_pending;
    m_pendingTooLong = false;
    m_hash = hashLine(m_hash, raw.constData(), raw.size()) ^ quint64(tooLong ? m_lineBytes : 0);
    m_lineOffset += m_lineBytes;
    m_lineBytes = 0;
    if (m_state.line >= kMaxLines) {
        if (m_state.line == kMaxLines) {
            ++m_state.line;
            error(m_state.line, 1, tr("the program is longer than %1 lines").arg(kMaxLines));
        }
        m_pending.resize(0);
        return;
    }
    ++m_state.line;
    if (m_state.percentClosed || m_state.endLine > 0) {
        // LinuxCNC reads nothing after M2/M30 or the closing "%" (a line too long to keep has
        // text too).
        if (tooLong)
            ++m_unread;
        else
            noteUnread(raw);
    } else {
        if (raw.endsWith('\r'))
            raw.chop(1);
        if (m_state.line == 1 && raw.startsWith("\xEF\xBB\xBF"))
            raw = raw.sliced(3); // a UTF-8 byte-order mark, as some editors on Windows write it
        const QString text = QString::fromUtf8(raw);
        if (tooLong || text.size() > kMaxLineLength)
            error(m_state.line, kMaxLineLength + 1,
                  tr("the line is longer than %1 characters").arg(kMaxLineLength));
        else
            readLine(text);
    }
    if (m_index && m_state.line % ProgramIndex::kCheckpointLines == 0)
        noteCheckpoint();
    m_pending.resize(0); // keeps its capacity: the next line needs no allocation
}

// The state before the next line, so that a reader can go on from there (ProgramIndex).
void ProgramParser::noteCheckpoint()
{
    m_index->checkpoints.back().hash = m_hash;
    m_hash = 0;
    // The newline of this line is not counted yet (feed() adds it after endLine()).
    m_index->checkpoints.push_back(ProgramCheckpoint{m_lineOffset + 1, 0, m_state});
}

bool ProgramParser::percentLine(const QString& text)
{
    if (text.trimmed() != QLatin1String("%"))
        return false;
    // LinuxCNC: a "%" on the first line with words (blank lines before it allowed) opens the
    // program, and a second "%" ends it; anywhere else it is an error.
    if (!m_state.anyWords && m_state.percentOpen == 0) {
        m_state.percentOpen = m_state.line;
        return true;
    }
    if (m_state.percentOpen > 0) {
        m_state.percentClosed = true;
        m_endedAt = m_state.line;
        return true;
    }
    error(m_state.line, int(text.indexOf(QLatin1Char('%'))) + 1,
          tr("\"%\" stands only on the program's first line and, closing it, its last"));
    return true;
}

// One line before the program's end: block delete, "%", GRBL's "$", a program number, words.
void ProgramParser::readLine(QString text)
{
    qsizetype first = 0;
    while (first < text.size() && text.at(first).isSpace())
        ++first;
    // LinuxCNC's block delete: "/" first on the line (canon starts with the switch on).
    if (first < text.size() && text.at(first) == QLatin1Char('/')) {
        if (m_blockDelete) {
            if (m_deleted.count++ == 0)
                m_deleted.line = sourceLine(m_state.line);
            return;
        }
        text[first] = QLatin1Char(' '); // the words keep their columns
    }
    if (percentLine(text) || dollarLine(text, first) || programNumberLine(text))
        return;
    parseLine(text);
}

void ProgramParser::noteUnread(QByteArrayView raw)
{
    const QByteArrayView t = raw.trimmed();
    if (t.isEmpty())
        return;
    // The "%" after M2/M30 that closes a program opened with one (a Fanuc-style post's last
    // line) is where LinuxCNC expects the file to end, not text left over.
    if (t == QByteArrayView("%") && m_state.percentOpen > 0 && !m_state.percentClosed) {
        m_state.percentClosed = true;
        return;
    }
    ++m_unread;
}

// GRBL's system commands, which senders' files carry: "$H" is GRBL's homing cycle, StepDeck's
// reference run of every axis (a bare G28). The others ("$X" the alarm lock, "$32=1" a
// setting, "$$" a report, "$J=" a jog) act on GRBL's own state, which StepDeck's controllers
// do not have: not run, each named in a note.
bool ProgramParser::dollarLine(const QString& text, qsizetype first)
{
    if (first >= text.size() || text.at(first) != QLatin1Char('$'))
        return false;
    m_state.anyWords = true;
    QString command; // as GRBL reads it: without white space or comments, in upper case
    for (const QChar c : QStringView(text).sliced(first)) {
        if (c == QLatin1Char('(') || c == QLatin1Char(';'))
            break;
        if (!c.isSpace())
            command += c.toUpper();
    }
    if (command == QLatin1String("$H")) {
        homeLine(text, int(first) + 1);
        return true;
    }
    note(m_state.line, int(first) + 1,
         tr("%1 is a GRBL command (a setting, the alarm lock, a report or a jog): not run")
             .arg(command));
    return true;
}

// "$H" as the block of a bare G28, in the modal state of its line, at the "$"'s column.
void ProgramParser::homeLine(const QString& text, int column)
{
    LexedLine lexed = ProgramLexer::lex(QStringLiteral("G28"), m_state.line);
    lexed.words[0].column = column;
    std::optional<ProgramError> failure;
    ModalState modal = m_state.modal;
    if (!ProgramLine::parse(lexed, m_state.line, m_axisNames, &modal, &m_lineBlocks, &failure) ||
        m_lineBlocks.size() != 1) {
        error(m_state.line, column, failure ? failure->message : tr("$H cannot run here"));
        return;
    }
    m_state.modal = modal;
    ProgramBlock& block = m_lineBlocks.front();
    block.line = sourceLine(m_state.line);
    block.text = text.trimmed();
    addBlock(std::move(block));
}

// Fanuc-style posts (Vectric, Fusion's fanuc) write the program's number before its first
// block; LinuxCNC's O words need a keyword, so a number alone there is only the name.
bool ProgramParser::programNumberLine(const QString& text)
{
    if (m_state.anyWords || m_state.named)
        return false;
    std::optional<QString> name = programNumber(text);
    if (!name)
        return false;
    m_state.named = true;
    m_name = *name;
    return true;
}

std::optional<QString> ProgramParser::programNumber(QStringView line)
{
    const QStringView t = line.trimmed();
    if (t.isEmpty() || (t.front().toUpper() != QLatin1Char('O') && t.front() != QLatin1Char(':')))
        return std::nullopt;
    qsizetype end = 1;
    while (end < t.size() && t.at(end).unicode() < 128 && t.at(end).isDigit())
        ++end;
    if (end == 1)
        return std::nullopt;
    // Only a comment may follow: the program's title ("O1001 (BRACKET)").
    const LexedLine rest = ProgramLexer::lex(t.sliced(end), 1);
    if (rest.error || !rest.words.isEmpty())
        return std::nullopt;
    return t.toString();
}

ProgramError ProgramParser::unreadNote(int lines, int endLine)
{
    return ProgramError{endLine, 1,
                        tr("%n line(s) after the program's end are not read, as in LinuxCNC "
                           "(nothing after M2, M30 or the closing \"%\" runs)",
                           nullptr, lines)};
}

ProgramError ProgramParser::blockDeleteNote(int lines, int firstLine)
{
    return ProgramError{firstLine, 1,
                        tr("block delete is on: %n line(s) starting with \"/\" are skipped, this "
                           "one the first (switch it off to run them)",
                           nullptr, lines)};
}

// An arc's offset along its plane's normal that is 0 ("K0.000" on a G17 arc, as FreeCAD's grbl
// post writes): ProgramLine leaves it out as GRBL does (LinuxCNC refuses it); counted for one
// note.
void ProgramParser::noteZeroNormal(const LexedLine& lexed, Plane plane)
{
    const QChar normal = plane == Plane::XY   ? QLatin1Char('K')
                         : plane == Plane::XZ ? QLatin1Char('J')
                                              : QLatin1Char('I');
    for (const ProgramWord& w : lexed.words) {
        if (w.letter != normal)
            continue;
        if (m_zeroNormal.count++ == 0)
            m_zeroNormal = Counted{1, sourceLine(m_state.line), w.column, w.valueText()};
        return;
    }
}

void ProgramParser::note(int line, int column, const QString& message)
{
    if (m_notes.size() >= kMaxErrors) {
        m_tooManyNotes = true;
        return;
    }
    m_notes << ProgramError{sourceLine(line), column, message};
}

// The notes in line order, the counted ones among them.
QList<ProgramError> ProgramParser::takeNotes()
{
    QList<ProgramError> out = m_notes;
    if (m_deleted.count > 0)
        out << blockDeleteNote(m_deleted.count, m_deleted.line);
    if (m_zeroNormal.count > 0)
        out << ProgramError{m_zeroNormal.line, m_zeroNormal.column,
                            tr("%1 on %n arc(s), this one the first: an offset along the plane's "
                               "normal that is 0 is left out, as GRBL does (LinuxCNC refuses it; "
                               "any other value is refused)",
                               nullptr, m_zeroNormal.count)
                                .arg(m_zeroNormal.word)};
    if (m_unread > 0)
        out << unreadNote(m_unread, sourceLine(m_endedAt));
    std::stable_sort(out.begin(), out.end(),
                     [](const ProgramError& a, const ProgramError& b) { return a.line < b.line; });
    if (m_tooManyNotes)
        out << ProgramError{
            sourceLine(m_state.line), 1,
            tr("more GRBL commands follow; only the first %1 are named").arg(kMaxErrors)};
    return out;
}

void ProgramParser::parseLine(const QString& text)
{
    LexedLine lexed = ProgramLexer::lex(text, m_state.line);
    if (m_lineMap) // a worked-out line: its words' columns in the file (issue 33)
        for (qsizetype k = 0; k < lexed.words.size(); ++k)
            lexed.words[k].column = m_lineMap->wordColumn(sourceLine(m_state.line), k);
    if (lexed.error) {
        error(lexed.error->line, lexed.error->column, lexed.error->message);
        return;
    }
    m_state.anyWords = m_state.anyWords || !lexed.words.isEmpty();
    std::optional<ProgramError> failure;
    ModalState modal = m_state.modal;
    if (!ProgramLine::parse(lexed, m_state.line, m_axisNames, &modal, &m_lineBlocks, &failure)) {
        error(failure->line, failure->column, failure->message);
        noteBrokenRepeat(lexed);
        return;
    }
    if (m_lineBlocks.empty())
        return; // blank or only a comment
    m_state.modal = modal;
    // A worked-out line keeps its words at their source columns (NgcLineExpander): shown
    // without the padding.
    const QString shown = m_lineMap ? text.simplified() : text.trimmed();
    for (ProgramBlock& block : m_lineBlocks) { // in LinuxCNC's order of execution
        block.line = sourceLine(m_state.line);
        block.text = shown;
        if (block.kind == BlockKind::End)
            m_state.endLine = m_endedAt = m_state.line;
        if (isArc(block.kind))
            noteZeroNormal(lexed, block.plane);
        addBlock(std::move(block));
    }
}

// An "O<n> repeat" line with an error still opens its repeat, so that its endrepeat is not
// reported as well.
void ProgramParser::noteBrokenRepeat(const LexedLine& lexed)
{
    const ProgramWords& w = lexed.words;
    const qsizetype o = !w.isEmpty() && w.first().letter == QLatin1Char('N') ? 1 : 0;
    if (o < w.size() && w.at(o).letter == QLatin1Char('O') &&
        lexed.keyword == QLatin1String("repeat") && m_openRepeats.size() < kMaxNesting &&
        w.at(o).value >= 0 && w.at(o).value < 1e9) // an int, or no repeat
        m_openRepeats << OpenRepeat{-1, int(w.at(o).value), m_state.line};
}

void ProgramParser::addBlock(ProgramBlock&& block)
{
    const int index = m_state.blocks;
    if (!linkRepeat(block, index))
        return;
    ++m_state.blocks;
    if (m_sink)
        m_sink(std::move(block));
}

// O repeat / endrepeat: nesting and pairs. Replay takes the pairs from the index. false: the
// line is an error and gives no block.
bool ProgramParser::linkRepeat(ProgramBlock& block, int index)
{
    if (block.kind != BlockKind::RepeatStart && block.kind != BlockKind::RepeatEnd)
        return true;
    if (m_replayIndex) {
        block.partner = m_replayIndex->partner(index);
        return true;
    }
    if (block.kind == BlockKind::RepeatStart) {
        if (m_openRepeats.size() >= kMaxNesting) {
            error(block.line, 1, tr("repeats nest deeper than %1").arg(kMaxNesting));
            return false;
        }
        m_openRepeats << OpenRepeat{index, block.oNumber, block.line};
        return true;
    }
    if (m_openRepeats.isEmpty()) {
        error(block.line, 1, tr("O%1 endrepeat without its O%1 repeat").arg(block.oNumber));
        return false;
    }
    const OpenRepeat open = m_openRepeats.last();
    if (open.oNumber != block.oNumber) {
        error(block.line, 1,
              tr("O%1 endrepeat does not close O%2 repeat (line %3)")
                  .arg(block.oNumber)
                  .arg(open.oNumber)
                  .arg(open.line));
        return false;
    }
    m_openRepeats.removeLast();
    if (open.index >= 0) {
        m_index->partners[open.index] = index;
        m_index->partners[index] = open.index;
        block.partner = open.index;
    }
    return true;
}

QList<int> ProgramParser::openRepeatBlocks() const
{
    QList<int> out;
    for (const OpenRepeat& open : m_openRepeats)
        if (open.index >= 0)
            out << open.index;
    return out;
}

void ProgramParser::error(int line, int column, const QString& message)
{
    if (m_errors.size() >= kMaxErrors) {
        m_tooManyErrors = true;
        return;
    }
    m_errors << ProgramError{sourceLine(line), column, message};
}

std::optional<Program> ProgramParser::finish(QList<ProgramError>* errors)
{
    flush();
    for (const OpenRepeat& open : std::as_const(m_openRepeats)) {
        if (open.index >= 0) // a broken one was reported already
            error(open.line, 1, tr("O%1 repeat is not closed by O%1 endrepeat").arg(open.oNumber));
    }
    m_openRepeats.clear();
    if (m_state.percentOpen > 0 && !m_state.percentClosed && m_state.endLine == 0)
        error(m_state.line, 1,
              tr("the program opened with \"%\" (line %1) ends with neither \"%\" nor M2/M30")
                  .arg(sourceLine(m_state.percentOpen)));
    std::stable_sort(m_errors.begin(), m_errors.end(),
                     [](const ProgramError& a, const ProgramError& b) { return a.line < b.line; });
    if (m_tooManyErrors)
        m_errors << ProgramError{
            sourceLine(m_state.line), 1,
            tr("more errors follow; only the first %1 are listed").arg(kMaxErrors)};
    if (errors)
        *errors = m_errors;
    if (!m_errors.isEmpty() || !m_index)
        return std::nullopt;
    m_index->checkpoints.back().hash = m_hash;
    m_index->bytes = m_lineOffset;
    Program program;
    program.axisNames = m_axisNames;
    program.lines = m_state.line;
    program.blockCount = m_state.blocks;
    program.index = m_index;
    program.name = m_name;
    program.notes = takeNotes();
    return program;
}

} // namespace stepdeck::program
