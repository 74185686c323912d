#include "NgcLineExpander.h"
#include <cmath>

namespace stepdeck::program {

bool NgcExpandedLine::has(char letter, double value) const
{
    for (const Word& w : words)
        if (w.letter == QLatin1Char(letter) && std::fabs(w.value - value) < 1e-9)
            return true;
    return false;
}

QString NgcLineExpander::format(double value)
{
    QString s = QString::number(value, 'f', 6);
    while (s.endsWith(QLatin1Char('0')))
        s.chop(1);
    if (s.endsWith(QLatin1Char('.')))
        s.chop(1);
    return s == QLatin1String("-0") ? QStringLiteral("0") : s;
}

// LinuxCNC's DEBUG and PRINT: "#123" (digits only, as written) and "#<name>" are replaced by
// their values; anything else, or a reference that does not read, stays as written.
QString NgcLineExpander::substitute(QStringView text, const NgcParameters& parameters)
{
    QString out;
    qsizetype pos = 0;
    while (pos < text.size()) {
        const qsizetype hash = text.indexOf(QLatin1Char('#'), pos);
        if (hash < 0) {
            out += text.mid(pos);
            break;
        }
        out += text.mid(pos, hash - pos);
        qsizetype end = hash + 1;
        std::optional<double> v;
        QString why;
        if (end < text.size() && text.at(end) == QLatin1Char('<')) {
            const qsizetype close = text.indexOf(QLatin1Char('>'), end);
            if (close > end + 1) {
                QString name;
                for (const QChar c : text.mid(end + 1, close - end - 1))
                    if (!c.isSpace())
                        name += c.toLower();
                v = parameters.named(name, &why);
                end = close + 1;
            }
        } else {
            while (end < text.size() && text.at(end).unicode() < 128 && text.at(end).isDigit())
                ++end;
            if (end > hash + 1 && end - hash <= 6)
                v = parameters.numbered(text.mid(hash + 1, end - hash - 1).toInt(), &why);
        }
        // A value too long to read in a message (LinuxCNC prints %lf) goes in exponent form.
        out += !v                    ? text.mid(hash, end - hash).toString()
               : std::fabs(*v) < 1e9 ? format(*v)
                                     : QString::number(*v, 'g', 9);
        pos = end;
    }
    return out;
}

namespace {

qsizetype skipLineSpaces(QStringView line, qsizetype pos)
{
    while (pos < line.size() && line.at(pos).isSpace())
        ++pos;
    return pos;
}

// Where the text of the line goes: each piece at its source column where the text before it
// leaves room.
void place(QString* out, qsizetype column, const QString& piece)
{
    if (out->size() < column)
        out->append(QString(column - out->size(), QLatin1Char(' ')));
    else if (!out->isEmpty())
        out->append(QLatin1Char(' '));
    out->append(piece);
}

} // namespace

// Reads one line piece by piece into an NgcExpandedLine; each piece returns where the next
// starts, or -1 with the error set.
class NgcLineExpander::Reader
{
public:
    Reader(QStringView line, int lineNumber, const NgcParameters& parameters,
           std::optional<ProgramError>* error)
        : m_line(line), m_lineNumber(lineNumber), m_parameters(parameters), m_error(error)
    {}

    bool run(NgcExpandedLine* out)
    {
        m_out = out;
        for (qsizetype pos = skipLineSpaces(m_line, 0); pos >= 0 && pos < m_line.size();) {
            const QChar c = m_line.at(pos);
            if (c == QLatin1Char(';')) {
                place(&out->text, pos, m_line.mid(pos).toString());
                out->keep = true;
                break;
            }
            pos = c == QLatin1Char('(')   ? comment(pos)
                  : c == QLatin1Char('#') ? assignment(pos)
                                          : word(pos);
            if (pos >= 0)
                pos = skipLineSpaces(m_line, pos);
        }
        return !*m_error;
    }

private:
    qsizetype fail(qsizetype pos, const QString& message)
    {
        *m_error = ProgramError{m_lineNumber, int(pos) + 1, message};
        return -1;
    }
    qsizetype failed(const NgcExpression& e)
    {
        *m_error = e.error();
        return -1;
    }

