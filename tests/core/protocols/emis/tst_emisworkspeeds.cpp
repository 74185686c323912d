// EmisWorkSpeeds: the move speed (written, else stored, else the assumed default) and the
// speed the board is known to have, from which the #E1 writes of a move, a jog and its end
// follow.
#include "TestMain.h"
#include "protocols/emis/EmisWorkSpeeds.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::emis;

namespace {
QList<QPair<Axis, qint64>> pairs(const QList<EmisWorkSpeeds::Write>& writes)
{
    QList<QPair<Axis, qint64>> out;
    for (const EmisWorkSpeeds::Write& w : writes)
        out << qMakePair(w.axis, w.speed);
    return out;
}
} // namespace

class TestEmisWorkSpeeds : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void moveSpeed_writtenThenStoredThenAssumed();
    void move_writesWhatTheBoardIsNotKnownToHave();
    void jog_rewritesOnlyBeyondTheTolerance();
    void restore_jogRateBackToMoveSpeed_notTwice();
    void forget_boardUnknown_nextMoveWritesAgain();
};

void TestEmisWorkSpeeds::moveSpeed_writtenThenStoredThenAssumed()
{
    EmisWorkSpeeds s;
    QCOMPARE(s.moveSpeed(Axis::X), EmisWorkSpeeds::kAssumedDefault);
    s.setStored({{Axis::X, 1800}, {Axis::Y, 600}});
    QCOMPARE(s.moveSpeed(Axis::X), 1800);
    s.setWritten(Axis::X, 500);
    QCOMPARE(s.moveSpeed(Axis::X), 500); // the working value written in this session wins
    QCOMPARE(s.moveSpeed(Axis::Y), 600);
    QCOMPARE(s.moveSpeed(Axis::U), EmisWorkSpeeds::kAssumedDefault);
}

void TestEmisWorkSpeeds::move_writesWhatTheBoardIsNotKnownToHave()
{
    EmisWorkSpeeds s;
    s.setStored({{Axis::Y, 600}});
    s.setWritten(Axis::X, 500); // acknowledged: the board has it
    using P = QList<QPair<Axis, qint64>>;
    QCOMPARE(pairs(s.writesForMove({Axis::U, Axis::X, Axis::Y})),
             (P{{Axis::Y, 600}, {Axis::U, EmisWorkSpeeds::kAssumedDefault}}));
    s.noteOnBoard(Axis::Y, 600);
    s.noteOnBoard(Axis::U, 1000);
    QVERIFY(s.writesForMove({Axis::X, Axis::Y, Axis::U}).isEmpty());
    s.noteOnBoard(Axis::X, 620); // a jog chunk's speed
    QCOMPARE(pairs(s.writesForMove({Axis::X})), (P{{Axis::X, 500}}));
}

void TestEmisWorkSpeeds::jog_rewritesOnlyBeyondTheTolerance()
{
    EmisWorkSpeeds s;
    QVERIFY(s.jogNeedsWrite(Axis::Z, 600)); // unknown
    s.noteOnBoard(Axis::Z, 600);
    QVERIFY(!s.jogNeedsWrite(Axis::Z, 650));
    QVERIFY(s.jogNeedsWrite(Axis::Z, 700));
}

void TestEmisWorkSpeeds::restore_jogRateBackToMoveSpeed_notTwice()
{
    EmisWorkSpeeds s;
    s.setWritten(Axis::X, 800);
    s.setWritten(Axis::Y, 900);
    s.noteOnBoard(Axis::X, 300); // jogged
    using P = QList<QPair<Axis, qint64>>;
    QCOMPARE(pairs(s.writesToRestore()), (P{{Axis::X, 800}}));
    s.noteWriting(Axis::X); // on its way: not asked for again
    QVERIFY(s.writesToRestore().isEmpty());
    s.noteOnBoard(Axis::X, 800);
    QVERIFY(s.writesToRestore().isEmpty());
}

void TestEmisWorkSpeeds::forget_boardUnknown_nextMoveWritesAgain()
{
    EmisWorkSpeeds s;
    s.setWritten(Axis::X, 800);
    s.setWritten(Axis::Y, 900);
    QVERIFY(s.writesForMove({Axis::X, Axis::Y}).isEmpty());
    s.forgetBoard(Axis::Y);
    QCOMPARE(s.writesForMove({Axis::X, Axis::Y}).size(), 1);
    s.forgetBoard();
    QCOMPARE(s.writesForMove({Axis::X, Axis::Y}).size(), 2);
    QVERIFY(s.writesToRestore().isEmpty()); // nothing known on the board: nothing to give back
    QCOMPARE(s.moveSpeed(Axis::X), 800);    // the written value stays the one moves run at
}

STEPDECK_TEST_GUILESS_MAIN(TestEmisWorkSpeeds)
#include "tst_emisworkspeeds.moc"
