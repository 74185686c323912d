#pragma once
#include <QObject>
#include <QStringList>
#include <QTimer>

class QMainWindow;

namespace stepdeck::ui {

// Whether the window's pages fit it (issue 31: "a layout that cannot fit says so instead of
// clipping"). A page that cannot have the room it needs scrolls; this names those pages once
// the layout settled after a resize, a new machine or a workspace switch, so the operator
// learns why something is out of sight. A page is a QScrollArea that sizes its widget to
// itself (the docks' pages, the jog panel's column) and is on screen; editors, tables and
// views scroll by nature and do not count, nor does the jog pad the operator gave some of its
// height to the Program dock (JogArea::isShortByChoice). In the Setup workspace only a page
// that scrolls sideways counts (setSidewaysOnly): its forms and lists (every axis' parameters,
// the status lamps, the records) are longer than any screen, and a Full HD window said "too
// small" for them (issue 47 item 13).
class WorkspaceFit : public QObject
{
    Q_OBJECT
public:
    explicit WorkspaceFit(QMainWindow* window);

    // Checks again once the layout settled.
    void schedule();
    // Only pages that scroll sideways count (the Setup workspace); else either way.
    void setSidewaysOnly(bool on);
    bool sidewaysOnly() const { return m_sidewaysOnly; }
    // The titles of the pages that scroll now (empty: everything fits).
    QStringList scrollingPages() const;
    QStringList lastReported() const { return m_reported; }

Q_SIGNALS:
    // Once the layout settled, before looking: the workspace may give its docks the room
    // their pages need (Workspaces::fitContent, e.g. after the window grew again).
    void fitRequested();
    // Only when the set changes: text says which pages scroll, or is empty once all fit.
    void fitChanged(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void report();

    QMainWindow* m_window;
    QTimer m_settle;
    bool m_fitAsked = false; // the first phase done: fitRequested() was sent
    bool m_sidewaysOnly = false;
    QStringList m_reported;
};

} // namespace stepdeck::ui
