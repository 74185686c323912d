// `--screenshot`: the main window at 1366x768 in the states in which its layout once moved
// under the operator's hand (issue 16): idle, during a move, with the longest message, and
// after a reconnect. Each picture is the whole window with its default layout.
#include "connection/ConnectionBar.h"
#include "controller/Controller.h"
#include "machine/MachineContext.h"
#include "messages/StatusMessages.h"
#include "safety/SafetyBanner.h"
#include "setup/SetupPage.h"
#include "window/MainWindow.h"
#include "window/ScreenshotScript.h"
#include <QCoreApplication>
#include <QDir>

namespace stepdeck::ui {

namespace {
// The longest message text the window has: the longest banner text and the note of a model
// without a stop command, one after the other.
QString longestMessage()
{
    QString longest;
    for (const QString& text : SafetyBanner::possibleTexts()) {
        if (text.size() > longest.size())
            longest = text;
    }
    return longest + QLatin1Char(' ') + Controller::noStopCommandText();
}
} // namespace

bool ScreenshotScript::captureState(const QString& state)
{
    QCoreApplication::processEvents();
    const QString file =
        QDir(m_directory).filePath(QStringLiteral("layout-1366x768-%1.png").arg(state));
    return m_window->grab().save(file);
}

void ScreenshotScript::captureLayoutStates(std::function<void(bool)> done)
{
    MachineContext* context = m_window->context();
    auto never = [] { return false; };
    m_window->resize(1366, 768);
    m_window->resetLayout();
    m_window->raisePage(m_window->setupPage());
    m_window->messages()->clearAll();
    waitFor(never, 300, [=] {
        bool ok = captureState(QStringLiteral("idle"));
        context->session()->moveRelative({{Axis::X, 20000}});
        auto moving = [context] { return context->status().axes.value(Axis::X).moving; };
        waitFor(moving, 3000, [=] {
            waitFor(never, 500, [=] {
                const bool movingOk = captureState(QStringLiteral("moving"));
                m_window->showError(longestMessage());
                const bool errorOk = captureState(QStringLiteral("long-error"));
                context->stop();
                context->disconnectFromController();
                auto disconnected = [context] { return !context->isConnected(); };
                waitFor(disconnected, 3000, [=] {
                    m_window->connectionBar()->connectNow();
                    auto connected = [context] { return context->isConnected(); };
                    waitFor(connected, 5000, [=] {
                        waitFor(never, 800, [=] {
                            done(ok && movingOk && errorOk &&
                                 captureState(QStringLiteral("reconnected")));
                        });
                    });
                });
            });
        });
    });
}

} // namespace stepdeck::ui
