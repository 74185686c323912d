#include "NgcStatement.h"
#include <algorithm>

namespace stepdeck::program {

namespace {

struct KeywordName
{
    const char* word;
    NgcStatement::Kind kind;
};
// Longer words first where one starts another ("endsub" before "end..."; "elseif" before
// "else").
constexpr KeywordName kKeywords[] = {
    {"endsub", NgcStatement::EndSub},     {"endif", NgcStatement::EndIf},
    {"endwhile", NgcStatement::EndWhile}, {"endrepeat", NgcStatement::EndRepeat},
    {"elseif", NgcStatement::ElseIf},     {"else", NgcStatement::Else},
    {"sub", NgcStatement::Sub},           {"call", NgcStatement::Call},
    {"return", NgcStatement::Return},     {"if", NgcStatement::If},
    {"while", NgcStatement::While},       {"do", NgcStatement::Do},
    {"break", NgcStatement::Break},       {"continue", NgcStatement::Continue},
    {"repeat", NgcStatement::Repeat},
};

qsizetype skipSpaces(QStringView line, qsizetype pos)
{
    while (pos < line.size() && line.at(pos).isSpace())
        ++pos;
    return pos;
}

bool isAsciiLetter(QChar c)
{
    return c.unicode() < 128 && c.isLetter();
}

bool isAsciiDigit(QChar c)
{
    return c.unicode() < 128 && c.isDigit();
}

} // namespace

const char* NgcStatement::keyword(Kind kind)
{
    if (kind == DoWhile)
        return "while";
    for (const KeywordName& k : kKeywords)
        if (k.kind == kind)
            return k.word;
    return "";
}

QString NgcStatement::labelText(const QString& label)
{
    const bool named = !label.isEmpty() && !isAsciiDigit(label.at(0));
    return named ? QStringLiteral("O<%1>").arg(label) : QStringLiteral("O%1").arg(label);
}

QString NgcStatement::name() const
{
    return QStringLiteral("%1 %2").arg(labelText(label), QLatin1String(keyword(kind)));
}

std::optional<NgcStatement> NgcStatement::read(QStringView line, int lineNumber,
                                               std::optional<ProgramError>* error)
{
    auto fail = [&](qsizetype pos, const QString& message) -> std::optional<NgcStatement> {
        *error = ProgramError{lineNumber, int(pos) + 1, message};
        return std::nullopt;
    };
    qsizetype pos = skipSpaces(line, 0);
    if (pos < line.size() && line.at(pos).toUpper() == QLatin1Char('N')) {
        qsizetype p = skipSpaces(line, pos + 1);
        while (p < line.size() && (isAsciiDigit(line.at(p)) || line.at(p).isSpace()))
            ++p;
        if (p < line.size() && line.at(p).toUpper() == QLatin1Char('O'))
            pos = p;
    }
    if (pos >= line.size() || line.at(pos).toUpper() != QLatin1Char('O'))
        return std::nullopt;
    NgcStatement s;
    s.column = int(pos) + 1;
    pos = skipSpaces(line, pos + 1);
    if (pos < line.size() && line.at(pos) == QLatin1Char('<')) {
        const qsizetype close = line.indexOf(QLatin1Char('>'), pos);
        if (close < 0)
            return fail(pos, NgcStructure::tr("the O word's name is not closed by \">\""));
        for (qsizetype i = pos + 1; i < close; ++i)
            if (!line.at(i).isSpace())
                s.label += line.at(i).toLower();
        pos = close + 1;
    } else {
        while (pos < line.size() && (isAsciiDigit(line.at(pos)) || line.at(pos).isSpace())) {
            if (!line.at(pos).isSpace() && !(s.label.isEmpty() && line.at(pos) == QLatin1Char('0')))
                s.label += line.at(pos);
            ++pos;
        }
        if (s.label.isEmpty() && pos > s.column)
            s.label = QStringLiteral("0");
    }
    if (s.label.isEmpty())
        return fail(s.column - 1, NgcStructure::tr("O needs a number or a <name>"));
    pos = skipSpaces(line, pos);
    QString word;
    const qsizetype keywordAt = pos;
    while (pos < line.size() && (isAsciiLetter(line.at(pos)) || line.at(pos).isSpace())) {
        if (!line.at(pos).isSpace())
            word += line.at(pos).toLower();
        ++pos;
    }
    for (const KeywordName& k : kKeywords) {
        if (word == QLatin1String(k.word)) {
            s.kind = k.kind;
            s.rest = pos;
            return s;
        }
    }
    return fail(keywordAt,
                word.isEmpty()
                    ? NgcStructure::tr("O%1 needs a keyword: sub, endsub, call, return, if, "
                                       "elseif, else, endif, while, endwhile, do, break, "
                                       "continue, repeat or endrepeat")
                          .arg(s.label)
                    : NgcStructure::tr("\"%1\" is not an O-word keyword").arg(word));
}

namespace {

struct Open
{
    NgcStatement::Kind kind;
    QString label;
    int line;
    QList<int> branches; // an if's if/elseif/else lines
};

class Scanner
{
public:
    Scanner(QList<ProgramError>* errors, int maxErrors) : m_errors(errors), m_maxErrors(maxErrors)
    {}
    bool failed = false;

