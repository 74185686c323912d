// ProgramPathView (issue 29), offscreen: fitted to the path, the wheel zooms about the pointer,
// a drag with the middle button or Shift pans by the drag, rapids and feeds painted in their own
// colours, the soft-limit box only with limits, the view chosen remembered and only the
// machine's views offered, the running line and the tool drawn over a path that is not drawn
// again for them. Turning (issue 47 item 14): a left drag turns by half a degree per pixel
// about the path's middle (which stays put), the selector says "Orbit" until a standard view
// turns it back, Fit fits the turned path, the wheel zooms about the pointer when turned, a new
// check keeps the turn, and a turn projects into the same memory. The legend (issue 47 item 13)
// has a room of its own beside or below the drawing, never over the path, and keeps it when a
// run adds its entries.
#include "PreviewTestData.h"
#include "program/PreviewStyle.h"
#include "program/ProgramPathView.h"
#include <QApplication>
#include <QComboBox>
#include <QSettings>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QToolButton>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::ui;
using namespace stepdeck::previewtest;

Q_DECLARE_METATYPE(stepdeck::ui::PreviewViewKind)

class TestProgramPathView : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void fit_onPreview_coversThePathsExtents();
    void fit_afterZoom_byButtonAndKey();
    void zoom_wheelAtCursor_keepsPointUnderCursor();
    void pan_drag_movesTheDrawingByTheDrag_data();
    void pan_drag_movesTheDrawingByTheDrag();
    void paint_rapidAndFeed_differentColours();
    void paint_softLimitBox_onlyWithLimits();
    void view_choice_rememberedByTheNextView();
    void view_xyMachine_onlyTopEnabledAndSaysWhy();
    void view_keyboard_selectorAndFitAreTabStops();
    void marker_moves_pathDrawnOnce();
    void runningLine_highlightedOverThePath();
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
    void legend_ownRoom_neverOverThePath_data();
    void legend_ownRoom_neverOverThePath();
    void legend_runStarts_nothingMoves();

private:
    static QImage render(ProgramPathView& view);
};

namespace {
// Whether some pixel within radius of p has about the hue of c, well saturated: antialiasing
// blends a line's colour with the background, which keeps its hue.
bool colourNear(const QImage& image, const QPointF& p, const QColor& c, int radius = 2)
{
    constexpr int kHueTolerance = 15; // degrees; the pens' hues are 60 and more apart
    constexpr int kMinSaturation = 60;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint at = p.toPoint() + QPoint(dx, dy);
            if (!image.rect().contains(at))
                continue;
            const QColor got = image.pixelColor(at).toHsv();
            const int hueDistance = std::abs(got.hsvHue() - c.toHsv().hsvHue()) % 360;
            if (got.hsvSaturation() >= kMinSaturation &&
                qMin(hueDistance, 360 - hueDistance) <= kHueTolerance)
                return true;
        }
    return false;
}

void wheel(QWidget* widget, const QPointF& at, int delta)
{
    QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
}

void mouse(QWidget* widget, QEvent::Type type, const QPointF& at, Qt::MouseButtons buttons,
           Qt::MouseButton button = Qt::LeftButton,
           Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QMouseEvent event(type, at, widget->mapToGlobal(at),
                      type == QEvent::MouseMove ? Qt::NoButton : button, buttons, modifiers);
    QApplication::sendEvent(widget, &event);
}

// A drag with the left button from `from` by `by`, in two moves (QTest keeps the button held
// between press and release).
void drag(QWidget* widget, const QPoint& from, const QPoint& by)
{
    QTest::mousePress(widget, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(widget, from + by / 2);
    QTest::mouseMove(widget, from + by);
    QTest::mouseRelease(widget, Qt::LeftButton, Qt::NoModifier, from + by);
}

bool within(const QPointF& a, const QPointF& b, double tolerance)
{
    return std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
}

QString text(const QPointF& p)
{
    return QStringLiteral("%1, %2").arg(p.x()).arg(p.y());
}

// A square of feeds with a rapid to it and back up: X 0..40, Y 0..20.
program::ProgramPreview squarePreview()
{
    return previewOf({{0, 0, 5},
                      {10, 5, 5, true},
                      {10, 5, -1},
                      {30, 5, -1},
                      {30, 15, -1},
                      {10, 15, -1},
                      {10, 5, -1},
                      {40, 20, 5, true}});
}
} // namespace

