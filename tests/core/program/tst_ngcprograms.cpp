// Programs in LinuxCNC's language (issue 33), our own, in tests/core/program/ngc/: a bolt circle
// by a while loop with COS and SIN, pockets by a subroutine called twice, an engraving placed
// and scaled by parameters with if/else and a repeat. Each is checked as the window and the CLI
// check it (ProgramCheck over the file: worked out, then parsed and checked against the ngcMill of
// the check's tests) and must pass; its preview path and the blocks read back must be the moves
// worked out here independently (NgcProgramsTestSupport.h), each block naming the source line it
// came from (the loop's or the subroutine's body), and its (DEBUG, …)/(PRINT, …) lines messages
// with the values in place. A copy of each with a deliberate error is refused at the source line.
#include "NgcProgramsTestSupport.h"
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/ProgramCheck.h"
#include "program/ProgramReader.h"
#include "program/language/ProgramExpansion.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;
using namespace stepdeck::program::ngctest;

namespace {

// The ngcMill of the check's tests (X 0..100, Y 0..200, Z -50..0 mm; X and Z 100 steps/mm, Y 200)
// standing at machine 0, with G54's zero 20 mm below it on Z: the programs' Z from +2 down to -3
// lie within the soft limits.
MachineFacts ngcMill()
{
    MachineFacts f = checktest::machineFacts(QStringLiteral("ngcMill"));
    f.knownPositions = {{"X", 0}, {"Y", 0}, {"Z", 0}};
    f.coordinateSystems[0] = {{"Z", -20.0}};
    return f;
}

QStringList axisNames(const MachineFacts& facts)
{
    QStringList names;
    for (const machine::MachineAxis& a : facts.description.axes)
        names << a.name;
    return names;
}

// Within half a step of the ngcMill's axis (the preview's positions are whole steps).
bool nearOnAxis(const QString& axis, double actual, double expected)
{
    const double steps = axis == QLatin1String("Y") ? 200 : 100;
    return std::abs(actual - expected) <= 0.5 / steps + 1e-9;
}

QString describePoint(const PreviewPoint& p)
{
    return QStringLiteral("line %1 X%2 Y%3 Z%4")
        .arg(p.line)
        .arg(p.position.value("X"))
        .arg(p.position.value("Y"))
        .arg(p.position.value("Z"));
}

} // namespace

class TestNgcPrograms : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void check_ngcProgram_passesWithTheComputedPath_data();
    void check_ngcProgram_passesWithTheComputedPath();
    void check_ngcProgram_blocksNameTheirSourceLines_data();
    void check_ngcProgram_blocksNameTheirSourceLines();
    void check_brokenNgcProgram_refusedAtItsSourceLine_data();
    void check_brokenNgcProgram_refusedAtItsSourceLine();
    void check_wordAfterALongerValue_namedAtItsSourceColumnOnce_data();
    void check_wordAfterALongerValue_namedAtItsSourceColumnOnce();

private:
    static void addProgramRows();
};

void TestNgcPrograms::addProgramRows()
{
    QTest::addColumn<QString>("file");
    for (const char* file : {"bolt-circle.ngc", "pocket-sub.ngc", "engrave-params.ngc"})
        QTest::newRow(file) << QString::fromLatin1(file);
}

void TestNgcPrograms::check_ngcProgram_passesWithTheComputedPath_data()
{
    addProgramRows();
}

