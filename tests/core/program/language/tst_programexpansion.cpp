// A program in LinuxCNC's language worked out and checked (issue 33): which programs are
// worked out, the line map, the text kept in memory or a temporary file, and the check's
// errors, blocks and refusals naming the source's lines.
#include "../ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/ProgramReader.h"
#include "program/language/ProgramExpansion.h"
#include <QtTest>

using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

class TestProgramExpansion : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void usesLanguage_text_detected_data();
    void usesLanguage_text_detected();
    void usesLanguage_file_detectedAcrossChunks();
    void lineMap_runs_mapBack();
    void expand_longOutput_spillsToATemporaryFile();
    void expand_largeSource_refused();
    void expand_longLine_refusedBeforeItRuns();
    void check_workedOut_blocksNameSourceLines();
    void check_grblReportInWorkedOutProgram_keptAsWrittenAndNoted();
    void check_errorInWorkedOutLine_namesSourceLineAndColumn_data();
    void check_errorInWorkedOutLine_namesSourceLineAndColumn();
    void check_runFromLine_refused();
    void check_offsetsChangedSinceWorkedOut_refused();
    void check_plainProgram_notWorkedOut();
    void check_branchOnM66_takesThePathTheRunCanReach();
    void check_progressFalse_cancelsWorkingOut();
};

namespace {

QStringList axesOf(const MachineFacts& f)
{
    QStringList names;
    for (const auto& a : f.description.axes)
        names << a.name;
    return names;
}

MachineFacts mill()
{
    MachineFacts f = machineFacts(QStringLiteral("mill"));
    f.knownPositions = positions(QStringLiteral("X=0 Y=0 Z=0 A=0"));
    return f;
}

ProgramCheckResult checkText(const QString& text, const MachineFacts& facts, int fromLine = 1)
{
    return ProgramCheck::check(ProgramSource::bytes(text.toUtf8()), axesOf(facts), facts, fromLine);
}

} // namespace

void TestProgramExpansion::usesLanguage_text_detected_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("uses");
    QTest::newRow("plain") << "G0 X1\nG1 Y2 F100" << false;
    QTest::newRow("repeat stays plain") << "O1 repeat [3]\nG0 X1\nO1 endrepeat" << false;
    QTest::newRow("repeat with a named label") << "o<x> repeat [2]\no<x> endrepeat" << true;
    QTest::newRow("repeat by a parameter") << "O1 repeat [#1]\nO1 endrepeat" << true;
    // Issue 50: block delete's "/" before an O word; a Fanuc program number is not the language.
    QTest::newRow("O word after a slash") << "/o100 call\nG0 X1" << true;
    QTest::newRow("program number") << "%\nO1001 (BRACKET)\nG0 X1\n%" << false;
    QTest::newRow("GRBL $ lines") << "$H\n$32=1\nG0 X1" << false;
    // GRBL's parameter report is no parameter of the language (found by fuzzing).
    QTest::newRow("GRBL $# report") << "$#\n$[x]\nG0 X1" << false;
    QTest::newRow("GRBL $ after white space of any kind") << "\r $\r0[\f\n\xC2\xA0$[1]" << false;
    QTest::newRow("repeat by an expression") << "O1 repeat [2*3]\nO1 endrepeat" << true;
    QTest::newRow("# in a comment") << "G0 X1 (part #3)\n; #4 here" << false;
    QTest::newRow("[ in a comment") << "(see [1])" << false;
    QTest::newRow("parameter") << "G0 X#1" << true;
    QTest::newRow("assignment") << "#<a>=1" << true;
    QTest::newRow("expression") << "G0 X[1+2]" << true;
    QTest::newRow("O sub") << "o<x> sub\no<x> endsub" << true;
    QTest::newRow("O if after N") << "N5 O1 if [1]" << true;
    QTest::newRow("DEBUG comment") << "( debug, hello)" << true;
    QTest::newRow("PRINT comment") << "G0 X1 (PRINT,x)" << true;
    QTest::newRow("MSG comment") << "(MSG, hello)" << false;
}

