#include "NumberParsing.h"
#include <QLocale>
#include <QtMath>
#include <limits>

namespace stepdeck::numbers {

namespace {
bool isDigit(QChar c)
{
    return c >= QLatin1Char('0') && c <= QLatin1Char('9');
}

// Counts the ASCII digits from *i on and advances past them.
int skipDigits(QStringView text, qsizetype* i)
{
    int count = 0;
    while (*i < text.size() && isDigit(text.at(*i))) {
        ++*i;
        ++count;
    }
    return count;
}

bool isSign(QChar c)
{
    return c == QLatin1Char('+') || c == QLatin1Char('-');
}

// [+-]? (digits [. digits*] | . digits) ([eE] [+-]? digits)?
bool isDecimalReal(QStringView text)
{
    qsizetype i = 0;
    if (i < text.size() && isSign(text.at(i)))
        ++i;
    int mantissaDigits = skipDigits(text, &i);
    if (i < text.size() && text.at(i) == QLatin1Char('.')) {
        ++i;
        mantissaDigits += skipDigits(text, &i);
    }
    if (mantissaDigits == 0)
        return false;
    if (i < text.size() && (text.at(i) == QLatin1Char('e') || text.at(i) == QLatin1Char('E'))) {
        ++i;
        if (i < text.size() && isSign(text.at(i)))
            ++i;
        if (skipDigits(text, &i) == 0)
            return false;
    }
    return i == text.size();
}
} // namespace

bool isNonFiniteWord(QStringView text)
{
    QStringView t = text.trimmed();
    if (!t.isEmpty() && isSign(t.front()))
        t = t.mid(1);
    return t.compare(QLatin1String("nan"), Qt::CaseInsensitive) == 0 ||
           t.compare(QLatin1String("inf"), Qt::CaseInsensitive) == 0 ||
           t.compare(QLatin1String("infinity"), Qt::CaseInsensitive) == 0;
}

NumberError parseInteger(QStringView text, qint64* value)
{
    const QStringView t = text.trimmed();
    if (isNonFiniteWord(t))
        return NumberError::NonFinite;
    qsizetype i = 0;
    const bool negative = !t.isEmpty() && t.front() == QLatin1Char('-');
    if (!t.isEmpty() && isSign(t.front()))
        ++i;
    if (i == t.size())
        return NumberError::Malformed;
    // Accumulated as a negative number: its range includes the minimum of qint64.
    constexpr qint64 lowest = std::numeric_limits<qint64>::min();
    qint64 acc = 0;
    bool overflow = false;
    for (; i < t.size(); ++i) {
        if (!isDigit(t.at(i)))
            return NumberError::Malformed;
        const int digit = t.at(i).unicode() - '0';
        if (acc < (lowest + digit) / 10)
            overflow = true; // keep scanning: "99999999999999999999x" is Malformed
        else
            acc = acc * 10 - digit;
    }
    if (overflow || (!negative && acc == lowest))
        return NumberError::OutOfRange;
    *value = negative ? acc : -acc;
    return NumberError::None;
}

NumberError parseInteger(QStringView text, qint64 minimum, qint64 maximum, qint64* value)
{
    qint64 v = 0;
    const NumberError e = parseInteger(text, &v);
    if (e != NumberError::None)
        return e;
    if (v < minimum || v > maximum)
        return NumberError::OutOfRange;
    *value = v;
    return NumberError::None;
}

NumberError parseInt(QStringView text, int minimum, int maximum, int* value)
{
    qint64 v = 0;
    const NumberError e = parseInteger(text, minimum, maximum, &v);
    if (e == NumberError::None)
        *value = int(v);
    return e;
}

NumberError parseReal(QStringView text, double* value)
{
    const QStringView t = text.trimmed();
    if (isNonFiniteWord(t))
        return NumberError::NonFinite;
    if (!isDecimalReal(t))
        return NumberError::Malformed;
    // The C locale: '.' is the decimal point whatever the user's locale says.
    bool ok = false;
    const double v = QLocale::c().toDouble(t, &ok);
    if (!ok || !qIsFinite(v))
        return NumberError::OutOfRange; // the grammar held, so only the magnitude can fail
    *value = v;
    return NumberError::None;
}

NumberError integerFromDouble(double value, qint64* out)
{
    if (!qIsFinite(value))
        return NumberError::NonFinite;
    if (value != std::trunc(value))
        return NumberError::Malformed;
    // -2^63 and 2^63 are exact doubles; anything in [-2^63, 2^63) converts without overflow.
    constexpr double limit = 9223372036854775808.0;
    if (value < -limit || value >= limit)
        return NumberError::OutOfRange;
    *out = qint64(value);
    return NumberError::None;
}

NumberError integerFromVariant(const QVariant& value, qint64* out)
{
    switch (value.typeId()) {
    case QMetaType::QString:
        return parseInteger(value.toString(), out);
    case QMetaType::QByteArray:
        return parseInteger(QString::fromLatin1(value.toByteArray()), out);
    case QMetaType::Double:
    case QMetaType::Float:
        return integerFromDouble(value.toDouble(), out);
    case QMetaType::ULongLong:
    case QMetaType::ULong:
        if (value.toULongLong() > quint64(std::numeric_limits<qint64>::max()))
            return NumberError::OutOfRange;
        *out = qint64(value.toULongLong());
        return NumberError::None;
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::Long:
    case QMetaType::LongLong:
    case QMetaType::Short:
    case QMetaType::UShort:
    case QMetaType::SChar:
    case QMetaType::UChar:
        *out = value.toLongLong();
        return NumberError::None;
    default:
        return NumberError::Malformed; // booleans, null, lists, ...
    }
}

} // namespace stepdeck::numbers
