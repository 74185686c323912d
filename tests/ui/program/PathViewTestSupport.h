#pragma once
// What the ProgramPathView tests share (tst_programpathview, tst_programpathvieworbit): events
// sent to the view, colour and point comparisons, a square preview.
#include "PreviewTestData.h"
#include "program/PreviewStyle.h"
#include "program/ProgramPathView.h"
#include <QApplication>
#include <QtTest>

namespace stepdeck::pathviewtest {

using namespace stepdeck::ui;
using namespace stepdeck::previewtest;

// Whether some pixel within radius of p has about the hue of c, well saturated: antialiasing
// blends a line's colour with the background, which keeps its hue.
inline bool colourNear(const QImage& image, const QPointF& p, const QColor& c, int radius = 2)
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

inline void wheel(QWidget* widget, const QPointF& at, int delta)
{
    QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
}

inline void mouse(QWidget* widget, QEvent::Type type, const QPointF& at, Qt::MouseButtons buttons,
                  Qt::MouseButton button = Qt::LeftButton,
                  Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QMouseEvent event(type, at, widget->mapToGlobal(at),
                      type == QEvent::MouseMove ? Qt::NoButton : button, buttons, modifiers);
    QApplication::sendEvent(widget, &event);
}

// A drag with the left button from `from` by `by`, in two moves (QTest keeps the button held
// between press and release).
inline void drag(QWidget* widget, const QPoint& from, const QPoint& by)
{
    QTest::mousePress(widget, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(widget, from + by / 2);
    QTest::mouseMove(widget, from + by);
    QTest::mouseRelease(widget, Qt::LeftButton, Qt::NoModifier, from + by);
}

inline bool within(const QPointF& a, const QPointF& b, double tolerance)
{
    return std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
}

inline QString text(const QPointF& p)
{
    return QStringLiteral("%1, %2").arg(p.x()).arg(p.y());
}

// A square of feeds with a rapid to it and back up: X 0..40, Y 0..20.
inline program::ProgramPreview squarePreview()
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

inline QImage render(ProgramPathView& view)
{
    return view.grab().toImage().convertToFormat(QImage::Format_RGB32);
}

} // namespace stepdeck::pathviewtest
