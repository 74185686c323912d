#include "ScreenshotScript.h"
#include "drives/DrivePanel.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "machine/MachineContext.h"
#include "position/ReferencePanel.h"
#include "programs/InputProgramsPage.h"
#include "records/RecordsPage.h"
#include "setup/SetupPage.h"
#include "window/MainWindow.h"
#include <QCheckBox>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTextStream>

namespace stepdeck::ui {

namespace {
// The script jogs as an operator at the keyboard does: a press, then the key's auto-repeat,
// which is what proves to KeyboardJog that the key is still held.
void key(QWidget* w, QEvent::Type type, int code, bool autoRepeat)
{
    QKeyEvent e(type, code, Qt::NoModifier, QString(), autoRepeat);
    QCoreApplication::sendEvent(w, &e);
}
} // namespace

ScreenshotScript::ScreenshotScript(MainWindow* window, const QString& directory, QObject* parent)
    : QObject(parent), m_window(window), m_directory(directory)
{
    m_poll.setInterval(50);
    connect(&m_poll, &QTimer::timeout, this, &ScreenshotScript::step);
    m_repeat.setInterval(33); // a typical keyboard auto-repeat rate (30 Hz)
    connect(&m_repeat, &QTimer::timeout, this, [this] {
        for (int code : {int(Qt::Key_Right), int(Qt::Key_Up)})
            key(m_window->jogPanel(), QEvent::KeyPress, code, true);
    });
}

void ScreenshotScript::waitFor(std::function<bool()> condition, int timeoutMs,
                               std::function<void()> next)
{
    m_condition = std::move(condition);
    m_next = std::move(next);
    m_deadline = QDateTime::currentMSecsSinceEpoch() + timeoutMs;
    m_poll.start();
}

void ScreenshotScript::step()
{
    if (!m_condition() && QDateTime::currentMSecsSinceEpoch() < m_deadline)
        return;
    m_poll.stop();
    auto next = std::move(m_next);
    next();
}

void ScreenshotScript::start()
{
    MachineContext* context = m_window->context();
    auto connected = [context] { return context->isConnected(); };
    auto never = [] { return false; };
    waitFor(connected, 5000, [=] {
        if (!context->isConnected()) {
            QTextStream(stderr) << "screenshot: the simulator did not connect\n";
            Q_EMIT finished(1);
            return;
        }
        m_window->setupPage()->write(false);
        waitFor(never, 800, [=] {
            m_window->referencePanel()->referenceAll();
            auto referenced = [context] {
                const MachineStatus& s = context->status();
                bool all = !s.axes.isEmpty();
                for (const AxisStatus& a : s.axes)
                    all = all && a.referenced;
                return all;
            };
            waitFor(referenced, 40000, [=] {
                fillModelPages([=] {
                    // A diagonal keyboard jog (Right + Up held), so the pad's velocity
                    // marker, the velocities and the charts show motion.
                    JogPanel* jog = m_window->jogPanel();
                    jog->keyboardCheck()->setChecked(true);
                    jog->setFocus(Qt::OtherFocusReason);
                    m_window->activateWindow();
                    for (int code : {int(Qt::Key_Right), int(Qt::Key_Up)})
                        key(jog, QEvent::KeyPress, code, false);
                    m_repeat.start();
                    waitFor(never, 2500, [=] {
                        const bool ok = capture();
                        m_repeat.stop();
                        for (int code : {int(Qt::Key_Right), int(Qt::Key_Up)})
                            key(jog, QEvent::KeyRelease, code, false);
                        waitFor(never, 600, [=] {
                            captureLayoutStates(
                                [=](bool statesOk) { Q_EMIT finished(ok && statesOk ? 0 : 1); });
                        });
                    });
                });
            });
        });
    });
}

void ScreenshotScript::fillModelPages(std::function<void()> next)
{
    const Capabilities caps = m_window->context()->capabilities();
    RecordsPage* records = m_window->recordsPage();
    DrivePanel* drives = m_window->drivePanel();
    auto scan = [=] {
        if (!caps.multiDrive)
            return next();
        drives->scanRange(1, 5); // the simulated bus; a full scan takes seconds
        waitFor([drives] { return drives->foundTable()->rowCount() > 0; }, 10000, next);
    };
    if (caps.inputPrograms) {
        // The manual's example program (9.17) on input 8, written to the simulator.
        InputProgramsPage* programs = m_window->inputProgramsPage();
        programs->selectInput(8);
        programs->titleEdit()->setText(QStringLiteral("Eingang 8: Vektorfahrt X-Motor"));
        programs->commandsEdit()->setPlainText(QStringLiteral("L1,x191\nW1500"));
        programs->writeProgram();
        return waitFor([programs] { return programs->writeButton()->isEnabled(); }, 5000, scan);
    }
    if (!caps.records)
        return scan();
    records->readAll();
    waitFor([records] { return !records->busy(); }, 20000,
            [=] {
                records->readErrorMemory();
                waitFor([records] { return !records->busy(); }, 10000, scan);
            });
}

bool ScreenshotScript::capture()
{
    m_window->resize(1600, 1000);
    m_window->resetLayout(); // the default dock shares of this size, not of the start size
    QCoreApplication::processEvents();
    QDir dir(m_directory);
    if (!dir.mkpath(QStringLiteral("."))) {
        QTextStream(stderr) << "screenshot: cannot create " << m_directory << "\n";
        return false;
    }
    bool ok = m_window->grab().save(dir.filePath(QStringLiteral("main.png")));
    const auto pages = m_window->pages();
    for (const auto& [stem, page] : pages) {
        m_window->raisePage(page);
        QCoreApplication::processEvents();
        ok = m_window->grab().save(dir.filePath(QStringLiteral("window-%1.png").arg(stem))) && ok;
    }
    // What an operator sees on a 1366x768 screen with the default layout (issue 11).
    m_window->resize(1366, 768);
    m_window->resetLayout();
    m_window->raisePage(m_window->setupPage());
    QCoreApplication::processEvents();
    ok = m_window->grab().save(dir.filePath(QStringLiteral("main-1366x768.png"))) && ok;
    m_window->resize(1600, 1000);
    m_window->resetLayout();
    QCoreApplication::processEvents();
    // Each page on its own at a size that shows all of it: docks float for the picture.
    static const QMap<QString, QSize> sizes{
        {QStringLiteral("position"), {480, 400}}, {QStringLiteral("reference"), {560, 300}},
        {QStringLiteral("status"), {470, 1020}},  {QStringLiteral("setup"), {1100, 760}},
        {QStringLiteral("traffic"), {1000, 560}}, {QStringLiteral("charts"), {1200, 640}},
        {QStringLiteral("gamepad"), {440, 560}},  {QStringLiteral("drives"), {620, 520}},
        {QStringLiteral("records"), {1300, 820}}, {QStringLiteral("inputPrograms"), {1000, 480}},
    };
    for (const auto& [stem, page] : pages) {
        QDockWidget* dock = m_window->dockOf(page);
        if (dock && sizes.contains(stem)) {
            dock->setFloating(true);
            dock->resize(sizes.value(stem));
            dock->show();
            QCoreApplication::processEvents();
        }
        ok = page->grab().save(dir.filePath(QStringLiteral("%1.png").arg(stem))) && ok;
    }
    QTextStream(stdout) << "screenshots written to " << dir.absolutePath() << "\n";
    return ok;
}

} // namespace stepdeck::ui
