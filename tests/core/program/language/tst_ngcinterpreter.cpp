// The control flow of LinuxCNC's language (issue 33): what lines a program gives out, in which
// order and from which source line, its structure errors and its bounds.
#include "TestMain.h"
#include "program/language/NgcInterpreter.h"
#include <QtTest>

using namespace stepdeck::program;

class TestNgcInterpreter : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void run_program_givesOutLines_data();
    void run_program_givesOutLines();
    void run_aroundTheProgram_blockDeleteAndUnreadLines_data();
    void run_aroundTheProgram_blockDeleteAndUnreadLines();
    void run_brokenProgram_errorAtLine_data();
    void run_brokenProgram_errorAtLine();
    void run_brokenStructure_everyErrorListed();
    void run_subroutineFolder_callsFileAndNamesIt();
    void run_outputRefuses_stops();
    void run_lowerLimits_eachBoundNamesItsLine();
};

namespace {

// "source:text" per line given out (text with single spaces), " | " between; or
// "E line:column message" for the first error.
QString run(const QString& program, const NgcContext& context = {})
{
    QStringList out;
    NgcInterpreter interpreter(program.split(QLatin1Char('\n')), context,
                               [&](const QString& text, int line, const QList<int>&) {
                                   out << QStringLiteral("%1:%2").arg(line).arg(text.simplified());
                                   return true;
                               });
    QList<ProgramError> errors;
    if (!interpreter.run(&errors, 10))
        return QStringLiteral("E %1:%2 %3")
            .arg(errors.value(0).line)
            .arg(errors.value(0).column)
            .arg(errors.value(0).message);
    return out.join(QStringLiteral(" | "));
}

} // namespace

