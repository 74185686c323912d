#pragma once
#include <QScrollArea>

namespace stepdeck::ui {

// The centre's room for the jog panel, below STOP, PANIC and the banner (issue 47 item 13).
// By default as high as the panel needs: the main window keeps that room (the centre's minimum
// height), the Program dock below gets the rest, and nothing scrolls. The separator above the
// Program dock did not move because of that minimum; now, while the operator drags a dock
// separator (beginDrag, MainWindow), the jog area may shrink to nothing, and the height it has
// when the drag ends is the operator's room (endDrag; each workspace keeps its own, Workspaces):
// the jog panel then scrolls up and down inside it, STOP, PANIC and the banner stay whole, and
// the toolpath has the height. Dragged back to the panel's height or more, or View > Reset
// layout, and the room is the panel's whole height again.
// Never scrolled sideways: as wide as the panel needs (its scroll bar included while the room
// is short of the panel). Neither the arrow and page keys (the keyboard jog's) nor the wheel
// while a button is held (a pad being dragged) scroll it; a scroll under a held pad ends that
// jog (JoystickPad watches its ancestors).
class JogArea : public QScrollArea
{
    Q_OBJECT
public:
    static constexpr int kWhole = -1; // room(): the panel's whole height

    JogArea(QWidget* panel, QWidget* parent);

    // The operator's room in pixels, or kWhole.
    int room() const { return m_room; }
    void setRoom(int height);
    // The operator gave some of the panel's height to the Program dock: the panel scrolls, and
    // that is no "window too small" (WorkspaceFit).
    bool isShortByChoice() const
    {
        return m_jobCollapsed || (m_room != kWhole && m_room < neededHeight());
    }
    // A dock separator is being dragged: any height down to none, until endDrag() keeps the
    // height the area has then.
    void beginDrag();
    void endDrag();
    bool isDragged() const { return m_dragged; }
    // A job has the pad's room (JobLayout, issue 47 item 15): any height down to none, the
    // operator's room() kept for the job's end.
    void setJobCollapsed(bool collapsed);
    bool isJobCollapsed() const { return m_jobCollapsed; }
    // The panel's whole height (what it takes not to scroll).
    int neededHeight() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void changed(); // the minimum changed: here and in the centre that holds the area

    int m_room = kWhole;
    bool m_dragged = false;
    bool m_jobCollapsed = false;
    int m_heightAtDrag = 0;
};

} // namespace stepdeck::ui
