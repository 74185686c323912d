// PreviewProjection (issue 29): each view puts a known point where its axes say, the isometric
// view keeps every axis at one scale, and a view is offered only where the machine has its
// axes.
#include "program/PreviewProjection.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck::ui;

Q_DECLARE_METATYPE(stepdeck::ui::PreviewViewKind)

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
};

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

QTEST_GUILESS_MAIN(TestPreviewProjection)
#include "tst_programpreviewprojection.moc"
