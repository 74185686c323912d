// MdiSession (issue 31's MDI line, issue 30's "MDI lines reach the controllers through the same
// run"): a line is a program of one line in the state the last finished line left; a refused or
// failed line leaves that state; the check of the line follows from that state.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/MdiSession.h"
#include "program/ProgramReader.h"
#include <QtTest>

using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

namespace {

const QStringList kMdiAxes{QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};

ProgramBlock onlyBlock(const Program& program)
{
    const QList<ProgramBlock> blocks = program.allBlocks();
    return blocks.size() == 1 ? blocks.first() : ProgramBlock{};
}

} // namespace

class TestMdiSession : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void prepare_afterFinishedLine_keepsItsModalWords_data();
    void prepare_afterFinishedLine_keepsItsModalWords();
    void prepare_afterFailedLine_keepsTheStateBefore();
    void prepare_badLine_errorAtItsColumn_data();
    void prepare_badLine_errorAtItsColumn();
    void lineRan_selectedSystem_givenOnceThenTheWindowsActiveOne();
    void check_relativeLine_endsFromWhereTheAxesStand();
    void history_boundedWithoutRepeatsInARow();
    void modalText_saysTheActiveWords();
};

void TestMdiSession::prepare_afterFinishedLine_keepsItsModalWords_data()
{
    QTest::addColumn<QString>("first");
    QTest::addColumn<QString>("second");
    QTest::addColumn<bool>("relative");
    QTest::addColumn<bool>("inches");
    QTest::addColumn<double>("feed");
    QTest::addColumn<int>("plane");
    QTest::newRow("G91 then a move") << "G91"
                                     << "G0 X1" << true << false << 0.0 << 0;
    QTest::newRow("F carries") << "G1 X1 F250"
                               << "G1 X2" << false << false << 250.0 << 0;
    QTest::newRow("G20 G91 F") << "G20 G91 F10"
                               << "G1 Y0.5" << true << true << 10.0 << 0;
    QTest::newRow("G18 plane") << "G18 F100"
                               << "G1 Z-1" << false << false << 100.0 << 1;
    QTest::newRow("G90 undoes G91") << "G91 F50"
                                    << "G90 G1 X3" << false << false << 50.0 << 0;
}

void TestMdiSession::prepare_afterFinishedLine_keepsItsModalWords()
{
    QFETCH(QString, first);
    QFETCH(QString, second);
    QFETCH(bool, relative);
    QFETCH(bool, inches);
    QFETCH(double, feed);
    QFETCH(int, plane);
    MdiSession mdi;
    QList<ProgramError> errors;
    QVERIFY(mdi.prepare(first, kMdiAxes, &errors));
    mdi.lineRan(true);
    const std::optional<Program> program = mdi.prepare(second, kMdiAxes, &errors);
    QVERIFY2(program, qPrintable(texts(errors).join('\n')));
    const ProgramBlock block = onlyBlock(*program);
    QCOMPARE(block.line, 1);
    QCOMPARE(block.relative, relative);
    QCOMPARE(block.inches, inches);
    QCOMPARE(block.feed.value_or(0), feed);
    QCOMPARE(int(block.plane), plane);
    // The run reads the line again through the index, from its first checkpoint: in the same
    // state.
    ProgramReader reader(*program);
    const ProgramBlock* read = reader.at(0);
    QVERIFY(read);
    QCOMPARE(read->relative, block.relative);
    QCOMPARE(read->feed, block.feed);
}

void TestMdiSession::prepare_afterFailedLine_keepsTheStateBefore()
{
    MdiSession mdi;
    QList<ProgramError> errors;
    QVERIFY(mdi.prepare(QStringLiteral("G91 G1 X1 F100"), kMdiAxes, &errors));
    mdi.lineRan(false); // refused, failed or aborted: LinuxCNC's state is not what it asked
    std::optional<Program> next = mdi.prepare(QStringLiteral("G1 X1"), kMdiAxes, &errors);
    QVERIFY(!next); // G1 without F: the state has no feed, so the line is refused as a program
    QVERIFY(!errors.isEmpty());
    next = mdi.prepare(QStringLiteral("G0 X1"), kMdiAxes, &errors);
    QVERIFY(next);
    QCOMPARE(onlyBlock(*next).relative, false);
    QVERIFY(!mdi.modal().relative);
}

void TestMdiSession::prepare_badLine_errorAtItsColumn_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("text");
    QTest::newRow("unknown axis") << "G0 X1 Q5" << 7 << "Q";
    QTest::newRow("comment only") << "(nothing)" << 1 << "nothing to run";
    QTest::newRow("two lines") << "G0 X1\nG0 X2" << 1 << "one line";
}