void TestProgramExpansion::usesLanguage_text_detected()
{
    QFETCH(QString, text);
    QFETCH(bool, uses);
    QCOMPARE(ProgramExpansion::usesLanguage(text.toUtf8()), uses);
    QString why;
    QCOMPARE(ProgramExpansion::usesLanguage(ProgramSource::bytes(text.toUtf8()), &why),
             std::optional<bool>(uses));
}

void TestProgramExpansion::usesLanguage_file_detectedAcrossChunks()
{
    // The reader reads 1 MB at a time: the "#" stands on the line across the first boundary.
    QByteArray text;
    while (text.size() < 1024 * 1024 - 8)
        text += "G0 X1\n";
    text.chop(text.size() - (1024 * 1024 - 3));
    text += "G0 X#1\nG0 X2\n";
    QString why;
    QCOMPARE(ProgramExpansion::usesLanguage(ProgramSource::bytes(text), &why),
             std::optional<bool>(true));
    QTemporaryFile file;
    QVERIFY(file.open());
    file.write("G0 X1\n");
    file.flush();
    QCOMPARE(ProgramExpansion::usesLanguage(ProgramSource::file(file.fileName()), &why),
             std::optional<bool>(false));
    QVERIFY(!ProgramExpansion::usesLanguage(ProgramSource::file(QStringLiteral("/nonexistent/x")),
                                            &why));
    QVERIFY(!why.isEmpty());
}

void TestProgramExpansion::lineMap_runs_mapBack()
{
    NgcLineMap map;
    // Lines 1..3 from 5..7, then 4..6 from 5..7 again (a loop), then 7 from 20.
    for (int i = 0; i < 3; ++i)
        map.add(1 + i, 5 + i);
    for (int i = 0; i < 3; ++i)
        map.add(4 + i, 5 + i);
    map.add(7, 20);
    QCOMPARE(map.runs(), size_t(3));
    const QList<int> expected{5, 6, 7, 5, 6, 7, 20, 20};
    for (int line = 1; line <= 8; ++line)
        QCOMPARE(map.sourceLine(line), expected.at(line - 1));
}

void TestProgramExpansion::expand_longOutput_spillsToATemporaryFile()
{
    // 300 000 lines of about 20 bytes: more than kMemoryBytes.
    const QByteArray text = "#1=0\no1 while [#1 LT 300000]\nG1 X[#1/10000] F100\n#1=[#1+1]\no1 "
                            "endwhile\n";
    QList<ProgramError> errors;
    QString path;
    {
        const std::optional<ProgramExpansion::Result> r =
            ProgramExpansion::expand(ProgramSource::bytes(text), {}, &errors);
        QVERIFY2(r, qPrintable(texts(errors).join(QLatin1Char('\n'))));
        QVERIFY(r->source.isFile());
        path = r->source.path();
        QVERIFY(QFile::exists(path));
        QVERIFY(r->source.size() > ProgramExpansion::kMemoryBytes);
        QCOMPARE(r->info->sourceLines, 5);
        QCOMPARE(r->info->lines->sourceLine(300000), 3);
        ProgramSourceReader reader(r->source);
        QString why;
        QVERIFY(reader.open(&why));
        const QByteArray tail = reader.read(reader.size() - 20, 20, &why);
        // The words keep their source columns (NgcLineExpander): compared without the padding.
        QVERIFY2(tail.simplified().endsWith("G1 X29.9999 F100"), tail.constData());
    }
    QVERIFY2(!QFile::exists(path), "the temporary file outlived its source");
}

void TestProgramExpansion::expand_largeSource_refused()
{
    QByteArray text = "G0 X#1\n";
    text += QByteArray(ProgramExpansion::kMaxSourceBytes, ' ');
    QList<ProgramError> errors;
    QVERIFY(!ProgramExpansion::expand(ProgramSource::bytes(text), {}, &errors));
    QCOMPARE(errors.size(), 1);
    QVERIFY2(errors.first().message.contains(QStringLiteral("at most 8 MB")),
             qPrintable(errors.first().message));
}

void TestProgramExpansion::expand_longLine_refusedBeforeItRuns()
{
    const QByteArray text = "G0 X#1\n(" + QByteArray(1100, 'x') + ")\nG0 X1\n";
    QList<ProgramError> errors;
    QVERIFY(!ProgramExpansion::expand(ProgramSource::bytes(text), {}, &errors));
    QCOMPARE(texts(errors), QStringList{"2:1025: the line is longer than 1024 characters"});
}

