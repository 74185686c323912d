// PreviewViewport (issue 29): fitting shows the whole of a rectangle, centred, Y up; zooming
// about a point keeps the plane point under it; panning moves the drawing by the drag; the
// scale stays within its bounds; a plane point is placed on a widget point (a turned view
// keeps its middle where it was, issue 47 item 14).
#include "TestMain.h"
#include "program/PreviewViewport.h"
#include <QtTest>

using namespace stepdeck::ui;

class TestPreviewViewport : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void fit_bounds_insideTheAreaCentredYUp();
    void fit_line_getsRoomAround();
    void zoomAt_widgetPoint_keepsThePlanePointUnderIt_data();
    void zoomAt_widgetPoint_keepsThePlanePointUnderIt();
    void panBy_delta_movesEveryPointByIt();
    void transform_samePlaceAsMap();
    void zoomAt_farOut_scaleStaysWithinBounds();
    void placeAt_planePoint_landsOnTheWidgetPointScaleKept_data();
    void placeAt_planePoint_landsOnTheWidgetPointScaleKept();
};

namespace {
bool nearPoint(const QPointF& a, const QPointF& b, double tolerance = 1e-9)
{
    return std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
}
} // namespace

void TestPreviewViewport::fit_bounds_insideTheAreaCentredYUp()
{
    PreviewViewport v;
    const QRectF area(10, 20, 400, 200);
    v.fit(QRectF(QPointF(-10, 0), QPointF(30, 10)), area); // 40 x 10: width decides
    QCOMPARE(v.scale(), 10.0);
    QVERIFY(nearPoint(v.map({-10, 0}), {10, 170}));    // lower left: the area's left, below centre
    QVERIFY(nearPoint(v.map({30, 10}), {410, 70}));    // upper right
    QVERIFY(nearPoint(v.map({10, 5}), area.center())); // centre on centre
}

void TestPreviewViewport::fit_line_getsRoomAround()
{
    PreviewViewport v;
    v.fit(QRectF(QPointF(0, 0), QPointF(100, 0)), QRectF(0, 0, 200, 200));
    QVERIFY(qIsFinite(v.scale()));
    QVERIFY(v.scale() > 0);
    QVERIFY(v.map({0, 0}).x() >= 0);
    QVERIFY(v.map({100, 0}).x() <= 200);
}

void TestPreviewViewport::zoomAt_widgetPoint_keepsThePlanePointUnderIt_data()
{
    QTest::addColumn<QPointF>("at");
    QTest::addColumn<double>("factor");
    QTest::addRow("in at a corner") << QPointF(17, 33) << 1.2;
    QTest::addRow("out at the centre") << QPointF(200, 100) << 1 / 1.2;
    QTest::addRow("far in") << QPointF(399, 1) << 50.0;
}

void TestPreviewViewport::zoomAt_widgetPoint_keepsThePlanePointUnderIt()
{
    QFETCH(QPointF, at);
    QFETCH(double, factor);
    PreviewViewport v;
    v.fit(QRectF(0, 0, 100, 50), QRectF(0, 0, 400, 200));
    const QPointF under = v.unmap(at);
    const double before = v.scale();
    v.zoomAt(at, factor);
    QVERIFY(nearPoint(v.map(under), at, 1e-6));
    QCOMPARE(v.scale(), before * factor);
}

void TestPreviewViewport::panBy_delta_movesEveryPointByIt()
{
    PreviewViewport v;
    v.fit(QRectF(0, 0, 100, 50), QRectF(0, 0, 400, 200));
    const QPointF a = v.map({0, 0}), b = v.map({70, -3});
    v.panBy({25, -7});
    QVERIFY(nearPoint(v.map({0, 0}), a + QPointF(25, -7)));
    QVERIFY(nearPoint(v.map({70, -3}), b + QPointF(25, -7)));
}

void TestPreviewViewport::transform_samePlaceAsMap()
{
    PreviewViewport v;
    v.fit(QRectF(-5, -5, 10, 20), QRectF(3, 4, 300, 100));
    v.zoomAt({40, 50}, 1.7);
    v.panBy({-9, 2});
    for (const QPointF& p : {QPointF(0, 0), QPointF(-5, 15), QPointF(3.25, -1)})
        QVERIFY(nearPoint(v.transform().map(p), v.map(p)));
}

void TestPreviewViewport::zoomAt_farOut_scaleStaysWithinBounds()
{
    PreviewViewport v;
    for (int i = 0; i < 200; ++i)
        v.zoomAt({10, 10}, 0.5);
    QCOMPARE(v.scale(), PreviewViewport::kMinScale);
    for (int i = 0; i < 400; ++i)
        v.zoomAt({10, 10}, 2);
    QCOMPARE(v.scale(), PreviewViewport::kMaxScale);
}

void TestPreviewViewport::placeAt_planePoint_landsOnTheWidgetPointScaleKept_data()
{
    QTest::addColumn<QPointF>("plane");
    QTest::addColumn<QPointF>("widget");
    QTest::addRow("origin to the centre") << QPointF(0, 0) << QPointF(200, 100);
    QTest::addRow("far point to a corner") << QPointF(-1e4, 2.5e3) << QPointF(3, 197);
    QTest::addRow("where it is") << QPointF(50, 25) << QPointF(200, 100);
}

void TestPreviewViewport::placeAt_planePoint_landsOnTheWidgetPointScaleKept()
{
    QFETCH(QPointF, plane);
    QFETCH(QPointF, widget);
    PreviewViewport v;
    v.fit(QRectF(0, 0, 100, 50), QRectF(0, 0, 400, 200));
    v.zoomAt({17, 33}, 3);
    const double scale = v.scale();
    const QPointF other = v.map({1, 2}) - v.map(plane); // how far another point is from it
    v.placeAt(plane, widget);
    QVERIFY(nearPoint(v.map(plane), widget, 1e-6));
    QCOMPARE(v.scale(), scale);
    QVERIFY(nearPoint(v.map({1, 2}) - v.map(plane), other, 1e-6)); // moved along, not scaled
}

STEPDECK_TEST_GUILESS_MAIN(TestPreviewViewport)
#include "tst_programpreviewviewport.moc"
