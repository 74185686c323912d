// PreviewScene (issue 29): rapids and feeds become separate paths, the soft-limit box is drawn
// only for axes with limits and in work coordinates, a point without a known position on a
// view's axis breaks the path, and a block's segments are found for the running line.
#include "PreviewTestData.h"
#include "PreviewViewKindMetaType.h"
#include "TestMain.h"
#include "program/PreviewScene.h"
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::ui;
using namespace stepdeck::previewtest;

class TestPreviewScene : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void project_rapidsAndFeeds_eachInItsOwnPath();
    void project_softLimits_boxOnlyWhereTheViewsAxesHaveThem_data();
    void project_softLimits_boxOnlyWhereTheViewsAxesHaveThem();
    void project_workOffset_boxInWorkCoordinates();
    void project_unknownAxis_pathBrokenThere();
    void segmentsOfLine_arcChords_allOfTheBlock();
    void projectPosition_missingAxis_none();
};

void TestPreviewScene::project_rapidsAndFeeds_eachInItsOwnPath()
{
    PreviewScene scene;
    scene.setPreview(previewOf({{0, 0, 5}, {10, 0, 5, true}, {10, 0, -1}, {20, 10, -1}}),
                     machineXyz(false));
    const PreviewScene::Projected top = scene.project(PreviewViewKind::Top);
    QCOMPARE(top.points.size(), 4);
    QCOMPARE(top.rapids.boundingRect(), QRectF(0, 0, 10, 0)); // the G0 from 0,0 to 10,0
    QCOMPARE(top.feeds.boundingRect(), QRectF(10, 0, 10, 10));
    QCOMPARE(top.start.value(), QPointF(0, 0));
    QCOMPARE(top.bounds.value(), QRectF(0, 0, 20, 10));
    const PreviewScene::Projected front = scene.project(PreviewViewKind::Front);
    QCOMPARE(front.rapids.boundingRect(), QRectF(0, 5, 10, 0));
    QCOMPARE(front.feeds.boundingRect(), QRectF(10, -1, 10, 6)); // the plunge and the cut
}

void TestPreviewScene::project_softLimits_boxOnlyWhereTheViewsAxesHaveThem_data()
{
    QTest::addColumn<PreviewViewKind>("kind");
    QTest::addColumn<bool>("zLimited");
    QTest::addColumn<QRectF>("box"); // empty: none
    QTest::addRow("top, XY limited") << PreviewViewKind::Top << false << QRectF(0, 0, 100, 50);
    QTest::addRow("front, Z unlimited") << PreviewViewKind::Front << false << QRectF();
    QTest::addRow("front, Z limited") << PreviewViewKind::Front << true << QRectF(0, -20, 100, 20);
    QTest::addRow("side, Z limited") << PreviewViewKind::Side << true << QRectF(0, -20, 50, 20);
}

void TestPreviewScene::project_softLimits_boxOnlyWhereTheViewsAxesHaveThem()
{
    QFETCH(PreviewViewKind, kind);
    QFETCH(bool, zLimited);
    QFETCH(QRectF, box);
    const machine::MachineDescription machine =
        zLimited ? machineXyz(true)
                 : machineWith({{QStringLiteral("X"), std::make_pair(0.0, 100.0)},
                                {QStringLiteral("Y"), std::make_pair(0.0, 50.0)},
                                {QStringLiteral("Z")}});
    PreviewScene scene;
    scene.setPreview(previewOf({{1, 1, -1}, {2, 2, -2}}), machine);
    const PreviewScene::Projected projected = scene.project(kind);
    if (box.isNull()) {
        QVERIFY(projected.softLimits.isEmpty());
    } else {
        QCOMPARE(projected.softLimits.boundingRect(), box);
        QVERIFY(projected.bounds->contains(box)); // the view's bounds hold the box
    }
}

void TestPreviewScene::project_workOffset_boxInWorkCoordinates()
{
    program::ProgramPreview preview = previewOf({{1, 1, 0}, {2, 2, 0}});
    preview.workOffsets = {{QStringLiteral("X"), 30.0}, {QStringLiteral("Y"), -5.0}};
    PreviewScene scene;
    scene.setPreview(preview, machineXyz(true));
    // Machine 0..100 with work zero at machine 30: work -30..70.
    QCOMPARE(scene.project(PreviewViewKind::Top).softLimits.boundingRect(),
             QRectF(QPointF(-30, 5), QPointF(70, 55)));
    // Isometric: the whole box, its twelve edges.
    const QPainterPath iso = scene.project(PreviewViewKind::Isometric).softLimits;
    QCOMPARE(iso.elementCount(), 24);
}

void TestPreviewScene::project_unknownAxis_pathBrokenThere()
{
    program::ProgramPreview preview = previewOf({{0, 0, 0}, {5, 0, 0}, {5, 5, 0}, {0, 5, 0}});
    preview.path[2].position.remove(QStringLiteral("Z")); // Z unknown there
    PreviewScene scene;
    scene.setPreview(preview, machineXyz(false));
    const PreviewScene::Projected front = scene.project(PreviewViewKind::Front);
    QCOMPARE(front.points.size(), 3);
    QCOMPARE(front.joined, (QList<bool>{false, true, false}));
    // The top view does not need Z: all four points, joined.
    QCOMPARE(scene.project(PreviewViewKind::Top).points.size(), 4);
}

void TestPreviewScene::segmentsOfLine_arcChords_allOfTheBlock()
{
    // Line 2 is an arc's chords (three points), line 3 a straight move.
    PreviewScene scene;
    scene.setPreview(previewOf({{0, 0, 0, false, 1},
                                {1, 1, 0, false, 2},
                                {2, 1.5, 0, false, 2},
                                {3, 1, 0, false, 2},
                                {9, 9, 0, false, 3}}),
                     machineXyz(false));
    const PreviewScene::Projected top = scene.project(PreviewViewKind::Top);
    const QPainterPath arc = PreviewScene::segmentsOfLine(top, 2);
    QCOMPARE(arc.boundingRect(), QRectF(0, 0, 3, 1.5)); // from the point before its first
    QCOMPARE(arc.elementCount(), 4);                    // one moveTo, three chords
    QVERIFY(PreviewScene::segmentsOfLine(top, 7).isEmpty());
}

void TestPreviewScene::projectPosition_missingAxis_none()
{
    const QMap<QString, double> xy{{QStringLiteral("X"), 1.0}, {QStringLiteral("Y"), 2.0}};
    QCOMPARE(PreviewScene::projectPosition(PreviewViewKind::Top, xy).value(), QPointF(1, 2));
    QVERIFY(!PreviewScene::projectPosition(PreviewViewKind::Front, xy));
}

STEPDECK_TEST_GUILESS_MAIN(TestPreviewScene)
#include "tst_programpreviewscene.moc"
