// CanonicalMove and MotionQueue (issue 30): a move's length, its point along the path and the
// rate each slot moves at per unit of feed, against geometry worked out by hand; the queue's
// bound.
#include "TestMain.h"
#include "motion/CanonicalMove.h"
#include "motion/MotionQueue.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck::motion;

class TestCanonicalMove : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void line_lengthPointsAndRates();
    void arc_quarterCircle_pointsOnTheCircleEndExact_data();
    void arc_quarterCircle_pointsOnTheCircleEndExact();
    void arc_helix_lengthCountsTheTravel();
    void invalid_eachReasonNamed_data();
    void invalid_eachReasonNamed();
    void queue_bounded_refusesWhenFullClearDropsAll();
};

namespace {

CanonicalMove quarterArc(double sweepSign)
{
    // Centre (10, 0), radius 10, from (0, 0) a quarter turn either way.
    CanonicalMove m;
    m.kind = CanonicalMove::Kind::Arc;
    m.axisCount = 3;
    m.start = {0, 0, 0};
    m.end = {10, sweepSign * 10, 0};
    m.feed = 5;
    ArcGeometry a;
    a.centre[0] = 10;
    a.centre[1] = 0;
    a.startRadius = a.endRadius = 10;
    a.startAngle = M_PI;
    a.sweep = -sweepSign * M_PI / 2; // to (10, 10): clockwise from the left
    m.arc = a;
    return m;
}

} // namespace

void TestCanonicalMove::line_lengthPointsAndRates()
{
    const CanonicalMove m = CanonicalMove::straight(3, {1, 2, 3}, {4, 6, 3}, 10, 7);
    QCOMPARE(m.length(), 5.0);
    const Position mid = m.at(2.5);
    QCOMPARE(mid[0], 2.5);
    QCOMPARE(mid[1], 4.0);
    QCOMPARE(mid[2], 3.0);
    QCOMPARE(m.at(99)[1], 6.0); // clamped to the end
    QCOMPARE(m.slotRatePerFeed(0), 0.6);
    QCOMPARE(m.slotRatePerFeed(1), 0.8);
    QCOMPARE(m.slotRatePerFeed(2), 0.0);
    QCOMPARE(m.line, 7);
}

void TestCanonicalMove::arc_quarterCircle_pointsOnTheCircleEndExact_data()
{
    QTest::addColumn<double>("sign");
    QTest::newRow("clockwise, to +Y") << 1.0;
    QTest::newRow("counter-clockwise, to -Y") << -1.0;
}

void TestCanonicalMove::arc_quarterCircle_pointsOnTheCircleEndExact()
{
    QFETCH(double, sign);
    const CanonicalMove m = quarterArc(sign);
    QVERIFY(m.invalidReason().isEmpty());
    QCOMPARE(m.length(), 10 * M_PI / 2);
    for (int i = 0; i <= 20; ++i) {
        const Position p = m.at(m.length() * i / 20);
        QVERIFY2(std::fabs(std::hypot(p[0] - 10, p[1]) - 10) < 1e-9,
                 qPrintable(QString::number(i)));
        QVERIFY(sign * p[1] >= -1e-12); // on its side of the X axis
    }
    const Position end = m.at(m.length());
    QCOMPARE(end[0], 10.0);
    QCOMPARE(end[1], sign * 10);
    // A plane slot moves at most radius x sweep / length = 1 unit per unit of path.
    QCOMPARE(m.slotRatePerFeed(0), 1.0);
    QCOMPARE(m.slotRatePerFeed(2), 0.0);
}

void TestCanonicalMove::arc_helix_lengthCountsTheTravel()
{
    CanonicalMove m = quarterArc(1);
    m.end[2] = -2 * M_PI; // a helix: Z goes down 2 pi while the plane turns 5 pi
    const double plane = 10 * M_PI / 2;
    QCOMPARE(m.length(), std::hypot(plane, 2 * M_PI));
    QCOMPARE(m.at(m.length() / 2)[2], -M_PI);
    QCOMPARE(m.slotRatePerFeed(2), 2 * M_PI / m.length());
}

void TestCanonicalMove::invalid_eachReasonNamed_data()
{
    QTest::addColumn<int>("fault");
    QTest::addColumn<QString>("reason");
    QTest::newRow("no axes") << 0 << "a move over 0 axes";
    QTest::newRow("not a number") << 1 << "not a number";
    QTest::newRow("no feed") << 2 << "without a feed rate";
    QTest::newRow("arc without centre") << 3 << "without its centre";
    QTest::newRow("arc in one slot") << 4 << "geometry is not valid";
}

void TestCanonicalMove::invalid_eachReasonNamed()
{
    QFETCH(int, fault);
    QFETCH(QString, reason);
    CanonicalMove m = quarterArc(1);
    switch (fault) {
    case 0:
        m.axisCount = 0;
        break;
    case 1:
        m.end[1] = std::nan("");
        break;
    case 2:
        m.feed = 0;
        break;
    case 3:
        m.arc.reset();
        break;
    default:
        m.arc->plane[1] = m.arc->plane[0];
        break;
    }
    QVERIFY2(m.invalidReason().contains(reason), qPrintable(m.invalidReason()));
}

void TestCanonicalMove::queue_bounded_refusesWhenFullClearDropsAll()
{
    MotionQueue q(3);
    for (int i = 1; i <= 3; ++i)
        QVERIFY(q.push(CanonicalMove::straight(1, {0}, {double(i)}, 1, i)));
    QVERIFY(q.isFull());
    QVERIFY(!q.push(CanonicalMove::straight(1, {0}, {4}, 1, 4)));
    QCOMPARE(q.size(), size_t(3));
    QCOMPARE(q.front().line, 1);
    q.pop();
    QCOMPARE(q.front().line, 2);
    QVERIFY(q.push(CanonicalMove::straight(1, {0}, {4}, 1, 4)));
    QCOMPARE(q.at(2).line, 4);
    q.clear();
    QVERIFY(q.isEmpty());
}

STEPDECK_TEST_GUILESS_MAIN(TestCanonicalMove)
#include "tst_canonicalmove.moc"