void TestProgramExpansion::check_workedOut_blocksNameSourceLines()
{
    const MachineFacts facts = mill();
    const ProgramCheckResult r = checkText(QStringLiteral("G21 G90\n"
                                                          "#<n>=3\n"
                                                          "o1 repeat [#<n>]\n"
                                                          "  G1 X[#1*10+5] F300\n"
                                                          "  #1=[#1+1]\n"
                                                          "o1 endrepeat\n"
                                                          "M2\n"),
                                           facts);
    QVERIFY2(r.ok(), qPrintable(texts(r.errors).join(QLatin1Char('\n'))));
    QVERIFY(r.program && r.program->expansion);
    QCOMPARE(r.preview.lines, 7);
    QCOMPARE(r.preview.extents.value(QStringLiteral("X")).maximum, 25.0);
    QStringList blocks;
    for (const ProgramBlock& b : ProgramReader::readAll(*r.program))
        blocks << QStringLiteral("%1:%2").arg(b.line).arg(b.text);
    QCOMPARE(blocks,
             QStringList({"1:G21 G90", "4:G1 X5 F300", "4:G1 X15 F300", "4:G1 X25 F300", "7:M2"}));
    // The run checks the same Program again (ProgramRunner::start).
    QVERIFY(ProgramCheck::check(*r.program, facts).ok());
}

// GRBL's "$#" (its parameter report) in a program that uses the language: not a parameter, so
// it reaches the parser as written, which names it and runs nothing for it (found by fuzzing).
void TestProgramExpansion::check_grblReportInWorkedOutProgram_keptAsWrittenAndNoted()
{
    const ProgramCheckResult r = checkText(QStringLiteral("#1=2\n$#\nG0 X#1\n"), mill());
    QVERIFY2(r.ok(), qPrintable(texts(r.errors).join(QLatin1Char('\n'))));
    QVERIFY(r.program && r.program->expansion);
    QStringList blocks;
    for (const ProgramBlock& b : ProgramReader::readAll(*r.program))
        blocks << QStringLiteral("%1:%2").arg(b.line).arg(b.text);
    QCOMPARE(blocks, QStringList({"3:G0 X2"}));
    QCOMPARE(r.notes.size(), 1);
    QCOMPARE(r.notes.first().line, 2);
    QVERIFY2(r.notes.first().message.contains(QLatin1String("$#")),
             qPrintable(r.notes.first().message));
}

void TestProgramExpansion::check_errorInWorkedOutLine_namesSourceLineAndColumn_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("error"); // ProgramError::text()
    QTest::newRow("beyond the soft limit in the third pass")
        << "G21 G90\no1 repeat [3]\n  G0 X[#1*60]\n  #1=[#1+1]\no1 endrepeat"
        << "3:6: X reaches 120 mm";
    QTest::newRow("unsupported word keeps its column") << "#1=2\nG0 X#1 G5"
                                                       << "2:8: ";
    // M98/M99: refused by the parser (ProgramLine), in a worked-out program as in any.
    QTest::newRow("M98 refused") << "#1=1\nG0 X#1\nM98 P100"
                                 << "3:1: M98 (a Fanuc-style subprogram) is not supported";
    QTest::newRow("M99 refused") << "#1=1\n  M99"
                                 << "2:3: M99 (a Fanuc-style subprogram) is not supported";
    QTest::newRow("expression error") << "G21\nG0 X[1/0]"
                                      << "2:7: ";
    // A value longer than what was written moves the words after it in the worked-out text:
    // errors still name the file's columns, once per word.
    QTest::newRow("word after a longer value") << "#<a> = 1.23456\nG0 X#<a> Y-5"
                                               << "2:10: Y reaches -5 mm";
    QTest::newRow("parser error after a longer value") << "#<a> = 1.23456\nG0 X#<a> Q5"
                                                       << "2:10: ";
    QTest::newRow("one error per word over passes")
        << "#1 = 1\no1 while [#1 LT 200]\nG0 X#1 Y-5\n#1 = [#1 * 10]\no1 endwhile"
        << "3:8: Y reaches -5 mm";
}