    void error(int line, int column, const QString& message)
    {
        failed = true;
        if (m_errors->size() < m_maxErrors)
            *m_errors << ProgramError{line + 1, column, message};
    }

private:
    QList<ProgramError>* m_errors;
    int m_maxErrors;
};

bool isLoop(NgcStatement::Kind k)
{
    return k == NgcStatement::While || k == NgcStatement::Do || k == NgcStatement::Repeat;
}

} // namespace

std::optional<NgcStructure> NgcStructure::scan(const QStringList& lines,
                                               QList<ProgramError>* errors, int maxErrors)
{
    NgcStructure out;
    const qsizetype firstError = errors->size();
    Scanner scanner(errors, maxErrors);
    QList<Open> stack;
    auto closes = [&](const NgcStatement& s, int line,
                      std::initializer_list<NgcStatement::Kind> kinds) {
        if (!stack.isEmpty() && stack.last().label == s.label)
            for (const NgcStatement::Kind k : kinds)
                if (stack.last().kind == k)
                    return true;
        scanner.error(
            line, s.column,
            stack.isEmpty()
                ? tr("%1 closes nothing that is open").arg(s.name())
                : tr("%1 does not close %2 (line %3)")
                      .arg(s.name(),
                           NgcStatement{stack.last().kind, stack.last().label, 0, 0}.name())
                      .arg(stack.last().line + 1));
        return false;
    };
    for (int i = 0; i < lines.size(); ++i) {
        std::optional<ProgramError> broken;
        std::optional<NgcStatement> read = NgcStatement::read(lines.at(i), i + 1, &broken);
        if (broken) {
            scanner.error(i, broken->column, broken->message);
            continue;
        }
        if (!read)
            continue;
        NgcStatement s = *read;
        switch (s.kind) {
        case NgcStatement::Sub:
            for (const Open& o : std::as_const(stack))
                if (o.kind == NgcStatement::Sub)
                    scanner.error(i, s.column,
                                  tr("%1 inside %2 sub (line %3): subroutines do "
                                     "not nest")
                                      .arg(s.name(), NgcStatement::labelText(o.label))
                                      .arg(o.line + 1));
            if (out.m_subs.contains(s.label))
                scanner.error(i, s.column,
                              tr("%1 is defined twice (line %2 first)")
                                  .arg(s.name())
                                  .arg(out.m_subs.value(s.label) + 1));
            out.m_subs.insert(s.label, i);
            stack << Open{s.kind, s.label, i, {}};
            break;
        case NgcStatement::If:
        case NgcStatement::While:
            if (s.kind == NgcStatement::While && !stack.isEmpty() &&
                stack.last().kind == NgcStatement::Do && stack.last().label == s.label) {
                s.kind = NgcStatement::DoWhile;
                out.m_partner.insert(stack.last().line, i);
                out.m_partner.insert(i, stack.last().line);
                stack.removeLast();
                break;
            }
            [[fallthrough]];
        case NgcStatement::Do:
        case NgcStatement::Repeat:
            stack << Open{s.kind, s.label, i, {i}};
            break;
        case NgcStatement::ElseIf:
        case NgcStatement::Else:
            if (closes(s, i, {NgcStatement::If, NgcStatement::ElseIf})) {
                out.m_partner.insert(stack.last().branches.last(), i);
                stack.last().branches << i;
                stack.last().kind = s.kind;
            }
            break;
        case NgcStatement::EndIf:
            if (closes(s, i, {NgcStatement::If, NgcStatement::ElseIf, NgcStatement::Else})) {
                out.m_partner.insert(stack.last().branches.last(), i);
                for (const int b : std::as_const(stack.last().branches))
                    out.m_endIf.insert(b, i);
                stack.removeLast();
            }
            break;
        case NgcStatement::EndSub:
        case NgcStatement::EndWhile:
        case NgcStatement::EndRepeat: {
            const NgcStatement::Kind opens = s.kind == NgcStatement::EndSub ? NgcStatement::Sub
                                             : s.kind == NgcStatement::EndWhile
                                                 ? NgcStatement::While
                                                 : NgcStatement::Repeat;
            if (closes(s, i, {opens})) {
                out.m_partner.insert(stack.last().line, i);
                out.m_partner.insert(i, stack.last().line);
                stack.removeLast();
            }
            break;
        }
        case NgcStatement::Break:
        case NgcStatement::Continue:
        case NgcStatement::Return: {
            int found = -1;
            for (qsizetype k = stack.size() - 1; k >= 0 && found < 0; --k) {
                const Open& o = stack.at(k);
                const bool fits =
                    s.kind == NgcStatement::Return ? o.kind == NgcStatement::Sub : isLoop(o.kind);
                if (fits && o.label == s.label)
                    found = o.line;
            }
            if (found < 0)
                scanner.error(
                    i, s.column,
                    s.kind == NgcStatement::Return
                        ? tr("%1 is outside %2 sub").arg(s.name(), NgcStatement::labelText(s.label))
                        : tr("%1 is outside a loop %2")
                              .arg(s.name(), NgcStatement::labelText(s.label)));
            out.m_loopOf.insert(i, found);
            break;
        }
        case NgcStatement::Call:
        case NgcStatement::DoWhile:
            break;
        }
        out.m_statements.insert(i, s);
    }
    for (const Open& o : std::as_const(stack))
        scanner.error(o.line, 1,
                      tr("%1 is not closed").arg(NgcStatement{o.kind, o.label, 0, 0}.name()));
    if (scanner.failed) {
        // In line order, as the parser lists its errors.
        std::stable_sort(
            errors->begin() + firstError, errors->end(),
            [](const ProgramError& a, const ProgramError& b) { return a.line < b.line; });
        return std::nullopt;
    }
    return out;
}

} // namespace stepdeck::program
