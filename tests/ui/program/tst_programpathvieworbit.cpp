// ProgramPathView turning (issue 47 item 14), offscreen: a left drag turns by half a degree per
// pixel about the path's middle (which stays put), the selector says "Orbit" until a standard
// view turns it back, Fit fits the turned path, the wheel zooms about the pointer when turned,
// Ctrl+arrow keys turn by a step, a new check keeps the turn, and a turn projects into the same
// memory.
#include "PathViewTestSupport.h"
#include "PreviewViewKindMetaType.h"
#include "TestMain.h"
#include <QComboBox>
#include <QSettings>
#include <QStandardPaths>
#include <QToolButton>

using namespace stepdeck;
using namespace stepdeck::ui;
using namespace stepdeck::previewtest;
using namespace stepdeck::pathviewtest;

class TestProgramPathViewOrbit : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void orbit_dragRight_turnsAzimuth_data();
    void orbit_dragRight_turnsAzimuth();
    void orbit_drag_middleOfThePathStaysPutAndIsDrawnTurned();
    void orbit_chooseStandardView_turnsBackAndFits();
    void orbit_fit_showsTheTurnedPathWhole();
    void zoom_wheelWhenTurned_keepsPointUnderCursor_data();
    void zoom_wheelWhenTurned_keepsPointUnderCursor();
    void orbit_ctrlArrowKeys_turnByTheKeyStep_data();
    void orbit_ctrlArrowKeys_turnByTheKeyStep();
    void orbit_newCheck_keepsTheTurn();
    void orbit_drag_projectsIntoTheSameMemory();
};

void TestProgramPathViewOrbit::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    QCoreApplication::setApplicationName(QStringLiteral("StepDeckUiTest-tst_programpathvieworbit"));
}

void TestProgramPathViewOrbit::init()
{
    QSettings().clear();
}

void TestProgramPathViewOrbit::orbit_dragRight_turnsAzimuth_data()
{
    QTest::addColumn<PreviewViewKind>("from");
    QTest::addColumn<QPoint>("drag"); // pixels: right and down
    QTest::addColumn<double>("azimuth");
    QTest::addColumn<double>("elevation");
    const double iso = PreviewOrientation::isometricElevation();
    // Half a degree per pixel: across about Z the way the pointer goes, down from higher up.
    QTest::addRow("front, right 40") << PreviewViewKind::Front << QPoint(40, 0) << 20.0 << 0.0;
    QTest::addRow("front, left 60") << PreviewViewKind::Front << QPoint(-60, 0) << -30.0 << 0.0;
    QTest::addRow("front, down 30") << PreviewViewKind::Front << QPoint(0, 30) << 0.0 << 15.0;
    QTest::addRow("front, up 30") << PreviewViewKind::Front << QPoint(0, -30) << 0.0 << -15.0;
    QTest::addRow("front, diagonal") << PreviewViewKind::Front << QPoint(20, -10) << 10.0 << -5.0;
    QTest::addRow("top, up 100") << PreviewViewKind::Top << QPoint(0, -100) << 0.0 << 40.0;
    QTest::addRow("top, down: stays on top")
        << PreviewViewKind::Top << QPoint(0, 40) << 0.0 << 90.0;
    QTest::addRow("front, down 300: clamped")
        << PreviewViewKind::Front << QPoint(0, 300) << 0.0 << 90.0;
    QTest::addRow("side, right 10") << PreviewViewKind::Side << QPoint(10, 0) << -85.0 << 0.0;
    QTest::addRow("isometric, right 10")
        << PreviewViewKind::Isometric << QPoint(10, 0) << 50.0 << iso;
}

void TestProgramPathViewOrbit::orbit_dragRight_turnsAzimuth()
{
    QFETCH(PreviewViewKind, from);
    QFETCH(QPoint, drag);
    QFETCH(double, azimuth);
    QFETCH(double, elevation);
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    QVERIFY(view.chooseView(from));
    QVERIFY(view.canTurn());
    ::drag(&view, QPoint(200, 150), drag);
    QCOMPARE(view.orientation().azimuth(), azimuth);
    QCOMPARE(view.orientation().elevation(), elevation);
    QCOMPARE(view.viewKind(), from); // the standard view it was turned from
    const bool turned = view.orientation() != PreviewOrientation::of(from);
    QCOMPARE(view.isTurned(), turned);
    QCOMPARE(view.viewSelector()->currentText(),
             turned ? QStringLiteral("Orbit") : PreviewProjection::title(from));
}

