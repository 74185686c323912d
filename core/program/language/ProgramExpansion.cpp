#include "ProgramExpansion.h"
#include "program/ProgramLogging.h"
#include "program/ProgramParser.h"
#include <QRegularExpression>
#include <QTemporaryFile>
#include <algorithm>

namespace stepdeck::program {

void NgcLineMap::add(int expandedLine, int sourceLine)
{
    if (!m_runs.empty() && expandedLine == m_lastExpanded + 1 && sourceLine == m_lastSource + 1) {
        m_lastExpanded = expandedLine;
        m_lastSource = sourceLine;
        return;
    }
    m_runs.push_back(Run{expandedLine, sourceLine});
    m_lastExpanded = expandedLine;
    m_lastSource = sourceLine;
}

void NgcLineMap::setWordColumns(int sourceLine, const QList<int>& columns)
{
    if (!columns.isEmpty() && !m_wordColumns.contains(sourceLine))
        m_wordColumns.insert(sourceLine, columns);
}

int NgcLineMap::wordColumn(int sourceLine, qsizetype index) const
{
    const auto it = m_wordColumns.constFind(sourceLine);
    return it != m_wordColumns.cend() && index < it->size() ? it->at(index) : 1;
}

int NgcLineMap::sourceLine(int expandedLine) const
{
    const auto it = std::upper_bound(m_runs.begin(), m_runs.end(), expandedLine,
                                     [](int line, const Run& r) { return line < r.expanded; });
    if (it == m_runs.begin())
        return expandedLine; // before the first line given out (none there)
    const Run& r = *std::prev(it);
    // A line after the last one given out (the parser's "end of program" errors): the last
    // source line's.
    return r.source + std::min(expandedLine - r.expanded, m_lastExpanded - r.expanded);
}

namespace {

bool startsWithNoCase(QByteArrayView text, const char* prefix)
{
    const QByteArrayView p(prefix);
    return text.size() >= p.size() && text.first(p.size()).compare(p, Qt::CaseInsensitive) == 0;
}

// GRBL's "$" lines as NgcLineExpander and the parser find them: "$" the first character that
// is not white space (QString::trimmed's: ASCII's, and Unicode's past ASCII).
bool dollarLine(QByteArrayView line)
{
    for (const char c : line) {
        if (c == ' ' || (c >= '\t' && c <= '\r'))
            continue;
        if (uchar(c) >= 0x80)
            return QString::fromUtf8(line).trimmed().startsWith(QLatin1Char('$'));
        return c == '$';
    }
    return false;
}

// One line: does it use the language?
bool lineUsesLanguage(QByteArrayView line)
{
    qsizetype i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
    if (i < line.size() && line[i] == '/') { // block delete's mark (NgcInterpreter) before it
        ++i;
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
    }
    // GRBL's system commands ("$#" its parameter report, "$32=1") are not G-code: they go to
    // the parser as written (NgcLineExpander), which runs "$H" and names the others.
    if (dollarLine(line.sliced(i)))
        return false;
    // An O word first (after an N number): anything but repeat/endrepeat is the language.
    qsizetype o = i;
    if (o < line.size() && (line[o] == 'N' || line[o] == 'n')) {
        ++o;
        while (o < line.size() && (line[o] == ' ' || (line[o] >= '0' && line[o] <= '9')))
            ++o;
    }
    if (o < line.size() && (line[o] == 'O' || line[o] == 'o')) {
        const QString text = QString::fromUtf8(line.sliced(i));
        std::optional<ProgramError> error;
        const std::optional<NgcStatement> s = NgcStatement::read(text, 1, &error);
        if (s && s->kind != NgcStatement::Repeat && s->kind != NgcStatement::EndRepeat)
            return true;
        // "O1 repeat [3]" with a plain count is the parser's own (issue 20): read as it is.
        static const QRegularExpression plainCount(
            QStringLiteral("^\\s*(\\[\\s*[0-9.]+\\s*\\]|[0-9.]+)?\\s*(\\(.*|;.*)?$"));
        if (s) // a named label ("o<x> repeat") is the language's, not the parser's
            return !s->label.at(0).isDigit() ||
                   !plainCount.match(QStringView(text).mid(s->rest)).hasMatch();
    }
    for (; i < line.size(); ++i) {
        const char c = line[i];
        if (c == ';')
            return false;
        if (c == '#' || c == '[')
            return true;
        if (c == '(') {
            const qsizetype close = line.indexOf(')', i);
            QByteArrayView body = line.sliced(i + 1, (close < 0 ? line.size() : close) - i - 1);
            body = body.trimmed();
            if (startsWithNoCase(body, "debug,") || startsWithNoCase(body, "print,"))
                return true;
            if (close < 0)
                return false;
            i = close;
        }
    }
    return false;
}

// Where the worked-out text goes: memory, then a temporary file once it grows.
class ExpandedWriter
{
public:
    bool append(const QString& text)
    {
        m_buffer += text.toUtf8();
        m_buffer += '\n';
        if (m_buffer.size() < ProgramExpansion::kMemoryBytes)
            return true;
        return spill();
    }
    std::optional<ProgramSource> finish(QString* why)
    {
        if (!m_file)
            return ProgramSource::bytes(m_buffer);
        if (!spill() || !m_file->flush()) {
            *why = m_file->errorString();
            return std::nullopt;
        }
        return ProgramSource::temporaryFile(m_file);
    }
    QString error() const { return m_file ? m_file->errorString() : QString(); }

private:
    bool spill()
    {
        if (!m_file) {
            m_file = std::make_shared<QTemporaryFile>();
            if (!m_file->open()) {
                qCWarning(lcProgram) << "cannot open a temporary file:" << m_file->errorString();
                return false;
            }
        }
        if (m_file->write(m_buffer) != m_buffer.size()) {
            qCWarning(lcProgram) << "cannot write the worked-out program:" << m_file->errorString();
            return false;
        }
        m_buffer.clear();
        return true;
    }

