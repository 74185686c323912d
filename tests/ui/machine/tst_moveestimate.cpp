// The trapezoidal estimate of a positioning move: starts at the start speed, never passes
// the target, arrives exactly at the computed duration, and takes the triangular shape when
// the move is too short to reach the maximum speed.
#include "TestMain.h"
#include "machine/MoveEstimate.h"
#include <QtTest>

using stepdeck::ui::MoveEstimate;
using stepdeck::ui::MoveProfile;

class TestMoveEstimate : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void travelled_isMonotonicAndEndsAtTheTarget_data();
    void travelled_isMonotonicAndEndsAtTheTarget();
    void duration_matchesTheProfile();
    void invalidProfile_estimatesNothing();
};

void TestMoveEstimate::travelled_isMonotonicAndEndsAtTheTarget_data()
{
    QTest::addColumn<double>("distance");
    QTest::newRow("long, with cruise") << 20000.0;
    QTest::newRow("short, triangular") << 300.0;
    QTest::newRow("one step") << 1.0;
}

void TestMoveEstimate::travelled_isMonotonicAndEndsAtTheTarget()
{
    QFETCH(double, distance);
    const MoveProfile p{100, 5000, 4000};
    const double total = MoveEstimate::duration(distance, p);
    QVERIFY(total > 0);
    double last = 0;
    for (int i = 0; i <= 200; ++i) {
        const double s = MoveEstimate::travelled(distance, p, total * i / 200.0);
        QVERIFY2(s >= last - 1e-9, qPrintable(QString::number(i)));
        QVERIFY(s <= distance);
        last = s;
    }
    QVERIFY(qAbs(MoveEstimate::travelled(distance, p, total) - distance) < 1e-6);
    QCOMPARE(MoveEstimate::travelled(distance, p, total * 3), distance);
    QVERIFY(MoveEstimate::travelled(distance, p, total / 2) < distance);
}

void TestMoveEstimate::duration_matchesTheProfile()
{
    // 100 -> 5000 steps/s at 4000 steps/s^2: 1.225 s and 3123.75 steps each way; the rest of
    // 20000 steps at 5000 steps/s takes 2.7505 s.
    const MoveProfile p{100, 5000, 4000};
    QVERIFY(qAbs(MoveEstimate::duration(20000, p) - (2 * 1.225 + 13752.5 / 5000)) < 1e-9);
    QVERIFY(qAbs(MoveEstimate::travelled(20000, p, 1.225) - 3123.75) < 1e-6);
    // Triangular: 300 steps never reach 5000 steps/s; the peak is sqrt(100^2 + 4000 * 300).
    const double peak = std::sqrt(100.0 * 100 + 4000.0 * 300);
    QVERIFY(qAbs(MoveEstimate::duration(300, p) - 2 * (peak - 100) / 4000) < 1e-9);
}

void TestMoveEstimate::invalidProfile_estimatesNothing()
{
    QCOMPARE(MoveEstimate::travelled(1000, MoveProfile{}, 5), 0.0);
    QCOMPARE(MoveEstimate::travelled(1000, MoveProfile{100, 0, 1000}, 5), 0.0);
    QCOMPARE(MoveEstimate::duration(1000, MoveProfile{100, 1000, 0}), 0.0);
}

STEPDECK_TEST_MAIN(TestMoveEstimate)
#include "tst_moveestimate.moc"