void TestProgramPathViewOrbit::orbit_drag_middleOfThePathStaysPutAndIsDrawnTurned()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    // The middle of the path's box: X 0..40, Y 0..20, Z -1..5.
    const PreviewPosition middle{20, 10, 2};
    const QPointF before = view.toWidget(view.orientation().project(middle));
    ::drag(&view, QPoint(100, 200), QPoint(70, -90));
    QVERIFY(view.isTurned());
    const QPointF after = view.toWidget(view.orientation().project(middle));
    QVERIFY2(within(after, before, 1e-6), qPrintable(text(after)));
    // Drawn turned: the projected points are the turned ones, and the middle of the square's
    // bottom (a feed, X 20, Y 5, Z -1) is painted where the turned view puts it.
    QCOMPARE(view.points().size(), 8);
    QVERIFY(within(view.points().at(3), view.orientation().project({30, 5, -1}), 1e-9));
    const QImage image = render(view);
    QVERIFY(colourNear(image, view.toWidget(view.orientation().project({20, 5, -1})),
                       PreviewStyle::feedColor()));
}

void TestProgramPathViewOrbit::orbit_chooseStandardView_turnsBackAndFits()
{
    ProgramPathView fresh;
    fresh.resize(400, 300);
    fresh.setPreview(squarePreview(), machineXyz(false));
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    ::drag(&view, QPoint(200, 150), QPoint(-50, -80));
    QCOMPARE(view.viewSelector()->currentText(), QStringLiteral("Orbit"));
    // "Orbit" is shown, not chosen.
    auto* model = qobject_cast<QStandardItemModel*>(view.viewSelector()->model());
    QVERIFY(model);
    QVERIFY(!model->item(view.viewSelector()->currentIndex())->isEnabled());
    // Choosing the top view with the selector turns the path back and fits it.
    view.viewSelector()->setCurrentIndex(0);
    emit view.viewSelector()->activated(0);
    QVERIFY(!view.isTurned());
    QCOMPARE(view.orientation(), PreviewOrientation::of(PreviewViewKind::Top));
    QCOMPARE(view.viewSelector()->currentText(), PreviewProjection::title(PreviewViewKind::Top));
    QCOMPARE(view.points(), fresh.points());
    QCOMPARE(view.points().at(1), QPointF(10, 5));
    QCOMPARE(view.toWidget({40, 20}), fresh.toWidget({40, 20}));
}

void TestProgramPathViewOrbit::orbit_fit_showsTheTurnedPathWhole()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    ::drag(&view, QPoint(200, 150), QPoint(60, -40));
    wheel(&view, {300, 60}, 600); // far in: most of the path outside the drawing
    view.fitButton()->click();
    QVERIFY(view.isTurned()); // Fit keeps the orientation
    double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
    view.legendRect(); // the fit (and the legend's place for it) happens on first use
    const QRect drawing = view.drawingRect(); // the view less the legend's room
    for (const QPointF& p : view.points()) {
        const QPointF w = view.toWidget(p);
        QVERIFY2(drawing.contains(w.toPoint()), qPrintable(text(w)));
        left = qMin(left, w.x());
        right = qMax(right, w.x());
        top = qMin(top, w.y());
        bottom = qMax(bottom, w.y());
    }
    // One direction of the drawing filled (its margins and the selector's row aside).
    QVERIFY2(right - left > 0.8 * drawing.width() || bottom - top > 0.6 * drawing.height(),
             qPrintable(QStringLiteral("%1 x %2 in %3 x %4")
                            .arg(right - left)
                            .arg(bottom - top)
                            .arg(drawing.width())
                            .arg(drawing.height())));
}

void TestProgramPathViewOrbit::zoom_wheelWhenTurned_keepsPointUnderCursor_data()
{
    QTest::addColumn<QPointF>("cursor");
    QTest::addColumn<int>("delta");
    QTest::addRow("in, off centre") << QPointF(123, 171) << 120;
    QTest::addRow("out, near a corner") << QPointF(380, 40) << -240;
    QTest::addRow("far in") << QPointF(250, 200) << 720;
}