void TestNgcInterpreter::run_program_givesOutLines_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("lines");
    QTest::newRow("plain line kept") << "G0 X1 Y2"
                                     << "1:G0 X1 Y2";
    QTest::newRow("assignment applies after its line") << "#1=5 G0 X#1\nG0 X#1"
                                                       << "1:G0 X0 | 2:G0 X5";
    QTest::newRow("assignments read old values") << "#1=1\n#1=2 #2=#1\nG0 X#2"
                                                 << "3:G0 X1";
    QTest::newRow("only assignments give out nothing") << "#1=1\n#<a>=2"
                                                       << "";
    QTest::newRow("while counts") << "#1=0\no1 while [#1 LT 3]\nG0 X#1\n#1=[#1+1]\no1 endwhile"
                                  << "3:G0 X0 | 3:G0 X1 | 3:G0 X2";
    QTest::newRow("while false never runs") << "o1 while [0]\nG0 X1\no1 endwhile\nG0 Y1"
                                            << "4:G0 Y1";
    QTest::newRow("do runs once at least") << "o2 do\nG0 X#3\no2 while [0]"
                                           << "2:G0 X0";
    QTest::newRow("do while") << "o2 do\n#3=[#3+1]\nG0 X#3\no2 while [#3 LT 2]"
                              << "3:G0 X1 | 3:G0 X2";
    QTest::newRow("repeat") << "o3 repeat [2]\nG0 Z1\no3 endrepeat"
                            << "2:G0 Z1 | 2:G0 Z1";
    QTest::newRow("repeat zero") << "o3 repeat [0]\nG0 Z1\no3 endrepeat\nG0 Z2"
                                 << "4:G0 Z2";
    QTest::newRow("if true") << "o1 if [1]\nG0 X1\no1 else\nG0 X2\no1 endif"
                             << "2:G0 X1";
    QTest::newRow("if false else") << "o1 if [0]\nG0 X1\no1 else\nG0 X2\no1 endif"
                                   << "4:G0 X2";
    QTest::newRow("elseif chain")
        << "#1=2\no1 if [#1 EQ 1]\nG0 X1\no1 elseif [#1 EQ 2]\nG0 X2\no1 elseif [1]\nG0 X3\no1 "
           "endif"
        << "5:G0 X2";
    QTest::newRow("if without branch taken") << "o1 if [0]\nG0 X1\no1 endif"
                                             << "";
    QTest::newRow("break")
        << "o1 while [1]\n#1=[#1+1]\no2 if [#1 GT 2]\no1 break\no2 endif\nG0 X#1\no1 endwhile"
        << "6:G0 X1 | 6:G0 X2";
    QTest::newRow("continue in while")
        << "o1 while [#1 LT 4]\n#1=[#1+1]\no2 if [#1 EQ 2]\no1 continue\no2 endif\nG0 "
           "X#1\no1 endwhile"
        << "6:G0 X1 | 6:G0 X3 | 6:G0 X4";
    QTest::newRow("continue in repeat counts the pass")
        << "o1 repeat [3]\n#1=[#1+1]\no1 continue\nG0 X9\no1 endrepeat\nG0 X#1"
        << "6:G0 X3";
    QTest::newRow("nested loops restart")
        << "o1 repeat [2]\no2 repeat [2]\nG0 X1\no2 endrepeat\no1 endrepeat"
        << "3:G0 X1 | 3:G0 X1 | 3:G0 X1 | 3:G0 X1";
    QTest::newRow("sub with arguments and locals")
        << "o<sq> sub\n#<w>=[#1*2]\nG1 X#<w> Y#2\no<sq> endsub\no<sq> call [3] [4]\nG0 X#1"
        << "3:G1 X6 Y4 | 6:G0 X0";
    QTest::newRow("sub defined after M2") << "o100 call [7]\nM2\no100 sub\nG0 X#1\no100 endsub"
                                          << "4:G0 X7 | 2:M2";
    QTest::newRow("return with a value")
        << "o<f> sub\no<f> return [#1*#1]\nG0 X99\no<f> endsub\no<f> call [3]\nG0 "
           "X#<_value> Y#<_value_returned>"
        << "6:G0 X9 Y1";
    // Issue 50 item 9: return named by a block of the sub around it (LinuxCNC runs it).
    QTest::newRow("return with the label of an if or a loop")
        << "o100 sub\no110 if [#1 GT 5]\no110 return [5]\no110 endif\no120 while [1]\no120 "
           "return [#1]\no120 endwhile\no100 endsub\no100 call [9]\nG0 X#<_value>\no100 call "
           "[2]\nG0 Y#<_value>"
        << "10:G0 X5 | 12:G0 Y2";
    QTest::newRow("polar words take values") // issue 50 item 6
        << "#<r>=5\nG0 @#<r> ^[45*3]"
        << "2:G0 @5 ^135";
    QTest::newRow("recursion within the depth")
        << "o<r> sub\no1 if [#1 GT 0]\nG0 X#1\no<r> call [#1-1]\no1 endif\no<r> endsub\no<r> "
           "call [3]"
        << "3:G0 X3 | 3:G0 X2 | 3:G0 X1";
    QTest::newRow("labels: leading zeros and name case")
        << "o010 if [1]\nG0 X1\no10 endif\no<A b> if [1]\nG0 X2\no<ab> endif"
        << "2:G0 X1 | 5:G0 X2";
    QTest::newRow("N number before the O word") << "N10 o1 if [1]\nG0 X1\nN20 o1 endif"
                                                << "2:G0 X1";
    QTest::newRow("DEBUG with values") << "#1=2.5\n#<n>=3\n(DEBUG, hole #<n> at #1 mm)"
                                       << "3:(MSG, hole 3 at 2.5 mm)";
    QTest::newRow("PRINT like DEBUG") << "(print, v=#1)"
                                      << "1:(MSG, v=0)";
    QTest::newRow("DEBUG: a number is its digits as written") << "#1=3\n(DEBUG, #1 2 #12)"
                                                              << "2:(MSG, 3 2 0)";
    QTest::newRow("DEBUG: unreadable references stay") << "(DEBUG, # #<> #<nope> #1234567)"
                                                       << "1:(MSG, # #<> #<nope> #1234567)";
    QTest::newRow("DEBUG: a huge value in exponent form") << "#1=[10**300]\n(DEBUG, #1)"
                                                          << "2:(MSG, 1e+300)";
    QTest::newRow("MSG kept") << "(MSG, change the clamp)"
                              << "1:(MSG, change the clamp)";
    QTest::newRow("comment kept on a line") << "G0 X[1+1] (rapid)"
                                            << "1:G0 X2 (rapid)";
    QTest::newRow("M30 ends the program") << "G0 X1\nM30\nG0 X2"
                                          << "1:G0 X1 | 2:M30";
    QTest::newRow("second percent ends it") << "%\nG0 X1\n%\nG0 X2"
                                            << "1:% | 2:G0 X1 | 3:%";
    // StepDeck's M66 stops the run when Q runs out: past it, the input reads as waited for.
    QTest::newRow("#5399 after M66 L3 (high)")
        << "M66 P1 L3 Q5\no1 if [#5399 EQ 1]\nG0 X1\no1 else\nG0 X2\no1 endif"
        << "1:M66 P1 L3 Q5 | 3:G0 X1";
    QTest::newRow("#5399 after M66 L4 (low)")
        << "M66 P1 L4 Q5\no1 if [#5399 EQ 1]\nG0 X1\no1 elseif [#5399 LT 0]\nG0 X9\no1 "
           "else\nG0 X2\no1 endif"
        << "1:M66 P1 L4 Q5 | 7:G0 X2";
    QTest::newRow("G54 changes #5220") << "G54\nG0 X#5220"
                                       << "1:G54 | 2:G0 X1";
    QTest::newRow("values six decimals") << "G0 X[1/3] Y[-0.0000001]"
                                         << "1:G0 X0.333333 Y0";
}

