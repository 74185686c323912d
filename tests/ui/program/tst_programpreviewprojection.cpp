// PreviewProjection (issue 29): each view puts a known point where its axes say, the isometric
// view keeps every axis at one scale, and a view is offered only where the machine has its
// axes. PreviewOrientation (issue 47 item 14): the standard views are its presets (the old
// points, the isometric one at the true projection's scale), a quarter turn puts X where Y
// was, the elevation stays within +-90 and the azimuth within (-180, 180], and every
// orientation is a rotation (no length across the screen changes).
#include "PreviewViewKindMetaType.h"
#include "TestMain.h"
#include "program/PreviewProjection.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck::ui;

class TestPreviewProjection : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void project_knownPoint_landsWhereTheViewsAxesSay_data();
    void project_knownPoint_landsWhereTheViewsAxesSay();
    void project_isometric_unitAlongEachAxisIsOneLong_data();
    void project_isometric_unitAlongEachAxisIsOneLong();
    void available_machineAxes_onlyViewsOfItsAxes_data();
    void available_machineAxes_onlyViewsOfItsAxes();
    void settingsName_roundTrip_sameView();
    void orientation_presets_pointsWhereTheOldViewsPutThem_data();
    void orientation_presets_pointsWhereTheOldViewsPutThem();
    void orientation_presets_knownAsPresets();
    void orbit_azimuth90_mapsXOntoTheOldYDirection_data();
    void orbit_azimuth90_mapsXOntoTheOldYDirection();
    void orbit_turned_elevationClampedAzimuthWrapped_data();
    void orbit_turned_elevationClampedAzimuthWrapped();
    void orbit_anyOrientation_isARotation_data();
    void orbit_anyOrientation_isARotation();
};

namespace {
bool near(const QPointF& a, const QPointF& b, double tolerance = 1e-12)
{
    return std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
}
QString text(const QPointF& p)
{
    return QStringLiteral("%1, %2").arg(p.x(), 0, 'g', 17).arg(p.y(), 0, 'g', 17);
}
} // namespace

void TestPreviewProjection::project_knownPoint_landsWhereTheViewsAxesSay_data()
{
    QTest::addColumn<PreviewViewKind>("kind");
    QTest::addColumn<QPointF>("expected");
    const double c = std::sqrt(3.0) / 2;
    // The point X 3, Y 5, Z -2.
    QTest::addRow("top") << PreviewViewKind::Top << QPointF(3, 5);
    QTest::addRow("front") << PreviewViewKind::Front << QPointF(3, -2);
    QTest::addRow("side") << PreviewViewKind::Side << QPointF(5, -2);
    QTest::addRow("isometric") << PreviewViewKind::Isometric
                               << QPointF((3 - 5) * c, (3 + 5) * 0.5 - 2);
}

void TestPreviewProjection::project_knownPoint_landsWhereTheViewsAxesSay()
{
    QFETCH(PreviewViewKind, kind);
    QFETCH(QPointF, expected);
    const QPointF p = PreviewProjection::project(kind, {3, 5, -2});
    QVERIFY2(std::abs(p.x() - expected.x()) < 1e-12 && std::abs(p.y() - expected.y()) < 1e-12,
             qPrintable(QStringLiteral("%1, %2").arg(p.x()).arg(p.y())));
}

void TestPreviewProjection::project_isometric_unitAlongEachAxisIsOneLong_data()
{
    QTest::addColumn<int>("axis");
    QTest::addColumn<double>("angleDegrees"); // of the axis' direction on the plane
    QTest::addRow("X") << 0 << 30.0;
    QTest::addRow("Y") << 1 << 150.0;
    QTest::addRow("Z") << 2 << 90.0;
}

void TestPreviewProjection::project_isometric_unitAlongEachAxisIsOneLong()
{
    QFETCH(int, axis);
    QFETCH(double, angleDegrees);
    PreviewPosition unit{};
    unit[size_t(axis)] = 1;
    const QPointF p = PreviewProjection::project(PreviewViewKind::Isometric, unit);
    QCOMPARE(qRound(std::hypot(p.x(), p.y()) * 1e9), qRound(1e9));
    QCOMPARE(qRound(std::atan2(p.y(), p.x()) * 180 / M_PI * 1e6), qRound(angleDegrees * 1e6));
}

