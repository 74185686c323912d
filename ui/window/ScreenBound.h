#pragma once
#include <QObject>

class QWidget;

namespace stepdeck::ui {

// Keeps a top-level window on its screen. Without a window manager (Xvfb, a kiosk) nobody
// else does: a layout whose minimum size grows resizes the window past the screen's edge
// (seen: 1366x871 on a 768-px screen after a reconnect, buttons and status bar off-screen,
// issue 16). So the window's minimum size is the layout's minimum bounded by the available
// geometry of its screen (an explicit minimum, which the layout then does not override), and
// when shown the window is moved and shrunk into that geometry. A window manager frames the
// window only after it is shown: its title bar is not counted then, and a window as high as
// the screen had its status bar below it (issue 47 item 13). So once the frame is known (the
// first move or resize after showing that has one), a window that is neither maximised nor
// full screen is fitted again, frame and all, once; and so is a window restored from
// maximised (the first start maximises a window on a small screen, MainWindow).
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
    bool frameKnown() const { return m_window->frameGeometry() != m_window->geometry(); }

    QWidget* m_window;
    bool m_awaitingFrame = false; // shown before its frame was known: fitted again once it is
};

} // namespace stepdeck::ui
