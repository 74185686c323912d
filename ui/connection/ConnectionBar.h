#pragma once
#include "common/LedIndicator.h"
#include "controller/Controller.h"
#include "controller/ControllerSession.h"
#include <QElapsedTimer>
#include <QTime>
#include <QWidget>

class QAction;
class QComboBox;
class QLabel;
class QMenu;
class QToolButton;
class QPushButton;
class QSpinBox;
class QTimer;

namespace stepdeck::ui {

class MachineContext;
class PortScanner;
class PortWatcher;

// Model, port (serial ports with description and VID:PID, the simulator, tcp:// or a typed
// path), the reset line of models that have one, connect/disconnect, link state and the
// achieved poll rate. The options menu holds the recent ports and auto-reconnect: when the
// USB device of a link that was lost comes back (same VID:PID and serial number), the bar
// connects again -- with the safety rules of any new link: positions unknown, nothing
// resumes, and the operator is told (reconnected()).
class ConnectionBar : public QWidget
{
    Q_OBJECT
public:
    explicit ConnectionBar(MachineContext* context, QWidget* parent = nullptr);

    // What the port field names: "sim", a device path or "tcp://HOST:PORT".
    QString portSpec() const;
    void setPortSpec(const QString& spec);
    QString selectedModelId() const;
    // The status poll interval for the next connect (and the current link); false when ms is
    // outside the range the field offers.
    bool setPollInterval(int ms);
    void setSelectedModel(const QString& modelId);

    QComboBox* portCombo() const { return m_port; }
    QComboBox* modelCombo() const { return m_model; }
    // RTS or DTR (issue 7, E-LAB); hidden for models without a reset line.
    QComboBox* resetLineCombo() const { return m_resetLine; }
    QToolButton* optionsButton() const { return m_options; }
    QAction* autoReconnectAction() const { return m_autoReconnect; }
    QMenu* recentPortsMenu() const { return m_recentMenu; }
    PortScanner* portScanner() const { return m_scanner; }
    PortWatcher* portWatcher() const { return m_watcher; }
    // The spec a connect would use now (model, port, poll interval, reset line).
    ConnectionSpec currentSpec() const;
    QPushButton* connectButton() const { return m_connect; }
    LedIndicator* linkLamp() const { return m_link; }
    // The achieved poll rate ("20.0 Hz"); its size never follows its text.
    QLabel* rateLabel() const { return m_rate; }
    // "Connected", "No reply since 14:03:07", "Link lost", ...: what the lamp says.
    QString linkText() const;
    // Connected, but the device has not answered for several poll intervals: shown at once
    // (amber), before the core declares the link lost.
    bool replyOverdue() const { return m_overdue; }
    int overdueAfterMs() const;

public Q_SLOTS:
    void connectNow();
    void disconnectNow();
    void toggleConnection();

Q_SIGNALS:
    void connectionFailed(const QString& reason);
    // The same USB device came back and the link was opened again; text tells the operator
    // what that means (positions unknown, nothing resumed).
    void reconnected(const QString& text);
    void linkTextChanged(const QString& text, bool warning);

private:
    void buildOptions();
    void fillPorts();
    void fillRecentPorts();
    void updateResetLine();
    bool connectWith(const ConnectionSpec& spec);
    void onPortsScanned();
    void onDeviceReturned(const QString& path);
    void onConnected();
    void onLinkState(LinkState state, const QString& reason);
    void onPollRate(double hz);
    static QString rateText(double hz);
    void checkReplies();
    void showLink(LedIndicator::State state, const QString& text);

    MachineContext* m_context;
    PortScanner* m_scanner;
    PortWatcher* m_watcher;
    QComboBox* m_model;
    QComboBox* m_port;
    QLabel* m_resetLabel;
    QComboBox* m_resetLine;
    QToolButton* m_options;
    QMenu* m_recentMenu = nullptr;
    QAction* m_autoReconnect = nullptr;
    QSpinBox* m_interval;
    QPushButton* m_connect;
    LedIndicator* m_link;
    QLabel* m_rate;
    QTimer* m_replyWatch;
    QElapsedTimer m_sinceReply; // since the last byte from the device
    bool m_overdue = false;
    bool m_reconnecting = false; // the open under way is an automatic reconnect
    LinkState m_lastState = LinkState::Disconnected;
};

} // namespace stepdeck::ui
