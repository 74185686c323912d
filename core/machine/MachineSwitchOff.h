#pragma once
#include "controller/ControllerSession.h"
#include <QCoreApplication>
#include <QList>
#include <QTimer>

namespace stepdeck::machine {

class Machine;

// Spindle and coolant off after a stop, a panic or a program's end (issue 47), as LinuxCNC
// does on abort, on emergency stop and at M2/M30, and GRBL on a reset. One part per connected
// controller whose capabilities have a spindle or coolant: its switch-off requests go out once
// its status shows the axes standing (the E-LAB board takes <SOH> and <SI> only at standstill,
// and refuses them while it brakes: such a refusal is tried again at the next status), and the
// part is done when the controller acknowledged both. The Machine forwards its sessions'
// statuses, results and link changes here; the end is the Machine's spindleAndCoolantOff.
class MachineSwitchOff
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::machine::Machine)
public:
    // How long the axes may take to stand and the controller to acknowledge: past it the
    // switch-off ends failed, and the operator is told to switch off by hand.
    static constexpr int kWaitMs = 15000;

    explicit MachineSwitchOff(Machine& machine);

    void start(); // anew, also while one runs
    bool isRunning() const { return !m_parts.isEmpty(); }
    void onStatus(ControllerSession* session);
    void onResult(ControllerSession* session, const CommandResult& result);
    void onLinkLost(ControllerSession* session);
    void cancel(); // the machine closes: nothing more is sent, nothing is said

private:
    struct Part
    {
        ControllerSession* session = nullptr;
        bool spindle = false; // still to switch off
        bool coolant = false;
        RequestId spindleRequest = 0; // under way
        RequestId coolantRequest = 0;
    };

    void send(Part& part);
    void finishIfDone();
    void fail(const QString& message);

    Machine& m_machine;
    QList<Part> m_parts;
    QTimer m_deadline;
};

} // namespace stepdeck::machine
