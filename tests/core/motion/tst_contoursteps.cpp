// ContourSteps (issue 30, "one <DC2> stream per contour"): lines in every direction, circles,
// helices and chains laid on ticks. Each tick's position is compared with the ideal path worked
// out here (not with the source's own geometry): within half a step per axis, so within one
// step of the path; the path speed is the feed (the tick count is the path's time at F); no
// axis steps twice in a tick; the end is the programmed end exactly. Pulled in random chunks,
// with underruns, refusals and a feed override.
#include "TestMain.h"
#include "motion/ContourSteps.h"
#include <QRandomGenerator>
#include <QtTest>
#include <cmath>
#include <functional>

using namespace stepdeck::motion;

class TestContourSteps : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void line_anyDirection_onThePathAtTheFeed_data();
    void line_anyDirection_onThePathAtTheFeed();
    void arc_circleAndHelix_onTheCircleAtTheFeed_data();
    void arc_circleAndHelix_onTheCircleAtTheFeed();
    void chain_linesAndArcAtTheirFeeds_continuousEndExact();
    void pull_randomChunks_sameTicksAsAtOnce();
    void underrun_nextMoveLate_waitsThenSameTicks();
    void append_refusals_eachWithItsReason_data();
    void append_refusals_eachWithItsReason();
    void feedFactor_double_halfTheTicksForTheRest();
    void highestFeed_lineAlongTheFinestAxis();
    void stepLimits_lineBeyond_endsAtTheLastTickInsideFaultSaysWhy();
    void stepLimits_twoSources_theTighterHolds();
    void invertedAxis_negativeScale_stepsTheOtherWayRateBounded();
    void origin_offTheStepGrid_everyTickTheNearestStep();
    void feedFactor_beyondAMovesTick_thatMoveAtOneStepPerTick();
    void movesDoneAndQueuedSeconds_followTheTicks();
};

namespace {

constexpr double kTickRate = 2000;

StepScale scale3(double x, double y, double z)
{
    StepScale s;
    s.axisCount = 3;
    s.stepsPerUnit = {x, y, z};
    return s;
}

// Every tick of a stream, pulled `chunk` at a time (0: random 1..50), as positions in steps.
QList<StepPosition> pullAll(ContourSteps& c, int chunk = 0, quint32 seed = 1)
{
    QRandomGenerator random(seed);
    QList<StepPosition> out;
    StepPosition at = c.steps();
    StepTick ticks[64];
    for (;;) {
        const int want = chunk > 0 ? chunk : 1 + random.bounded(50);
        const int n = c.pull(ticks, want);
        for (int i = 0; i < n; ++i) {
            for (int a = 0; a < kMaxAxes; ++a)
                at[size_t(a)] += ticks[i].step[size_t(a)];
            out << at;
        }
        if (n < want)
            return out;
    }
}

// The largest distance (in steps, per axis) between a tick and ideal(seconds) in units, both
// measured from origin (units) and originSteps (steps); by default both are 0: whole steps.
double worstDeviation(const QList<StepPosition>& ticks, const StepScale& s,
                      const std::function<Position(double)>& ideal, const Position& origin = {},
                      const StepPosition& originSteps = {})
{
    double worst = 0;
    for (int k = 0; k < ticks.size(); ++k) {
        const Position p = ideal(double(k + 1) / kTickRate);
        for (int a = 0; a < s.axisCount; ++a) {
            const double laid = double(ticks.at(k)[size_t(a)] - originSteps[size_t(a)]);
            const double wanted = (p[size_t(a)] - origin[size_t(a)]) * s.stepsPerUnit[size_t(a)];
            worst = std::max(worst, std::fabs(laid - wanted));
        }
    }
    return worst;
}

bool singleSteps(const QList<StepPosition>& ticks, const StepPosition& from)
{
    StepPosition before = from;
    for (const StepPosition& p : ticks) {
        for (int a = 0; a < kMaxAxes; ++a)
            if (std::abs(p[size_t(a)] - before[size_t(a)]) > 1)
                return false;
        before = p;
    }
    return true;
}

CanonicalMove circle(double cx, double cy, double r, double startAngle, double sweep,
                     double zTravel, double feed)
{
    CanonicalMove m;
    m.kind = CanonicalMove::Kind::Arc;
    m.axisCount = 3;
    m.start = {cx + r * std::cos(startAngle), cy + r * std::sin(startAngle), 0};
    m.end = {cx + r * std::cos(startAngle + sweep), cy + r * std::sin(startAngle + sweep), zTravel};
    m.feed = feed;
    ArcGeometry a;
    a.centre[0] = cx;
    a.centre[1] = cy;
    a.startRadius = a.endRadius = r;
    a.startAngle = startAngle;
    a.sweep = sweep;
    m.arc = a;
    return m;
}

} // namespace