void TestNgcInterpreter::run_program_givesOutLines()
{
    QFETCH(QString, program);
    QFETCH(QString, lines);
    NgcContext context;
    context.activeSystem = 2;
    QCOMPARE(run(program, context), lines);
}

// Issue 50: block delete skips a "/" line whole, O words and assignments too (off: the line runs
// without the "/"); GRBL's "$" lines go to the parser as written; the lines after the program's
// end that LinuxCNC does not read are counted, but not a subroutine defined there nor the "%"
// closing a program opened with one.
void TestNgcInterpreter::run_aroundTheProgram_blockDeleteAndUnreadLines_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<bool>("blockDelete");
    QTest::addColumn<QString>("lines");
    QTest::addColumn<QList<int>>("counts"); // deleted, the first of them, end line, unread
    const QString slashes = "/o1 if [1]\nG0 X1\n/o1 endif\n/#1=5\nG0 X#1";
    QTest::newRow("block delete on")
        << slashes << true << "2:G0 X1 | 5:G0 X0" << QList<int>{3, 1, 0, 0};
    QTest::newRow("block delete off")
        << slashes << false << "2:G0 X1 | 5:G0 X5" << QList<int>{0, 0, 0, 0};
    QTest::newRow("$ lines as written")
        << "$H\nG0 X1\n$32=1" << true << "1:$H | 2:G0 X1 | 3:$32=1" << QList<int>{0, 0, 0, 0};
    QTest::newRow("after M2: a sub is read, the rest counted")
        << "o1 call\nM2\nG0 X9\no1 sub\nG0 X1\no1 endsub\n\n(trailer)" << true << "5:G0 X1 | 2:M2"
        << QList<int>{0, 0, 2, 2};
    QTest::newRow("the % after M30 closes")
        << "%\nG0 X1\nM30\n%\n"
        << true << "1:% | 2:G0 X1 | 3:M30" << QList<int>{0, 0, 3, 0};
    QTest::newRow("after the closing %")
        << "%\nG0 X1\n%\nG0 X2\n%" << true << "1:% | 2:G0 X1 | 3:%" << QList<int>{0, 0, 3, 2};
    QTest::newRow("M2 in a call: nothing counted") << "o<e> sub\nM2\no<e> endsub\no<e> call\nG0 X1"
                                                   << true << "2:M2" << QList<int>{0, 0, 0, 0};
}

void TestNgcInterpreter::run_aroundTheProgram_blockDeleteAndUnreadLines()
{
    QFETCH(QString, program);
    QFETCH(bool, blockDelete);
    QFETCH(QString, lines);
    QFETCH(QList<int>, counts);
    NgcContext context;
    context.blockDelete = blockDelete;
    QStringList out;
    NgcInterpreter interpreter(program.split(QLatin1Char('\n')), context,
                               [&](const QString& text, int line, const QList<int>&) {
                                   out << QStringLiteral("%1:%2").arg(line).arg(text.simplified());
                                   return true;
                               });
    QList<ProgramError> errors;
    QVERIFY2(interpreter.run(&errors, 10), qPrintable(errors.value(0).text()));
    QCOMPARE(out.join(QStringLiteral(" | ")), lines);
    QCOMPARE((QList<int>{interpreter.deletedLines(), interpreter.firstDeletedLine(),
                         interpreter.endLine(), interpreter.unreadLines()}),
             counts);
}

