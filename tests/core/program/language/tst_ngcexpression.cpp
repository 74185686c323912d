// LinuxCNC's expressions (issue 33): values, precedence, functions in degrees, and errors at
// their line:column, against a fixed set of parameters.
#include "TestMain.h"
#include "program/language/NgcExpression.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck::program;

namespace {

// #1 = 2, #2 = -3, #10 = 10, #<len> = 4, #<_g> = 0.5; #99 refused; other names unset.
class FixedParameters : public NgcParameterSource
{
public:
    std::optional<double> numbered(int n, QString* why) const override
    {
        switch (n) {
        case 1:
            return 2.0;
        case 2:
            return -3.0;
        case 10:
            return 10.0;
        case 99:
            *why = QStringLiteral("#99 is refused");
            return std::nullopt;
        default:
            return 0.0;
        }
    }
    std::optional<double> named(const QString& name, QString* why) const override
    {
        if (name == QLatin1String("len"))
            return 4.0;
        if (name == QLatin1String("_g"))
            return 0.5;
        *why = QStringLiteral("#<%1> is not set").arg(name);
        return std::nullopt;
    }
    bool exists(const QString& name) const override
    {
        return name == QLatin1String("len") || name == QLatin1String("_g");
    }
};

} // namespace

class TestNgcExpression : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void readValue_expression_valueAndEnd_data();
    void readValue_expression_valueAndEnd();
    void readValue_brokenExpression_errorAtColumn_data();
    void readValue_brokenExpression_errorAtColumn();
    void readReference_forms_numberOrName_data();
    void readReference_forms_numberOrName();
};

void TestNgcExpression::readValue_expression_valueAndEnd_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("end"); // where the reader stops (0-based)
    auto row = [](const char* name, const char* text, double value, int end = -1) {
        QTest::newRow(name) << QString::fromUtf8(text) << value
                            << (end < 0 ? int(std::strlen(text)) : end);
    };
    // Values.
    row("number", "12.5", 12.5);
    row("leading point", ".5", 0.5);
    row("trailing point", "3.", 3);
    row("negative number", "-4", -4);
    row("spaces inside a number (LinuxCNC leaves them out)", "1 2", 12);
    row("stops before the next word", "2Y3", 2, 1);
    row("parameter", "#1", 2);
    row("parameter after minus", "-#2", 3);
    row("indirect parameter", "##1", -3); // #[#1] = #2
    row("named", "#<len>", 4);
    row("named, case and spaces left out", "#<L e N>", 4);
    row("global", "#<_g>", 0.5);
    row("parameter by expression", "#[5*2]", 10);
    // Precedence: ** above * / MOD above + - above comparisons above AND OR XOR.
    row("times before plus", "[1+2*3]", 7);
    row("power before times", "[2*3**2]", 18);
    row("left to right minus", "[8-2-1]", 5);
    row("left to right divide", "[8/2/2]", 2);
    row("left to right power (LinuxCNC)", "[2**3**2]", 64);
    row("brackets first", "[[1+2]*3]", 9);
    row("unary minus of a bracket", "-[2+3]", -5);
    row("comparison below plus", "[1+1 EQ 2]", 1);
    row("and below comparison", "[1 LT 2 AND 3 GT 2]", 1);
    row("or", "[0 OR 0]", 0);
    row("xor", "[1 XOR 1]", 0);
    row("xor of different", "[1 XOR 0]", 1);
    row("and with zero", "[5 AND 0]", 0);
    row("EQ within 0.0001", "[1 EQ 1.00005]", 1);
    row("NE beyond 0.0001", "[1 NE 1.0002]", 1);
    row("GT exact", "[1.00005 GT 1]", 1);
    row("GE", "[2 GE 2]", 1);
    row("LE", "[3 LE 2]", 0);
    row("lower-case operators", "[7 mod 3 eq 1]", 1);
    row("MOD never negative", "[-7 MOD 3]", 2);
    row("MOD by a negative", "[7 MOD -3]", 1);
    row("parameters in an expression", "[#1 * #<len> + #2]", 5);
    // Functions, angles in degrees.
    row("ABS", "ABS[-2.5]", 2.5);
    row("SIN 30", "SIN[30]", 0.5);
    row("COS 60", "COS[60]", 0.5);
    row("TAN 45", "TAN[45]", 1);
    row("ASIN", "ASIN[0.5]", 30);
    row("ACOS", "ACOS[0.5]", 60);
    row("ATAN two values", "ATAN[1]/[1]", 45);
    row("ATAN quadrant", "ATAN[1]/[-1]", 135);
    row("SQRT", "SQRT[16]", 4);
    row("EXP LN", "LN[EXP[2]]", 2);
    row("FIX down", "FIX[-2.5]", -3);
    row("FUP up", "FUP[2.1]", 3);
    row("ROUND half away from zero", "ROUND[2.5]", 3);
    row("ROUND negative half", "ROUND[-2.5]", -3);
    row("EXISTS set", "EXISTS[#<len>]", 1);
    row("EXISTS unset", "EXISTS[#<nope>]", 0);
    row("function in an expression", "[2*SIN[90]+1]", 3);
    row("spaced function name", "s q r t [9]", 3);
}