// The preview's path: the start, then one point per move at its source line, rapid or not, at
// the computed position (work coordinates: machine Z 0 is work Z 20).
void TestNgcPrograms::check_ngcProgram_passesWithTheComputedPath()
{
    QFETCH(QString, file);
    const QStringList lines = sourceLines(ngcText(file));
    QVERIFY2(!lines.isEmpty(), qPrintable(ngcPath(file)));
    const Expected expected = expectedOf(file, lines);
    QVERIFY(linesFound(expected));
    const MachineFacts facts = ngcMill();
    const ProgramCheckResult result =
        ProgramCheck::check(ProgramSource::file(ngcPath(file)), axisNames(facts), facts);
    QVERIFY2(result.ok(), qPrintable(checktest::texts(result.errors).join('\n')));
    QVERIFY(result.program && result.program->expansion); // worked out, not read as it is
    QCOMPARE(result.preview.lines, int(lines.size()));
    const QList<PreviewPoint>& path = result.preview.path;
    QVERIFY(!result.preview.pathDecimated);
    QCOMPARE(path.size(), expected.moves.size() + 1);
    QCOMPARE(path.first().line, 0);
    QCOMPARE(path.first().position, (QMap<QString, double>{{"X", 0}, {"Y", 0}, {"Z", 20}}));
    const QList<Point> at = positionsAfter(expected.moves, Point{0, 0, 20});
    for (int i = 0; i < expected.moves.size(); ++i) {
        const PreviewPoint& p = path.at(i + 1);
        const QString where = QStringLiteral("move %1: %2").arg(i).arg(describePoint(p));
        QVERIFY2(p.line == expected.moves.at(i).line, qPrintable(where));
        QVERIFY2(p.rapid == expected.moves.at(i).rapid, qPrintable(where));
        QVERIFY2(nearOnAxis("X", p.position.value("X", NAN), at.at(i).x) &&
                     nearOnAxis("Y", p.position.value("Y", NAN), at.at(i).y) &&
                     nearOnAxis("Z", p.position.value("Z", NAN), at.at(i).z),
                 qPrintable(where + QStringLiteral(", computed X%1 Y%2 Z%3")
                                        .arg(at.at(i).x)
                                        .arg(at.at(i).y)
                                        .arg(at.at(i).z)));
    }
}

void TestNgcPrograms::check_ngcProgram_blocksNameTheirSourceLines_data()
{
    addProgramRows();
}

// The blocks the run reads back: every G0 and G1 in the order the control flow runs them, with
// the words worked out (six decimals) and the line of the source they were written on; the
// (DEBUG, …)/(PRINT, …) lines as the operator's messages with the values in place.
void TestNgcPrograms::check_ngcProgram_blocksNameTheirSourceLines()
{
    QFETCH(QString, file);
    const QStringList lines = sourceLines(ngcText(file));
    const Expected expected = expectedOf(file, lines);
    QVERIFY(linesFound(expected));
    const MachineFacts facts = ngcMill();
    const ProgramCheckResult result =
        ProgramCheck::check(ProgramSource::file(ngcPath(file)), axisNames(facts), facts);
    QVERIFY2(result.ok(), qPrintable(checktest::texts(result.errors).join('\n')));
    QList<ProgramBlock> moves;
    QList<Message> messages;
    for (const ProgramBlock& b : ProgramReader::readAll(*result.program)) {
        if (b.kind == BlockKind::Rapid || b.kind == BlockKind::Feed)
            moves << b;
        if (!b.message.isEmpty())
            messages << Message{b.line, b.message};
    }
    QCOMPARE(moves.size(), expected.moves.size());
    for (int i = 0; i < moves.size(); ++i) {
        const ProgramBlock& b = moves.at(i);
        const Move& m = expected.moves.at(i);
        const QString where = QStringLiteral("move %1, line %2: %3").arg(i).arg(b.line).arg(b.text);
        QVERIFY2(b.line == m.line, qPrintable(where));
        QVERIFY2((b.kind == BlockKind::Rapid) == m.rapid, qPrintable(where));
        QStringList named;
        for (const auto& [axis, value] : {std::pair{"X", m.x}, {"Y", m.y}, {"Z", m.z}}) {
            if (!value)
                continue;
            named << axis;
            QVERIFY2(std::abs(b.axes.value(axis, NAN) - *value) <= 1e-6, qPrintable(where));
        }
        QCOMPARE(b.axes.keys(), named);
    }
    QCOMPARE(messages, expected.messages);
}