    QByteArray m_buffer;
    std::shared_ptr<QTemporaryFile> m_file;
};

QStringList splitLines(const QByteArray& bytes)
{
    QByteArrayView text = bytes;
    if (text.startsWith("\xEF\xBB\xBF"))
        text = text.sliced(3);
    QStringList lines;
    for (qsizetype start = 0; start <= text.size();) {
        qsizetype end = text.indexOf('\n', start);
        if (end < 0)
            end = text.size();
        QByteArrayView l = text.sliced(start, end - start);
        if (l.endsWith('\r'))
            l.chop(1);
        lines << QString::fromUtf8(l);
        start = end + 1;
    }
    if (!lines.isEmpty() && lines.last().isEmpty() && text.endsWith('\n'))
        lines.removeLast();
    return lines;
}

// The line of a Fanuc program number before the first block (ProgramParser::programNumber),
// -1: none. It is not one of LinuxCNC's O words (they take a keyword).
int programNumberLine(const QStringList& lines, bool blockDelete)
{
    for (int i = 0; i < lines.size(); ++i) {
        const QString t = lines.at(i).trimmed();
        if (t.isEmpty() || t == QLatin1String("%") ||
            (blockDelete && t.startsWith(QLatin1Char('/'))))
            continue;
        if (ProgramParser::programNumber(t))
            return i;
        const LexedLine lexed = ProgramLexer::lex(t, i + 1);
        if (lexed.error || !lexed.words.isEmpty() || !lexed.message.isEmpty())
            return -1; // a block came first
    }
    return -1;
}

// The notes of the lines the parser never sees (ProgramExpansionInfo::notes).
QList<ProgramError> expansionNotes(const NgcInterpreter& interpreter)
{
    QList<ProgramError> notes;
    if (interpreter.deletedLines() > 0)
        notes << ProgramParser::blockDeleteNote(interpreter.deletedLines(),
                                                interpreter.firstDeletedLine());
    if (const int unread = interpreter.unreadLines(); unread > 0)
        notes << ProgramParser::unreadNote(unread, interpreter.endLine());
    return notes;
}

} // namespace

bool ProgramExpansion::usesLanguage(QByteArrayView text)
{
    qsizetype start = 0;
    while (start < text.size()) {
        qsizetype end = text.indexOf('\n', start);
        if (end < 0)
            end = text.size();
        if (lineUsesLanguage(text.sliced(start, end - start)))
            return true;
        start = end + 1;
    }
    return false;
}

std::optional<bool> ProgramExpansion::usesLanguage(const ProgramSource& source, QString* error)
{
    ProgramSourceReader reader(source);
    if (!reader.open(error))
        return std::nullopt;
    constexpr qint64 kChunk = 1024 * 1024;
    QByteArray carry;
    for (qint64 offset = 0;;) {
        QString why;
        const QByteArray bytes = reader.read(offset, kChunk, &why);
        if (!why.isEmpty()) {
            *error = why;
            return std::nullopt;
        }
        if (bytes.isEmpty())
            return lineUsesLanguage(carry);
        offset += bytes.size();
        const qsizetype lastNewline = bytes.lastIndexOf('\n');
        if (lastNewline < 0) {
            carry += bytes;
            if (carry.size() > 64 * 1024) // a line this long is the parser's error
                carry = carry.right(4096);
            continue;
        }
        if (lineUsesLanguage(carry + bytes.left(bytes.indexOf('\n'))) ||
            usesLanguage(QByteArrayView(bytes).sliced(0, lastNewline)))
            return true;
        carry = bytes.mid(lastNewline + 1);
    }
}

std::optional<ProgramExpansion::Result>
ProgramExpansion::expand(const ProgramSource& source, const NgcContext& context,
                         QList<ProgramError>* errors, int maxErrors,
                         const std::function<bool()>& keepGoing)
{
    QString why;
    ProgramSourceReader reader(source);
    if (!reader.open(&why)) {
        *errors = {ProgramError{0, 0, why}};
        return std::nullopt;
    }
    if (reader.size() > kMaxSourceBytes) {
        *errors = {ProgramError{
            0, 0,
            tr("a program with parameters or O words is read into memory whole: at most %1 MB, "
               "this one has %2 MB")
                .arg(kMaxSourceBytes / (1024 * 1024))
                .arg(double(reader.size()) / (1024 * 1024), 0, 'f', 1)}};
        return std::nullopt;
    }
    const QByteArray bytes = reader.read(0, reader.size(), &why);
    if (!why.isEmpty()) {
        *errors = {ProgramError{0, 0, why}};
        return std::nullopt;
    }
    QStringList lines = splitLines(bytes);
    // The parser's limit, here before anything runs: a line is read again at every pass.
    const qsizetype before = errors->size();
    for (qsizetype i = 0; i < lines.size() && errors->size() - before < maxErrors; ++i)
        if (lines.at(i).size() > ProgramParser::kMaxLineLength)
            *errors << ProgramError{int(i) + 1, ProgramParser::kMaxLineLength + 1,
                                    ProgramParser::tr("the line is longer than %1 characters")
                                        .arg(ProgramParser::kMaxLineLength)};
    if (errors->size() > before)
        return std::nullopt;
    auto map = std::make_shared<NgcLineMap>();
    ExpandedWriter writer;
    int given = 0;
    // A program number goes to the parser, which takes it as the name, and not to the
    // interpreter. In its place among the lines (the comments, "%" and blank lines before it
    // come first): the worked-out lines keep the file's order (tools/fuzz, program_expand).
    const int name = programNumberLine(lines, context.blockDelete);
    QString nameText;
    if (name >= 0) {
        nameText = lines.at(name);
        lines[name].clear();
    }
    bool nameGiven = name < 0;
    const auto giveName = [&] {
        nameGiven = true;
        map->add(++given, name + 1);
        return writer.append(nameText);
    };
    NgcInterpreter interpreter(lines, context,
                               [&](const QString& text, int sourceLine, const QList<int>& columns) {
                                   if (!nameGiven && sourceLine > name + 1 && !giveName())
                                       return false;
                                   map->add(++given, sourceLine);
                                   map->setWordColumns(sourceLine, columns);
                                   return writer.append(text);
                               });
    interpreter.setKeepGoing(keepGoing);
    if (!interpreter.run(errors, maxErrors))
        return std::nullopt;
    if (!nameGiven)
        giveName(); // nothing after it ran; a failure shows in finish()
    std::optional<ProgramSource> text = writer.finish(&why);
    if (!text) {
        *errors = {ProgramError{0, 0, tr("the worked-out program cannot be kept: %1").arg(why)}};
        return std::nullopt;
    }
    auto info = std::make_shared<ProgramExpansionInfo>();
    info->lines = map;
    info->sourceLines = int(lines.size());
    info->coordinateSystems = context.coordinateSystems;
    info->activeSystem = context.activeSystem;
    info->notes = expansionNotes(interpreter);
    qCDebug(lcProgram) << "worked out" << lines.size() << "lines into" << given << "lines,"
                       << map->runs() << "runs";
    return Result{*text, info};
}

} // namespace stepdeck::program
