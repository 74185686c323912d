// The program lexer (issue 20): words, values and columns as LinuxCNC reads a line, comments,
// and the first thing on a line that is not G-code, with its column.
#include "TestMain.h"
#include "program/ProgramLexer.h"
#include <QtTest>
#include <cstring>

using namespace stepdeck::program;

class TestProgramLexer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void lex_validLine_wordsValuesColumns_data();
    void lex_validLine_wordsValuesColumns();
    void lex_number_exactlyAsQtReadsIt_data();
    void lex_number_exactlyAsQtReadsIt();
    void lex_invalidLine_errorAtColumn_data();
    void lex_invalidLine_errorAtColumn();
    void lex_comments_firstIsKept();
    void lex_repeat_keywordAndCount();
};

// "letter value column" per word, space separated.
static QString describe(const LexedLine& l)
{
    QStringList out;
    for (const ProgramWord& w : l.words)
        out << QStringLiteral("%1%2@%3").arg(w.letter).arg(w.value).arg(w.column);
    return out.join(QLatin1Char(' '));
}

void TestProgramLexer::lex_validLine_wordsValuesColumns_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("words");
    QTest::newRow("G0 X10") << "G0 X10"
                            << "G0@1 X10@4";
    QTest::newRow("lower case, no spaces") << "g1x-2.5f300"
                                           << "G1@1 X-2.5@3 F300@8";
    QTest::newRow("space inside a word") << "X 12.5"
                                         << "X12.5@1";
    QTest::newRow("leading point") << "Y.5"
                                   << "Y0.5@1";
    QTest::newRow("trailing point") << "Z3."
                                    << "Z3@1";
    QTest::newRow("plus sign") << "A+90"
                               << "A90@1";
    QTest::newRow("G01 is G1") << "G01"
                               << "G1@1";
    QTest::newRow("N number") << "N10 M64 P1"
                              << "N10@1 M64@5 P1@9";
    QTest::newRow("comment between") << "G0 (rapid) X1"
                                     << "G0@1 X1@12";
    QTest::newRow("blank") << "   "
                           << "";
    QTest::newRow("only comment") << "; nothing"
                                  << "";
    QTest::newRow("tab") << "\tG4\tP1.5"
                         << "G4@2 P1.5@5";
}

void TestProgramLexer::lex_validLine_wordsValuesColumns()
{
    QFETCH(QString, line);
    QFETCH(QString, words);
    const LexedLine l = ProgramLexer::lex(line, 7);
    QVERIFY2(!l.error, qPrintable(l.error ? l.error->text() : QString()));
    QCOMPARE(describe(l), words);
}

// The lexer reads numbers without QString (a long program reads millions): the value must be
// the one QString::toDouble gives, to the last bit.
void TestProgramLexer::lex_number_exactlyAsQtReadsIt_data()
{
    QTest::addColumn<QString>("number");
    for (const char* n : {"0.1", "-.5", "+3.", "123456.789012", "0.000001", "-0", "2.675",
                          "1234567890123456789", "0.30000000000000004", "9007199254740993"})
        QTest::newRow(n) << QString::fromLatin1(n);
    QTest::newRow("95 digits") << QStringLiteral("1.") + QString(93, QLatin1Char('3'));
}

void TestProgramLexer::lex_number_exactlyAsQtReadsIt()
{
    QFETCH(QString, number);
    const LexedLine l = ProgramLexer::lex(QStringLiteral("X") + number, 1);
    QVERIFY(!l.error);
    QCOMPARE(l.words.size(), 1);
    const double expected = number.toDouble();
    QCOMPARE(std::memcmp(&l.words.first().value, &expected, sizeof expected), 0);
}

void TestProgramLexer::lex_invalidLine_errorAtColumn_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("says");
    QTest::newRow("missing value") << "G0 X" << 5 << "X needs a number";
    QTest::newRow("letter then letter") << "G0 XY1" << 5 << "X needs a number";
    QTest::newRow("two points") << "X1.2.3" << 2 << "is not a decimal number";
    QTest::newRow("exponent") << "X1e5" << 2 << "is not a decimal number";
    QTest::newRow("only a sign") << "X-" << 2 << "X needs a number";
    QTest::newRow("unclosed comment") << "G0 (rapid X1" << 4 << "comment is not closed";
    QTest::newRow("stray character") << "G0 X1 #" << 7 << "unexpected character \"#\"";
    QTest::newRow("percent") << "%" << 1 << "unexpected character";
    QTest::newRow("non-ASCII letter") << "G0 \u00c4 1" << 4 << "unexpected character";
    QTest::newRow("not finite") << QStringLiteral("X") + QString(400, QLatin1Char('9')) << 2
                                << "is not a finite number";
    QTest::newRow("repeat bracket open") << "O1 repeat [3" << 13 << "\"]\" is missing";
}

void TestProgramLexer::lex_invalidLine_errorAtColumn()
{
    QFETCH(QString, line);
    QFETCH(int, column);
    QFETCH(QString, says);
    const LexedLine l = ProgramLexer::lex(line, 3);
    QVERIFY(l.error);
    QCOMPARE(l.error->line, 3);
    QCOMPARE(l.error->column, column);
    QVERIFY2(l.error->message.contains(says), qPrintable(l.error->message));
}

void TestProgramLexer::lex_comments_firstIsKept()
{
    LexedLine l = ProgramLexer::lex(QStringLiteral("M0 ( Load the part ) (second)"), 1);
    QCOMPARE(l.comment, QStringLiteral("Load the part"));
    l = ProgramLexer::lex(QStringLiteral("M0 ; press Resume"), 1);
    QCOMPARE(l.comment, QStringLiteral("press Resume"));
    QCOMPARE(describe(l), QStringLiteral("M0@1"));
}

void TestProgramLexer::lex_repeat_keywordAndCount()
{
    LexedLine l = ProgramLexer::lex(QStringLiteral("o100 REPEAT [25]"), 1);
    QVERIFY(!l.error);
    QCOMPARE(describe(l), QStringLiteral("O100@1"));
    QCOMPARE(l.keyword, QStringLiteral("repeat"));
    QCOMPARE(l.keywordColumn, 6);
    QCOMPARE(l.keywordValue, 25.0);
    QCOMPARE(l.keywordValueColumn, 14);
    l = ProgramLexer::lex(QStringLiteral("O100 endrepeat"), 1);
    QCOMPARE(l.keyword, QStringLiteral("endrepeat"));
    QVERIFY(!l.keywordValue);
}

STEPDECK_TEST_APPLESS_MAIN(TestProgramLexer)
#include "tst_programlexer.moc"