    // "( … )": kept; (DEBUG, …) and (PRINT, …) become (MSG, …) with the values (LinuxCNC).
    qsizetype comment(qsizetype pos)
    {
        const qsizetype close = m_line.indexOf(QLatin1Char(')'), pos);
        if (close < 0)
            return fail(pos, tr("the comment is not closed: \")\" is missing"));
        const QStringView t = m_line.mid(pos + 1, close - pos - 1).trimmed();
        const bool debug = t.startsWith(QLatin1String("debug,"), Qt::CaseInsensitive);
        const bool print = t.startsWith(QLatin1String("print,"), Qt::CaseInsensitive);
        place(&m_out->text, pos,
              debug || print
                  ? QStringLiteral("(MSG, %1)").arg(substitute(t.mid(6).trimmed(), m_parameters))
                  : m_line.mid(pos, close - pos + 1).toString());
        m_out->keep = true;
        return close + 1;
    }

    // "#<ref> = value": applied after the line (the caller).
    qsizetype assignment(qsizetype pos)
    {
        NgcExpression e(m_line, m_parameters);
        e.setLineNumber(m_lineNumber);
        qsizetype p = pos + 1;
        const std::optional<NgcExpression::Reference> target = e.readReference(&p);
        if (!target)
            return failed(e);
        p = skipLineSpaces(m_line, p);
        if (p >= m_line.size() || m_line.at(p) != QLatin1Char('='))
            return fail(p, tr("\"=\" is missing: a parameter is set with #…=value"));
        ++p;
        const std::optional<double> v = e.readValue(&p);
        if (!v)
            return failed(e);
        m_out->assignments << NgcExpandedLine::Assignment{*target, *v};
        return p;
    }

    qsizetype word(qsizetype pos)
    {
        const QChar c = m_line.at(pos);
        const bool polar = c == QLatin1Char('@') || c == QLatin1Char('^'); // ProgramLine
        if (!polar && !(c.unicode() < 128 && c.isLetter()))
            return fail(pos, tr("unexpected character \"%1\"").arg(c));
        const QChar letter = c.toUpper();
        if (letter == QLatin1Char('O')) // NgcStatement reads it where it stands first
            return fail(pos, tr("an O word stands first on its line (after an N number at most)"));
        NgcExpression e(m_line, m_parameters);
        e.setLineNumber(m_lineNumber);
        qsizetype p = pos + 1;
        const std::optional<double> v = e.readValue(&p);
        if (!v)
            return failed(e);
        if (std::fabs(*v) > kMaxWordValue)
            return fail(pos, tr("%1%2 is beyond the values StepDeck takes (±%3)")
                                 .arg(letter)
                                 .arg(*v)
                                 .arg(kMaxWordValue));
        place(&m_out->text, pos, QString(letter) + format(*v));
        m_out->words.push_back(NgcExpandedLine::Word{letter, *v, int(pos) + 1});
        m_out->keep = true;
        return p;
    }

    QStringView m_line;
    int m_lineNumber;
    const NgcParameters& m_parameters;
    std::optional<ProgramError>* m_error;
    NgcExpandedLine* m_out = nullptr;
};

std::optional<NgcExpandedLine> NgcLineExpander::expand(QStringView line, int lineNumber,
                                                       const NgcParameters& parameters,
                                                       std::optional<ProgramError>* error)
{
    NgcExpandedLine out;
    // "%" and GRBL's "$" lines go to the parser as written (ProgramParser reads them).
    if (line.trimmed() == QLatin1String("%") || line.trimmed().startsWith(QLatin1Char('$'))) {
        out.text = line.toString();
        out.keep = true;
        return out;
    }
    error->reset();
    if (!Reader(line, lineNumber, parameters, error).run(&out))
        return std::nullopt;
    return out;
}

} // namespace stepdeck::program
