#include "MainWindowJogArea.h"
#include <QEvent>
#include <QKeyEvent>
#include <QScrollBar>
#include <QWheelEvent>

namespace stepdeck::ui {

JogArea::JogArea(QWidget* panel, QWidget* parent) : QScrollArea(parent)
{
    setObjectName(QStringLiteral("jogScroll"));
    setFrameShape(QFrame::NoFrame);
    setWidgetResizable(true);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setFocusPolicy(Qt::NoFocus); // the arrows keep jogging
    setWidget(panel);
}

int JogArea::neededHeight() const
{
    const QWidget* panel = widget();
    return panel ? qMax(panel->minimumSizeHint().height(), panel->minimumHeight()) : 0;
}

void JogArea::setRoom(int height)
{
    const int room = height < 0 ? kWhole : height;
    if (room == m_room)
        return;
    m_room = room;
    changed();
}

void JogArea::beginDrag()
{
    if (m_dragged)
        return;
    m_dragged = true;
    m_heightAtDrag = height();
    changed();
}

void JogArea::setJobCollapsed(bool collapsed)
{
    if (collapsed == m_jobCollapsed)
        return;
    m_jobCollapsed = collapsed;
    changed();
}

void JogArea::endDrag()
{
    if (!m_dragged)
        return;
    m_dragged = false;
    // During a job the drag moved the job's split only; the operator's room stays for its end.
    if (m_jobCollapsed) {
        changed();
        return;
    }
    // What the drag left: the whole panel, or the operator's share of it. A press that moved
    // nothing (another separator, a click) changes nothing.
    if (height() != m_heightAtDrag) {
        const int has = height() - 2 * frameWidth();
        m_room = has >= neededHeight() ? kWhole : qMax(0, has);
    }
    changed();
}

QSize JogArea::sizeHint() const
{
    const QWidget* panel = widget();
    return panel ? panel->sizeHint().expandedTo(minimumSizeHint()) : QScrollArea::sizeHint();
}

QSize JogArea::minimumSizeHint() const
{
    const QWidget* panel = widget();
    if (!panel)
        return QScrollArea::minimumSizeHint();
    const int need = neededHeight();
    const int least = m_dragged || m_jobCollapsed ? 0
                      : m_room == kWhole          ? need
                                                  : qMin(m_room, need);
    int wide = qMax(panel->minimumSizeHint().width(), panel->minimumWidth());
    // Short of the panel the scroll bar shows beside it: room for both, nothing cut on the
    // right (no scrolling sideways).
    if (m_dragged || m_jobCollapsed || least < need)
        wide += verticalScrollBar()->sizeHint().width();
    return QSize(wide, least) + QSize(2 * frameWidth(), 2 * frameWidth());
}

void JogArea::changed()
{
    updateGeometry();
    // The main window's layout caches the centre's minimum: a separator being dragged sees the
    // new one at once (QMainWindowLayout reads it on every step of the drag).
    if (QWidget* centre = parentWidget())
        centre->updateGeometry();
}

bool JogArea::event(QEvent* event)
{
    // The panel's own minimum changed (a machine of more axes): so did the area's.
    if (event->type() == QEvent::LayoutRequest)
        updateGeometry();
    return QScrollArea::event(event);
}

void JogArea::keyPressEvent(QKeyEvent* event)
{
    event->ignore(); // arrows and Page Up/Down are the keyboard jog's, never a scroll
}

void JogArea::wheelEvent(QWheelEvent* event)
{
    // Not while a pad is held: nothing moves under the operator's hand.
    if (event->buttons() != Qt::NoButton) {
        event->ignore();
        return;
    }
    QScrollArea::wheelEvent(event);
}

} // namespace stepdeck::ui
