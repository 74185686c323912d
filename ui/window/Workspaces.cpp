#include "Workspaces.h"
#include "MainWindowJogArea.h"
#include <QAction>
#include <QActionGroup>
#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>
#include <QSettings>
#include <QTabBar>

namespace stepdeck::ui {

namespace {
// A layout's version: a layout saved by another arrangement of docks is not restored.
constexpr int kLayoutVersion = 34;
const char* const kKeys[2] = {"window/workspace/run", "window/workspace/setup"};
const char* const kJogRoomKeys[2] = {"window/jogRoom/run", "window/jogRoom/setup"};
const char* const kCurrentKey = "window/workspace/current";
// The window height from which the Run workspace's left column holds the position and
// referencing one above the other (four axes each; a Full HD screen less a panel and a title
// bar has 1020).
constexpr int kBothInTheColumn = 900;
} // namespace

Workspaces::Workspaces(QMainWindow* window, const QStringList& runDocks,
                       const QStringList& setupDocks)
    : QObject(window), m_window(window), m_tabs(new QTabBar(window))
{
    m_docks[0] = runDocks;
    m_docks[1] = setupDocks;
    m_tabs->setObjectName(QStringLiteral("workspaceTabs"));
    m_tabs->setDocumentMode(true);
    m_tabs->setDrawBase(false);
    m_tabs->setFocusPolicy(Qt::NoFocus); // the arrows keep jogging
    m_tabs->addTab(tr("Run"));
    m_tabs->addTab(tr("Setup"));
    m_tabs->setTabToolTip(0, tr("The program, its preview, the position and the jog pad "
                                "(Ctrl+1)"));
    m_tabs->setTabToolTip(1, tr("Parameters, drives, records, traffic, charts and status "
                                "(Ctrl+2)"));
    auto* group = new QActionGroup(this);
    const QString names[2] = {tr("&Run workspace"), tr("&Setup workspace")};
    const QKeySequence keys[2] = {QKeySequence(Qt::CTRL | Qt::Key_1),
                                  QKeySequence(Qt::CTRL | Qt::Key_2)};
    for (int i = 0; i < 2; ++i) {
        m_actions[i] = new QAction(names[i], this);
        m_actions[i]->setCheckable(true);
        m_actions[i]->setShortcut(keys[i]);
        m_actions[i]->setShortcutContext(Qt::ApplicationShortcut);
        group->addAction(m_actions[i]);
        const Workspace w = i == 0 ? Workspace::Run : Workspace::Setup;
        connect(m_actions[i], &QAction::triggered, this, [this, w] {
            m_byHand = true;
            switchTo(w);
        });
        window->addAction(m_actions[i]);
    }
    connect(m_tabs, &QTabBar::tabBarClicked, this, [this](int i) {
        if (i < 0)
            return;
        m_byHand = true;
        switchTo(i == 0 ? Workspace::Run : Workspace::Setup);
    });
}

QAction* Workspaces::action(Workspace workspace) const
{
    return m_actions[index(workspace)];
}

bool Workspaces::belongsToCurrent(QDockWidget* dock) const
{
    return dock && m_docks[index(m_current)].contains(dock->objectName());
}

QDockWidget* Workspaces::dock(const QString& name) const
{
    return m_window->findChild<QDockWidget*>(name);
}

QByteArray Workspaces::defaultLayout(Workspace workspace)
{
    const QStringList& shown = m_docks[index(workspace)];
    for (QDockWidget* d : m_window->findChildren<QDockWidget*>())
        d->setVisible(shown.contains(d->objectName()) && d->toggleViewAction()->isVisible());
    m_current = workspace;
    if (m_jogArea)
        m_jogArea->setRoom(JogArea::kWhole); // the whole jog pad, the rest to the docks
    setCorners(workspace);
    arrange(workspace);
    return m_window->saveState(kLayoutVersion);
}

void Workspaces::setCorners(Workspace workspace)
{
    // Run: the position column runs the whole height, the program spans the rest below the
    // centre. Setup: the setup pages span the whole width below.
    m_window->setCorner(Qt::BottomLeftCorner, workspace == Workspace::Run
                                                  ? Qt::LeftDockWidgetArea
                                                  : Qt::BottomDockWidgetArea);
}

void Workspaces::arrange(Workspace workspace)
{
    const int width = m_window->width();
    const int height = m_window->height();
    QDockWidget* position = dock(QStringLiteral("positionDock"));
    if (workspace == Workspace::Run) {
        // The program (its lines and preview) gets 37 % of the height, from a Full HD height
        // half of it (issue 47 item 13: the toolpath is what a running job is watched by), the
        // centre (the jog pad and its controls) the rest above it, never less than the jog
        // pad needs; the position the left column, the read-out's room (issue 16). Dragging
        // the separator gives the program more, the jog pad then scrolls (JogArea).
        QDockWidget* program = dock(QStringLiteral("programDock"));
        // Below a Full HD height, referencing behind the position, one click away: the
        // position of four axes with Go to takes the column's height at 1366x768 less a panel
        // and a title bar, and "Reference all" stands in the centre.
        if (QDockWidget* reference = dock(QStringLiteral("referenceDock"));
            reference && position && height < kBothInTheColumn) {
            m_window->tabifyDockWidget(position, reference);
            position->raise();
        }
        m_window->resizeDocks({position}, {qBound(300, width * 30 / 100, 480)}, Qt::Horizontal);
        const int programShare = height < kBothInTheColumn ? qBound(200, height * 37 / 100, 600)
                                                           : qBound(200, height / 2, 900);
        m_window->resizeDocks({program}, {programShare}, Qt::Vertical);
        fitContent();
        return;
    }
    // Shares of the window, so the default layout suits 1024x768 as well as Full HD: the
    // side docks a third and a fifth of the width (a little more: the German gamepad page's
    // mapping at 1366), the bottom tabs a third of the height. The status lamps arrange
    // themselves in one column when narrow.
    QDockWidget* status = dock(QStringLiteral("statusDock"));
    QDockWidget* setup = dock(QStringLiteral("setupDock"));
    m_window->resizeDocks({position, status},
                          {qBound(220, width * 32 / 100, 480), qBound(220, width * 21 / 100, 470)},
                          Qt::Horizontal);
    m_window->resizeDocks({setup}, {qBound(160, height / 3, 320)}, Qt::Vertical);
}

void Workspaces::initialise()
{
    // Both defaults from the layout as built (every dock in place), the Setup one first.
    const QByteArray built = m_window->saveState(kLayoutVersion);
    m_default[1] = defaultLayout(Workspace::Setup);
    m_window->restoreState(built, kLayoutVersion);
    m_default[0] = defaultLayout(Workspace::Run);
    const QSettings settings;
    for (int i = 0; i < 2; ++i) {
        const QByteArray saved = settings.value(QLatin1String(kKeys[i])).toByteArray();
        m_state[i] = saved.isEmpty() ? m_default[i] : saved;
        m_jogRoom[i] =
            saved.isEmpty()
                ? JogArea::kWhole
                : settings.value(QLatin1String(kJogRoomKeys[i]), JogArea::kWhole).toInt();
    }
    const bool run =
        settings.value(QLatin1String(kCurrentKey), QStringLiteral("setup")).toString() ==
        QLatin1String("run");
    const Workspace start = run ? Workspace::Run : Workspace::Setup;
    apply(start, m_state[index(start)], m_jogRoom[index(start)]);
    announce();
}

void Workspaces::apply(Workspace workspace, const QByteArray& state, int jogRoom)
{
    setCorners(workspace);
    // The jog pad's room first: the layout restored may give the program more than the centre
    // would let it have with the whole pad.
    if (m_jogArea)
        m_jogArea->setRoom(jogRoom);
    // A layout that does not restore (another version) falls back to the default.
    if (!m_window->restoreState(state, kLayoutVersion)) {
        if (m_jogArea)
            m_jogArea->setRoom(JogArea::kWhole);
        m_jogRoom[index(workspace)] = JogArea::kWhole;
        m_window->restoreState(m_default[index(workspace)], kLayoutVersion);
    }
    m_current = workspace;
}

void Workspaces::switchTo(Workspace workspace)
{
    if (workspace != m_current) {
        m_state[index(m_current)] = m_window->saveState(kLayoutVersion);
        if (m_jogArea)
            m_jogRoom[index(m_current)] = m_jogArea->room();
        apply(workspace, m_state[index(workspace)], m_jogRoom[index(workspace)]);
    }
    announce();
}

void Workspaces::announce()
{
    m_tabs->setCurrentIndex(index(m_current));
    m_actions[index(m_current)]->setChecked(true);
    // Once the restored layout has its geometry.
    QMetaObject::invokeMethod(this, &Workspaces::fitContent, Qt::QueuedConnection);
    Q_EMIT switched(m_current);
}

void Workspaces::suggest(Workspace workspace)
{
    if (!m_byHand && workspace != m_current)
        switchTo(workspace);
}

void Workspaces::resetCurrent()
{
    m_state[index(m_current)] = m_default[index(m_current)];
    m_jogRoom[index(m_current)] = JogArea::kWhole;
    apply(m_current, m_default[index(m_current)], JogArea::kWhole);
    arrange(m_current); // for the window's size now
    announce();
}

namespace {
// How much larger than now a dock must be for its page not to scroll (0: it fits), in height
// or width.
int missing(QDockWidget* dock, Qt::Orientation orientation)
{
    auto* scroll = dock ? qobject_cast<QScrollArea*>(dock->widget()) : nullptr;
    if (!scroll || !scroll->widget() || !Workspaces::isOnScreen(dock) || dock->isFloating())
        return 0;
    const QSize needed = scroll->widget()->minimumSizeHint();
    const QSize has = scroll->viewport()->size();
    return qMax(0, orientation == Qt::Vertical ? needed.height() - has.height()
                                               : needed.width() - has.width());
}
} // namespace

bool Workspaces::isOnScreen(const QDockWidget* dock)
{
    // A dock behind another's tab is visible too, moved off the window (QWidgetAnimator).
    return dock && dock->isVisible() && !dock->visibleRegion().isEmpty();
}

void Workspaces::fitContent()
{
    if (m_current != Workspace::Run)
        return;
    // Only what would scroll grows (a machine of more axes, longer German texts); a dock the
    // operator made larger stays so.
    QDockWidget* position = dock(QStringLiteral("positionDock"));
    QDockWidget* reference = dock(QStringLiteral("referenceDock"));
    QDockWidget* program = dock(QStringLiteral("programDock"));
    // The read-out as high as its content asks (every axis, Go to), referencing below it.
    if (const int more = missing(position, Qt::Vertical); more > 0) {
        if (isOnScreen(reference) && !reference->isFloating())
            m_window->resizeDocks({position, reference},
                                  {position->height() + more, qMax(0, reference->height() - more)},
                                  Qt::Vertical);
        else
            m_window->resizeDocks({position}, {position->height() + more}, Qt::Vertical);
    }
    // Referencing likewise, from what the read-out has to spare.
    auto* positionScroll = position ? qobject_cast<QScrollArea*>(position->widget()) : nullptr;
    if (const int more = missing(reference, Qt::Vertical);
        more > 0 && positionScroll && positionScroll->widget() && !position->isFloating()) {
        const int spare = positionScroll->viewport()->height() -
                          positionScroll->widget()->minimumSizeHint().height();
        const int moved = qMin(more, spare);
        if (moved > 0)
            m_window->resizeDocks({position, reference},
                                  {position->height() - moved, reference->height() + moved},
                                  Qt::Vertical);
    }
    if (const int more = missing(program, Qt::Vertical); more > 0)
        m_window->resizeDocks({program}, {program->height() + more}, Qt::Vertical);
    if (const int more = missing(position, Qt::Horizontal); more > 0)
        m_window->resizeDocks({position}, {position->width() + more}, Qt::Horizontal);
}

void Workspaces::save() const
{
    QSettings settings;
    for (int i = 0; i < 2; ++i) {
        const bool current = i == index(m_current);
        const QByteArray state = current ? m_window->saveState(kLayoutVersion) : m_state[i];
        settings.setValue(QLatin1String(kKeys[i]), state);
        settings.setValue(QLatin1String(kJogRoomKeys[i]),
                          current && m_jogArea ? m_jogArea->room() : m_jogRoom[i]);
    }
    settings.setValue(QLatin1String(kCurrentKey), m_current == Workspace::Run
                                                      ? QStringLiteral("run")
                                                      : QStringLiteral("setup"));
}

} // namespace stepdeck::ui