void TestProgramPathView::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    QCoreApplication::setApplicationName(QStringLiteral("StepDeckUiTest-tst_programpathview"));
}

void TestProgramPathView::init()
{
    QSettings().clear();
}

QImage TestProgramPathView::render(ProgramPathView& view)
{
    return view.grab().toImage().convertToFormat(QImage::Format_RGB32);
}

void TestProgramPathView::fit_onPreview_coversThePathsExtents()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(true));
    // The path's corners inside the drawing (the view less the legend's room), and it fills
    // one direction of it (not the machine's much larger soft-limit box).
    const QRect drawing = view.drawingRect();
    const QPointF low = view.toWidget({0, 0}), high = view.toWidget({40, 20});
    QVERIFY(drawing.contains(low.toPoint()));
    QVERIFY(drawing.contains(high.toPoint()));
    QVERIFY2(high.x() - low.x() > 0.8 * drawing.width() ||
                 low.y() - high.y() > 0.6 * drawing.height(),
             qPrintable(QStringLiteral("%1 x %2 in %3 x %4")
                            .arg(high.x() - low.x())
                            .arg(low.y() - high.y())
                            .arg(drawing.width())
                            .arg(drawing.height())));
    // Another size fits again (until the operator zooms).
    view.resize(600, 300);
    QVERIFY(view.toWidget({40, 20}).x() > high.x());
    QVERIFY(view.drawingRect().contains(view.toWidget({40, 20}).toPoint()));
}

void TestProgramPathView::fit_afterZoom_byButtonAndKey()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    const QPointF fitted = view.toWidget({40, 20});
    wheel(&view, {100, 100}, 480);
    QVERIFY(view.toWidget({40, 20}) != fitted);
    view.fitButton()->click();
    QCOMPARE(view.toWidget({40, 20}), fitted);
    wheel(&view, {100, 100}, -240);
    QTest::keyClick(&view, Qt::Key_F);
    QCOMPARE(view.toWidget({40, 20}), fitted);
    // A zoomed view stays as it is when the program is checked again.
    wheel(&view, {100, 100}, 240);
    const QPointF zoomed = view.toWidget({40, 20});
    view.setPreview(squarePreview(), machineXyz(false));
    QCOMPARE(view.toWidget({40, 20}), zoomed);
}

void TestProgramPathView::zoom_wheelAtCursor_keepsPointUnderCursor()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    const QPointF cursor(123, 171);
    const QPointF under = view.toPlane(cursor);
    const QPointF a = view.toWidget({0, 0}), b = view.toWidget({40, 0});
    wheel(&view, cursor, 120); // one notch in
    const QPointF now = view.toWidget(under);
    QVERIFY2(std::abs(now.x() - cursor.x()) < 1e-6 && std::abs(now.y() - cursor.y()) < 1e-6,
             qPrintable(QStringLiteral("%1, %2").arg(now.x()).arg(now.y())));
    const double grown = (view.toWidget({40, 0}).x() - view.toWidget({0, 0}).x()) / (b.x() - a.x());
    QCOMPARE(qRound(grown * 1000), 1200);
}

void TestProgramPathView::pan_drag_movesTheDrawingByTheDrag_data()
{
    QTest::addColumn<int>("button");
    QTest::addColumn<int>("modifiers");
    QTest::addColumn<bool>("xyz"); // the machine has X, Y and Z (a left drag turns)
    QTest::addRow("middle button") << int(Qt::MiddleButton) << int(Qt::NoModifier) << true;
    QTest::addRow("Shift+left") << int(Qt::LeftButton) << int(Qt::ShiftModifier) << true;
    QTest::addRow("left, nothing to turn") << int(Qt::LeftButton) << int(Qt::NoModifier) << false;
}

