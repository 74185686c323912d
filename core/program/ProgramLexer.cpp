#include "ProgramLexer.h"
#include <charconv>
#include <cmath>

namespace stepdeck::program {

namespace {

// The value of digits with an optional sign and point (readNumber checked the form): as
// QString::toDouble, but without its conversion to UTF-8 and allocation per number.
double toDouble(QStringView text)
{
    char ascii[96];
    if (text.size() >= qsizetype(sizeof ascii))
        return text.toDouble(); // a long one (a line holds at most 1024 characters)
    qsizetype n = 0;
    for (const QChar c : text)
        if (c != QLatin1Char('+'))
            ascii[n++] = char(c.unicode());
    double value = 0;
    const std::from_chars_result r = std::from_chars(ascii, ascii + n, value);
    if (r.ec == std::errc::result_out_of_range)
        return text.toDouble(); // inf, or a subnormal: as Qt reads it
    return value;
}

class LineReader
{
public:
    LineReader(QStringView line, int lineNumber, LexedLine* out)
        : m_line(line), m_lineNumber(lineNumber), m_out(out)
    {}

    void run()
    {
        while (!m_out->error && skipBlanksAndComments())
            readWord();
    }

private:
    bool atEnd() const { return m_pos >= m_line.size(); }
    QChar peek() const { return atEnd() ? QChar() : m_line.at(m_pos); }
    int column() const { return int(m_pos) + 1; }

    void fail(int column, const QString& message)
    {
        if (!m_out->error)
            m_out->error = ProgramError{m_lineNumber, column, message};
    }

    void skipSpaces()
    {
        while (!atEnd() && peek().isSpace())
            ++m_pos;
    }

    // False at the end of the line (a ";" comment ends it too).
    bool skipBlanksAndComments()
    {
        for (;;) {
            skipSpaces();
            if (atEnd())
                return false;
            if (peek() == QLatin1Char(';')) {
                noteComment(m_line.mid(m_pos + 1));
                m_pos = m_line.size();
                return false;
            }
            if (peek() != QLatin1Char('('))
                return true;
            const qsizetype close = m_line.indexOf(QLatin1Char(')'), m_pos);
            if (close < 0) {
                fail(column(), ProgramLexer::tr("the comment is not closed: \")\" is missing"));
                return false;
            }
            noteComment(m_line.mid(m_pos + 1, close - m_pos - 1));
            noteMessage(m_line.mid(m_pos + 1, close - m_pos - 1));
            m_pos = close + 1;
        }
    }

    // LinuxCNC: a parenthesised comment that starts with "MSG," (any case, spaces before it
    // allowed) is shown to the operator; the first one of a line counts.
    void noteMessage(QStringView text)
    {
        const QStringView t = text.trimmed();
        if (m_out->message.isEmpty() && t.startsWith(QLatin1String("MSG,"), Qt::CaseInsensitive))
            m_out->message = t.mid(4).trimmed().toString();
    }

    void noteComment(QStringView text)
    {
        if (m_out->comment.isEmpty())
            m_out->comment = text.trimmed().toString();
    }

    // [+-]digits[.digits] or [+-].digits; nullopt (and an error) otherwise. what(): the word's
    // name for the message (formed only then: a program of millions of lines reads millions of
    // numbers).
    template <typename What> std::optional<double> readNumber(const What& what)
    {
        skipSpaces();
        const qsizetype start = m_pos;
        if (peek() == QLatin1Char('+') || peek() == QLatin1Char('-'))
            ++m_pos;
        int digits = 0;
        while (!atEnd() && peek().isDigit() && peek().unicode() < 128) {
            ++m_pos;
            ++digits;
        }
        if (peek() == QLatin1Char('.')) {
            ++m_pos;
            while (!atEnd() && peek().isDigit() && peek().unicode() < 128) {
                ++m_pos;
                ++digits;
            }
        }
        const QStringView text = m_line.mid(start, m_pos - start);
        if (digits == 0) {
            fail(int(start) + 1, ProgramLexer::tr("%1 needs a number").arg(what()));
            return std::nullopt;
        }
        const QChar next = peek();
        if (!atEnd() && (next.isDigit() || next == QLatin1Char('.') || next == QLatin1Char('e') ||
                         next == QLatin1Char('E'))) {
            fail(int(start) + 1, ProgramLexer::tr("%1: \"%2%3\" is not a decimal number")
                                     .arg(what(), text.toString(), QString(next)));
            return std::nullopt;
        }
        const double value = toDouble(text);
        if (!std::isfinite(value)) {
            fail(int(start) + 1,
                 ProgramLexer::tr("%1: %2 is not a finite number").arg(what(), text.toString()));
            return std::nullopt;
        }
        return value;
    }

    void readWord()
    {
        const QChar c = peek();
        const int letterColumn = column();
        // "@" and "^": LinuxCNC's polar coordinates (ProgramLine, issue 50 item 6).
        const bool polar = c == QLatin1Char('@') || c == QLatin1Char('^');
        if (!polar && !(c.unicode() < 128 && c.isLetter())) {
            fail(letterColumn, ProgramLexer::tr("unexpected character \"%1\"").arg(QString(c)));
            return;
        }
        ++m_pos;
        // An ASCII letter (checked above): upper case without QChar's Unicode tables.
        const QChar letter = c.unicode() >= 'a' ? QChar(c.unicode() - ('a' - 'A')) : c;
        const qsizetype valueStart = m_pos;
        const std::optional<double> value = readNumber([letter] { return QString(letter); });
        if (!value)
            return;
        const QStringView written = m_line.mid(valueStart, m_pos - valueStart);
        // ASCII: the letter, sign, digits and point are (readWord, readNumber); only the white
        // space between them may not be, and it is left out.
        std::string text(1, char(letter.unicode()));
        for (const QChar ch : written)
            if (!ch.isSpace())
                text += char(ch.unicode());
        m_out->words.push_back(ProgramWord{letter, *value, letterColumn, std::move(text)});
        if (letter == QLatin1Char('O'))
            readKeyword();
    }

    // "O<n> repeat [count]" / "O<n> endrepeat": the keyword and the optional count.
    void readKeyword()
    {
        skipSpaces();
        const qsizetype start = m_pos;
        while (!atEnd() && peek().unicode() < 128 && peek().isLetter())
            ++m_pos;
        m_out->keyword = m_line.mid(start, m_pos - start).toString().toLower();
        m_out->keywordColumn = int(start) + 1;
        skipSpaces();
        if (atEnd() || (peek() != QLatin1Char('[') && !peek().isDigit()))
            return;
        const bool bracket = peek() == QLatin1Char('[');
        if (bracket)
            ++m_pos;
        m_out->keywordValueColumn = column();
        m_out->keywordValue = readNumber([this] { return m_out->keyword; });
        skipSpaces();
        if (bracket && m_out->keywordValue) {
            if (peek() != QLatin1Char(']'))
                fail(column(), ProgramLexer::tr("\"]\" is missing"));
            else
                ++m_pos;
        }
    }

    QStringView m_line;
    int m_lineNumber;
    LexedLine* m_out;
    qsizetype m_pos = 0;
};

} // namespace

LexedLine ProgramLexer::lex(QStringView line, int lineNumber)
{
    LexedLine out;
    LineReader(line, lineNumber, &out).run();
    return out;
}

} // namespace stepdeck::program
