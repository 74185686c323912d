// NumberParsing: the one place user input becomes a number (issue 12, "a leading zero makes a
// value octal", "huge JSON numbers are undefined behaviour", "jog X=nan").
#include "NumberErrorMetaType.h"
#include "TestMain.h"
#include "model/NumberParsing.h"
#include <QtTest>
#include <limits>

using namespace stepdeck;

namespace {
constexpr qint64 kMax = std::numeric_limits<qint64>::max();
constexpr qint64 kMin = std::numeric_limits<qint64>::min();
} // namespace

class TestNumberParsing : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parseInteger_decimalOnly_data();
    void parseInteger_decimalOnly();
    void parseInteger_range_data();
    void parseInteger_range();
    void parseReal_decimalOnly_data();
    void parseReal_decimalOnly();
    void parseReal_ignoresTheUsersLocale();
    void integerFromDouble_checksBeforeConverting_data();
    void integerFromDouble_checksBeforeConverting();
    void integerFromVariant_byType_data();
    void integerFromVariant_byType();
};

void TestNumberParsing::parseInteger_decimalOnly_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<NumberError>("error");
    QTest::addColumn<qint64>("value");
    const auto ok = NumberError::None;
    const auto bad = NumberError::Malformed;
    QTest::newRow("plain") << "100" << ok << qint64(100);
    QTest::newRow("leading zero is not octal") << "0100" << ok << qint64(100);
    QTest::newRow("010 is ten") << "010" << ok << qint64(10);
    QTest::newRow("zero") << "0" << ok << qint64(0);
    QTest::newRow("minus zero") << "-0" << ok << qint64(0);
    QTest::newRow("negative") << "-1500" << ok << qint64(-1500);
    QTest::newRow("plus sign") << "+42" << ok << qint64(42);
    QTest::newRow("surrounding blanks") << "  7\t" << ok << qint64(7);
    QTest::newRow("many leading zeros") << "000000000000000000000000001" << ok << qint64(1);
    QTest::newRow("qint64 max") << "9223372036854775807" << ok << kMax;
    QTest::newRow("qint64 min") << "-9223372036854775808" << ok << kMin;
    QTest::newRow("max + 1") << "9223372036854775808" << NumberError::OutOfRange << qint64(0);
    QTest::newRow("min - 1") << "-9223372036854775809" << NumberError::OutOfRange << qint64(0);
    QTest::newRow("20 digits") << "99999999999999999999" << NumberError::OutOfRange << qint64(0);
    QTest::newRow("hex") << "0x40" << bad << qint64(0);
    QTest::newRow("hex upper") << "0X40" << bad << qint64(0);
    QTest::newRow("binary") << "0b101" << bad << qint64(0);
    QTest::newRow("exponent") << "1e3" << bad << qint64(0);
    QTest::newRow("fraction") << "12.5" << bad << qint64(0);
    QTest::newRow("trailing dot") << "12." << bad << qint64(0);
    QTest::newRow("blank inside") << "1 000" << bad << qint64(0);
    QTest::newRow("comma") << "1,5" << bad << qint64(0);
    QTest::newRow("empty") << "" << bad << qint64(0);
    QTest::newRow("blank") << "   " << bad << qint64(0);
    QTest::newRow("sign only") << "-" << bad << qint64(0);
    QTest::newRow("two signs") << "--5" << bad << qint64(0);
    QTest::newRow("sign after blank") << "- 5" << bad << qint64(0);
    QTest::newRow("word") << "fast" << bad << qint64(0);
    QTest::newRow("trailing letter") << "100x" << bad << qint64(0);
    QTest::newRow("overflow then letter") << "99999999999999999999x" << bad << qint64(0);
    QTest::newRow("arabic-indic digits") << QString::fromUtf8("\u0661\u0662") << bad << qint64(0);
    QTest::newRow("fullwidth digit") << QString::fromUtf8("\uff11") << bad << qint64(0);
    QTest::newRow("nan") << "nan" << NumberError::NonFinite << qint64(0);
    QTest::newRow("NaN") << "NaN" << NumberError::NonFinite << qint64(0);
    QTest::newRow("inf") << "inf" << NumberError::NonFinite << qint64(0);
    QTest::newRow("-Infinity") << "-Infinity" << NumberError::NonFinite << qint64(0);
    QTest::newRow("+inf") << "+inf" << NumberError::NonFinite << qint64(0);
}