void TestProgramPathView::pan_drag_movesTheDrawingByTheDrag()
{
    QFETCH(int, button);
    QFETCH(int, modifiers);
    QFETCH(bool, xyz);
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(),
                    xyz ? machineXyz(false)
                        : machineWith({{QStringLiteral("X")}, {QStringLiteral("Y")}}));
    const auto b = Qt::MouseButton(button);
    const auto m = Qt::KeyboardModifiers::fromInt(modifiers);
    const QPointF before = view.toWidget({30, 15});
    mouse(&view, QEvent::MouseButtonPress, {200, 150}, b, b, m);
    mouse(&view, QEvent::MouseMove, {230, 140}, b, b, m);
    mouse(&view, QEvent::MouseMove, {250, 110}, b, b, m);
    mouse(&view, QEvent::MouseButtonRelease, {250, 110}, Qt::NoButton, b, m);
    QCOMPARE(view.toWidget({30, 15}), before + QPointF(50, -40));
    QVERIFY(!view.isTurned());
    QCOMPARE(view.orientation(), PreviewOrientation::of(PreviewViewKind::Top));
    // A move without the button held pans nothing.
    mouse(&view, QEvent::MouseMove, {10, 10}, Qt::NoButton);
    QCOMPARE(view.toWidget({30, 15}), before + QPointF(50, -40));
}

void TestProgramPathView::paint_rapidAndFeed_differentColours()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    const QImage image = render(view);
    // The middle of the square's bottom (a feed) and of the way back up (a rapid).
    const QPointF feed = view.toWidget({20, 5});
    QVERIFY(colourNear(image, feed, PreviewStyle::feedColor()));
    QVERIFY(!colourNear(image, feed, PreviewStyle::rapidColor()));
    // A dashed line: some of a stretch of it is drawn.
    bool rapidSeen = false;
    for (double t = 0.3; t < 0.55; t += 0.02) {
        const QPointF rapid = view.toWidget(QPointF(10 + 30 * t, 5 + 15 * t));
        rapidSeen = rapidSeen || colourNear(image, rapid, PreviewStyle::rapidColor(), 1);
        QVERIFY(!colourNear(image, rapid, PreviewStyle::feedColor(), 1));
    }
    QVERIFY(rapidSeen);
    QCOMPARE(view.legendEntries(),
             (QStringList{QStringLiteral("Feed (G1, arcs)"), QStringLiteral("Rapid (G0)")}));
}

void TestProgramPathView::paint_softLimitBox_onlyWithLimits()
{
    ProgramPathView view;
    view.resize(400, 300);
    program::ProgramPreview preview = squarePreview();
    // A box near the path: machine X 0..50, Y 0..30 with work zero at machine 5, 5.
    preview.workOffsets = {{QStringLiteral("X"), 5.0}, {QStringLiteral("Y"), 5.0}};
    view.setPreview(preview, machineWith({{QStringLiteral("X"), std::make_pair(0.0, 50.0)},
                                          {QStringLiteral("Y"), std::make_pair(0.0, 30.0)}}));
    QTest::keyClick(&view, Qt::Key_Minus); // the box's edges inside the drawing
    // The box's top edge runs along work Y 25, from work X -5 to 45.
    auto boxEdgeSeen = [&](const QImage& image) {
        int seen = 0;
        for (double x = -4; x < 44; x += 1)
            seen += colourNear(image, view.toWidget({x, 25}), PreviewStyle::limitsColor(), 1);
        return seen;
    };
    QVERIFY(boxEdgeSeen(render(view)) > 10);
    QCOMPARE(view.legendEntries().size(), 3); // feed, rapid, soft limits
    view.setPreview(preview, machineWith({{QStringLiteral("X")}, {QStringLiteral("Y")}}));
    QCOMPARE(boxEdgeSeen(render(view)), 0);
    QCOMPARE(view.legendEntries().size(), 2);
}

