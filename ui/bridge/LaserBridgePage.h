#pragma once
#include "bridge/LaserBridge.h"
#include "common/ElidedLabel.h"
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stepdeck {
class Transport;
}

namespace stepdeck::ui {

class MachineContext;
class PortScanner;

// The Laser bridge page: StepDeck is the motor axes of a laser marker, with the connected
// controller behind it (core: bridge::LaserBridge). The operator chooses the laser's port, the
// axis map, the scale and the reference directions, starts and stops the bridge, and watches a
// live log of the laser's frames and the answers, and the bridge's state per axis. STOP,
// PANIC and jog on the other pages keep priority: the bridge does not fight them.
class LaserBridgePage : public QWidget
{
    Q_OBJECT
public:
    // ports: the application's port scanner (the connection bar's); the page lists what it
    // found and never enumerates ports in the GUI thread itself.
    LaserBridgePage(MachineContext* context, PortScanner* ports, QWidget* parent = nullptr);
    ~LaserBridgePage() override;

    QComboBox* portCombo() const { return m_port; }
    QComboBox* mapCombo(Axis laserAxis) const { return m_map.value(laserAxis); }
    QComboBox* homeCombo(Axis laserAxis) const { return m_home.value(laserAxis); }
    QDoubleSpinBox* scaleSpin() const { return m_scale; }
    QSpinBox* doorInputSpin() const { return m_doorInput; }
    QPushButton* startButton() const { return m_start; }
    QPushButton* stopButton() const { return m_stop; }
    QLabel* stateLabel() const { return m_state; }
    QPlainTextEdit* logView() const { return m_log; }
    QTableWidget* axisTable() const { return m_table; }
    bridge::LaserBridge* bridge() const { return m_bridge; }
    bool isRunning() const;

public Q_SLOTS:
    void startBridge();
    void stopBridge();

private:
    QWidget* buildForm();
    void rebuildAxisChoices();
    void fillPorts();
    bool configFromForm(bridge::LaserBridgeConfig* config, QString* error) const;
    void appendLog(const bridge::LaserBridge::LogEntry& entry);
    void showAxis(const bridge::LaserBridge::AxisView& view);
    void onFinished();
    void updateControls();
    void setState(const QString& text, bool error = false);

    MachineContext* m_context;
    PortScanner* m_ports;
    QComboBox* m_port;
    QMap<Axis, QComboBox*> m_map;  // per laser axis: the controller axis (or none)
    QMap<Axis, QComboBox*> m_home; // per laser axis: reference direction
    QDoubleSpinBox* m_scale;
    QSpinBox* m_doorInput;
    QPushButton* m_start;
    QPushButton* m_stop;
    ElidedLabel* m_state;
    QTableWidget* m_table;
    QPlainTextEdit* m_log;
    Transport* m_laserPort = nullptr;
    bridge::LaserBridge* m_bridge = nullptr;
    bool m_stopping = false;
};

} // namespace stepdeck::ui
