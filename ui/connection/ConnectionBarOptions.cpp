// ConnectionBar, part 2: the reset line, the options menu (recent ports, auto-reconnect) and
// reconnecting to a USB device that came back (issues 7 and 10).
#include "connection/ConnectionBar.h"
#include "connection/ConnectionSettings.h"
#include "connection/PortScanner.h"
#include "connection/PortWatcher.h"
#include "machine/MachineContext.h"
#include "protocols/Registry.h"
#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QToolButton>

namespace stepdeck::ui {

void ConnectionBar::buildOptions()
{
    m_options->setText(QStringLiteral("\u22ef"));
    m_options->setToolTip(tr("Recent ports and reconnect options"));
    m_options->setAccessibleName(tr("Connection options"));
    m_options->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(m_options);
    m_recentMenu = menu->addMenu(tr("Recent ports"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &ConnectionBar::fillRecentPorts);
    fillRecentPorts();
    menu->addSeparator();
    m_autoReconnect = menu->addAction(tr("Reconnect when the USB device returns"));
    m_autoReconnect->setToolTip(
        tr("When the USB adapter of a lost link is plugged in again (same vendor, product and "
           "serial number), connect again. Positions count as unknown afterwards and nothing "
           "resumes by itself."));
    m_autoReconnect->setCheckable(true);
    m_autoReconnect->setChecked(connectionsettings::autoReconnect());
    connect(m_autoReconnect, &QAction::toggled, this, [this](bool on) {
        connectionsettings::setAutoReconnect(on);
        if (!on)
            m_watcher->forget();
    });
    m_options->setMenu(menu);
}

void ConnectionBar::fillRecentPorts()
{
    m_recentMenu->clear();
    const QStringList ports = connectionsettings::recentPorts();
    for (const QString& port : ports) {
        const QString text =
            port == QLatin1String("sim") ? tr("Simulator (in-process)") : QString(port);
        QAction* action = m_recentMenu->addAction(text, this, [this, port] { setPortSpec(port); });
        action->setData(port);
        action->setEnabled(m_port->isEnabled());
    }
    if (ports.isEmpty())
        m_recentMenu->addAction(tr("(none yet)"))->setEnabled(false);
}

void ConnectionBar::updateResetLine()
{
    const ModelInfo* model = findModel(selectedModelId());
    const bool hasResetLine = model && model->capabilities.resetLine;
    m_resetLabel->setVisible(hasResetLine);
    m_resetLine->setVisible(hasResetLine);
    const LineSettings::ResetLine line = connectionsettings::resetLine(selectedModelId());
    m_resetLine->setCurrentIndex(m_resetLine->findData(resetLineName(line)));
}

void ConnectionBar::onConnected()
{
    if (!m_context->isConnectionMachine())
        return; // a machine file's ports are its file's: not recent ports, not followed
    const QString port = m_context->portName();
    connectionsettings::addRecentPort(port);
    if (m_autoReconnect->isChecked() && !m_watcher->isWatching())
        m_watcher->watch(port, m_scanner->ports());
    if (!m_reconnecting)
        return;
    m_reconnecting = false;
    Q_EMIT reconnected(
        tr("Reconnected to %1: the USB device came back. Positions are unknown until the axes "
           "are referenced; nothing was resumed (no jog, move or bridge).")
            .arg(port));
}

void ConnectionBar::onPortsScanned()
{
    if (m_context->hasMachineFile())
        return;
    // A link opened before the first scan came back is followed from the next one on.
    if (m_autoReconnect->isChecked() && m_context->isConnected() && !m_watcher->isWatching())
        m_watcher->watch(m_context->portName(), m_scanner->ports());
    m_watcher->update(m_scanner->ports());
}

void ConnectionBar::onDeviceReturned(const QString& path)
{
    ControllerSession* session = m_context->session();
    const LinkState state = session->linkState();
    if (!m_autoReconnect->isChecked() || m_context->hasMachineFile() ||
        (session->isCreated() && (state == LinkState::Connected || state == LinkState::Connecting)))
        return;
    // The link as it was (model, poll interval, reset line), on the device's new path.
    ConnectionSpec spec = currentSpec();
    spec.port = path;
    setPortSpec(path);
    m_reconnecting = true;
    if (!connectWith(spec)) {
        m_reconnecting = false;
        m_watcher->reconnectFailed();
    }
}

} // namespace stepdeck::ui