void TestProgramPathView::view_choice_rememberedByTheNextView()
{
    {
        ProgramPathView view;
        view.setPreview(squarePreview(), machineXyz(false));
        QCOMPARE(view.viewKind(), PreviewViewKind::Top);
        QVERIFY(view.chooseView(PreviewViewKind::Front));
        QCOMPARE(view.points().at(1), QPointF(10, 5)); // X 10, Z 5
    }
    ProgramPathView next;
    next.setPreview(squarePreview(), machineXyz(false));
    QCOMPARE(next.viewKind(), PreviewViewKind::Front);
    QCOMPARE(next.viewSelector()->currentText(), PreviewProjection::title(PreviewViewKind::Front));
    // Chosen with the selector (as the keyboard or the mouse does): remembered too.
    next.viewSelector()->setCurrentIndex(3);
    emit next.viewSelector()->activated(3);
    QCOMPARE(next.viewKind(), PreviewViewKind::Isometric);
    QCOMPARE(QSettings().value(QLatin1String(ProgramPathView::kSettingsKey)).toString(),
             QStringLiteral("isometric"));
}

void TestProgramPathView::view_xyMachine_onlyTopEnabledAndSaysWhy()
{
    QSettings().setValue(QLatin1String(ProgramPathView::kSettingsKey), QStringLiteral("side"));
    ProgramPathView view;
    view.setPreview(squarePreview(), machineWith({{QStringLiteral("X")}, {QStringLiteral("Y")}}));
    QCOMPARE(view.viewKind(), PreviewViewKind::Top); // side needs Z
    auto* model = qobject_cast<QStandardItemModel*>(view.viewSelector()->model());
    QVERIFY(model);
    QVERIFY(model->item(0)->isEnabled());
    for (int i = 1; i < 4; ++i)
        QVERIFY(!model->item(i)->isEnabled());
    QVERIFY(view.viewSelector()->toolTip().contains(QStringLiteral("Z")));
    QVERIFY(!view.chooseView(PreviewViewKind::Isometric));
    QCOMPARE(view.viewKind(), PreviewViewKind::Top);
    // The choice stays for a machine that has Z.
    QCOMPARE(QSettings().value(QLatin1String(ProgramPathView::kSettingsKey)).toString(),
             QStringLiteral("side"));
}

void TestProgramPathView::view_keyboard_selectorAndFitAreTabStops()
{
    ProgramPathView view;
    QVERIFY(view.viewSelector()->focusPolicy() & Qt::TabFocus);
    QVERIFY(view.fitButton()->focusPolicy() & Qt::TabFocus);
    QVERIFY(view.focusPolicy() & Qt::TabFocus); // the drawing takes + - F and the arrows
}

void TestProgramPathView::marker_moves_pathDrawnOnce()
{
    ProgramPathView view;
    view.resize(400, 300);
    program::ProgramPreview preview;
    for (int i = 0; i < program::ProgramPreview::kMaxPathPoints; ++i) {
        program::PreviewPoint p;
        p.line = i + 1;
        p.position = {{QStringLiteral("X"), double(i % 100)},
                      {QStringLiteral("Y"), i / 200.0},
                      {QStringLiteral("Z"), 0.0}};
        p.rapid = i % 7 == 0;
        preview.path << p;
    }
    view.setPreview(preview, machineXyz(true));
    view.grab();
    QCOMPARE(view.pathRenders(), 1);
    const QPointF before = view.toWidget({50, 50});
    for (int i = 0; i < 10; ++i) {
        view.setCurrent({{QStringLiteral("X"), 10.0 + i}, {QStringLiteral("Y"), 20.0 + i}});
        view.setRunningLine(100 + i);
        view.grab();
    }
    QCOMPARE(*view.current(), QPointF(19, 29));
    QCOMPARE(view.pathRenders(), 1);
    QCOMPARE(view.toWidget({50, 50}), before); // the drawing held still
    wheel(&view, {50, 50}, 120);               // zoomed: drawn again, once
    view.grab();
    view.grab();
    QCOMPARE(view.pathRenders(), 2);
    view.chooseView(PreviewViewKind::Isometric); // another view
    view.grab();
    QCOMPARE(view.pathRenders(), 3);
}