void TestPreviewProjection::available_machineAxes_onlyViewsOfItsAxes_data()
{
    QTest::addColumn<QStringList>("axes");
    QTest::addColumn<QList<bool>>("available"); // top, front, side, isometric
    QTest::addRow("XYZ") << QStringList{"X", "Y", "Z"} << QList<bool>{true, true, true, true};
    QTest::addRow("XY") << QStringList{"X", "Y"} << QList<bool>{true, false, false, false};
    QTest::addRow("XZ") << QStringList{"X", "Z", "A"} << QList<bool>{false, true, false, false};
    QTest::addRow("X") << QStringList{"X"} << QList<bool>{false, false, false, false};
}

void TestPreviewProjection::available_machineAxes_onlyViewsOfItsAxes()
{
    QFETCH(QStringList, axes);
    QFETCH(QList<bool>, available);
    for (size_t i = 0; i < PreviewProjection::kAll.size(); ++i) {
        const PreviewViewKind kind = PreviewProjection::kAll[i];
        QCOMPARE(PreviewProjection::available(kind, axes), available.at(qsizetype(i)));
        // An unavailable view says which axis it lacks.
        QCOMPARE(PreviewProjection::unavailableReason(kind, axes).isEmpty(),
                 available.at(qsizetype(i)));
    }
    if (!available.at(1))
        QVERIFY(PreviewProjection::unavailableReason(PreviewViewKind::Front, axes)
                    .contains(axes.contains("X") ? QStringLiteral("Z") : QStringLiteral("X")));
}

void TestPreviewProjection::settingsName_roundTrip_sameView()
{
    for (PreviewViewKind kind : PreviewProjection::kAll)
        QCOMPARE(PreviewProjection::fromSettingsName(PreviewProjection::settingsName(kind),
                                                     PreviewViewKind::Top),
                 kind);
    QCOMPARE(PreviewProjection::fromSettingsName(QStringLiteral("nonsense"), PreviewViewKind::Side),
             PreviewViewKind::Side);
}

void TestPreviewProjection::orientation_presets_pointsWhereTheOldViewsPutThem_data()
{
    QTest::addColumn<PreviewViewKind>("kind");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<double>("z");
    QTest::addColumn<QPointF>("old"); // where PreviewProjection::project put it (issue 29)
    // The isometric preset is the true projection: the old isometric drawing (every axis at
    // full length) at sqrt(2/3) of its size, the same picture once fitted.
    QTest::addColumn<double>("scale");
    const double c = std::sqrt(3.0) / 2;
    const double iso = std::sqrt(2.0 / 3.0);
    QTest::addRow("top") << PreviewViewKind::Top << 3.0 << 5.0 << -2.0 << QPointF(3, 5) << 1.0;
    // Z has no influence at all on the top view (not cos 90 = 6e-17 of it).
    QTest::addRow("top, far Z") << PreviewViewKind::Top << -7.25 << 0.5 << 1e9
                                << QPointF(-7.25, 0.5) << 1.0;
    QTest::addRow("front") << PreviewViewKind::Front << 3.0 << 5.0 << -2.0 << QPointF(3, -2) << 1.0;
    QTest::addRow("front, far Y") << PreviewViewKind::Front << 1.5 << -1e9 << 4.0 << QPointF(1.5, 4)
                                  << 1.0;
    QTest::addRow("side") << PreviewViewKind::Side << 3.0 << 5.0 << -2.0 << QPointF(5, -2) << 1.0;
    QTest::addRow("side, far X") << PreviewViewKind::Side << 1e9 << -3.0 << 0.125
                                 << QPointF(-3, 0.125) << 1.0;
    QTest::addRow("isometric") << PreviewViewKind::Isometric << 3.0 << 5.0 << -2.0
                               << QPointF((3 - 5) * c, (3 + 5) * 0.5 - 2) << iso;
    QTest::addRow("isometric, unit X")
        << PreviewViewKind::Isometric << 1.0 << 0.0 << 0.0 << QPointF(c, 0.5) << iso;
    QTest::addRow("isometric, unit Z")
        << PreviewViewKind::Isometric << 0.0 << 0.0 << 1.0 << QPointF(0, 1) << iso;
}

