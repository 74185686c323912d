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

bool isLoop(NgcStatement::Kind k)
{
    return k == NgcStatement::While || k == NgcStatement::Do || k == NgcStatement::Repeat;
}

} // namespace

// Matches a file's O words line by line over a stack of the open ones.
class NgcStructure::Scanner
{
public:
    Scanner(NgcStructure* out, QList<ProgramError>* errors, int maxErrors)
        : m_out(*out), m_errors(errors), m_firstError(errors->size()), m_maxErrors(maxErrors)
    {}

    void line(int i, const QString& text)
    {
        std::optional<ProgramError> broken;
        std::optional<NgcStatement> read = NgcStatement::read(text, i + 1, &broken);
        if (broken)
            error(i, broken->column, broken->message);
        else if (read)
            statement(i, *read);
    }

    // false: the structure is broken (the errors in line order, as the parser lists its own).
    bool finish()
    {
        for (const Open& o : std::as_const(m_stack))
            error(o.line, 1, tr("%1 is not closed").arg(name(o)));
        std::stable_sort(
            m_errors->begin() + m_firstError, m_errors->end(),
            [](const ProgramError& a, const ProgramError& b) { return a.line < b.line; });
        return !m_failed;
    }

private:
    static QString name(const Open& o) { return NgcStatement{o.kind, o.label, 0, 0}.name(); }

    void error(int line, int column, const QString& message)
    {
        m_failed = true;
        if (m_errors->size() < m_maxErrors)
            *m_errors << ProgramError{line + 1, column, message};
    }

    void statement(int i, NgcStatement s)
    {
        switch (s.kind) {
        case NgcStatement::Sub:
            openSub(i, s);
            break;
        case NgcStatement::While:
            if (closesDo(i, s)) {
                s.kind = NgcStatement::DoWhile;
                break;
            }
            [[fallthrough]];
        case NgcStatement::If:
        case NgcStatement::Do:
        case NgcStatement::Repeat:
            m_stack << Open{s.kind, s.label, i, {i}};
            break;
        case NgcStatement::ElseIf:
        case NgcStatement::Else:
            branch(i, s);
            break;
        case NgcStatement::EndIf:
            endIf(i, s);
            break;
        case NgcStatement::EndSub:
        case NgcStatement::EndWhile:
        case NgcStatement::EndRepeat:
            end(i, s);
            break;
        case NgcStatement::Break:
        case NgcStatement::Continue:
        case NgcStatement::Return:
            jumpOut(i, s);
            break;
        case NgcStatement::Call:
        case NgcStatement::DoWhile:
            break;
        }
        m_out.m_statements.insert(i, s);
    }

    bool closes(const NgcStatement& s, int line, std::initializer_list<NgcStatement::Kind> kinds)
    {
        if (!m_stack.isEmpty() && m_stack.last().label == s.label)
            for (const NgcStatement::Kind k : kinds)
                if (m_stack.last().kind == k)
                    return true;
        error(line, s.column,
              m_stack.isEmpty() ? tr("%1 closes nothing that is open").arg(s.name())
                                : tr("%1 does not close %2 (line %3)")
                                      .arg(s.name(), name(m_stack.last()))
                                      .arg(m_stack.last().line + 1));
        return false;
    }

    void pair(int a, int b)
    {
        m_out.m_partner.insert(a, b);
        m_out.m_partner.insert(b, a);
    }

    void openSub(int i, const NgcStatement& s)
    {
        for (const Open& o : std::as_const(m_stack))
            if (o.kind == NgcStatement::Sub)
                error(i, s.column,
                      tr("%1 inside %2 sub (line %3): subroutines do not nest")
                          .arg(s.name(), NgcStatement::labelText(o.label))
                          .arg(o.line + 1));
        if (m_out.m_subs.contains(s.label))
            error(i, s.column,
                  tr("%1 is defined twice (line %2 first)")
                      .arg(s.name())
                      .arg(m_out.m_subs.value(s.label) + 1));
        m_out.m_subs.insert(s.label, i);
        m_stack << Open{s.kind, s.label, i, {}};
    }

    // "O1 while" right after "O1 do" ... : the end of the do.
    bool closesDo(int i, const NgcStatement& s)
    {
        if (m_stack.isEmpty() || m_stack.last().kind != NgcStatement::Do ||
            m_stack.last().label != s.label)
            return false;
        pair(m_stack.last().line, i);
        m_stack.removeLast();
        return true;
    }

    void branch(int i, const NgcStatement& s)
    {
        if (!closes(s, i, {NgcStatement::If, NgcStatement::ElseIf}))
            return;
        m_out.m_partner.insert(m_stack.last().branches.last(), i);
        m_stack.last().branches << i;
        m_stack.last().kind = s.kind;
    }

    void endIf(int i, const NgcStatement& s)
    {
        if (!closes(s, i, {NgcStatement::If, NgcStatement::ElseIf, NgcStatement::Else}))
            return;
        m_out.m_partner.insert(m_stack.last().branches.last(), i);
        for (const int b : std::as_const(m_stack.last().branches))
            m_out.m_endIf.insert(b, i);
        m_stack.removeLast();
    }

    void end(int i, const NgcStatement& s)
    {
        const NgcStatement::Kind opens = s.kind == NgcStatement::EndSub     ? NgcStatement::Sub
                                         : s.kind == NgcStatement::EndWhile ? NgcStatement::While
                                                                            : NgcStatement::Repeat;
        if (!closes(s, i, {opens}))
            return;
        pair(m_stack.last().line, i);
        m_stack.removeLast();
    }

    // break/continue: the loop of its label around it; return: its sub, named by the sub's
    // label or by that of a block of the sub around the return ("o110 return [5]" inside
    // "o110 if", as LinuxCNC runs it, issue 50 item 9).
    void jumpOut(int i, const NgcStatement& s)
    {
        int found = -1;
        bool labelled = false; // return: a block around it has its label
        for (qsizetype k = m_stack.size() - 1; k >= 0 && found < 0; --k) {
            const Open& o = m_stack.at(k);
            labelled = labelled || o.label == s.label;
            if (s.kind == NgcStatement::Return) {
                if (o.kind != NgcStatement::Sub)
                    continue;
                if (labelled)
                    found = o.line;
                break; // subroutines do not nest: the innermost is the one to leave
            }
            if (o.kind == NgcStatement::Sub)
                break; // a loop outside the subroutine is not this one's to leave
            if (isLoop(o.kind) && o.label == s.label)
                found = o.line;
        }
        if (found < 0)
            error(i, s.column,
                  s.kind == NgcStatement::Return
                      ? tr("%1 is outside %2 sub").arg(s.name(), NgcStatement::labelText(s.label))
                      : tr("%1 is outside a loop %2")
                            .arg(s.name(), NgcStatement::labelText(s.label)));
        m_out.m_loopOf.insert(i, found);
    }

    NgcStructure& m_out;
    QList<ProgramError>* m_errors;
    qsizetype m_firstError;
    int m_maxErrors;
    bool m_failed = false;
    QList<Open> m_stack;
};

std::optional<NgcStructure> NgcStructure::scan(const QStringList& lines,
                                               QList<ProgramError>* errors, int maxErrors)
{
    NgcStructure out;
    Scanner scanner(&out, errors, maxErrors);
    for (int i = 0; i < lines.size(); ++i)
        scanner.line(i, lines.at(i));
    if (!scanner.finish())
        return std::nullopt;
    return out;
}

} // namespace stepdeck::program