void TestProgramPathView::runningLine_highlightedOverThePath()
{
    ProgramPathView view;
    view.resize(400, 300);
    view.setPreview(squarePreview(), machineXyz(false));
    // Line 4 ends at 30, 5: the square's bottom from 10, 5.
    const QColor running = PreviewStyle::runningColor();
    QVERIFY(!colourNear(render(view), view.toWidget({20, 5}), running));
    view.setRunningLine(4);
    view.setCurrent({{QStringLiteral("X"), 20.0}, {QStringLiteral("Y"), 5.0}});
    const QImage image = render(view);
    QVERIFY(colourNear(image, view.toWidget({15, 5}), running));
    QVERIFY(!colourNear(image, view.toWidget({30, 10}), running)); // line 5 is not
    QVERIFY(view.legendEntries().contains(QStringLiteral("Tool")));
    view.setRunningLine(0);
    view.setCurrent({});
    QVERIFY(!view.current());
    QVERIFY(!colourNear(render(view), view.toWidget({15, 5}), running));
}

void TestProgramPathView::orbit_dragRight_turnsAzimuth_data()
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

void TestProgramPathView::orbit_dragRight_turnsAzimuth()
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

void TestProgramPathView::orbit_drag_middleOfThePathStaysPutAndIsDrawnTurned()
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

void TestProgramPathView::orbit_chooseStandardView_turnsBackAndFits()
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

void TestProgramPathView::orbit_fit_showsTheTurnedPathWhole()
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

void TestProgramPathView::zoom_wheelWhenTurned_keepsPointUnderCursor_data()
{
    QTest::addColumn<QPointF>("cursor");
    QTest::addColumn<int>("delta");
    QTest::addRow("in, off centre") << QPointF(123, 171) << 120;
    QTest::addRow("out, near a corner") << QPointF(380, 40) << -240;
    QTest::addRow("far in") << QPointF(250, 200) << 720;
}

void TestProgramPathView::zoom_wheelWhenTurned_keepsPointUnderCursor()
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

void TestProgramPathView::orbit_ctrlArrowKeys_turnByTheKeyStep_data()
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

void TestProgramPathView::orbit_ctrlArrowKeys_turnByTheKeyStep()
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

void TestProgramPathView::orbit_newCheck_keepsTheTurn()
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

void TestProgramPathView::orbit_drag_projectsIntoTheSameMemory()
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

void TestProgramPathView::legend_ownRoom_neverOverThePath_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<bool>("shown"); // room enough for a legend beside or below the path
    // The Run workspace's preview at 1366x768 (issue 47 item 13: about 360 x 150, the legend
    // covered the drawing), a larger one, one wide and low, one narrow and high, and one too
    // small for a legend.
    QTest::newRow("1366x768's preview") << QSize(360, 150) << true;
    QTest::newRow("400x300") << QSize(400, 300) << true;
    QTest::newRow("wide and low") << QSize(900, 200) << true;
    QTest::newRow("narrow and high") << QSize(300, 600) << true;
    QTest::newRow("too small") << QSize(150, 70) << false;
}

