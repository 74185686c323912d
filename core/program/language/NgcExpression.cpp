#include "NgcExpression.h"
#include <QHash>
#include <QVarLengthArray>
#include <cmath>

namespace stepdeck::program {

namespace {

enum Operator { And, Or, Xor, Eq, Ne, Gt, Ge, Lt, Le, Plus, Minus, Times, Divide, Mod, Power };

// LinuxCNC's precedence (rs274ngc's precedence()): the higher binds tighter.
int precedence(int op)
{
    switch (op) {
    case And:
    case Or:
    case Xor:
        return 1;
    case Eq:
    case Ne:
    case Gt:
    case Ge:
    case Lt:
    case Le:
        return 2;
    case Plus:
    case Minus:
        return 3;
    case Times:
    case Divide:
    case Mod:
        return 4;
    default:
        return 5; // Power
    }
}

constexpr double kDegree = M_PI / 180.0;

} // namespace

QChar NgcExpression::peek() const
{
    return atEnd() ? QChar() : m_line.at(m_pos);
}

bool NgcExpression::atEnd() const
{
    return m_pos >= m_line.size();
}

void NgcExpression::skipSpaces()
{
    while (!atEnd() && m_line.at(m_pos).isSpace())
        ++m_pos;
}

std::nullopt_t NgcExpression::fail(int column, const QString& message)
{
    if (!m_error)
        m_error = ProgramError{m_lineNumber, column, message};
    return std::nullopt;
}

std::optional<double> NgcExpression::readValue(qsizetype* pos)
{
    m_pos = *pos;
    const std::optional<double> v = value(0);
    *pos = m_pos;
    return v;
}

// rs274ngc's read_real_value: a sign before anything but a digit or point is an operator on
// the value that follows.
std::optional<double> NgcExpression::value(int depth)
{
    if (depth > kMaxDepth)
        return fail(column(), tr("the expression nests deeper than %1").arg(kMaxDepth));
    skipSpaces();
    const QChar c = peek();
    if (c == QLatin1Char('['))
        return bracketed(depth + 1);
    if (c == QLatin1Char('#')) {
        ++m_pos;
        return parameter(depth + 1);
    }
    if (c == QLatin1Char('+') || c == QLatin1Char('-')) {
        qsizetype next = m_pos + 1;
        while (next < m_line.size() && m_line.at(next).isSpace())
            ++next;
        const QChar after = next < m_line.size() ? m_line.at(next) : QChar();
        if (!after.isDigit() && after != QLatin1Char('.')) {
            m_pos = next;
            const std::optional<double> v = value(depth + 1);
            if (!v)
                return std::nullopt;
            return c == QLatin1Char('-') ? -*v : *v;
        }
        return number();
    }
    if (c.unicode() < 128 && c.isLetter()) {
        const int start = column();
        QString name;
        while (!atEnd() && ((peek().unicode() < 128 && peek().isLetter()) || peek().isSpace())) {
            if (!peek().isSpace())
                name += peek().toLower();
            ++m_pos;
        }
        return function(name, start, depth + 1);
    }
    return number();
}

std::optional<double> NgcExpression::number()
{
    skipSpaces();
    const int start = column();
    QString text;
    if (peek() == QLatin1Char('+') || peek() == QLatin1Char('-')) {
        text += peek();
        ++m_pos;
    }
    int digits = 0;
    bool point = false;
    for (;; ++m_pos) {
        skipSpaces();
        const QChar ch = peek();
        if (ch.unicode() < 128 && ch.isDigit())
            ++digits;
        else if (ch == QLatin1Char('.') && !point)
            point = true;
        else
            break;
        text += ch;
    }
    if (digits == 0)
        return fail(start, atEnd() ? tr("a value is missing at the end of the line")
                                   : tr("\"%1\" does not start a value").arg(QString(peek())));
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return fail(start, tr("%1 is not a finite number").arg(text));
    return v;
}

std::optional<double> NgcExpression::bracketed(int depth)
{
    const int open = column();
    ++m_pos; // '['
    const std::optional<double> v = binary(depth);
    if (!v)
        return std::nullopt;
    skipSpaces();
    if (peek() != QLatin1Char(']'))
        return fail(atEnd() ? open : column(),
                    atEnd() ? tr("\"[\" is not closed by \"]\"")
                            : tr("an operator or \"]\" is missing before \"%1\"").arg(peek()));
    ++m_pos;
    return v;
}

// Precedence climbing over the operators of one bracket: equal ones left to right.
std::optional<double> NgcExpression::binary(int depth)
{
    struct Pending
    {
        double value;
        int op;
        int column;
    };
    QVarLengthArray<Pending, 8> stack;
    std::optional<double> v = value(depth);
    for (;;) {
        if (!v)
            return std::nullopt;
        skipSpaces();
        const int at = column();
        const int op = readOperator();
        double right = *v;
        // Fold what binds at least as tight as the next operator (none: everything).
        while (!stack.isEmpty() && (op < 0 || precedence(stack.last().op) >= precedence(op))) {
            const Pending p = stack.last();
            stack.removeLast();
            double left = p.value;
            if (!apply(p.op, &left, right, p.column))
                return std::nullopt;
            right = left;
        }
        if (op < 0)
            return right;
        stack.push_back(Pending{right, op, at});
        v = value(depth);
    }
}

int NgcExpression::readOperator()
{
    const QChar c = peek();
    auto take = [this](qsizetype n, int op) {
        m_pos += n;
        return op;
    };
    if (c == QLatin1Char('+'))
        return take(1, Plus);
    if (c == QLatin1Char('-'))
        return take(1, Minus);
    if (c == QLatin1Char('/'))
        return take(1, Divide);
    if (c == QLatin1Char('*')) {
        qsizetype next = m_pos + 1;
        while (next < m_line.size() && m_line.at(next).isSpace())
            ++next;
        if (next < m_line.size() && m_line.at(next) == QLatin1Char('*'))
            return take(next + 1 - m_pos, Power);
        return take(1, Times);
    }
    static const struct
    {
        const char* word;
        int op;
    } words[] = {{"mod", Mod}, {"and", And}, {"xor", Xor}, {"or", Or}, {"eq", Eq},
                 {"ne", Ne},   {"gt", Gt},   {"ge", Ge},   {"lt", Lt}, {"le", Le}};
    for (const auto& w : words) {
        qsizetype p = m_pos;
        const char* s = w.word;
        for (; *s; ++s) {
            while (p < m_line.size() && m_line.at(p).isSpace())
                ++p;
            if (p >= m_line.size() || m_line.at(p).toLower() != QLatin1Char(*s))
                break;
            ++p;
        }
        if (!*s)
            return take(p - m_pos, w.op);
    }
    return -1;
}

bool NgcExpression::failed(int column, const QString& message)
{
    fail(column, message);
    return false;
}

// AND OR XOR and the comparisons: 1 or 0 (LinuxCNC).
double NgcExpression::logical(int op, double l, double r)
{
    switch (op) {
    case And:
        return (l == 0.0 || r == 0.0) ? 0.0 : 1.0;
    case Or:
        return (l != 0.0 || r != 0.0) ? 1.0 : 0.0;
    case Xor:
        return ((l == 0.0) != (r == 0.0)) ? 1.0 : 0.0;
    case Eq:
        return std::fabs(l - r) < kEqualTolerance ? 1.0 : 0.0;
    case Ne:
        return std::fabs(l - r) >= kEqualTolerance ? 1.0 : 0.0;
    case Gt:
        return l > r ? 1.0 : 0.0;
    case Ge:
        return l >= r ? 1.0 : 0.0;
    case Lt:
        return l < r ? 1.0 : 0.0;
    default:
        return l <= r ? 1.0 : 0.0; // Le
    }
}

bool NgcExpression::apply(int op, double* left, double right, int column)
{
    const double l = *left;
    double r = 0;
    switch (op) {
    case Plus:
        r = l + right;
        break;
    case Minus:
        r = l - right;
        break;
    case Times:
        r = l * right;
        break;
    case Divide:
        if (right == 0.0)
            return failed(column, tr("division by zero"));
        r = l / right;
        break;
    case Mod:
        if (right == 0.0)
            return failed(column, tr("MOD by zero"));
        // LinuxCNC's MOD: never negative.
        r = std::fmod(l, right);
        if (r < 0.0)
            r += std::fabs(right);
        break;
    case Power:
        if (l < 0.0 && std::floor(right) != right)
            return failed(column, tr("a negative number to a fractional power"));
        r = std::pow(l, right);
        break;
    default:
        r = logical(op, l, right);
        break;
    }
    if (!std::isfinite(r))
        return failed(column, tr("the result is not a finite number"));
    *left = r;
    return true;
}

std::optional<double> NgcExpression::function(const QString& name, int column, int depth)
{
    skipSpaces();
    if (peek() != QLatin1Char('['))
        return fail(column, tr("\"%1\" is not a value: a number, #, [ or a function").arg(name));
    if (name == QLatin1String("exists"))
        return exists();
    const std::optional<double> x = bracketed(depth);
    if (!x)
        return std::nullopt;
    std::optional<double> r;
    if (name == QLatin1String("atan")) {
        skipSpaces();
        if (peek() != QLatin1Char('/'))
            return fail(this->column(), tr("ATAN takes two values: ATAN[y]/[x]"));
        ++m_pos;
        skipSpaces();
        if (peek() != QLatin1Char('['))
            return fail(this->column(), tr("ATAN takes two values: ATAN[y]/[x]"));
        const std::optional<double> b = bracketed(depth);
        if (!b)
            return std::nullopt;
        r = std::atan2(*x, *b) / kDegree;
    } else {
        r = unary(name, *x, column);
    }
    if (r && !std::isfinite(*r))
        return fail(column, tr("%1: the result is not a finite number").arg(name.toUpper()));
    return r;
}

// "EXISTS[#<name>]", at its "[".
std::optional<double> NgcExpression::exists()
{
    const int open = column();
    ++m_pos;
    skipSpaces();
    if (peek() != QLatin1Char('#'))
        return fail(column(), tr("EXISTS takes a named parameter: EXISTS[#<name>]"));
    ++m_pos;
    skipSpaces();
    const QString n = readName(&m_pos);
    if (n.isEmpty())
        return std::nullopt;
    skipSpaces();
    if (peek() != QLatin1Char(']'))
        return fail(atEnd() ? open : column(), tr("\"[\" is not closed by \"]\""));
    ++m_pos;
    return m_parameters.exists(n) ? 1.0 : 0.0;
}

// LinuxCNC's unary functions; angles in degrees.
std::optional<double> NgcExpression::unary(const QString& name, double x, int column)
{
    using Function = double (*)(double);
    static const QHash<QString, Function> functions{
        {QStringLiteral("abs"), [](double v) { return std::fabs(v); }},
        {QStringLiteral("acos"), [](double v) { return std::acos(v) / kDegree; }},
        {QStringLiteral("asin"), [](double v) { return std::asin(v) / kDegree; }},
        {QStringLiteral("cos"), [](double v) { return std::cos(v * kDegree); }},
        {QStringLiteral("sin"), [](double v) { return std::sin(v * kDegree); }},
        {QStringLiteral("tan"), [](double v) { return std::tan(v * kDegree); }},
        {QStringLiteral("exp"), [](double v) { return std::exp(v); }},
        {QStringLiteral("ln"), [](double v) { return std::log(v); }},
        {QStringLiteral("sqrt"), [](double v) { return std::sqrt(v); }},
        {QStringLiteral("fix"), [](double v) { return std::floor(v); }},
        {QStringLiteral("fup"), [](double v) { return std::ceil(v); }},
        // LinuxCNC: half away from zero.
        {QStringLiteral("round"), [](double v) { return std::trunc(v + (v < 0.0 ? -0.5 : 0.5)); }},
    };
    const Function f = functions.value(name);
    if (!f)
        return fail(column, tr("unknown function \"%1\"").arg(name.toUpper()));
    QString why;
    if ((name == QLatin1String("acos") || name == QLatin1String("asin")) && (x < -1.0 || x > 1.0))
        why = tr("outside -1..1");
    else if (name == QLatin1String("ln") && x <= 0.0)
        why = tr("needs a value above 0");
    else if (name == QLatin1String("sqrt") && x < 0.0)
        why = tr("needs a value of 0 or more");
    if (!why.isEmpty())
        return fail(column, tr("%1[%2]: %3").arg(name.toUpper()).arg(x).arg(why));
    return f(x);
}

QString NgcExpression::readName(qsizetype* pos)
{
    m_pos = *pos;
    const int start = column();
    if (peek() != QLatin1Char('<')) {
        fail(start, tr("a parameter name is written #<name>"));
        return {};
    }
    const qsizetype close = m_line.indexOf(QLatin1Char('>'), m_pos);
    if (close < 0) {
        fail(start, tr("the parameter name is not closed by \">\""));
        return {};
    }
    QString name;
    for (qsizetype i = m_pos + 1; i < close; ++i)
        if (!m_line.at(i).isSpace())
            name += m_line.at(i).toLower();
    if (name.isEmpty()) {
        fail(start, tr("the parameter name is empty"));
        return {};
    }
    m_pos = close + 1;
    *pos = m_pos;
    return name;
}

std::optional<NgcExpression::Reference> NgcExpression::readReference(qsizetype* pos)
{
    m_pos = *pos;
    skipSpaces();
    Reference ref;
    ref.column = column();
    if (peek() == QLatin1Char('<')) {
        ref.name = readName(&m_pos);
        if (ref.name.isEmpty())
            return std::nullopt;
    } else {
        const std::optional<double> n = value(1);
        if (!n)
            return std::nullopt;
        const double rounded = std::round(*n);
        if (std::fabs(*n - rounded) >= kEqualTolerance || rounded < 1 || rounded > 99999)
            return fail(ref.column, tr("#%1 is not a parameter: parameters are whole numbers "
                                       "from 1")
                                        .arg(*n));
        ref.number = int(rounded);
    }
    *pos = m_pos;
    return ref;
}

std::optional<double> NgcExpression::parameter(int depth)
{
    const qsizetype at = m_pos - 1; // the '#'
    skipSpaces();
    if (peek() == QLatin1Char('<')) {
        const QString name = readName(&m_pos);
        if (name.isEmpty())
            return std::nullopt;
        QString why;
        const std::optional<double> v = m_parameters.named(name, &why);
        return v ? v : fail(int(at) + 1, why);
    }
    qsizetype p = m_pos;
    m_pos = p;
    const std::optional<double> n = value(depth);
    if (!n)
        return std::nullopt;
    const double rounded = std::round(*n);
    if (std::fabs(*n - rounded) >= kEqualTolerance || rounded < 1 || rounded > 99999)
        return fail(int(at) + 1,
                    tr("#%1 is not a parameter: parameters are whole numbers from 1").arg(*n));
    QString why;
    const std::optional<double> v = m_parameters.numbered(int(rounded), &why);
    return v ? v : fail(int(at) + 1, why);
}

} // namespace stepdeck::program