void TestPreviewProjection::orientation_presets_pointsWhereTheOldViewsPutThem()
{
    QFETCH(PreviewViewKind, kind);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(double, z);
    QFETCH(QPointF, old);
    QFETCH(double, scale);
    const PreviewPosition p{x, y, z};
    // The old projection itself is unchanged.
    QVERIFY2(near(PreviewProjection::project(kind, p), old),
             qPrintable(text(PreviewProjection::project(kind, p))));
    const QPointF turned = PreviewOrientation::of(kind).project(p);
    if (scale == 1.0) // exactly (QPointF's == is fuzzy)
        QVERIFY2(turned.x() == old.x() && turned.y() == old.y(), qPrintable(text(turned)));
    else
        QVERIFY2(near(turned, old * scale, 1e-12), qPrintable(text(turned)));
}

void TestPreviewProjection::orientation_presets_knownAsPresets()
{
    for (PreviewViewKind kind : PreviewProjection::kAll) {
        QVERIFY(PreviewOrientation::of(kind).preset() == kind);
        QVERIFY(!PreviewOrientation::of(kind).turned(0.5, 0).preset());
    }
    QVERIFY(PreviewOrientation() == PreviewOrientation::of(PreviewViewKind::Top));
    QCOMPARE(qRound(PreviewOrientation::isometricElevation() * 1e4), 352644); // 35.2644 degrees
}

void TestPreviewProjection::orbit_azimuth90_mapsXOntoTheOldYDirection_data()
{
    QTest::addColumn<PreviewViewKind>("from");
    QTest::addColumn<double>("azimuth"); // turned by
    QTest::addColumn<int>("axis");
    QTest::addColumn<QPointF>("expected"); // where the unit along axis lands
    // Seen from above, a quarter turn (counterclockwise) puts X where the top view had Y (up)
    // and Y where it had -X.
    QTest::addRow("top, X after +90") << PreviewViewKind::Top << 90.0 << 0 << QPointF(0, 1);
    QTest::addRow("top, Y after +90") << PreviewViewKind::Top << 90.0 << 1 << QPointF(-1, 0);
    QTest::addRow("top, X after -90") << PreviewViewKind::Top << -90.0 << 0 << QPointF(0, -1);
    QTest::addRow("top, X after 180") << PreviewViewKind::Top << 180.0 << 0 << QPointF(-1, 0);
    QTest::addRow("top, Z after 90") << PreviewViewKind::Top << 90.0 << 2 << QPointF(0, 0);
    // From the front, a quarter turn back is the side view: Y to the right.
    QTest::addRow("front, Y after -90") << PreviewViewKind::Front << -90.0 << 1 << QPointF(1, 0);
    QTest::addRow("front, X after +90") << PreviewViewKind::Front << 90.0 << 0 << QPointF(0, 0);
}

void TestPreviewProjection::orbit_azimuth90_mapsXOntoTheOldYDirection()
{
    QFETCH(PreviewViewKind, from);
    QFETCH(double, azimuth);
    QFETCH(int, axis);
    QFETCH(QPointF, expected);
    PreviewPosition unit{};
    unit[size_t(axis)] = 1;
    const QPointF p = PreviewOrientation::of(from).turned(azimuth, 0).project(unit);
    QVERIFY2(near(p, expected), qPrintable(text(p)));
}