void TestProgramExpansion::check_errorInWorkedOutLine_namesSourceLineAndColumn()
{
    QFETCH(QString, text);
    QFETCH(QString, error);
    const ProgramCheckResult r = checkText(text, mill());
    QVERIFY(!r.ok());
    QVERIFY(!r.program);
    QVERIFY2(r.errors.first().text().startsWith(error), qPrintable(r.errors.first().text()));
    QVERIFY2(r.errors.size() == 1, qPrintable(texts(r.errors).join(QLatin1Char('\n'))));
}

void TestProgramExpansion::check_runFromLine_refused()
{
    const ProgramCheckResult r = checkText(QStringLiteral("#1=5\nG0 X#1\nG0 X1"), mill(), 3);
    QVERIFY(!r.ok());
    QVERIFY2(r.errors.first().message.contains(QStringLiteral("run it from its start")),
             qPrintable(r.errors.first().message));
}

void TestProgramExpansion::check_offsetsChangedSinceWorkedOut_refused()
{
    MachineFacts facts = mill();
    facts.coordinateSystems[0].insert(QStringLiteral("X"), 10);
    const ProgramCheckResult r = checkText(QStringLiteral("G0 X[#5221+1]"), facts);
    QVERIFY2(r.ok(), qPrintable(texts(r.errors).join(QLatin1Char('\n'))));
    // X = 10 + 1 in work coordinates, machine X = 21.
    QCOMPARE(ProgramReader::readAll(*r.program).first().text, QStringLiteral("G0 X11"));
    MachineFacts moved = facts;
    moved.coordinateSystems[0].insert(QStringLiteral("X"), 12);
    const ProgramCheckResult again = ProgramCheck::check(*r.program, moved);
    QVERIFY(!again.ok());
    QVERIFY2(again.errors.first().message.contains(QStringLiteral("check it again")),
             qPrintable(again.errors.first().message));
}

void TestProgramExpansion::check_plainProgram_notWorkedOut()
{
    const ProgramCheckResult r = checkText(QStringLiteral("G0 X1 (part #3)\nG0 X2"), mill(), 2);
    QVERIFY2(r.ok(), qPrintable(texts(r.errors).join(QLatin1Char('\n'))));
    QVERIFY(!r.program->expansion);
}

// A branch on what M66 read: StepDeck's M66 stops the run when Q runs out, so past it the input
// reads as waited for (L3: 1) and the check follows that path, the only one the run can take.
void TestProgramExpansion::check_branchOnM66_takesThePathTheRunCanReach()
{
    MachineFacts facts = machineFacts(QStringLiteral("io"));
    facts.knownPositions = positions(QStringLiteral("X=0 U=0 V=0"));
    const ProgramCheckResult r = checkText(QStringLiteral("M66 P1 L3 Q5\n"
                                                          "o1 if [#5399 EQ 1]\n"
                                                          "  G0 X10\n"
                                                          "o1 else\n"
                                                          "  G0 X500\n"
                                                          "o1 endif\n"),
                                           facts);
    QVERIFY2(r.ok(), qPrintable(texts(r.errors).join(QLatin1Char('\n'))));
    QStringList blocks;
    for (const ProgramBlock& b : ProgramReader::readAll(*r.program))
        blocks << QStringLiteral("%1:%2").arg(b.line).arg(b.text);
    QCOMPARE(blocks, QStringList({"1:M66 P1 L3 Q5", "3:G0 X10"}));
}

// A long loop is ended by the check's progress (the window's Cancel, a newer text), not run out.
void TestProgramExpansion::check_progressFalse_cancelsWorkingOut()
{
    const MachineFacts facts = mill();
    int asked = 0;
    const ProgramCheckResult r =
        ProgramCheck::check(ProgramSource::bytes("o1 while [1]\n#1=[#1+1]\no1 endwhile\n"),
                            axesOf(facts), facts, 1, [&](qint64 done, qint64) {
                                ++asked;
                                return done != 0 || asked < 3;
                            });
    QVERIFY(r.cancelled);
    QVERIFY(r.errors.isEmpty());
    QCOMPARE(asked, 3);
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramExpansion)
#include "tst_programexpansion.moc"