// Issue 47 item 13: "the toolpath about 360x150 px with its legend over the drawing". The legend
// has its own room beside or below the drawing; the fitted path lies in the drawing; zoomed and
// panned, the path is not drawn over the legend.
void TestProgramPathView::legend_ownRoom_neverOverThePath()
{
    QFETCH(QSize, size);
    QFETCH(bool, shown);
    ProgramPathView view;
    view.resize(size);
    program::ProgramPreview preview = squarePreview();
    preview.workOffsets = {{QStringLiteral("X"), 5.0}, {QStringLiteral("Y"), 5.0}};
    view.setPreview(preview, machineWith({{QStringLiteral("X"), std::make_pair(0.0, 50.0)},
                                          {QStringLiteral("Y"), std::make_pair(0.0, 30.0)}}));
    const QRect legend = view.legendRect();
    const QRect drawing = view.drawingRect();
    QCOMPARE(!legend.isEmpty(), shown);
    QVERIFY(view.rect().contains(drawing));
    if (!shown) {
        QCOMPARE(drawing, view.rect()); // the path keeps the whole view
        return;
    }
    QVERIFY(view.rect().contains(legend));
    QVERIFY2(!legend.intersects(drawing),
             qPrintable(QStringLiteral("legend %1,%2 %3x%4 over the drawing %5,%6 %7x%8")
                            .arg(legend.x())
                            .arg(legend.y())
                            .arg(legend.width())
                            .arg(legend.height())
                            .arg(drawing.x())
                            .arg(drawing.y())
                            .arg(drawing.width())
                            .arg(drawing.height())));
    // Beside (a column at the right) or below (a strip along the bottom), the drawing the rest.
    if (view.legendBeside())
        QCOMPARE(legend.right(), view.rect().right());
    else
        QCOMPARE(legend.bottom(), view.rect().bottom());
    QCOMPARE(drawing.united(legend), view.rect());
    // The fitted path in the drawing.
    for (const QPointF& p : view.points())
        QVERIFY2(drawing.contains(view.toWidget(p).toPoint()), qPrintable(text(view.toWidget(p))));
    // The legend's entries are drawn in its room: a sample of the feed's pen.
    const QImage image = render(view);
    bool feedSample = false;
    for (int y = legend.top(); y <= legend.bottom() && !feedSample; ++y)
        for (int x = legend.left(); x < legend.left() + 40 && !feedSample; ++x)
            feedSample = colourNear(image, QPointF(x, y), PreviewStyle::feedColor(), 0);
    QVERIFY(feedSample);
    // Zoomed far in about the drawing's right edge: the feeds reach into the legend's room but
    // are not drawn there (away from its samples, its texts are black).
    for (int i = 0; i < 6; ++i)
        wheel(&view, QPointF(drawing.right() - 2, drawing.center().y()), 240);
    const QImage zoomed = render(view);
    const QRect textPart = legend.adjusted(40, 0, 0, 0);
    int feedPixels = 0;
    for (int y = textPart.top(); y <= textPart.bottom(); ++y)
        for (int x = textPart.left(); x <= textPart.right(); ++x)
            feedPixels += colourNear(zoomed, QPointF(x, y), PreviewStyle::feedColor(), 0);
    QCOMPARE(feedPixels, 0);
}

// The legend's room is kept for the entries a run adds (the running line, the tool): when a run
// starts, nothing moves and the path is not fitted again.
void TestProgramPathView::legend_runStarts_nothingMoves()
{
    ProgramPathView view;
    view.resize(360, 150);
    view.setPreview(squarePreview(), machineXyz(false));
    const QRect legend = view.legendRect();
    const QRect drawing = view.drawingRect();
    const QPointF corner = view.toWidget({40, 20});
    QCOMPARE(view.legendEntries().size(), 2);
    view.setRunningLine(4);
    view.setCurrent({{QStringLiteral("X"), 20.0}, {QStringLiteral("Y"), 5.0}});
    view.grab();
    QCOMPARE(view.legendEntries().size(), 4);
    QCOMPARE(view.legendRect(), legend);
    QCOMPARE(view.drawingRect(), drawing);
    QCOMPARE(view.toWidget({40, 20}), corner);
}

QTEST_MAIN(TestProgramPathView)
#include "tst_programpathview.moc"