void TestNgcInterpreter::run_brokenProgram_errorAtLine_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("error"); // "E line:column" and a part of the message
    QTest::newRow("runaway while") << "G0 X1\no7 while [1]\no7 endwhile"
                                   << "E 2:1 O7 while (line 2) has run 1000000 passes";
    QTest::newRow("runaway do") << "o7 do\n#1=[#1+1]\no7 while [1]"
                                << "E 1:1 O7 do (line 1) has run 1000000 passes";
    QTest::newRow("repeat beyond the bound") << "o1 repeat [2000000]\no1 endrepeat"
                                             << "E 1:1 O1 repeat needs a whole count";
    QTest::newRow("repeat not whole") << "o1 repeat [1.5]\no1 endrepeat"
                                      << "E 1:1 O1 repeat needs a whole count";
    QTest::newRow("call depth") << "o<a> sub\no<a> call\no<a> endsub\no<a> call"
                                << "E 2:1 O<a> call: calls nest deeper than 10";
    QTest::newRow("no such sub") << "o<nope> call"
                                 << "E 1:1 O<nope> call: the program has no O<nope> sub";
    QTest::newRow("too many arguments")
        << "o1 sub\no1 endsub\no1 call" + QString(" [1]").repeated(31)
        << "E 3:129 a call takes at most 30 arguments";
    QTest::newRow("if without condition") << "o1 if\no1 endif"
                                          << "E 1:6 O1 if needs a value";
    QTest::newRow("text after the condition") << "o1 while [1] G0\no1 endwhile"
                                              << "E 1:14 O1 while takes one value";
    QTest::newRow("expression error in a loop body") << "o1 repeat [2]\nG0 X[1/#1]\no1 endrepeat"
                                                     << "E 2:7 division by zero";
    QTest::newRow("unset local in a sub") << "#<a>=1\no<s> sub\nG0 X#<a>\no<s> endsub\no<s> call"
                                          << "E 3:5 #<a> is not set here";
    QTest::newRow("read-only named") << "#<_value>=1"
                                     << "E 1:2 #<_value> is LinuxCNC's, read-only";
    QTest::newRow("#5399 before any M66") << "o1 if [#5399 EQ 1]\nG0 X1\no1 endif"
                                          << "E 1:8 #5399 holds what M66 read, and no M66 has run";
    QTest::newRow("read-only offset") << "#5221=1"
                                      << "E 1:2 #5221 is a coordinate system's offset";
    QTest::newRow("offset after G10") << "G10 L2 P1 X5\nG0 X#5221"
                                      << "E 2:5 #5221 is an offset that line 1 changed";
    QTest::newRow("value too large") << "G0 X[10**12]"
                                     << "E 1:4 X1e+12 is beyond the values";
    // "#1 5": LinuxCNC leaves the space out, so this is #15 without its "=".
    QTest::newRow("O word after another word") << "#1=2 O1"
                                               << "E 1:6 an O word stands first on its line";
    QTest::newRow("O word after a decimal N") << "N1.0 O1"
                                              << "E 1:6 an O word stands first on its line";
    QTest::newRow("break to a loop outside the sub")
        << "o2 call\nM2\no1 do\no2 sub\no1 break\no2 endsub\no1 while [0]"
        << "E 5:1 O1 break is outside a loop O1";
    QTest::newRow("return named by a block outside the sub")
        << "o1 if [1]\no2 call\no1 endif\no2 sub\no1 return\no2 endsub"
        << "E 5:1 O1 return is outside O1 sub";
    QTest::newRow("missing =") << "#1 5"
                               << "E 1:5 \"=\" is missing";
}

void TestNgcInterpreter::run_brokenProgram_errorAtLine()
{
    QFETCH(QString, program);
    QFETCH(QString, error);
    const QString got = run(program);
    QVERIFY2(got.startsWith(error), qPrintable(got));
}

void TestNgcInterpreter::run_brokenStructure_everyErrorListed()
{
    const QString program = QStringLiteral("o1 if [1]\n"           // 1: not closed
                                           "o2 endwhile\n"         // 2: closes nothing
                                           "o3 sub\n"              // 3
                                           "o4 sub\n"              // 4: nested
                                           "o4 endsub\n"           // 5
                                           "o3 endsub\n"           // 6
                                           "o5 break\n"            // 7: outside a loop
                                           "o6 return\n"           // 8: outside a sub
                                           "o7 frobnicate\n"       // 9: no keyword
                                           "o3 sub\no3 endsub\n"); // 10: twice
    NgcInterpreter interpreter(program.split(QLatin1Char('\n')), {},
                               [](const QString&, int, const QList<int>&) { return true; });
    QList<ProgramError> errors;
    QVERIFY(!interpreter.run(&errors, 20));
    QStringList lines;
    for (const ProgramError& e : errors)
        lines << QStringLiteral("%1:%2").arg(e.line).arg(e.column);
    QCOMPARE(lines.join(QLatin1Char(' ')), QStringLiteral("1:1 2:1 4:1 7:1 8:1 9:4 10:1"));
    QVERIFY(errors.at(0).message.contains(QStringLiteral("O1 if is not closed")));
    QVERIFY(errors.at(1).message.contains(QStringLiteral("O2 endwhile does not close O1 if")));
    QVERIFY(errors.at(2).message.contains(QStringLiteral("do not nest")));
    QVERIFY(errors.at(3).message.contains(QStringLiteral("outside a loop O5")));
    QVERIFY(errors.at(4).message.contains(QStringLiteral("outside O6 sub")));
    QVERIFY(errors.at(5).message.contains(QStringLiteral("frobnicate")));
    QVERIFY(errors.at(6).message.contains(QStringLiteral("defined twice")));
}

