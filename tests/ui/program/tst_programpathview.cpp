// ProgramPathView (issue 29), offscreen: fitted to the path, the wheel zooms about the pointer,
// a drag with the middle button or Shift pans by the drag, rapids and feeds painted in their own
// colours, the soft-limit box only with limits, the view chosen remembered and only the
// machine's views offered, the running line and the tool drawn over a path that is not drawn
// again for them (turning it: tst_programpathvieworbit). The legend (issue 47 item 13)
// has a room of its own beside or below the drawing, never over the path, and keeps it when a
// run adds its entries.
#include "PathViewTestSupport.h"
#include "PreviewTestData.h"
#include "PreviewViewKindMetaType.h"
#include "TestMain.h"
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
using namespace stepdeck::pathviewtest;

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
    void legend_ownRoom_neverOverThePath_data();
    void legend_ownRoom_neverOverThePath();
    void legend_runStarts_nothingMoves();
};

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

STEPDECK_TEST_MAIN(TestProgramPathView)
#include "tst_programpathview.moc"
