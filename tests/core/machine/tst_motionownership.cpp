// Who moves the machine (issue 49 item 4): one holder at a time, a refusal names the holder,
// only the holder gives it back, and a holder that is deleted holds nothing. Pure.
#include "TestMain.h"
#include "machine/MotionOwnership.h"
#include <QtTest>

using namespace stepdeck::machine;

class TestMotionOwnership : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void claim_free_takenAndNamed();
    void claim_heldByAnother_refusedWithTheHoldersName();
    void claim_again_byTheHolder_keepsIt();
    void release_byAnother_changesNothing();
    void holderDeleted_free();
    void lend_onlyByTheHolder_endsWithTheRelease();
};

void TestMotionOwnership::claim_free_takenAndNamed()
{
    MotionOwnership o;
    QObject program;
    QVERIFY(o.isFree());
    QVERIFY(o.claim(&program, QStringLiteral("a program runs")));
    QVERIFY(!o.isFree());
    QVERIFY(o.isHeldBy(&program));
    QCOMPARE(o.holder(), QStringLiteral("a program runs"));
    o.release(&program);
    QVERIFY(o.isFree());
    QVERIFY(o.holder().isEmpty());
}

void TestMotionOwnership::claim_heldByAnother_refusedWithTheHoldersName()
{
    MotionOwnership o;
    QObject program, mdi;
    QVERIFY(o.claim(&program, QStringLiteral("a program runs")));
    QString why;
    QVERIFY(!o.claim(&mdi, QStringLiteral("an MDI line runs"), &why));
    QCOMPARE(why, QStringLiteral("a program runs"));
    QVERIFY(!o.isHeldBy(&mdi));
    QVERIFY(!o.isHeldBy(nullptr));
}

void TestMotionOwnership::claim_again_byTheHolder_keepsIt()
{
    MotionOwnership o;
    QObject mdi;
    QVERIFY(o.claim(&mdi, QStringLiteral("an MDI line runs")));
    QVERIFY(o.claim(&mdi, QStringLiteral("an MDI line runs")));
    QVERIFY(o.isHeldBy(&mdi));
}

void TestMotionOwnership::release_byAnother_changesNothing()
{
    MotionOwnership o;
    QObject program, mdi;
    QVERIFY(o.claim(&program, QStringLiteral("a program runs")));
    o.release(&mdi);
    QVERIFY(o.isHeldBy(&program));
}

void TestMotionOwnership::holderDeleted_free()
{
    MotionOwnership o;
    auto program = std::make_unique<QObject>();
    QVERIFY(o.claim(program.get(), QStringLiteral("a program runs")));
    program.reset();
    QVERIFY(o.isFree());
    QObject mdi;
    QVERIFY(o.claim(&mdi, QStringLiteral("an MDI line runs")));
}

void TestMotionOwnership::lend_onlyByTheHolder_endsWithTheRelease()
{
    MotionOwnership o;
    QObject program, mdi;
    QVERIFY(o.admitsManualMotion()); // free
    QVERIFY(o.claim(&program, QStringLiteral("a program runs")));
    QVERIFY(!o.admitsManualMotion());
    o.setLent(&mdi, true); // not the holder's to lend
    QVERIFY(!o.admitsManualMotion());
    o.setLent(&program, true);
    QVERIFY(o.admitsManualMotion());
    QVERIFY(!o.isFree()); // lent, still held: no other run starts
    QVERIFY(!o.claim(&mdi, QStringLiteral("an MDI line runs")));
    o.setLent(&program, false);
    QVERIFY(!o.admitsManualMotion());
    o.setLent(&program, true);
    o.release(&program);
    QVERIFY(o.claim(&mdi, QStringLiteral("an MDI line runs")));
    QVERIFY(!o.admitsManualMotion()); // a new holder starts unlent
}

STEPDECK_TEST_GUILESS_MAIN(TestMotionOwnership)
#include "tst_motionownership.moc"