void TestNgcPrograms::check_brokenNgcProgram_refusedAtItsSourceLine_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("from"); // a line of the file ...
    QTest::addColumn<QString>("to");   // ... written instead
    QTest::addColumn<QStringList>("errors");
    const QString limitX = QStringLiteral("X reaches %1 mm, outside the soft limits 0..100 mm");
    // The circle's centre at X 90: the first hole (15°) at X 101.591, named on the loop's line
    // at the column of its X word, once though the loop runs it six times.
    const QStringList bolt = sourceLines(ngcText("bolt-circle.ngc"));
    QTest::newRow("bolt circle: a hole beyond the soft limit")
        << "bolt-circle.ngc"
        << "#<cx> = 30"
        << "#<cx> = 90"
        << QStringList{QStringLiteral("%1:6: ").arg(lineOf(bolt, "G0 X#<x> Y#<y>")) +
                       limitX.arg("101.591")};
    // The second pocket 12 mm wide at X 92: its passes 2 mm apart, the sixth at X 102, on the
    // subroutine's line (not the call's).
    const QStringList pocket = sourceLines(ngcText("pocket-sub.ngc"));
    QTest::newRow("pocket: the second call's beyond the soft limit")
        << "pocket-sub.ngc"
        << "o<pocket> call [22] [10] [5] [3] [-1.5]"
        << "o<pocket> call [92] [10] [12] [3] [-1.5]"
        << QStringList{QStringLiteral("%1:10: ").arg(
                           lineOf(pocket, "G1 X[#<x0> + #<width> * #<c> / #<cols>]")) +
                       limitX.arg("102")};
    // Letters of 30 mm: the third (an N, left at 12 + 2 * 45) beyond X 100 at both its X words.
    const QStringList engrave = sourceLines(ngcText("engrave-params.ngc"));
    QTest::newRow("engraving: scaled beyond the soft limit")
        << "engrave-params.ngc"
        << "#<_scale> = 2.5"
        << "#<_scale> = 30"
        << QStringList{QStringLiteral("%1:8: ").arg(lineOf(engrave, "G0 X#<left> Y#<y0>")) +
                           limitX.arg("102"),
                       QStringLiteral("%1:8: ").arg(lineOf(engrave, "G1 X#<right> Y#<y0>")) +
                           limitX.arg("132")};
    QTest::newRow("engraving: a count that is not whole")
        << "engrave-params.ngc"
        << "#<copies> = 3"
        << "#<copies> = 2.5"
        << QStringList{QStringLiteral("%1:1: O10 repeat needs a whole count from 0 to 1000000, "
                                      "got 2.5")
                           .arg(lineOf(engrave, "o10 repeat [#<copies>]"))};
}

// Nothing of a broken copy is kept to run: the errors name the lines the operator wrote, at the
// columns of the words at fault.
void TestNgcPrograms::check_brokenNgcProgram_refusedAtItsSourceLine()
{
    QFETCH(QString, file);
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(QStringList, errors);
    QString text = QString::fromUtf8(ngcText(file));
    QCOMPARE(text.count(from + '\n'), 1);
    text.replace(from + '\n', to + '\n');
    const MachineFacts facts = ngcMill();
    const ProgramCheckResult result =
        ProgramCheck::check(ProgramSource::bytes(text.toUtf8()), axisNames(facts), facts);
    QCOMPARE(checktest::texts(result.errors), errors);
    QVERIFY(!result.program);
}

void TestNgcPrograms::check_wordAfterALongerValue_namedAtItsSourceColumnOnce_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("errors");
    const QString below = QStringLiteral("Y reaches -5 mm, outside the soft limits 0..200 mm");
    // "G0 X#<a> Y-5": Y written at column 10.
    QTest::newRow("after a parameter") << "#<a> = 1.23456\nG0 X#<a> Y-5\n"
                                       << QStringList{"2:10: " + below};
    // "G0 X#1 Y-5" run with X1, X10, X100: Y written at column 8, one word named once (docs/
    // programs.md "Check": "named once per word").
    QTest::newRow("in a loop")
        << "#1 = 1\no1 while [#1 LT 200]\nG0 X#1 Y-5\n#1 = [#1 * 10]\no1 endwhile\n"
        << QStringList{"3:8: " + below};
}

// A word after a value whose worked-out text is longer than what the operator wrote: the check
// names it where it is written, once.
void TestNgcPrograms::check_wordAfterALongerValue_namedAtItsSourceColumnOnce()
{
    QFETCH(QString, program);
    QFETCH(QStringList, errors);
    const MachineFacts facts = ngcMill();
    const ProgramCheckResult result =
        ProgramCheck::check(ProgramSource::bytes(program.toUtf8()), axisNames(facts), facts);
    QVERIFY(!result.ok());
    QCOMPARE(checktest::texts(result.errors), errors);
}

STEPDECK_TEST_MAIN(TestNgcPrograms)
#include "tst_ngcprograms.moc"