void TestNumberParsing::parseInteger_decimalOnly()
{
    QFETCH(QString, text);
    QFETCH(NumberError, error);
    QFETCH(qint64, value);
    qint64 out = -4711;
    QCOMPARE(numbers::parseInteger(text, &out), error);
    QCOMPARE(out, error == NumberError::None ? value : qint64(-4711)); // untouched on failure
}

void TestNumberParsing::parseInteger_range_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<NumberError>("error");
    QTest::newRow("at minimum") << "1" << NumberError::None;
    QTest::newRow("at maximum") << "254" << NumberError::None;
    QTest::newRow("below") << "0" << NumberError::OutOfRange;
    QTest::newRow("above") << "255" << NumberError::OutOfRange;
    QTest::newRow("leading zeros inside") << "0254" << NumberError::None;
    QTest::newRow("malformed beats range") << "0x1" << NumberError::Malformed;
}

void TestNumberParsing::parseInteger_range()
{
    QFETCH(QString, text);
    QFETCH(NumberError, error);
    int out = 0;
    QCOMPARE(numbers::parseInt(text, 1, 254, &out), error);
}

void TestNumberParsing::parseReal_decimalOnly_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<NumberError>("error");
    QTest::addColumn<double>("value");
    const auto ok = NumberError::None;
    const auto bad = NumberError::Malformed;
    QTest::newRow("integer") << "1500" << ok << 1500.0;
    QTest::newRow("leading zero") << "0100" << ok << 100.0;
    QTest::newRow("fraction") << "-2.5" << ok << -2.5;
    QTest::newRow("dot first") << ".5" << ok << 0.5;
    QTest::newRow("dot last") << "5." << ok << 5.0;
    QTest::newRow("exponent") << "1e3" << ok << 1000.0;
    QTest::newRow("signed exponent") << "+2.5E-1" << ok << 0.25;
    QTest::newRow("too small for a double") << "1e-400" << NumberError::OutOfRange << 0.0;
    QTest::newRow("too large") << "1e400" << NumberError::OutOfRange << 0.0;
    QTest::newRow("too large negative") << "-1e400" << NumberError::OutOfRange << 0.0;
    QTest::newRow("nan") << "nan" << NumberError::NonFinite << 0.0;
    QTest::newRow("inf") << "inf" << NumberError::NonFinite << 0.0;
    QTest::newRow("-inf") << "-inf" << NumberError::NonFinite << 0.0;
    QTest::newRow("infinity") << "INFINITY" << NumberError::NonFinite << 0.0;
    QTest::newRow("hex") << "0x40" << bad << 0.0;
    QTest::newRow("hex float") << "0x1p3" << bad << 0.0;
    QTest::newRow("comma decimal") << "2,5" << bad << 0.0;
    QTest::newRow("dot only") << "." << bad << 0.0;
    QTest::newRow("exponent only") << "e5" << bad << 0.0;
    QTest::newRow("exponent without digits") << "1e" << bad << 0.0;
    QTest::newRow("exponent sign only") << "1e+" << bad << 0.0;
    QTest::newRow("empty") << "" << bad << 0.0;
    QTest::newRow("word") << "fast" << bad << 0.0;
    QTest::newRow("nan with tail") << "nanx" << bad << 0.0;
}

void TestNumberParsing::parseReal_decimalOnly()
{
    QFETCH(QString, text);
    QFETCH(NumberError, error);
    QFETCH(double, value);
    double out = -4711;
    QCOMPARE(numbers::parseReal(text, &out), error);
    QCOMPARE(out, error == NumberError::None ? value : -4711.0);
}

