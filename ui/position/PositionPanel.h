#pragma once
#include <QWidget>

namespace stepdeck::ui {

class MachineContext;
class MachineDro;
class MachineGoTo;
class SpindleCoolantBar;

// The Position dock: the machine's read-out (MachineDro: every axis in its units, work and
// machine position, how each is known) and its Go to (MachineGoTo). Every connection is a
// machine (issue 28, item 0), so this is the one position display for a controller of the
// connection bar as for a machine file; units and soft limits are the machine's, edited in
// the machine editor ("Units and limits…" asks for it). Below them the spindle and the
// coolant with a switch each (SpindleCoolantBar, issue 47).
class PositionPanel : public QWidget
{
    Q_OBJECT
public:
    explicit PositionPanel(MachineContext* context, QWidget* parent = nullptr);

    MachineDro* machineDro() const { return m_machineDro; }
    MachineGoTo* machineGoTo() const { return m_machineGoTo; }
    SpindleCoolantBar* spindleCoolant() const { return m_spindleCoolant; }

Q_SIGNALS:
    // The operator asked to edit the machine's axes (units, soft limits, referencing).
    void editMachineRequested();

private:
    MachineDro* m_machineDro;
    MachineGoTo* m_machineGoTo;
    SpindleCoolantBar* m_spindleCoolant;
};

} // namespace stepdeck::ui