void TestNgcExpression::readValue_expression_valueAndEnd()
{
    QFETCH(QString, text);
    QFETCH(double, value);
    QFETCH(int, end);
    FixedParameters p;
    NgcExpression e(text, p);
    qsizetype pos = 0;
    const std::optional<double> v = e.readValue(&pos);
    QVERIFY2(v, qPrintable(e.error() ? e.error()->message : QStringLiteral("no error")));
    QVERIFY2(std::fabs(*v - value) < 1e-9, qPrintable(QString::number(*v, 'g', 17)));
    QCOMPARE(int(pos), end);
}

void TestNgcExpression::readValue_brokenExpression_errorAtColumn_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("message"); // a part of it
    QTest::newRow("division by zero") << "[1/0]" << 3 << "division by zero";
    QTest::newRow("MOD by zero") << "[1 MOD 0]" << 4 << "MOD by zero";
    QTest::newRow("negative to fractional power") << "[-8**0.5]" << 4 << "fractional power";
    QTest::newRow("unclosed bracket") << "[1+2" << 1 << "not closed";
    QTest::newRow("missing operand") << "[1+]" << 4 << "does not start a value";
    QTest::newRow("two values") << "[1 #1]" << 4 << "an operator or \"]\" is missing";
    QTest::newRow("unknown function") << "[FOO[1]]" << 2 << "unknown function \"FOO\"";
    QTest::newRow("function without bracket") << "SIN 30" << 1 << "is not a value";
    QTest::newRow("ASIN domain") << "ASIN[2]" << 1 << "outside -1..1";
    QTest::newRow("ACOS domain") << "[1+ACOS[-1.5]]" << 4 << "outside -1..1";
    QTest::newRow("LN of zero") << "LN[0]" << 1 << "above 0";
    QTest::newRow("SQRT of negative") << "SQRT[-1]" << 1 << "0 or more";
    QTest::newRow("ATAN with one value") << "ATAN[1]" << 8 << "ATAN[y]/[x]";
    QTest::newRow("EXISTS of a number") << "EXISTS[#1]" << 9 << "#<name>";
    QTest::newRow("unset name") << "[1+#<nope>]" << 4 << "#<nope> is not set";
    QTest::newRow("refused number") << "#99" << 1 << "#99 is refused";
    QTest::newRow("parameter not whole") << "#[1.5]" << 1 << "not a parameter";
    QTest::newRow("parameter zero") << "#0" << 1 << "not a parameter";
    QTest::newRow("unclosed name") << "#<len" << 2 << "not closed by \">\"";
    QTest::newRow("empty name") << "#<>" << 2 << "empty";
    QTest::newRow("nothing") << "" << 1 << "missing at the end";
    QTest::newRow("exponent form") << "1e5" << 1 << "";
    QTest::newRow("overflow") << "[10**400]" << 4 << "not a finite number";
    QTest::newRow("deep nesting") << QString(80, QLatin1Char('[')) + "1" +
                                         QString(80, QLatin1Char(']'))
                                  << 0 << "nests deeper";
}

void TestNgcExpression::readValue_brokenExpression_errorAtColumn()
{
    QFETCH(QString, text);
    QFETCH(int, column);
    QFETCH(QString, message);
    FixedParameters p;
    NgcExpression e(text, p);
    e.setLineNumber(7);
    qsizetype pos = 0;
    const std::optional<double> v = e.readValue(&pos);
    if (QByteArray(QTest::currentDataTag()) == "exponent form") {
        // "1e5" reads 1 and stops at "e": the caller sees "e5" as the next word.
        QVERIFY(v);
        QCOMPARE(*v, 1.0);
        QCOMPARE(int(pos), 1);
        return;
    }
    QVERIFY(!v);
    QVERIFY(e.error());
    QCOMPARE(e.error()->line, 7);
    if (column > 0)
        QCOMPARE(e.error()->column, column);
    QVERIFY2(e.error()->message.contains(message), qPrintable(e.error()->message));
}

void TestNgcExpression::readReference_forms_numberOrName_data()
{
    QTest::addColumn<QString>("text"); // after the '#'
    QTest::addColumn<int>("number");
    QTest::addColumn<QString>("name");
    QTest::newRow("number") << "12=3" << 12 << "";
    QTest::newRow("by expression") << "[#1+1]=3" << 3 << "";
    QTest::newRow("name") << "<My Var>=3" << 0 << "myvar";
    QTest::newRow("global") << "<_Tool>=3" << 0 << "_tool";
}

void TestNgcExpression::readReference_forms_numberOrName()
{
    QFETCH(QString, text);
    QFETCH(int, number);
    QFETCH(QString, name);
    FixedParameters p;
    NgcExpression e(text, p);
    qsizetype pos = 0;
    const std::optional<NgcExpression::Reference> r = e.readReference(&pos);
    QVERIFY(r);
    QCOMPARE(r->number, number);
    QCOMPARE(r->name, name);
    QCOMPARE(text.at(pos), QLatin1Char('='));
}

STEPDECK_TEST_GUILESS_MAIN(TestNgcExpression)
#include "tst_ngcexpression.moc"