void TestPreviewProjection::orbit_turned_elevationClampedAzimuthWrapped_data()
{
    QTest::addColumn<double>("azimuth");   // from
    QTest::addColumn<double>("elevation"); // from
    QTest::addColumn<double>("turnAzimuth");
    QTest::addColumn<double>("turnElevation");
    QTest::addColumn<double>("expectedAzimuth");
    QTest::addColumn<double>("expectedElevation");
    QTest::addRow("within") << 10.0 << 20.0 << 15.0 << -5.0 << 25.0 << 15.0;
    QTest::addRow("over the top") << 0.0 << 80.0 << 0.0 << 30.0 << 0.0 << 90.0;
    QTest::addRow("under the bottom") << 0.0 << -10.0 << 0.0 << -200.0 << 0.0 << -90.0;
    QTest::addRow("at the top, further") << 0.0 << 90.0 << 0.0 << 0.5 << 0.0 << 90.0;
    QTest::addRow("azimuth past 180") << 170.0 << 0.0 << 20.0 << 0.0 << -170.0 << 0.0;
    QTest::addRow("azimuth past -180") << -170.0 << 0.0 << -30.0 << 0.0 << 160.0 << 0.0;
    QTest::addRow("azimuth -180 is 180") << 0.0 << 0.0 << -180.0 << 0.0 << 180.0 << 0.0;
    QTest::addRow("many turns") << 0.0 << 0.0 << 3 * 360.0 + 45 << 0.0 << 45.0 << 0.0;
}

void TestPreviewProjection::orbit_turned_elevationClampedAzimuthWrapped()
{
    QFETCH(double, azimuth);
    QFETCH(double, elevation);
    QFETCH(double, turnAzimuth);
    QFETCH(double, turnElevation);
    QFETCH(double, expectedAzimuth);
    QFETCH(double, expectedElevation);
    const PreviewOrientation o =
        PreviewOrientation(azimuth, elevation).turned(turnAzimuth, turnElevation);
    QCOMPARE(o.azimuth(), expectedAzimuth);
    QCOMPARE(o.elevation(), expectedElevation);
    // Clamped at +-90: looking straight down (or up), Z has no influence.
    if (std::abs(expectedElevation) == 90)
        QCOMPARE(o.project({2, 3, 1e6}), o.project({2, 3, 0}));
}

void TestPreviewProjection::orbit_anyOrientation_isARotation_data()
{
    QTest::addColumn<double>("azimuth");
    QTest::addColumn<double>("elevation");
    QTest::addRow("isometric") << 45.0 << PreviewOrientation::isometricElevation();
    QTest::addRow("odd angles") << -123.4 << 17.9;
    QTest::addRow("from below") << 77.0 << -60.0;
    QTest::addRow("top, turned") << 33.0 << 90.0;
}

void TestPreviewProjection::orbit_anyOrientation_isARotation()
{
    QFETCH(double, azimuth);
    QFETCH(double, elevation);
    const PreviewOrientation o(azimuth, elevation);
    // The screen's right and up, as the images of the three unit axes: both of length one and
    // at right angles (an orthographic view of a turned body, one scale across the screen).
    double rightLength = 0, upLength = 0, dot = 0;
    for (size_t axis = 0; axis < 3; ++axis) {
        PreviewPosition unit{};
        unit[axis] = 1;
        const QPointF p = o.project(unit);
        rightLength += p.x() * p.x();
        upLength += p.y() * p.y();
        dot += p.x() * p.y();
    }
    QCOMPARE(qRound(rightLength * 1e9), qRound(1e9));
    QCOMPARE(qRound(upLength * 1e9), qRound(1e9));
    QCOMPARE(qRound(dot * 1e9), 0);
    // Linear: a point's image is the sum of its parts'.
    const QPointF sum =
        o.project({1, 0, 0}) * 3 + o.project({0, 1, 0}) * -2 + o.project({0, 0, 1}) * 0.5;
    QVERIFY2(near(o.project({3, -2, 0.5}), sum, 1e-12), qPrintable(text(sum)));
}

STEPDECK_TEST_GUILESS_MAIN(TestPreviewProjection)
#include "tst_programpreviewprojection.moc"
