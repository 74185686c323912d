#include "WorkspaceFit.h"
#include "MainWindowJogArea.h"
#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>
#include <QScrollArea>
#include <QScrollBar>

namespace stepdeck::ui {

namespace {
// The settling time: the dock layout applies a resize on posted layout requests, the scroll
// areas decide on their bars after that.
constexpr int kSettleMs = 150;

QString pageTitle(const QScrollArea* area)
{
    for (const QWidget* w = area; w; w = w->parentWidget()) {
        if (auto* dock = qobject_cast<const QDockWidget*>(w))
            return dock->windowTitle();
    }
    return WorkspaceFit::tr("Jog controls"); // the centre's one page
}

// The centre's jog area w is (or is in), or nullptr.
const JogArea* enclosingJogArea(const QWidget* w)
{
    for (; w; w = w->parentWidget()) {
        if (auto* jog = qobject_cast<const JogArea*>(w))
            return jog;
    }
    return nullptr;
}
} // namespace

WorkspaceFit::WorkspaceFit(QMainWindow* window) : QObject(window), m_window(window)
{
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &WorkspaceFit::report);
    window->installEventFilter(this);
}

void WorkspaceFit::schedule()
{
    m_fitAsked = false;
    m_settle.start();
}

void WorkspaceFit::setSidewaysOnly(bool on)
{
    m_sidewaysOnly = on;
}

bool WorkspaceFit::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_window && (event->type() == QEvent::Resize || event->type() == QEvent::Show))
        schedule();
    return QObject::eventFilter(watched, event);
}

QStringList WorkspaceFit::scrollingPages() const
{
    QStringList pages;
    for (const QScrollArea* area : m_window->findChildren<QScrollArea*>()) {
        if (!area->widgetResizable() || !area->isVisible() || area->visibleRegion().isEmpty())
            continue;
        // The operator gave the jog pad's height to the Program dock: no news, for the pad nor
        // for its column of controls (the pad at its least height).
        if (const JogArea* jog = enclosingJogArea(area); jog && jog->isShortByChoice())
            continue;
        const bool upAndDown = !m_sidewaysOnly && area->verticalScrollBar()->isVisible();
        if (upAndDown || area->horizontalScrollBar()->isVisible()) {
            const QString title = pageTitle(area);
            if (!pages.contains(title))
                pages << title;
        }
    }
    pages.sort();
    return pages;
}

void WorkspaceFit::report()
{
    if (!m_fitAsked) {
        m_fitAsked = true;
        Q_EMIT fitRequested();
        m_settle.start(); // then look, once that layout settled too
        return;
    }
    m_fitAsked = false;
    const QStringList pages = m_window->isVisible() ? scrollingPages() : QStringList();
    if (pages == m_reported)
        return;
    m_reported = pages;
    Q_EMIT fitChanged(pages.isEmpty()
                          ? QString()
                          : tr("The window is too small for these pages, they scroll: %1. A "
                               "larger window, or View > Reset layout, gives them room.")
                                .arg(pages.join(QStringLiteral(", "))));
}

} // namespace stepdeck::ui