void TestMdiSession::prepare_badLine_errorAtItsColumn()
{
    QFETCH(QString, line);
    QFETCH(int, column);
    QFETCH(QString, text);
    MdiSession mdi;
    QList<ProgramError> errors;
    QVERIFY(!mdi.prepare(line, kMdiAxes, &errors));
    QVERIFY(!errors.isEmpty());
    QCOMPARE(errors.first().line, 1);
    QCOMPARE(errors.first().column, column);
    QVERIFY2(errors.first().text().contains(text), qPrintable(errors.first().text()));
    QVERIFY(!mdi.lineRan(true)); // nothing prepared: nothing taken
    QCOMPARE(MdiSession::modalText(mdi.modal()), MdiSession::modalText(ModalState{}));
}

void TestMdiSession::lineRan_selectedSystem_givenOnceThenTheWindowsActiveOne()
{
    MdiSession mdi;
    QList<ProgramError> errors;
    QVERIFY(mdi.prepare(QStringLiteral("G55"), kMdiAxes, &errors));
    QCOMPARE(mdi.lineRan(true), std::optional<int>(1));
    QCOMPARE(mdi.modal().coordinateSystem, -1);
    QVERIFY(mdi.prepare(QStringLiteral("G0 X1"), kMdiAxes, &errors));
    QCOMPARE(mdi.lineRan(true), std::nullopt);
}

void TestMdiSession::check_relativeLine_endsFromWhereTheAxesStand()
{
    MachineFacts facts = machineFacts(QStringLiteral("mill"));
    facts.knownPositions = positions(QStringLiteral("X=10 Y=20 Z=-5 A=0"));
    QStringList axes;
    for (const MachineAxis& a : facts.description.axes)
        axes << a.name;
    MdiSession mdi;
    QList<ProgramError> errors;
    QVERIFY(mdi.prepare(QStringLiteral("G91"), axes, &errors));
    mdi.lineRan(true);
    const std::optional<Program> program =
        mdi.prepare(QStringLiteral("G0 X5 Y-2.5"), axes, &errors);
    QVERIFY(program);
    const ProgramCheckResult result = ProgramCheck::check(*program, facts);
    QVERIFY2(result.ok(), qPrintable(texts(result.errors).join('\n')));
    QVERIFY(!result.preview.path.isEmpty());
    QCOMPARE(result.preview.path.last().position.value(QStringLiteral("X")), 15.0);
    QCOMPARE(result.preview.path.last().position.value(QStringLiteral("Y")), 17.5);
    // The same move beyond the soft limit (X 0..100) is refused by the check, as in a program.
    const std::optional<Program> far = mdi.prepare(QStringLiteral("G0 X95"), axes, &errors);
    QVERIFY(far);
    QVERIFY(!ProgramCheck::check(*far, facts).ok());
}

void TestMdiSession::history_boundedWithoutRepeatsInARow()
{
    MdiSession mdi;
    QList<ProgramError> errors;
    mdi.prepare(QStringLiteral("G0 X1"), kMdiAxes, &errors);
    mdi.prepare(QStringLiteral("  G0 X1 "), kMdiAxes, &errors);
    mdi.prepare(QStringLiteral("G0 X2 Q"), kMdiAxes, &errors); // a refused line too: Up corrects it
    QCOMPARE(mdi.history(), QStringList({QStringLiteral("G0 X1"), QStringLiteral("G0 X2 Q")}));
    for (int i = 0; i < MdiSession::kHistoryLines + 5; ++i)
        mdi.prepare(QStringLiteral("G0 X%1").arg(i), kMdiAxes, &errors);
    QCOMPARE(mdi.history().size(), MdiSession::kHistoryLines);
    QCOMPARE(mdi.history().last(), QStringLiteral("G0 X%1").arg(MdiSession::kHistoryLines + 4));
}

void TestMdiSession::modalText_saysTheActiveWords()
{
    MdiSession mdi;
    QCOMPARE(MdiSession::modalText(mdi.modal()), QStringLiteral("G90 G21 G17 G64"));
    QList<ProgramError> errors;
    QVERIFY(mdi.prepare(QStringLiteral("G91 G20 G19 G61 F12.5"), kMdiAxes, &errors));
    mdi.lineRan(true);
    QCOMPARE(MdiSession::modalText(mdi.modal()), QStringLiteral("G91 G20 G19 G61 F12.5"));
    mdi.reset();
    QCOMPARE(MdiSession::modalText(mdi.modal()), QStringLiteral("G90 G21 G17 G64"));
}

STEPDECK_TEST_GUILESS_MAIN(TestMdiSession)
#include "tst_mdisession.moc"
