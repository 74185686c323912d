#pragma once
#include "controller/Controller.h"
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace stepdeck::ui {

class LedIndicator;
class MachineContext;
class PortScanner;

// Model, port (serial ports with description and VID:PID, the simulator, tcp:// or a typed
// path), connect/disconnect, link state and the achieved poll rate.
class ConnectionBar : public QWidget
{
    Q_OBJECT
public:
    explicit ConnectionBar(MachineContext* context, QWidget* parent = nullptr);

    // What the port field names: "sim", a device path or "tcp://HOST:PORT".
    QString portSpec() const;
    void setPortSpec(const QString& spec);
    QString selectedModelId() const;
    void setSelectedModel(const QString& modelId);

    QComboBox* portCombo() const { return m_port; }
    QPushButton* connectButton() const { return m_connect; }

public Q_SLOTS:
    void connectNow();
    void disconnectNow();
    void toggleConnection();

Q_SIGNALS:
    void connectionFailed(const QString& reason);

private:
    void fillPorts();
    void onLinkState(LinkState state, const QString& reason);
    void onPollRate(double hz);

    MachineContext* m_context;
    PortScanner* m_scanner;
    QComboBox* m_model;
    QComboBox* m_port;
    QSpinBox* m_interval;
    QPushButton* m_connect;
    LedIndicator* m_link;
    QLabel* m_rate;
};

} // namespace stepdeck::ui