void TestNumberParsing::parseReal_ignoresTheUsersLocale()
{
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    double out = 0;
    const NumberError dot = numbers::parseReal(u"2.5", &out);
    const double dotValue = out;
    const NumberError comma = numbers::parseReal(u"2,5", &out);
    QLocale::setDefault(before);
    QCOMPARE(dot, NumberError::None);
    QCOMPARE(dotValue, 2.5);
    QCOMPARE(comma, NumberError::Malformed);
}

void TestNumberParsing::integerFromDouble_checksBeforeConverting_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<NumberError>("error");
    QTest::addColumn<qint64>("expected");
    QTest::newRow("whole") << 66.0 << NumberError::None << qint64(66);
    QTest::newRow("negative whole") << -3.0 << NumberError::None << qint64(-3);
    QTest::newRow("fraction") << 12.5 << NumberError::Malformed << qint64(0);
    QTest::newRow("1e300") << 1e300 << NumberError::OutOfRange << qint64(0);
    QTest::newRow("-1e300") << -1e300 << NumberError::OutOfRange << qint64(0);
    QTest::newRow("2^63") << 9223372036854775808.0 << NumberError::OutOfRange << qint64(0);
    QTest::newRow("-2^63") << -9223372036854775808.0 << NumberError::None << kMin;
    QTest::newRow("largest below 2^63")
        << 9223372036854774784.0 << NumberError::None << qint64(9223372036854774784LL);
    QTest::newRow("nan") << qQNaN() << NumberError::NonFinite << qint64(0);
    QTest::newRow("inf") << qInf() << NumberError::NonFinite << qint64(0);
    QTest::newRow("-inf") << -qInf() << NumberError::NonFinite << qint64(0);
}

void TestNumberParsing::integerFromDouble_checksBeforeConverting()
{
    QFETCH(double, value);
    QFETCH(NumberError, error);
    QFETCH(qint64, expected);
    qint64 out = 0;
    QCOMPARE(numbers::integerFromDouble(value, &out), error);
    QCOMPARE(out, expected);
}

void TestNumberParsing::integerFromVariant_byType_data()
{
    QTest::addColumn<QVariant>("value");
    QTest::addColumn<NumberError>("error");
    QTest::addColumn<qint64>("expected");
    QTest::newRow("int") << QVariant(42) << NumberError::None << qint64(42);
    QTest::newRow("long long") << QVariant(qint64(-7)) << NumberError::None << qint64(-7);
    QTest::newRow("uint") << QVariant(4000000000u) << NumberError::None << qint64(4000000000LL);
    QTest::newRow("huge unsigned")
        << QVariant(quint64(1) << 63) << NumberError::OutOfRange << qint64(0);
    QTest::newRow("decimal text") << QVariant("0100") << NumberError::None << qint64(100);
    QTest::newRow("hex text") << QVariant("0x40") << NumberError::Malformed << qint64(0);
    QTest::newRow("nan text") << QVariant("nan") << NumberError::NonFinite << qint64(0);
    QTest::newRow("byte array") << QVariant(QByteArray("12")) << NumberError::None << qint64(12);
    QTest::newRow("double whole") << QVariant(100.0) << NumberError::None << qint64(100);
    QTest::newRow("double huge") << QVariant(1e300) << NumberError::OutOfRange << qint64(0);
    QTest::newRow("double nan") << QVariant(qQNaN()) << NumberError::NonFinite << qint64(0);
    QTest::newRow("float") << QVariant(2.0f) << NumberError::None << qint64(2);
    QTest::newRow("bool") << QVariant(true) << NumberError::Malformed << qint64(0);
    QTest::newRow("null") << QVariant() << NumberError::Malformed << qint64(0);
    QTest::newRow("list") << QVariant(QVariantList{1}) << NumberError::Malformed << qint64(0);
}

void TestNumberParsing::integerFromVariant_byType()
{
    QFETCH(QVariant, value);
    QFETCH(NumberError, error);
    QFETCH(qint64, expected);
    qint64 out = 0;
    QCOMPARE(numbers::integerFromVariant(value, &out), error);
    QCOMPARE(out, expected);
}

STEPDECK_TEST_GUILESS_MAIN(TestNumberParsing)
#include "tst_numberparsing.moc"