void TestNgcInterpreter::run_subroutineFolder_callsFileAndNamesIt()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    auto write = [&](const QString& name, const QByteArray& text) {
        QFile f(dir.filePath(name));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
    };
    write(QStringLiteral("hole.ngc"), "o<hole> sub\r\nG0 X#1\r\nG1 Z[-#2]\r\no<hole> endsub\r\n");
    write(QStringLiteral("broken.ngc"), "o<broken> sub\nG0 X[1/0]\no<broken> endsub\n");
    write(QStringLiteral("other.ngc"), "o<something> sub\no<something> endsub\n");
    NgcContext context;
    context.subroutineFolder = dir.path();
    QCOMPARE(run(QStringLiteral("G21\no<hole> call [5] [2]\no<hole> call [6] [1]"), context),
             QStringLiteral("1:G21 | 2:G0 X5 | 2:G1 Z-2 | 3:G0 X6 | 3:G1 Z-1"));
    // An error in the folder's file names the file and its line, at the call's line.
    const QString broken = run(QStringLiteral("G21\no<broken> call"), context);
    QVERIFY2(broken.startsWith(QStringLiteral("E 2:1 ")), qPrintable(broken));
    QVERIFY2(broken.contains(QStringLiteral("broken.ngc:2:")) &&
                 broken.contains(QStringLiteral("division by zero")),
             qPrintable(broken));
    const QString other = run(QStringLiteral("o<other> call"), context);
    QVERIFY2(other.contains(QStringLiteral("does not define O<other> sub")), qPrintable(other));
    const QString missing = run(QStringLiteral("o<missing> call"), context);
    QVERIFY2(missing.contains(QStringLiteral("missing.ngc")), qPrintable(missing));
}

void TestNgcInterpreter::run_outputRefuses_stops()
{
    int given = 0;
    NgcInterpreter interpreter(QStringLiteral("G0 X1\nG0 X2\nG0 X3").split(QLatin1Char('\n')), {},
                               [&](const QString&, int, const QList<int>&) { return ++given < 2; });
    QList<ProgramError> errors;
    QVERIFY(!interpreter.run(&errors, 10));
    QCOMPARE(given, 2);
    QCOMPARE(errors.value(0).line, 2);
}

// The three bounds, lowered (NgcContext::limits): each ends the work with the line it was
// reached on.
void TestNgcInterpreter::run_lowerLimits_eachBoundNamesItsLine()
{
    NgcContext context;
    context.limits = NgcLimits{5, 50, 3};
    // Within the bound: no error, nothing given out.
    QCOMPARE(run(QStringLiteral("o1 repeat [5]\n#1=[#1+1]\no1 endrepeat"), context), QString());
    QVERIFY(run(QStringLiteral("o1 repeat [6]\no1 endrepeat"), context)
                .startsWith(QStringLiteral("E 1:1 O1 repeat needs a whole count from 0 to 5")));
    const QString passes = run(QStringLiteral("o1 while [1]\no1 endwhile"), context);
    QVERIFY2(passes.startsWith(QStringLiteral("E 1:1 O1 while (line 1) has run 5 passes")),
             qPrintable(passes));
    const QString steps =
        run(QStringLiteral("o1 repeat [5]\no2 repeat [5]\n#1=1\n#2=2\no2 endrepeat\no1 "
                           "endrepeat"),
            context);
    QVERIFY2(steps.contains(QStringLiteral("runs more than 50 lines")), qPrintable(steps));
    // A long line counts once per 64 characters: 3200 characters are 51 lines' work.
    const QString longLine =
        run(QStringLiteral("(%1)").arg(QString(3198, QLatin1Char('x'))), context);
    QVERIFY2(longLine.startsWith(QStringLiteral("E 1:1 the program runs more than 50 lines")),
             qPrintable(longLine));
    const QString lines = run(QStringLiteral("G0 X1\nG0 X2\nG0 X3\nG0 X4"), context);
    QVERIFY2(lines.startsWith(QStringLiteral("E 4:1 the program gives out more than 3 lines")),
             qPrintable(lines));
}

STEPDECK_TEST_GUILESS_MAIN(TestNgcInterpreter)
#include "tst_ngcinterpreter.moc"
