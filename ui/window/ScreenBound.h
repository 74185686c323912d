#pragma once
#include <QObject>

class QWidget;

namespace stepdeck::ui {

// Keeps a top-level window on its screen. Without a window manager (Xvfb, a kiosk) nobody
// else does: a layout whose minimum size grows resizes the window past the screen's edge
// (seen: 1366x871 on a 768-px screen after a reconnect, buttons and status bar off-screen,
// issue 16). So the window's minimum size is the layout's minimum bounded by the available
// geometry of its screen (an explicit minimum, which the layout then does not override), and
// when shown the window is moved and shrunk into that geometry.
class ScreenBound : public QObject
{
    Q_OBJECT
public:
    explicit ScreenBound(QWidget* window);

    // The largest client size whose frame fits the available geometry of w's screen.
    static QSize room(const QWidget* window);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void boundMinimum();
    void fitOnScreen();

    QWidget* m_window;
};

} // namespace stepdeck::ui