void TestProgramPathViewOrbit::zoom_wheelWhenTurned_keepsPointUnderCursor()
{
    QFETCH(QPointF, cursor);
    QFETCH(int, delta);
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    ::drag(&view, QPoint(200, 150), QPoint(33, -47));
    QVERIFY(view.isTurned());
    const PreviewOrientation turned = view.orientation();
    const QPointF under = view.toPlane(cursor);
    wheel(&view, cursor, delta);
    const QPointF now = view.toWidget(under);
    QVERIFY2(within(now, cursor, 1.0), qPrintable(text(now))); // within a pixel
    QCOMPARE(view.orientation(), turned);                      // zooming does not turn
}

void TestProgramPathViewOrbit::orbit_ctrlArrowKeys_turnByTheKeyStep_data()
{
    QTest::addColumn<int>("key");
    QTest::addColumn<double>("azimuth");
    QTest::addColumn<double>("elevation");
    // From the front, as a drag the same way would.
    const double step = ProgramPathView::kKeyTurnDegrees;
    QTest::addRow("right") << int(Qt::Key_Right) << step << 0.0;
    QTest::addRow("left") << int(Qt::Key_Left) << -step << 0.0;
    QTest::addRow("down") << int(Qt::Key_Down) << 0.0 << step;
    QTest::addRow("up") << int(Qt::Key_Up) << 0.0 << -step;
}

void TestProgramPathViewOrbit::orbit_ctrlArrowKeys_turnByTheKeyStep()
{
    QFETCH(int, key);
    QFETCH(double, azimuth);
    QFETCH(double, elevation);
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    view.chooseView(PreviewViewKind::Front);
    QTest::keyClick(&view, Qt::Key(key), Qt::ControlModifier);
    QCOMPARE(view.orientation().azimuth(), azimuth);
    QCOMPARE(view.orientation().elevation(), elevation);
    // Without Ctrl the arrow keys still pan, and do not turn.
    const PreviewOrientation turned = view.orientation();
    const QPointF turnedAt = view.toWidget({30, 15});
    QTest::keyClick(&view, Qt::Key(key));
    QCOMPARE(view.orientation(), turned);
    QVERIFY(view.toWidget({30, 15}) != turnedAt);
}

void TestProgramPathViewOrbit::orbit_newCheck_keepsTheTurn()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    ::drag(&view, QPoint(200, 150), QPoint(30, 20));
    const PreviewOrientation turned = view.orientation();
    const QPointF at = view.toWidget({40, 20});
    view.setPreview(squarePreview(), machineXyz(false)); // checked again while typing
    QCOMPARE(view.orientation(), turned);
    QCOMPARE(view.toWidget({40, 20}), at);
    QCOMPARE(view.viewSelector()->currentText(), QStringLiteral("Orbit"));
    // A machine without Z cannot be turned: its standard view.
    view.setPreview(squarePreview(), machineWith({{QStringLiteral("X")}, {QStringLiteral("Y")}}));
    QVERIFY(!view.isTurned());
    QVERIFY(!view.canTurn());
    QCOMPARE(view.viewSelector()->currentText(), PreviewProjection::title(PreviewViewKind::Top));
}

void TestProgramPathViewOrbit::orbit_drag_projectsIntoTheSameMemory()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    ::drag(&view, QPoint(200, 150), QPoint(4, 2)); // turned: X, Y and Z drawn
    const QPointF* points = view.points().constData();
    const QPointF first = view.points().at(0);
    QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, QPoint(200, 150));
    for (int i = 1; i <= 20; ++i)
        QTest::mouseMove(&view, QPoint(200 + 3 * i, 150 - i));
    QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, QPoint(260, 130));
    QVERIFY(view.points().at(0) != first);       // projected again
    QCOMPARE(view.points().constData(), points); // into the same list
    QCOMPARE(view.points().size(), qsizetype(8));
}

STEPDECK_TEST_MAIN(TestProgramPathViewOrbit)
#include "tst_programpathvieworbit.moc"