void TestContourSteps::line_anyDirection_onThePathAtTheFeed_data()
{
    QTest::addColumn<double>("degrees");
    QTest::addColumn<double>("yStepsPerMm");
    for (int d = 0; d < 360; d += 15) {
        QTest::addRow("%d deg, 100/100", d) << double(d) << 100.0;
        QTest::addRow("%d deg, 100/250", d) << double(d) << 250.0;
    }
}

void TestContourSteps::line_anyDirection_onThePathAtTheFeed()
{
    QFETCH(double, degrees);
    QFETCH(double, yStepsPerMm);
    const StepScale s = scale3(100, yStepsPerMm, 400);
    const double length = 20, feed = 5; // mm, mm/s: 4 s
    const double a = degrees * M_PI / 180;
    const Position end{length * std::cos(a), length * std::sin(a), 0};
    ContourSteps c(s, {}, {}, kTickRate);
    QVERIFY(c.append(CanonicalMove::straight(3, {}, end, feed, 1)).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    QVERIFY(c.finished());
    // The path's time at F, tick by tick: 4 s at 2000 ticks/s (the last tick may be short).
    QVERIFY2(std::abs(ticks.size() - 8000) <= 1, qPrintable(QString::number(ticks.size())));
    const double deviation = worstDeviation(ticks, s, [&](double t) {
        const double along = std::min(feed * t, length);
        return Position{along * std::cos(a), along * std::sin(a), 0};
    });
    QVERIFY2(deviation <= 0.5 + 1e-6, qPrintable(QString::number(deviation)));
    QVERIFY(singleSteps(ticks, {}));
    QCOMPARE(c.clampedSteps(), qint64(0));
    QCOMPARE(ticks.last()[0], std::llround(end[0] * 100));
    QCOMPARE(ticks.last()[1], std::llround(end[1] * yStepsPerMm));
    QCOMPARE(ticks.last()[2], qint64(0));
}

void TestContourSteps::arc_circleAndHelix_onTheCircleAtTheFeed_data()
{
    QTest::addColumn<double>("startAngle");
    QTest::addColumn<double>("sweep");
    QTest::addColumn<double>("zTravel");
    QTest::newRow("50 mm circle, counter-clockwise") << 0.0 << 2 * M_PI << 0.0;
    QTest::newRow("50 mm circle, clockwise") << M_PI / 3 << -2 * M_PI << 0.0;
    QTest::newRow("quarter, clockwise") << M_PI / 2 << -M_PI / 2 << 0.0;
    QTest::newRow("helix, 1.5 turns, 3 mm down") << M_PI << 3 * M_PI << -3.0;
}

void TestContourSteps::arc_circleAndHelix_onTheCircleAtTheFeed()
{
    QFETCH(double, startAngle);
    QFETCH(double, sweep);
    QFETCH(double, zTravel);
    const StepScale s = scale3(100, 100, 400);
    const double r = 25, cx = 30, cy = 40, feed = 10;
    const CanonicalMove arc = circle(cx, cy, r, startAngle, sweep, zTravel, feed);
    const StepPosition from{std::llround(arc.start[0] * 100), std::llround(arc.start[1] * 100), 0};
    ContourSteps c(s, arc.start, from, kTickRate);
    QVERIFY(c.append(arc).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    const double length = std::hypot(r * std::fabs(sweep), zTravel);
    const int expected = int(std::ceil(length / feed * kTickRate - 1e-9));
    QVERIFY2(std::abs(ticks.size() - expected) <= 1,
             qPrintable(QStringLiteral("%1 ticks, %2 expected").arg(ticks.size()).arg(expected)));
    // Every tick within half a step (per axis) of the true helix at that time, and within one
    // step of the circle (its distance from the centre). The board starts on the step nearest
    // the arc's start, and every tick is the step nearest its point (ContourSteps::stepsAt),
    // so the ticks are compared in whole steps, not from the start.
    const double deviation = worstDeviation(ticks, s, [&](double t) {
        const double u = std::min(feed * t / length, 1.0);
        const double angle = startAngle + u * sweep;
        return Position{cx + r * std::cos(angle), cy + r * std::sin(angle), u * zTravel};
    });
    QVERIFY2(deviation <= 0.5 + 1e-6, qPrintable(QString::number(deviation)));
    double radial = 0;
    for (const StepPosition& p : ticks)
        radial =
            std::max(radial, std::fabs(std::hypot(p[0] - cx * 100, p[1] - cy * 100) - r * 100));
    QVERIFY2(radial <= 1.0, qPrintable(QString::number(radial)));
    QVERIFY(singleSteps(ticks, from));
    QCOMPARE(ticks.last()[0], from[0] + std::llround((arc.end[0] - arc.start[0]) * 100));
    QCOMPARE(ticks.last()[1], from[1] + std::llround((arc.end[1] - arc.start[1]) * 100));
    QCOMPARE(ticks.last()[2], std::llround(zTravel * 400));
}

void TestContourSteps::chain_linesAndArcAtTheirFeeds_continuousEndExact()
{
    const StepScale s = scale3(100, 100, 400);
    // A line at 5 mm/s, a half circle at 10 mm/s, a line back at 2.5 mm/s.
    const CanonicalMove in = CanonicalMove::straight(3, {0, 0, 0}, {10, 0, 0}, 5, 1);
    const CanonicalMove turn = circle(10, 5, 5, -M_PI / 2, M_PI, 0, 10);
    CanonicalMove arc = turn;
    arc.line = 2;
    const CanonicalMove back = CanonicalMove::straight(3, arc.end, {0, 10, 0}, 2.5, 3);
    ContourSteps c(s, {}, {}, kTickRate);
    for (const CanonicalMove& m : {in, arc, back})
        QVERIFY(c.append(m).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    // Time along the path: 2 s + (5 pi / 10) s + 4 s, tick for tick.
    const double seconds = 2 + 5 * M_PI / 10 + 4;
    QVERIFY2(std::abs(ticks.size() - seconds * kTickRate) <= 1.0,
             qPrintable(QString::number(ticks.size())));
    const double deviation = worstDeviation(ticks, s, [&](double t) {
        if (t <= 2)
            return Position{5 * t, 0, 0};
        if (t <= 2 + M_PI / 2) {
            const double angle = -M_PI / 2 + (t - 2) * 10 / 5;
            return Position{10 + 5 * std::cos(angle), 5 + 5 * std::sin(angle), 0};
        }
        return Position{std::max(10 - 2.5 * (t - 2 - M_PI / 2), 0.0), 10, 0};
    });
    QVERIFY2(deviation <= 0.5 + 1e-6, qPrintable(QString::number(deviation)));
    QVERIFY(singleSteps(ticks, {}));
    QCOMPARE(ticks.last(), (StepPosition{0, 1000, 0}));
    QCOMPARE(c.currentLine(), 3);
}

void TestContourSteps::pull_randomChunks_sameTicksAsAtOnce()
{
    const StepScale s = scale3(100, 100, 400);
    const auto make = [&] {
        auto c = std::make_unique<ContourSteps>(s, Position{}, StepPosition{}, kTickRate);
        const QString a = c->append(CanonicalMove::straight(3, {}, {3, 4, 0}, 7, 1));
        const QString b = c->append(circle(3 - 2, 4, 2, 0, M_PI * 1.5, 0.5, 9));
        if (!a.isEmpty() || !b.isEmpty())
            qFatal("refused: %s %s", qPrintable(a), qPrintable(b));
        c->close();
        return c;
    };
    auto once = make();
    const QList<StepPosition> reference = pullAll(*once, 64);
    for (quint32 seed : {1u, 2u, 3u}) {
        auto chunked = make();
        QCOMPARE(pullAll(*chunked, 0, seed), reference);
    }
}

void TestContourSteps::underrun_nextMoveLate_waitsThenSameTicks()
{
    const StepScale s = scale3(100, 100, 400);
    const CanonicalMove first = CanonicalMove::straight(3, {}, {2, 0, 0}, 4, 1);
    const CanonicalMove second = CanonicalMove::straight(3, {2, 0, 0}, {2, 3, 0}, 4, 2);
    ContourSteps both(s, {}, {}, kTickRate);
    QVERIFY(both.append(first).isEmpty());
    QVERIFY(both.append(second).isEmpty());
    both.close();
    const QList<StepPosition> reference = pullAll(both, 64);

    ContourSteps late(s, {}, {}, kTickRate);
    QVERIFY(late.append(first).isEmpty());
    QList<StepPosition> ticks = pullAll(late, 64);
    // It stops short of the first move's end (0.5 s, 1000 ticks): the tick that would cross
    // into the next move waits for it.
    QVERIFY2(ticks.size() >= 999 && ticks.size() <= 1000,
             qPrintable(QString::number(ticks.size())));
    QVERIFY(!late.finished());
    StepTick none[8];
    QCOMPARE(late.pull(none, 8), 0);
    QVERIFY(late.append(second).isEmpty());
    late.close();
    ticks += pullAll(late, 64);
    QCOMPARE(ticks, reference);
    QVERIFY(late.finished());
}

void TestContourSteps::append_refusals_eachWithItsReason_data()
{
    QTest::addColumn<int>("fault");
    QTest::addColumn<QString>("reason");
    QTest::newRow("rapid") << 0 << "a rapid is not part of a contour";
    QTest::newRow("too fast") << 1 << "highest feed 20 unit/s";
    QTest::newRow("elsewhere") << 2 << "does not start where the contour stands";
    QTest::newRow("closed") << 3 << "the contour is closed";
    QTest::newRow("queue full") << 4 << "queue is full";
    QTest::newRow("axes") << 5 << "a move over 2 axes in a stream of 3";
}

void TestContourSteps::append_refusals_eachWithItsReason()
{
    QFETCH(int, fault);
    QFETCH(QString, reason);
    ContourSteps c(scale3(100, 100, 400), {}, {}, kTickRate, 1.0, 2);
    CanonicalMove m = CanonicalMove::straight(3, {}, {10, 0, 0}, 5, 4);
    switch (fault) {
    case 0:
        m.kind = CanonicalMove::Kind::Rapid;
        break;
    case 1:
        m.feed = 25; // 2500 steps/s on X: past 2000 ticks/s
        break;
    case 2:
        m.start[1] = 0.01;
        break;
    case 3:
        c.close();
        break;
    case 4:
        QVERIFY(c.append(CanonicalMove::straight(3, {}, {1, 0, 0}, 5, 1)).isEmpty());
        QVERIFY(c.append(CanonicalMove::straight(3, {1, 0, 0}, {2, 0, 0}, 5, 2)).isEmpty());
        m.start = {2, 0, 0};
        break;
    default:
        m.axisCount = 2;
        break;
    }
    const QString why = c.append(m);
    QVERIFY2(why.contains(reason), qPrintable(why));
    QCOMPARE(c.steps(), StepPosition{}); // nothing laid
}

void TestContourSteps::feedFactor_double_halfTheTicksForTheRest()
{
    const StepScale s = scale3(100, 100, 400);
    ContourSteps c(s, {}, {}, kTickRate, 2.0);
    QVERIFY(c.append(CanonicalMove::straight(3, {}, {8, 0, 0}, 4, 1)).isEmpty()); // 2 s at F
    c.close();
    StepTick ticks[1000];
    QCOMPARE(c.pull(ticks, 1000), 1000); // 0.5 s: 2 mm
    QCOMPARE(c.steps()[0], qint64(200));
    c.setFeedFactor(2.0);
    const QList<StepPosition> rest = pullAll(c, 64);
    QVERIFY(std::abs(rest.size() - 1500) <= 1); // 6 mm at 8 mm/s: 0.75 s
    QCOMPARE(rest.last()[0], qint64(800));
    QVERIFY(singleSteps(rest, {200, 0, 0}));
    c.setFeedFactor(5.0);
    QCOMPARE(c.feedFactor(), 2.0); // at most what the stream's tick allows
    c.setFeedFactor(0.01);
    QCOMPARE(c.feedFactor(), 0.1);
}

void TestContourSteps::highestFeed_lineAlongTheFinestAxis()
{
    const StepScale s = scale3(100, 250, 400);
    const CanonicalMove alongX = CanonicalMove::straight(3, {}, {10, 0, 0}, 1, 1);
    const CanonicalMove alongY = CanonicalMove::straight(3, {}, {0, 10, 0}, 1, 1);
    QVERIFY(std::fabs(ContourSteps::highestFeed(alongX, s, kTickRate) - 20) < 1e-6);
    QVERIFY(std::fabs(ContourSteps::highestFeed(alongY, s, kTickRate) - 8) < 1e-6);
}

void TestContourSteps::stepLimits_lineBeyond_endsAtTheLastTickInsideFaultSaysWhy()
{
    ContourSteps c(scale3(100, 100, 400), {}, {100, 0, 0}, kTickRate);
    c.setStepLimits(0, QStringLiteral("X"), 0, 600);
    QVERIFY(c.append(CanonicalMove::straight(3, {}, {10, 0, 0}, 5, 3)).isEmpty());
    QVERIFY(c.append(CanonicalMove::straight(3, {10, 0, 0}, {10, 5, 0}, 5, 4)).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    QVERIFY(c.finished());
    QCOMPARE(ticks.last()[0], qint64(600)); // 500 steps from 100: the limit, not beyond
    for (const StepPosition& p : ticks)
        QVERIFY(p[0] <= 600);
    QVERIFY2(c.fault().contains(QStringLiteral("line 3 would take axis X to 601 steps, beyond "
                                               "its soft limit 600")),
             qPrintable(c.fault()));
    StepTick none[4];
    QCOMPARE(c.pull(none, 4), 0);
    QVERIFY(!c.append(CanonicalMove::straight(3, {10, 5, 0}, {0, 5, 0}, 5, 5)).isEmpty());
}

// The machine's soft limits and the controller's own both hold: the second call narrows.
void TestContourSteps::stepLimits_twoSources_theTighterHolds()
{
    ContourSteps c(scale3(100, 100, 400), {}, {}, kTickRate);
    c.setStepLimits(0, QStringLiteral("X"), -1000, 300);
    c.setStepLimits(0, QStringLiteral("X"), -50, 800);
    QVERIFY(c.append(CanonicalMove::straight(3, {}, {5, 0, 0}, 5, 1)).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    QCOMPARE(ticks.last()[0], qint64(300));
    QVERIFY2(c.fault().contains(QStringLiteral("beyond its soft limit 300")),
             qPrintable(c.fault()));
}

// An inverted axis counts -100 steps/mm: a move of +2 mm is -200 steps, one step per tick at
// most (its rate bound uses the scale's size), and a feed beyond the tick is refused as on an
// axis that is not inverted.
void TestContourSteps::invertedAxis_negativeScale_stepsTheOtherWayRateBounded()
{
    const StepScale s = scale3(-100, 100, 400);
    ContourSteps c(s, {}, {}, kTickRate);
    QVERIFY(!c.append(CanonicalMove::straight(3, {}, {2, 0, 0}, 25, 1)).isEmpty()); // 2500/s
    QVERIFY(c.append(CanonicalMove::straight(3, {}, {2, 0, 0}, 10, 1)).isEmpty());
    QVERIFY(!c.append(CanonicalMove::straight(3, {0.5, 0, 0}, {3, 0, 0}, 10, 2)).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    QCOMPARE(ticks.last()[0], qint64(-200));
    QVERIFY(singleSteps(ticks, {}));
    QVERIFY(std::abs(ticks.size() - 400) <= 1); // 2 mm at 10 mm/s: 0.2 s of 2000 ticks/s
    for (qsizetype k = 0; k < ticks.size(); ++k)
        QVERIFY(std::fabs(double(ticks.at(k)[0]) + double(k + 1) * 10 / kTickRate * 100) <=
                0.5 + 1e-9);
}

// A contour starting off the step grid (X at 0.004 mm, 100 steps/mm: the board at step 0):
// every tick is the step nearest the ideal point itself, as a positioning move to it would end,
// and the end is the step nearest the end (1.004 mm -> 100, not 0 + round(100.0)).
void TestContourSteps::origin_offTheStepGrid_everyTickTheNearestStep()
{
    ContourSteps c(scale3(100, 100, 400), {0.004, 0, 0}, {}, kTickRate);
    QVERIFY(c.append(CanonicalMove::straight(3, {0.004, 0, 0}, {1.006, 0, 0}, 5, 1)).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    QCOMPARE(ticks.last()[0], qint64(101)); // round(100.6)
    for (qsizetype k = 0; k < ticks.size(); ++k) {
        const double ideal = std::min(0.004 + double(k + 1) * 5 / kTickRate, 1.006) * 100;
        QVERIFY(std::fabs(double(ticks.at(k)[0]) - ideal) <= 0.5 + 1e-9);
    }
}

// At 200 %: a move at 5 mm/s on X (500 steps/s at 100 steps/mm) runs at 10 mm/s; one at
// 15 mm/s (1500 steps/s, taken at 100 %) can only go to 20 mm/s at 2000 ticks/s: it runs
// there, one step per tick, and no tick carries two steps.
void TestContourSteps::feedFactor_beyondAMovesTick_thatMoveAtOneStepPerTick()
{
    ContourSteps c(scale3(100, 100, 400), {}, {}, kTickRate, 2.0);
    c.setFeedFactor(2.0);
    QVERIFY(c.append(CanonicalMove::straight(3, {}, {1, 0, 0}, 5, 1)).isEmpty());
    QVERIFY(c.append(CanonicalMove::straight(3, {1, 0, 0}, {3, 0, 0}, 15, 2)).isEmpty());
    c.close();
    const QList<StepPosition> ticks = pullAll(c);
    QVERIFY(singleSteps(ticks, {}));
    QCOMPARE(c.clampedSteps(), qint64(0));
    // 1 mm at 10 mm/s (200 ticks), then 2 mm at 20 mm/s (200 ticks).
    QVERIFY2(std::abs(ticks.size() - 400) <= 1, qPrintable(QString::number(ticks.size())));
    QCOMPARE(ticks.last()[0], qint64(300));
}

void TestContourSteps::movesDoneAndQueuedSeconds_followTheTicks()
{
    ContourSteps c(scale3(100, 100, 400), {}, {}, kTickRate);
    QVERIFY(c.append(CanonicalMove::straight(3, {}, {1, 0, 0}, 5, 1)).isEmpty());        // 0.2 s
    QVERIFY(c.append(CanonicalMove::straight(3, {1, 0, 0}, {1, 0, 0}, 5, 2)).isEmpty()); // 0 s
    QVERIFY(c.append(CanonicalMove::straight(3, {1, 0, 0}, {1, 2, 0}, 5, 3)).isEmpty()); // 0.4 s
    QCOMPARE(c.movesTaken(), qint64(3));
    QCOMPARE(c.movesDone(), qint64(1)); // the empty move
    QVERIFY(std::fabs(c.queuedSeconds() - 0.6) < 1e-9);
    StepTick ticks[500];
    QCOMPARE(c.pull(ticks, 500), 500); // 0.25 s: into the third move
    QCOMPARE(c.movesDone(), qint64(2));
    QVERIFY(std::fabs(c.queuedSeconds() - 0.35) < 1e-6);
    c.close();
    pullAll(c);
    QCOMPARE(c.movesDone(), qint64(3));
    QCOMPARE(c.queuedSeconds(), 0.0);
}

STEPDECK_TEST_GUILESS_MAIN(TestContourSteps)
#include "tst_contoursteps.moc"
