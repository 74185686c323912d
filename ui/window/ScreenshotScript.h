#pragma once
#include <QObject>
#include <QTimer>

namespace stepdeck::ui {

class MainWindow;

// `stepdeck --simulate elab --screenshot DIR`: drives the window through a short scripted
// session against the simulator (write the setup, reference, jog) and saves every main page
// to DIR as PNG (QWidget::grab, works offscreen), then the window at 1366x768 idle, moving,
// with the longest message and after a reconnect; then quits with 0 (or 1 on failure).
class ScreenshotScript : public QObject
{
    Q_OBJECT
public:
    ScreenshotScript(MainWindow* window, const QString& directory, QObject* parent = nullptr);

    void start();

Q_SIGNALS:
    void finished(int exitCode);

private:
    void step();
    void waitFor(std::function<bool()> condition, int timeoutMs, std::function<void()> next);
    bool capture();
    // Fills the model-specific pages (records, error memory, bus scan), then calls next.
    void fillModelPages(std::function<void()> next);
    // layout-1366x768-{idle,moving,long-error,reconnected}.png (ScreenshotLayoutStates.cpp).
    void captureLayoutStates(std::function<void(bool)> done);
    bool captureState(const QString& state);

    MainWindow* m_window;
    QString m_directory;
    QTimer m_poll;
    QTimer m_repeat; // key auto-repeat of the scripted jog
    std::function<bool()> m_condition;
    std::function<void()> m_next;
    qint64 m_deadline = 0;
};

} // namespace stepdeck::ui
