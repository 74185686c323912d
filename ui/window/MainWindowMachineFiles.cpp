// MainWindow, the File menu's machine files: what opens a machine, and the machine editor's
// Re-open machine (issue 31) with its refusal while anything moves or runs.
#include "MainWindow.h"
#include "bridge/LaserBridgePage.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineControl.h"
#include "machine/MachineFileActions.h"
#include "machine/MachineMdi.h"
#include "machine/MachineStopWatch.h"
#include "messages/StatusMessages.h"
#include "position/PositionPanel.h"
#include "program/ProgramPage.h"

namespace stepdeck::ui {

void MainWindow::connectMachineFiles(MachineFileActions* files)
{
    connect(m_position, &PositionPanel::editMachineRequested, files,
            &MachineFileActions::editMachine);
    // An opened machine is the one "Edit machine…" edits; an invalid file opens nothing and
    // its message names the field.
    connect(files, &MachineFileActions::openRequested, this, [this, files](const QString& path) {
        if (openMachine(path))
            files->setCurrentMachine(path);
    });
    connect(files, &MachineFileActions::openMachineSaved, this, [this](const QString& text) {
        m_messages->show(StatusMessages::Owner::General, text, StatusMessages::Severity::Info,
                         30000);
    });
    files->setReopen([this](const QString& path) { return reopenMachine(path); });
}

QString MainWindow::machineBusyText() const
{
    const machine::Machine* m = m_context->machine();
    // A program or an MDI line (Go to included), checked or running: what holds the motion.
    if (m && !m->motionHolder().isEmpty())
        return m->motionHolder();
    if (m_laserBridge && m_laserBridge->isRunning())
        return tr("the laser bridge runs");
    if (!m)
        return {};
    if (m->isReferencing())
        return tr("a reference run is under way");
    if (m_machineControl->isFollowingStop())
        return tr("a stop is still waiting for its confirmation");
    for (const machine::MachineController& c : m->description().controllers) {
        const ControllerSession* s = m->session(c.id);
        if (s && s->linkState() == LinkState::Connected && MachineStopWatch::motionIn(s->status()))
            return tr("the machine is moving (%1): stop it first").arg(c.id);
    }
    return {};
}

QString MainWindow::reopenMachine(const QString& path)
{
    const QString busy = machineBusyText();
    if (!busy.isEmpty()) {
        m_messages->show(StatusMessages::Owner::General, tr("Machine not re-opened: %1").arg(busy));
        return busy;
    }
    const bool wasConnected = m_context->machineLinkBusy();
    // The ordinary open: the file is read and checked first (an invalid one leaves the
    // machine as it is), then the machine open now stops and closes every controller
    // (MachineContext::uninstall) and the new one is built with new sessions. Positions are
    // unknown until referenced, as on any connect (Controller::markAllUnreferenced).
    if (!openMachine(path))
        return tr("the saved file does not open: see the message line");
    if (wasConnected)
        m_machineControl->connect();
    m_messages->show(StatusMessages::Owner::General,
                     tr("Machine re-opened from %1: positions are unknown until the axes are "
                        "referenced again.")
                         .arg(path),
                     StatusMessages::Severity::Info, 15000);
    return {};
}

} // namespace stepdeck::ui
