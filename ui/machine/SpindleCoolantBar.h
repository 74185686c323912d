#pragma once
#include <QWidget>

class QPushButton;
class QSpinBox;

namespace stepdeck {
class ControllerSession;
}
namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::ui {

class LedIndicator;
class MachineContext;

// The spindle and the coolant in the Run workspace's Position dock (issue 47): each one's state,
// marked by how it is known -- the spindle as the board reads it back (E-LAB tmSpindleOn), S as
// last written in rpm (the machine file's spindle scale; the board cannot read a speed back), the
// coolant as last switched in this session (the board cannot read its relay back; unknown before)
// -- and a switch each. The switches work while no program runs (at M0 or M6 too); while one runs
// the program owns them and STOP switches both off (Machine::stop). Nothing moves: the texts keep
// their room.
class SpindleCoolantBar : public QWidget
{
    Q_OBJECT
public:
    explicit SpindleCoolantBar(MachineContext* context, QWidget* parent = nullptr);

    void setProgramRunning(bool running); // a run (not held) owns the switches
    QString spindleText() const;
    QString coolantText() const;
    QPushButton* spindleButton() const { return m_spindleSwitch; }
    QPushButton* coolantButton() const { return m_coolantSwitch; }
    QSpinBox* rpmBox() const { return m_rpm; }

private:
    void refresh();
    void fitSpeedRange(const machine::Machine* m, const ControllerSession* s);
    void switchSpindle();
    void switchCoolant();

    MachineContext* m_context;
    LedIndicator* m_spindle;
    QSpinBox* m_rpm;
    QPushButton* m_spindleSwitch;
    LedIndicator* m_coolant;
    QPushButton* m_coolantSwitch;
    bool m_programRunning = false;
};

} // namespace stepdeck::ui
